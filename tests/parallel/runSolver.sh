#!/usr/bin/env bash
# Runs sphSolid under `mpirun -np RANKS sphSolid -parallel` on a copy of a case and checks one
# thing against the serial run (tests/parallel/solverRuns.cmake adds the tests).
# Usage: runSolver.sh MPIEXEC BIN_DIR CASE_DIR RANKS CHECK [sphSolid arguments...]
#   sameError     the serial run fails with exit 1; the parallel run exits 1 with the serial
#                 run's message (its stderr) exactly once in stdout+stderr
#   dryRunOnce    -dryRun: exit 0, the header and the "Dry run" line once, "Ranks  RANKS"
#   sameResults   exit 0 both, and VTK/ and postProcessing/*/*.dat identical (cmp) to serial
#   bitIdentical  exit 0 both, and every output VTK/NAME_<n>.pvtu (read with VTK's parallel
#                 reader) bit-identical to the serial VTK/NAME_<n>.vtu: positions, velocities, F;
#                 the function objects' tables identical (the energy balance to round-off)
#   migrating     bitIdentical, and the particles were partitioned again during the run
#   sameFailure   exit 2 both (a numerical failure), the serial diagnosis line once, and the
#                 last good level written bit-identical to the serial one
#   restartOn:M:T the run stopped at time T on RANKS ranks, then continued to its endTime on M
#                 ranks (M = 1: serially, without -parallel), ends bit-identical to the
#                 uninterrupted serial run, with its tables (as bitIdentical)
#   refused       exit 1 with the one "does not run on several ranks yet" message; no VTK/
#   withoutParallel  mpirun -np RANKS sphSolid with -parallel forgotten: the processes refuse
#                 (each would run the whole case over the same files), mpirun exits non-zero,
#                 no VTK/ (issue 31 item 11: all exited 0 before)
#   signalOneRank the parallel run gets SIGTERM on its last rank alone after its second output:
#                 every rank stops at the same step (exit 5, summary "stopped" by SIGTERM), and
#                 continued serially (startFrom latestTime) it ends bit-identical to the
#                 uninterrupted serial run, with its tables (as bitIdentical)
# The case is copied into a temporary folder (never written in place). -parallel goes last, so
# columns in messages about the command line are those of the serial run.
set -u
mpiexec=$1
bin=$2
case=$3
ranks=$4
check=$5
shift 5
name=$(basename "$case")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0

fail()
{
    echo "FAIL: $*"
    status=1
}

