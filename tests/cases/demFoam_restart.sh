#!/usr/bin/env bash
# Restart is a bit-exact continuation: 200 spheres settling on a plane, run
# to t = 0.2 s in one go, and run to 0.1 s then restarted (startFrom
# latestTime) to 0.2 s: the two 0.2/polyDEM/state files must be identical
# bytes (the engine restores neighbour lists, springs and forces exactly).
# A side wall removed at t = 0.15 s (activeUntil) makes the restarted part
# cross a wall removal as well.
. "$(dirname "$0")/common.sh"

addFence()
{
    setEntry constant/demProperties walls/fence \
        "{ type plane; point (0.03 0 0); normal (-1 0 0); material steel; activeUntil 0.15; }"
}

copyCase settlingSpheres
mv "$testDir/settlingSpheres" "$testDir/oneGo"
cd "$testDir/oneGo" || fail "no case"
addFence
demFoam > log.demFoam 2>&1 || { tail -30 log.demFoam; fail "demFoam (one go) failed"; }

copyCase settlingSpheres
mv "$testDir/settlingSpheres" "$testDir/restarted"
cd "$testDir/restarted" || fail "no case"
addFence
setEntry system/controlDict endTime 0.1
demFoam > log.demFoam.1 2>&1 || { tail -30 log.demFoam.1; fail "demFoam (to 0.1) failed"; }
setEntry system/controlDict endTime 0.2
demFoam > log.demFoam.2 2>&1 || { tail -30 log.demFoam.2; fail "demFoam (restart) failed"; }
grep -q "restarting from" log.demFoam.2 || fail "the second run did not restart"
grep -q "wall 'fence' removed" log.demFoam.2 || fail "the restarted run did not remove the wall 'fence'"

compareStates "$testDir/oneGo/0.2/polyDEM/state" "$testDir/restarted/0.2/polyDEM/state" "state at t = 0.2 s"
