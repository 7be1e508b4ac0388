# sphSolid -parallel under mpirun on copies of small cases (runSolver.sh says what each check
# compares). As root, OpenMPI starts only when told twice; each run has a time limit, so a hung
# rank fails the test instead of hanging the suite. On a busy machine (another job, or a second
# test suite beside this one) idle ranks must not spin: OpenMPI's ranks yield the core while they
# wait (mpi_yield_when_idle) and OpenMP's threads sleep (passive); CTest counts each run's ranks
# as processors, so `ctest -j2` runs a 3-rank test alone instead of beside another; the limit
# is for a hung rank, not a tight budget (issue 31, item 12).
set(sphSolverRunEnvironment "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_WAIT_POLICY=passive;OMPI_MCA_mpi_yield_when_idle=1")
set(sphDykaBar ${CMAKE_SOURCE_DIR}/tutorials/bar1D/dykaBar)

# sph_add_solver_run(NAME RANKS CASE CHECK [sphSolid arguments...])
function(sph_add_solver_run name ranks case check)
    add_test(NAME "parallel:sphSolid ${name}"
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/runSolver.sh ${MPIEXEC_EXECUTABLE}
                     ${CMAKE_BINARY_DIR}/bin ${case} ${ranks} ${check} ${ARGN})
    set_tests_properties("parallel:sphSolid ${name}" PROPERTIES
        TIMEOUT 400 PROCESSORS ${ranks} ENVIRONMENT "${sphSolverRunEnvironment}")
endfunction()

foreach(ranks 2 3)
    # A misspelled model name, through -set and in the file (the broken case of tests/errors).
    sph_add_solver_run("bad -set reported once on ${ranks} ranks" ${ranks} ${sphDykaBar} sameError
                       -set stabilisation.type=vidall)
    sph_add_solver_run("bad sphSchemes reported once on ${ranks} ranks" ${ranks}
                       ${CMAKE_SOURCE_DIR}/tests/errors/unknownStabilisation sameError)