# How many times $2 occurs in $1.
occurrences()
{
    local text=$1 count=0
    [ -z "$2" ] && { echo 0; return; }
    while [[ "$text" == *"$2"* ]]; do
        text=${text#*"$2"}
        count=$((count + 1))
    done
    echo "$count"
}

expectCode()
{
    [ "$1" = "$2" ] || fail "$3 exited with $1, expected $2"
}

expectOnce()
{
    local count
    count=$(occurrences "$output" "$1")
    [ "$count" = 1 ] || fail "found $count times in the parallel output (expected once): $1"
}

# A copy of the case in $1/NAME, with its particles (sphParticles, if the case has none yet).
copyCase()
{
    mkdir -p "$1" && cp -r "$case" "$1/$name"
    if [ ! -e "$1/$name/constant/particles.vtu" ] && [ -e "$1/$name/system/particlesDict" ]; then
        # SPH_PARTICLES_SET: -set options for sphParticles, space-separated (a coarser lattice)
        local options=()
        for option in ${SPH_PARTICLES_SET:-}; do options+=(-set "$option"); done
        (cd "$1/$name" && "$bin/sphParticles" -case . "${options[@]}" >/dev/null) ||
            fail "sphParticles failed"
    fi
}

# The serial run in serial/NAME, its stdout and stderr apart (serialOut, serialErr, serialCode).
runSerial()
{
    copyCase "$work/serial"
    (cd "$work/serial/$name" && "$bin/sphSolid" -case . "$@" >"$work/serial.out" 2>"$work/serial.err")
    serialCode=$?
    serialErr=$(cat "$work/serial.err")
}

# The parallel run in parallel/NAME, stdout and stderr together in output (as a user sees it).
runParallel()
{
    copyCase "$work/parallel"
    output=$(cd "$work/parallel/$name" &&
        "$mpiexec" --oversubscribe -np "$ranks" "$bin/sphSolid" -case . "$@" -parallel 2>&1)
    code=$?
    echo "$output"
    echo "--- exit code $code"
    if echo "$output" | grep -qE "Segmentation|terminate called|core dumped|MPI_ABORT"; then
        fail "a rank crashed or aborted instead of reporting the error"
    fi
}

# The function objects' tables (postProcessing/*/*.dat) of the two runs: identical, byte for
# byte, but for the energy balance (and the function objects SPH_ROUNDOFF_TABLES names, e.g.
# "energy wall" for wallForce), sums over the ranks that may differ at round-off: every
# value within 1e-9 of the largest magnitude in the table (the kinetic or total energy; a
# momentum that is zero to round-off has no scale of its own).
# Usage: compareTables [the parallel run's case folder]
compareTables()
{
    local serialTables parallelTables file other=${1:-$work/parallel/$name}
    serialTables=$(cd "$work/serial/$name" && find postProcessing -name "*.dat" 2>/dev/null | sort)
    parallelTables=$(cd "$other" && find postProcessing -name "*.dat" 2>/dev/null | sort)
    [ "$serialTables" = "$parallelTables" ] ||
        fail "different tables: serial ($serialTables) parallel ($parallelTables)"
    for file in $serialTables; do
        if [[ " ${SPH_ROUNDOFF_TABLES:-energy} " == *" $(basename "$(dirname "$file")") "* ]]; then
            awk 'NR == FNR { line[FNR] = $0; n1 = FNR; next }
                 /^#/ { if ($0 != line[FNR]) bad = 1; next }
                 { n = split(line[FNR], s); if (n != NF) bad = 1
                   for (i = 1; i <= NF; ++i) { v[FNR, i] = $i; w[FNR, i] = s[i]
                     m = $i < 0 ? -$i : $i; if (i > 1 && m > top) top = m } rows = FNR; cols = NF }
                 END { if (rows != n1) bad = 1
                       for (r = 1; r <= rows; ++r) {
                         if (v[r, 1] != w[r, 1]) bad = 1
                         for (i = 2; i <= cols; ++i) {
                           d = v[r, i] - w[r, i]; if (d < 0) d = -d
                           if (d > 1e-9 * top) bad = 1 } }
                       exit bad }' "$work/serial/$name/$file" "$other/$file" ||
                fail "$file differs beyond round-off"
        else
            cmp "$work/serial/$name/$file" "$other/$file" || fail "$file differs"
        fi
    done
    [ -z "$serialTables" ] || echo "compared $(echo "$serialTables" | wc -l) postProcessing tables"
}

case $check in
sameError)
    runSerial "$@"
    runParallel "$@"
    expectCode "$serialCode" 1 "the serial run"
    expectCode "$code" 1 "the parallel run"
    [ -n "$serialErr" ] || fail "the serial run printed no error"
    expectOnce "$serialErr"
    expectOnce "FATAL"
    ;;
dryRunOnce)
    runParallel -dryRun "$@"
    expectCode "$code" 0 "the parallel dry run"
    expectOnce "Dry run: every dictionary is valid and every model was built; not running."
    expectOnce "Threads     "
    expectOnce "Ranks       $ranks"
    ;;
