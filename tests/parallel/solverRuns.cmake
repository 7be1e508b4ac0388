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
sph_add_solver_run("run on 2 ranks not available yet" 2 ${sphDykaBar} notAvailable)