endforeach()
# A dry run partitions the case and checks each rank's neighbourhoods, as the run would.
sph_add_solver_run("dry run once on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/hardCases/twistingColumn dryRunOnce)
sph_add_solver_run("dry run of a 1D case once on 2 ranks" 2 ${sphDykaBar} dryRunOnce)
sph_add_solver_run("on 1 rank writes the serial output" 1 ${sphDykaBar} sameResults
                   -threads 1 -set endTime=5e-4)
# 1D: the Dyka bar (the seed's first benchmark, 40 particles) to its end, 1.6 periods of the
# tip; and the bar's particle order, checked on each rank's local particles after every drift:
# at courant 1.9 the tip passes its neighbour at step 9, diagnosed once, as serially.
foreach(ranks 2 3)
    sph_add_solver_run("Dyka bar 1D bit-identical on ${ranks} ranks" ${ranks} ${sphDykaBar}
                       bitIdentical -threads 1)
endforeach()
sph_add_solver_run("1D particles crossing diagnosed once on 2 ranks" 2 ${sphDykaBar} sameFailure
                   -threads 1 -set courant=1.9 -set writeInterval=1e-4)
# What a distributed run cannot do is refused once, before anything is written: a user's
# function object that does not say it reduces over the ranks (FunctionObject::distributable;
# the test plugin's keeps a per-particle peak speed and says nothing).
# -parallel forgotten: two processes that would each run the whole case are refused.
sph_add_solver_run("without -parallel refused on 2 ranks" 2 ${sphDykaBar} withoutParallel -threads 1)
sph_add_solver_run("refuses a plugin's function object once on 2 ranks" 2 ${sphDykaBar} refused
                   -threads 1 -set "controlDict.libs=(\"${CMAKE_BINARY_DIR}/tests/plugin/libsphTestPlugin.so\")"
                   -set "functions={peak {type pluginPeakSpeed\;}}")

# Bit-identity with the serial run (issue 14): the twisting column (3D, 3072 particles, a fixed
# base), updated-Lagrangian gradF (the reference moves, and the ghosts are gathered again, every
# step) and total-Lagrangian gradF, on 2, 3 and 4 ranks.
set(sphTwistingColumn ${CMAKE_SOURCE_DIR}/tutorials/hardCases/twistingColumn)
# Too few neighbours in the initial configuration: a distributed run checks its ranks' shares
# when it first has them (it never builds the whole set's neighbourhoods on one rank), and
# reports the serial run's input error, once.
foreach(ranks 2 3)
    sph_add_solver_run("too few neighbours reported once on ${ranks} ranks" ${ranks}
                       ${sphTwistingColumn} sameError -set kernel.hOverDx=0.55)
endforeach()
sph_add_solver_run("too few neighbours reported once by a dry run on 2 ranks" 2
                   ${sphTwistingColumn} sameError -dryRun -set kernel.hOverDx=0.55)
foreach(ranks 2 3 4)
    sph_add_solver_run("UL gradF 3D column bit-identical on ${ranks} ranks" ${ranks}
                       ${sphTwistingColumn} bitIdentical -threads 1 -set endTime=0.01
                       -set writeInterval=0.005 -set functions={})
    sph_add_solver_run("TL gradF 3D column bit-identical on ${ranks} ranks" ${ranks}
                       ${sphTwistingColumn} bitIdentical -threads 1 -set endTime=0.01
                       -set writeInterval=0.005 -set functions={}
                       -set formulation.type=totalLagrangian)
endforeach()

# A numerical failure (det F <= 0 at one particle, owned by one rank: courant 1.5) stops every
# rank with the serial run's diagnosis, once, and the last good level as the serial run wrote it.
foreach(ranks 2 3)
    sph_add_solver_run("failure diagnosed once on ${ranks} ranks" ${ranks} ${sphTwistingColumn}
                       sameFailure -threads 1 -set endTime=0.02 -set courant=1.5
                       -set writeInterval=0.002 -set functions={})
endforeach()

# Particles that change owner during the run: the large-rotation plate (2D, UL gradF) spun at
# 40 rad/s, so its particles sweep across the ranks' regions, partitioned again whenever a rank
# holds 1 % more than the mean (maxLoadImbalance 1.01): still bit-identical.
sph_add_solver_run("migrating particles bit-identical on 3 ranks" 3
                   ${CMAKE_SOURCE_DIR}/tutorials/hardCases/largeRotation migrating -threads 1
                   -set endTime=0.01 -set writeInterval=0.0025 -set functions={}
                   -set bodies.plate.initialVelocity.spin.omega=40
                   -set controlDict.maxLoadImbalance=1.01)
# The same with the kick split at the moves (splitKick, gradF-plastic.md §G20): the closing
# forces, computed before a move, travel with their particles through the move's repartition.
sph_add_solver_run("migrating particles with the kick split bit-identical on 3 ranks" 3
                   ${CMAKE_SOURCE_DIR}/tutorials/hardCases/largeRotation migrating -threads 1
                   -set endTime=0.01 -set writeInterval=0.0025 -set functions={}
                   -set bodies.plate.initialVelocity.spin.omega=40
                   -set controlDict.maxLoadImbalance=1.01 -set formulation.splitKick=yes)
# On 4 ranks: the copper bar of the impact tutorial with UL gradF, its samples' plastic states
# migrating with their particles (12 repartitions in 394 steps). On 2 ranks these cases stay
# balanced (RCB cuts them along a symmetry, so both ranks hold the same load): migration on 2
# ranks is tested by the exchange itself (communicator, RCB and exchange on 2 ranks).
sph_add_solver_run("migrating particles with per-sample history bit-identical on 4 ranks" 4
                   ${CMAKE_SOURCE_DIR}/tutorials/plasticity2D/impact migrating -threads 1
                   -set endTime=1.5e-5 -set writeInterval=5e-6 -set formulation.type=updatedLagrangian
                   -set stabilisation.type=gradF -set controlDict.maxLoadImbalance=1.01)
set_property(TEST "parallel:sphSolid migrating particles with per-sample history bit-identical on 4 ranks"
             APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy wall")

# A graceful stop (SIGTERM to one rank alone): every rank stops at the same step, exit 5, and the
# run continued serially ends bit-identical to the uninterrupted serial one (issue 32, item 3).
sph_add_solver_run("stopped by SIGTERM on one of 2 ranks continues bit-identically" 2
                   ${sphDykaBar} signalOneRank -threads 1)

# Restart N -> M: stopped at 5 ms on N ranks, continued to 10 ms on M ranks (1: serially), the
# end bit-identical to the uninterrupted serial run (UL gradF: the reference, the integrator and
# the audit travel through the pieces).
foreach(pair "2;3" "3;2" "2;1")
    list(GET pair 0 first)
    list(GET pair 1 second)
    sph_add_solver_run("restart from ${first} on ${second} ranks bit-identical" ${first}
                       ${sphTwistingColumn} restartOn:${second}:0.005 -threads 1
                       -set endTime=0.01 -set writeInterval=0.0025 -set functions={})
endforeach()

# Contact between bodies on different ranks: the colliding rings (seed §3.2) on a 2 mm lattice
# (1120 particles), to 20 ms: the rings meet at about 3.4 ms (within the 6 mm kernel support)
# and are pressed together to the end. RCB puts the rings on different ranks (2) or splits
# them (3, 4); the contact ghosts are gathered again as the rings move. Updated-Lagrangian gradF
# on 2, 3, 4 ranks, total-Lagrangian gradF on 2 and 3 (its contact ghosts have cut
# neighbourhoods in X, which nothing may read).
set(sphCollidingRings ${CMAKE_SOURCE_DIR}/tutorials/rings2D/collidingRings)
set(sphCoarseRings "ringA.spacing=2e-3 ringB.spacing=2e-3")
foreach(ranks 2 3 4)
    sph_add_solver_run("rings with contact UL gradF bit-identical on ${ranks} ranks" ${ranks}
                       ${sphCollidingRings} bitIdentical -threads 1 -set endTime=0.02
                       -set writeInterval=0.004 -set functions={} -set courant=0.3)
    set_property(TEST "parallel:sphSolid rings with contact UL gradF bit-identical on ${ranks} ranks"
                 APPEND PROPERTY ENVIRONMENT "SPH_PARTICLES_SET=${sphCoarseRings}")
endforeach()
foreach(ranks 2 3)
    sph_add_solver_run("rings with contact TL gradF bit-identical on ${ranks} ranks" ${ranks}
                       ${sphCollidingRings} bitIdentical -threads 1 -set endTime=0.02
                       -set writeInterval=0.004 -set functions={} -set courant=0.3
                       -set formulation.type=totalLagrangian)
    set_property(TEST "parallel:sphSolid rings with contact TL gradF bit-identical on ${ranks} ranks"
                 APPEND PROPERTY ENVIRONMENT "SPH_PARTICLES_SET=${sphCoarseRings}")
endforeach()

# Function objects on several ranks: each visits the owned particles, reduces over the ranks, and
# rank 0 writes postProcessing/. The flagship tutorial as it is (extent, energy, stability monitor,
# snapshots of every particle) on the coarse lattice, and the twisting column's own (a probe at
# the free corner, energy, stability monitor): every table identical to the serial run's but
# the energy balance (a sum over the ranks: round-off).
foreach(ranks 2 3)
    sph_add_solver_run("flagship rings with function objects bit-identical on ${ranks} ranks" ${ranks}
                       ${sphCollidingRings} bitIdentical -threads 1 -set endTime=0.02
                       -set writeInterval=0.01 -set courant=0.3)
    set_property(TEST "parallel:sphSolid flagship rings with function objects bit-identical on ${ranks} ranks"
                 APPEND PROPERTY ENVIRONMENT "SPH_PARTICLES_SET=${sphCoarseRings}")
endforeach()
sph_add_solver_run("column with function objects bit-identical on 2 ranks" 2 ${sphTwistingColumn}
                   bitIdentical -threads 1 -set endTime=0.01 -set writeInterval=0.005)
sph_add_solver_run("restart from 2 on 3 ranks with function objects" 2 ${sphTwistingColumn}
                   restartOn:3:0.005 -threads 1 -set endTime=0.01 -set writeInterval=0.0025)

# The flagship tutorial copied out of the tree and run as its README says: ./Allrun -np 2.
add_test(NAME "parallel:flagship Allrun -np 2 from a copy"
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/allrunParallel.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR})
set_tests_properties("parallel:flagship Allrun -np 2 from a copy" PROPERTIES
    TIMEOUT 400 PROCESSORS 2 ENVIRONMENT "OMP_WAIT_POLICY=passive;OMPI_MCA_mpi_yield_when_idle=1")

# Rigid walls: the copper bar of tutorials/plasticity2D/impact made elastic (hencky) hits the
# wall at 227 m/s; each rank applies the wall to its own particles and the wall's loads are summed
# over the ranks (wallForce and the energy balance to round-off, every other table and output
# bit for bit).
foreach(ranks 2 3)
    sph_add_solver_run("impact on a wall bit-identical on ${ranks} ranks" ${ranks}
                       ${CMAKE_SOURCE_DIR}/tutorials/plasticity2D/impact bitIdentical -threads 1
                       -set endTime=2e-5 -set writeInterval=1e-5
                       -set "bodies.bar.material={type hencky\\; E 117e9\\; nu 0.35\\; rho 8930\\;}")
    set_property(TEST "parallel:sphSolid impact on a wall bit-identical on ${ranks} ranks"
                 APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy wall")
    # With Monaghan's artificial viscosity: pairs in x^n reading the neighbours' v, so the
    # ghosts in x and their velocities are refreshed; its bound on the time step is agreed by
    # every rank (the run takes 1224 steps instead of 569: the same on every rank count).
    sph_add_solver_run("impact with artificial viscosity bit-identical on ${ranks} ranks" ${ranks}
                       ${CMAKE_SOURCE_DIR}/tutorials/plasticity2D/impact bitIdentical -threads 1
                       -set endTime=2e-5 -set writeInterval=1e-5
                       -set "bodies.bar.material={type hencky\\; E 117e9\\; nu 0.35\\; rho 8930\\;}"
                       -set "sphSchemes.artificialViscosity={type monaghan\\;}")
    set_property(TEST "parallel:sphSolid impact with artificial viscosity bit-identical on ${ranks} ranks"
                 APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy wall")
endforeach()

# Plastic materials: the impact tutorial as it is (a j2Plasticity copper bar, TL none) on 2 and
# 3 ranks; UL gradF with its per-sample history (plasticSamples ownHistory, the default) on 2
# and 3 (to 15 us: UL gradF fails at the wall at 19 us, serially as distributed), and with
# plasticSamples linearised on 2. Each particle's plastic history is a registry
# field, and gradF's samples a ragged one (a state per neighbour pair, keyed by the neighbour's
# global id), so both travel with their particle; every rank commits its ghosts too (their
# stress is read in the next force evaluation), and only owned particles count in the
# dissipated energy.
set(sphImpact ${CMAKE_SOURCE_DIR}/tutorials/plasticity2D/impact)
set(sphImpactUL -set formulation.type=updatedLagrangian -set stabilisation.type=gradF)
foreach(ranks 2 3)
    sph_add_solver_run("plastic impact bit-identical on ${ranks} ranks" ${ranks} ${sphImpact}
                       bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5)
    sph_add_solver_run("plastic impact UL gradF per-sample history bit-identical on ${ranks} ranks"
                       ${ranks} ${sphImpact} bitIdentical -threads 1 -set endTime=1.5e-5
                       -set writeInterval=5e-6 ${sphImpactUL})
endforeach()
sph_add_solver_run("plastic impact UL gradF linearised bit-identical on 2 ranks" 2 ${sphImpact}
                   bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactUL} -set stabilisation.plasticSamples=linearised)
# plasticSamples elasticState (docs/theory/gradF-plastic.md): the samples' states rebased at every
# move, new pairs started from the neighbour's state (a ghost's, at a rank's edge), F^r the
# dilation; with the moves' energy tabulated (a collective energy evaluation before each move).
# And with the samples' energy weights chosen at every move (moveWeights conserving, §G9: per-pair
# state that travels with its particle).
sph_add_solver_run("plastic impact UL gradF elasticState conserving weights bit-identical on 2 ranks" 2
                   ${sphImpact} bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactUL} -set stabilisation.plasticSamples=elasticState
                   -set stabilisation.moveWeights=conserving
                   -set controlDict.functions.energy.referenceMoves=yes)
# The kick split at the moves (updatedLagrangian splitKick, gradF-plastic.md §G20): the closing
# forces with the reference before each move (ghosts read as in any evaluation), their difference
# from the level's kept per particle.
sph_add_solver_run("plastic impact UL gradF elasticState split kick bit-identical on 2 ranks" 2
                   ${sphImpact} bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactUL} -set stabilisation.plasticSamples=elasticState
                   -set stabilisation.moveWeights=conserving
                   -set "formulation={ type updatedLagrangian$<SEMICOLON> referenceUpdateInterval 3$<SEMICOLON> splitKick yes$<SEMICOLON> }")
