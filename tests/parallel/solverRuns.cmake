# sphSolid -parallel under mpirun on copies of small cases (runSolver.sh says what each check
# compares). As root, OpenMPI starts only when told twice; each run has a time limit, so a hung
# rank fails the test instead of hanging the suite.
set(sphSolverRunEnvironment "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_WAIT_POLICY=passive")
set(sphDykaBar ${CMAKE_SOURCE_DIR}/tutorials/bar1D/dykaBar)

# sph_add_solver_run(NAME RANKS CASE CHECK [sphSolid arguments...])
function(sph_add_solver_run name ranks case check)
    add_test(NAME "parallel:sphSolid ${name}"
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/runSolver.sh ${MPIEXEC_EXECUTABLE}
                     ${CMAKE_BINARY_DIR}/bin ${case} ${ranks} ${check} ${ARGN})
    set_tests_properties("parallel:sphSolid ${name}" PROPERTIES
        TIMEOUT 120 ENVIRONMENT "${sphSolverRunEnvironment}")
endfunction()

foreach(ranks 2 3)
    # A misspelled model name, through -set and in the file (the broken case of tests/errors).
    sph_add_solver_run("bad -set reported once on ${ranks} ranks" ${ranks} ${sphDykaBar} sameError
                       -set stabilisation.type=vidall)
    sph_add_solver_run("bad sphSchemes reported once on ${ranks} ranks" ${ranks}
                       ${CMAKE_SOURCE_DIR}/tests/errors/unknownStabilisation sameError)
endforeach()
sph_add_solver_run("dry run once on 2 ranks" 2 ${sphDykaBar} dryRunOnce)
sph_add_solver_run("on 1 rank writes the serial output" 1 ${sphDykaBar} sameResults
                   -threads 1 -set endTime=5e-4)
sph_add_solver_run("refuses a 1D case on 2 ranks" 2 ${sphDykaBar} refused)

# Bit-identity with the serial run (issue 14): the twisting column (3D, 3072 particles, a fixed
# base), updated-Lagrangian gradF (the reference moves, and the ghosts are gathered again, every
# step) and total-Lagrangian gradF, on 2, 3 and 4 ranks.
set(sphTwistingColumn ${CMAKE_SOURCE_DIR}/tutorials/hardCases/twistingColumn)
foreach(ranks 2 3 4)
    sph_add_solver_run("UL gradF 3D column bit-identical on ${ranks} ranks" ${ranks}
                       ${sphTwistingColumn} bitIdentical -threads 1 -set endTime=0.01
                       -set writeInterval=0.005 -set functions={})
    sph_add_solver_run("TL gradF 3D column bit-identical on ${ranks} ranks" ${ranks}
                       ${sphTwistingColumn} bitIdentical -threads 1 -set endTime=0.01
                       -set writeInterval=0.005 -set functions={}
                       -set formulation.type=totalLagrangian)
endforeach()
