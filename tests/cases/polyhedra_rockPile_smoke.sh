#!/usr/bin/env bash
# Smoke test of the rockPile tutorial: ./Allrun -test (120 rocks and 120
# spheres poured on the plate, 0.8 s) runs both cases, writes polyhedra.vtp
# for the rocks (and none for the spheres), and pileAngle.py measures a
# finite angle for both piles.
. "$(dirname "$0")/common.sh"

rm -rf "$testDir/rockPile"
cp -r "$hedraRoot/tutorials/demFoam/rockPile" "$testDir/rockPile"
cd "$testDir/rockPile" || fail "no case"
./Allclean >/dev/null 2>&1
./Allrun -test > log.Allrun 2>&1 \
    || { tail -40 log.Allrun; tail -30 log.demFoam.rocks 2>/dev/null; fail "Allrun -test failed"; }

grep -q "^End" log.demFoam.rocks || fail "rocks run did not end"
grep -q "^End" log.demFoam.spheres || fail "spheres run did not end"
[ -s rocks/0.8/polyDEM/polyhedra.vtp ] || fail "no rocks/0.8/polyDEM/polyhedra.vtp"
grep -q "0.8/polyDEM/polyhedra.vtp" rocks/polyhedra.pvd || fail "rocks/polyhedra.pvd lacks t = 0.8"
grep -q "NumberOfPolys=\"0\"" spheres/0.8/polyDEM/polyhedra.vtp || fail "spheres case has polyhedra in polyhedra.vtp"
for c in rocks spheresRolling
do
    a=$(awk '!/^#/ { print $3 }' $c/postProcessing/pileAngle.dat)
    echo "$c: angle $a deg"
    awk -v a="$a" 'BEGIN { exit !(a + 0 > 1 && a + 0 < 80) }' \
        || fail "$c: angle '$a' is not between 1 and 80 degrees"
done
echo "PASS"