# Moves by the strain since the last one (referenceUpdateStrain, §G21): the largest strain is a
# maximum over every rank's owned particles, so every rank moves at the serial run's levels.
sph_add_solver_run("plastic impact UL gradF elasticState moves by strain bit-identical on 2 ranks" 2
                   ${sphImpact} bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactUL} -set stabilisation.plasticSamples=elasticState
                   -set "formulation={ type updatedLagrangian$<SEMICOLON> referenceUpdateStrain 2e-4$<SEMICOLON> splitKick yes$<SEMICOLON> }")
# The step from the forces' measured largest frequency (docs/theory/timeStep.md): the probe's
# perturbed ghosts take their owners' mode, its sums are exact in any order, so every rank takes
# the serial run's steps.
# (writeControl timeStep: the steps are the integrator's own, not split to land on the tables'
# times, so that a step differing in its last bit would show.)
sph_add_solver_run("plastic impact UL gradF elasticState stepBound operator bit-identical on 2 ranks" 2
                   ${sphImpact} bitIdentical -threads 1 -set endTime=2e-5
                   ${sphImpactUL} -set stabilisation.plasticSamples=elasticState
                   -set controlDict.writeControl=timeStep -set writeInterval=250
                   -set "sphSchemes.timeIntegration={ stepBound operator\\; probeInterval 7\\; }")
