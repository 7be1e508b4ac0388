#!/usr/bin/env bash
# The flagship tutorial as a newcomer runs it on 2 ranks (issue 14's "done when"): its committed
# files copied out of the tree, `./Allrun -np 2` (runParallel of etc/RunFunctions: mpirun -np 2
# sphSolid -parallel), shortened to 3 ms. Checks the log's Ranks line, that the series lists one
# .pvtu per output with a piece per rank, that the function objects wrote their tables once,
# and that Allclean leaves exactly the copied files.
# Usage: allrunParallel.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
src=$(cd "$1" && pwd -P)
build=$(cd "$2" && pwd -P)
tutorial=tutorials/rings2D/collidingRings
work=$(mktemp -d "${TMPDIR:-/tmp}/sphAllrunParallel.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail()
{
    echo "FAIL: $*" >&2
    exit 1
}
copy=$work/myRings
mkdir "$copy"
if git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    (cd "$src/$tutorial" && git ls-files -z . | xargs -0 cp --parents -t "$copy") || fail "copy"
else
    cp -r "$src/$tutorial/." "$copy" && (cd "$copy" && rm -rf VTK postProcessing log.* ./*.png)
fi
shipped=$(cd "$copy" && find . -type f | sort)
export PATH=$build/bin:$PATH
(cd "$work" && "$copy/Allrun" -np 2 -threads 1 -set endTime=3e-3 -set writeInterval=1e-3) ||
    fail "Allrun -np 2 failed"
grep -E "^Ranks +2: " "$copy/log.sphSolid" || fail "log.sphSolid has no 'Ranks 2' line"
grep -q "^End: " "$copy/log.sphSolid" || fail "the run did not end"
outputs=$(grep -c 'file="myRings_[0-9]*.pvtu"' "$copy/VTK/myRings.pvd")
[ "$outputs" = 4 ] || fail "the series lists $outputs .pvtu outputs (expected 4: 0 to 3 ms)"
for n in 0 1 2 3; do
    for r in 0 1; do
        [ -s "$copy/VTK/myRings_$n/myRings_${n}_$r.vtu" ] || fail "no piece $r of output $n"
    done
done
for table in extent/extent.dat energy/energy.dat stability/stability.dat; do
    rows=$(grep -vc '^#' "$copy/postProcessing/$table") || fail "no $table"
    [ "$rows" -ge 4 ] || fail "$table has $rows rows (a row at least every millisecond)"
    headers=$(grep -c '^#' "$copy/postProcessing/$table")
    [ "$headers" = 1 ] || fail "$table has $headers header lines (written by more than one rank?)"
done
"$copy/Allclean" || fail "Allclean failed"
left=$(cd "$copy" && find . -type f | sort)
[ "$left" = "$shipped" ] || fail "Allclean left: $(comm -13 <(echo "$shipped") <(echo "$left"))"
echo "Allrun -np 2: $outputs outputs of 2 pieces, the tables written once, Allclean clean"