sameResults)
    runSerial "$@"
    runParallel "$@"
    expectCode "$serialCode" 0 "the serial run"
    expectCode "$code" 0 "the parallel run"
    expectOnce $'\nEnd: ' # the last line of a run
    serialFiles=$(cd "$work/serial/$name" && find VTK postProcessing -name "*.vtu" -o -name "*.pvd" -o -name "*.dat" | sort)
    parallelFiles=$(cd "$work/parallel/$name" && find VTK postProcessing -name "*.vtu" -o -name "*.pvd" -o -name "*.dat" | sort)
    [ -n "$serialFiles" ] || fail "the serial run wrote no output"
    [ "$serialFiles" = "$parallelFiles" ] || fail "different files: serial ($serialFiles) parallel ($parallelFiles)"
    for file in $serialFiles; do
        cmp "$work/serial/$name/$file" "$work/parallel/$name/$file" || fail "$file differs"
    done
    echo "compared $(echo "$serialFiles" | wc -l) files"
    ;;
bitIdentical | migrating)
    runSerial "$@"
    runParallel "$@"
    expectCode "$serialCode" 0 "the serial run"
    expectCode "$code" 0 "the parallel run"
    expectOnce $'\nEnd: '
    outputs=0
    for file in "$work/serial/$name"/VTK/"$name"_*.vtu; do
        [ -e "$file" ] || break
        pvtu="$work/parallel/$name/VTK/$(basename "$file" .vtu).pvtu"
        "$bin/compareOutputs" "$file" "$pvtu" || fail "$(basename "$pvtu") differs from the serial output"
        outputs=$((outputs + 1))
    done
    [ "$outputs" -gt 1 ] || fail "the serial run wrote $outputs outputs"
    serialTimes=$(grep -o 'timestep="[^"]*"' "$work/serial/$name/VTK/$name.pvd")
    parallelTimes=$(grep -o 'timestep="[^"]*"' "$work/parallel/$name/VTK/$name.pvd")
    [ "$serialTimes" = "$parallelTimes" ] || fail "the .pvd series list other times"
    echo "compared $outputs outputs"
    compareTables
    if [ "$check" = migrating ]; then
        echo "$output" | grep -qE "^Ranks +$ranks: .* [1-9][0-9]* repartitions" ||
            fail "no repartition during the run"
    fi
    ;;
sameFailure)
    runSerial "$@"
    runParallel "$@"
    expectCode "$serialCode" 2 "the serial run"
    expectCode "$code" 2 "the parallel run"
    expectOnce "--> sphSolid NUMERICAL FAILURE"
    diagnosis=$(echo "$serialErr" | grep -A1 "NUMERICAL FAILURE" | tail -1)
    [ -n "$diagnosis" ] || fail "the serial run gave no diagnosis"
    expectOnce "$diagnosis"
    last=$(grep -o 'file="[^"]*"' "$work/serial/$name/VTK/$name.pvd" | tail -1 | cut -d'"' -f2)
    "$bin/compareOutputs" "$work/serial/$name/VTK/$last" \
        "$work/parallel/$name/VTK/$(basename "$last" .vtu).pvtu" ||
        fail "the last good level differs from the serial one"
    ;;
restartOn:*)
    IFS=: read -r _ continueRanks stopTime <<<"$check"
    runSerial "$@"
    expectCode "$serialCode" 0 "the serial run"
    copyCase "$work/restarted"
    dir="$work/restarted/$name"
    (cd "$dir" && "$mpiexec" --oversubscribe -np "$ranks" "$bin/sphSolid" -case . "$@" \
        -set endTime="$stopTime" -parallel >"$work/first.log" 2>&1)
    expectCode "$?" 0 "the first part on $ranks ranks"
    if [ "$continueRanks" = 1 ]; then
        (cd "$dir" && "$bin/sphSolid" -case . "$@" -set controlDict.startFrom=latestTime \
            >"$work/second.log" 2>&1)
    else
        (cd "$dir" && "$mpiexec" --oversubscribe -np "$continueRanks" "$bin/sphSolid" -case . "$@" \
            -set controlDict.startFrom=latestTime -parallel >"$work/second.log" 2>&1)
    fi
    expectCode "$?" 0 "the continuation on $continueRanks ranks"
    cat "$work/first.log" "$work/second.log"
    grep -q "^Restart     from $name" "$work/second.log" || fail "the continuation did not restart"
    last=$(grep -o 'file="[^"]*"' "$work/serial/$name/VTK/$name.pvd" | tail -1 | cut -d'"' -f2)
    stem=$(basename "$last" .vtu)
    ending="$stem.pvtu"
    [ "$continueRanks" = 1 ] && ending="$stem.vtu"
    "$bin/compareOutputs" "$work/serial/$name/VTK/$last" "$dir/VTK/$ending" ||
        fail "$ending differs from the serial run's $last"
    compareTables "$dir"
    ;;