# With the close-pair energy (docs/theory/impenetrability.md) at a distance where it acts from the
# first step (0.9 spacings: pairs across a rank's edge read the ghosts' positions).
sph_add_solver_run("plastic impact UL gradF elasticState impenetrability bit-identical on 2 ranks" 2
                   ${sphImpact} bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactUL} -set stabilisation.plasticSamples=elasticState
                   -set "sphSchemes.impenetrability={ distance 0.9$<SEMICOLON> }")
# Total-Lagrangian elasticState (gradF-plastic.md §G25): each particle's frame (F°, G°, x° of the
# last commit) is a registry field, and a sample reads its neighbour's x° (a ghost's at a rank's
# edge); every rank moves its frames and rebases its samples at each commit. Distributed, and
# continued serially from a distributed output.
set(sphImpactTLFrames -set stabilisation.type=gradF -set stabilisation.plasticSamples=elasticState)
sph_add_solver_run("plastic impact TL gradF elasticState bit-identical on 2 ranks" 2 ${sphImpact}
                   bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactTLFrames})
sph_add_solver_run("plastic impact TL gradF elasticState restart from 2 on 1 ranks bit-identical" 2
                   ${sphImpact} restartOn:1:1e-5 -threads 1 -set endTime=1.5e-5
                   -set writeInterval=5e-6 ${sphImpactTLFrames})
