#!/usr/bin/env bash
# Polyhedra restart is a bit-exact continuation: 80 polyhedra (four random
# rock shapes of one type, and cubes) settling on a plane, run to t = 0.2 s in
# one go, and to 0.1 s then restarted to 0.2 s: the two 0.2/polyDEM/state
# files must be identical bytes (types, orientations, springs), and the
# polyhedra.pvd index of the restarted run must list 0, 0.1 and 0.2.
. "$(dirname "$0")/common.sh"

copyCase settlingRocks
mv "$testDir/settlingRocks" "$testDir/oneGo"
cd "$testDir/oneGo" || fail "no case"
demFoam > log.demFoam 2>&1 || { tail -30 log.demFoam; fail "demFoam (one go) failed"; }

copyCase settlingRocks
mv "$testDir/settlingRocks" "$testDir/restarted"
cd "$testDir/restarted" || fail "no case"
setEntry system/controlDict endTime 0.1
demFoam > log.demFoam.1 2>&1 || { tail -30 log.demFoam.1; fail "demFoam (to 0.1) failed"; }
setEntry system/controlDict endTime 0.2
demFoam > log.demFoam.2 2>&1 || { tail -30 log.demFoam.2; fail "demFoam (restart) failed"; }
grep -q "restarting from" log.demFoam.2 || fail "the second run did not restart"

for t in 0 0.1 0.2
do
    grep -q "file=\"$t/polyDEM/polyhedra.vtp\"" polyhedra.pvd \
        || fail "polyhedra.pvd of the restarted run lacks t = $t"
    [ -s "$t/polyDEM/polyhedra.vtp" ] || fail "no $t/polyDEM/polyhedra.vtp"
done
# 80 particles: 60 rocks of 20 faces and 20 cubes of 6 faces
grep -q 'NumberOfPolys="1320"' 0.2/polyDEM/polyhedra.vtp \
    || fail "0.2/polyDEM/polyhedra.vtp does not have the 1320 faces of the 80 polyhedra"

compareStates "$testDir/oneGo/0.2/polyDEM/state" "$testDir/restarted/0.2/polyDEM/state" "polyhedra state at t = 0.2 s"