signalOneRank)
    runSerial "$@"
    expectCode "$serialCode" 0 "the serial run"
    copyCase "$work/stopped"
    dir="$work/stopped/$name"
    (cd "$dir" && exec "$mpiexec" --oversubscribe -np "$ranks" "$bin/sphSolid" -case . "$@" \
        -parallel >"$work/first.log" 2>&1) &
    launcher=$!
    for _ in $(seq 600); do
        [ "$(grep -c 'file=' "$dir/VTK/$name.pvd" 2>/dev/null)" -ge 2 ] 2>/dev/null && break
        sleep 0.05
    done
    # The last rank: the child of mpirun whose environment says so.
    target=""
    for pid in $(pgrep -P "$launcher"); do
        if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null |
            grep -qx "OMPI_COMM_WORLD_RANK=$((ranks - 1))"; then
            target=$pid
        fi
    done
    [ -n "$target" ] || fail "no rank $((ranks - 1)) among the children of mpirun"
    [ -n "$target" ] && kill -TERM "$target"
    wait "$launcher"
    expectCode "$?" 5 "the run stopped by SIGTERM on $ranks ranks"
    cat "$work/first.log"
    output=$(cat "$work/first.log")
    expectOnce "Stopping    SIGTERM: writing step"
    grep -q '"stoppedBy": "SIGTERM"' "$dir/postProcessing/summary.json" ||
        fail "summary.json does not say stopped by SIGTERM"
    (cd "$dir" && "$bin/sphSolid" -case . "$@" -set controlDict.startFrom=latestTime \
        >"$work/second.log" 2>&1)
    expectCode "$?" 0 "the serial continuation"
    cat "$work/second.log"
    grep -q "^Restart     from $name" "$work/second.log" || fail "the continuation did not restart"
    last=$(grep -o 'file="[^"]*"' "$work/serial/$name/VTK/$name.pvd" | tail -1 | cut -d'"' -f2)
    "$bin/compareOutputs" "$work/serial/$name/VTK/$last" "$dir/VTK/$last" ||
        fail "$last differs from the serial run's"
    compareTables "$dir"
    ;;
refused)
    runParallel "$@"
    expectCode "$code" 1 "the parallel run"
    expectOnce "--> sphSolid FATAL INPUT ERROR"
    expectOnce "does not run on several ranks yet"
    [ ! -e "$work/parallel/$name/VTK" ] || fail "the run wrote VTK/"
    ;;
withoutParallel)
    copyCase "$work/parallel"
    output=$(cd "$work/parallel/$name" &&
        "$mpiexec" --oversubscribe -np "$ranks" "$bin/sphSolid" -case . "$@" 2>&1)
    code=$?
    echo "$output"
    echo "--- exit code $code"
    [ "$code" != 0 ] || fail "mpirun exited 0"
    [ "$(occurrences "$output" "sphSolid is one of $ranks processes mpirun started, without -parallel")" -ge 1 ] ||
        fail "no process refused"
    [ ! -e "$work/parallel/$name/VTK" ] || fail "the run wrote VTK/"
    ;;
*)
    echo "runSolver.sh: unknown check '$check'" >&2
    exit 2
    ;;
esac
exit $status