# The joint fit's frame terms (§G26: the increment fitted in x°, its pairs' linear part too).
sph_add_solver_run("plastic impact TL gradF elasticState fit joint bit-identical on 2 ranks" 2
                   ${sphImpact} bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactTLFrames} -set stabilisation.fit=joint)
# Moment points (gradF-moments.md): each particle's points from its reference neighbourhood
# (a ghost's too), neighbouring particles' samples returned in one block of lanes, their states
# in the history's first slots. Distributed, and continued serially from a distributed output.
set(sphImpactTLMoments -set stabilisation.type=gradF -set stabilisation.samplePoints=moments)
sph_add_solver_run("plastic impact TL gradF moments bit-identical on 2 ranks" 2 ${sphImpact}
                   bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactTLMoments})
sph_add_solver_run("plastic impact TL gradF moments restart from 2 on 1 ranks bit-identical" 2
                   ${sphImpact} restartOn:1:1e-5 -threads 1 -set endTime=1.5e-5
                   -set writeInterval=5e-6 ${sphImpactTLMoments})
# In updated Lagrangian form with plastic history (§M7): the points turn with the material at
# each move, their axes a restart field, their states laid out per particle; written on 2 ranks
# and continued on 3.
set(sphImpactULMoments -set formulation.type=updatedLagrangian -set stabilisation.type=gradF
    -set stabilisation.plasticSamples=elasticState -set stabilisation.samplePoints=moments)
sph_add_solver_run("plastic impact UL gradF moments bit-identical on 2 ranks" 2 ${sphImpact}
                   bitIdentical -threads 1 -set endTime=2e-5 -set writeInterval=1e-5
                   ${sphImpactULMoments})
sph_add_solver_run("plastic impact UL gradF moments restart from 2 on 3 ranks bit-identical" 2
                   ${sphImpact} restartOn:3:1e-5 -threads 1 -set endTime=1.5e-5
                   -set writeInterval=5e-6 ${sphImpactULMoments})
# The samples' states travel through the output's pieces: written on 2 ranks, continued on 3
# and serially.
foreach(second 3 1)
    sph_add_solver_run("plastic impact UL gradF restart from 2 on ${second} ranks bit-identical" 2
                       ${sphImpact} restartOn:${second}:1e-5 -threads 1 -set endTime=1.5e-5
                       -set writeInterval=5e-6 ${sphImpactUL})
endforeach()
foreach(test "plastic impact bit-identical on 2 ranks" "plastic impact bit-identical on 3 ranks"
             "plastic impact UL gradF per-sample history bit-identical on 2 ranks"
             "plastic impact UL gradF per-sample history bit-identical on 3 ranks"
             "plastic impact UL gradF linearised bit-identical on 2 ranks"
             "plastic impact UL gradF elasticState conserving weights bit-identical on 2 ranks"
             "plastic impact UL gradF elasticState split kick bit-identical on 2 ranks"
             "plastic impact UL gradF elasticState moves by strain bit-identical on 2 ranks"
             "plastic impact UL gradF elasticState stepBound operator bit-identical on 2 ranks"
             "plastic impact UL gradF elasticState impenetrability bit-identical on 2 ranks"
             "plastic impact UL gradF restart from 2 on 3 ranks bit-identical"
             "plastic impact UL gradF restart from 2 on 1 ranks bit-identical"
             "plastic impact TL gradF elasticState bit-identical on 2 ranks"
             "plastic impact TL gradF elasticState restart from 2 on 1 ranks bit-identical"
             "plastic impact TL gradF elasticState fit joint bit-identical on 2 ranks"
             "plastic impact TL gradF moments bit-identical on 2 ranks"
             "plastic impact TL gradF moments restart from 2 on 1 ranks bit-identical"
             "plastic impact UL gradF moments bit-identical on 2 ranks"
             "plastic impact UL gradF moments restart from 2 on 3 ranks bit-identical")
    set_property(TEST "parallel:sphSolid ${test}" APPEND PROPERTY ENVIRONMENT
                 "SPH_ROUNDOFF_TABLES=energy wall")
endforeach()
# In 3D: the Taylor bar (copper, yielding from the first step) with UL gradF's samples.
sph_add_solver_run("Taylor bar UL gradF per-sample history bit-identical on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/plasticity3D/taylorBar bitIdentical -threads 1
                   -set endTime=4e-6 -set writeInterval=2e-6 -set functions={}
                   -set formulation.type=updatedLagrangian -set stabilisation.type=gradF)
# Its moment points in 3D: two particles' seven points a block.
sph_add_solver_run("Taylor bar TL gradF moments bit-identical on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/plasticity3D/taylorBar bitIdentical -threads 1
                   -set endTime=4e-6 -set writeInterval=2e-6 -set functions={}
                   -set stabilisation.type=gradF -set stabilisation.samplePoints=moments)
# A geomaterial: the column collapse tutorial as it is (druckerPrager sand under gravity
# between walls; issue 29's UL gradF: samples that carry their elastic state, the moves' energy
# weights chosen per pair, the close-pair energy, the reference moved every fifth step; every
# function object of the tutorial: surface profiles, snapshots of plasticStrain), on 2 ranks,
# through the opening of the front (0.04 s).
sph_add_solver_run("geomaterial column collapse bit-identical on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/geomaterials/columnCollapse bitIdentical -threads 1
                   -set endTime=0.04 -set writeInterval=0.02
                   -set functions.surface.writeInterval=0.02 -set functions.particles.writeInterval=0.02)
set_property(TEST "parallel:sphSolid geomaterial column collapse bit-identical on 2 ranks"
             APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy walls")
# The same with the samples of opened particles taking their state at each move
# (openedSamples particle, gradF-plastic.md §G22): an owned particle's samples of a ghost take
# the ghost's state, which the ghost computes from its own (inner) neighbourhood.
sph_add_solver_run("geomaterial column collapse openedSamples bit-identical on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/geomaterials/columnCollapse bitIdentical -threads 1
                   -set endTime=0.06 -set writeInterval=0.03
                   -set functions.surface.writeInterval=0.03 -set functions.particles.writeInterval=0.03
                   -set stabilisation.openedSamples=particle)
set_property(TEST "parallel:sphSolid geomaterial column collapse openedSamples bit-identical on 2 ranks"
             APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy walls")
# The same with total-Lagrangian gradF (per-sample history since t = 0).
sph_add_solver_run("geomaterial column collapse TL gradF bit-identical on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/geomaterials/columnCollapse bitIdentical -threads 1
                   -set endTime=0.02 -set writeInterval=0.01
                   -set functions.surface.writeInterval=0.01 -set functions.particles.writeInterval=0.01
                   -set "formulation={ type totalLagrangian$<SEMICOLON> }" -set "stabilisation={ type gradF$<SEMICOLON> }"
                   -set "impenetrability={ distance 0$<SEMICOLON> }")
set_property(TEST "parallel:sphSolid geomaterial column collapse TL gradF bit-identical on 2 ranks"
             APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy walls")
# The collapse as a 3D slab between frictionless side walls (tutorials/geomaterials/
# columnCollapse3D: five walls, the geostatic start in 3D, TL gradF's per-sample history, the
# mid-plane surface profile), 2 000 particles, on 2 ranks (issue 33).
sph_add_solver_run("geomaterial column collapse 3D slab bit-identical on 2 ranks" 2
                   ${CMAKE_SOURCE_DIR}/tutorials/geomaterials/columnCollapse3D bitIdentical -threads 1
                   -set endTime=0.01 -set writeInterval=0.005
                   -set functions.surface.writeInterval=0.005 -set functions.particles.writeInterval=0.005)
set_property(TEST "parallel:sphSolid geomaterial column collapse 3D slab bit-identical on 2 ranks"
             APPEND PROPERTY ENVIRONMENT "SPH_ROUNDOFF_TABLES=energy walls")
