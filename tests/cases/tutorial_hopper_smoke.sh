#!/usr/bin/env bash
# Smoke test of the hopper tutorial: ./Allrun -test (filling, plate removal,
# first 0.2 s of discharge at reduced size) runs, writes states and the
# planeFlux monitor, and particles leave through the orifice.
. "$(dirname "$0")/common.sh"

rm -rf "$testDir/hopper"
cp -r "$hedraRoot/tutorials/demFoam/hopper" "$testDir/hopper"
cd "$testDir/hopper" || fail "no case"
./Allclean >/dev/null 2>&1
./Allrun -test > log.Allrun 2>&1 || { tail -40 log.Allrun; tail -30 log.demFoam 2>/dev/null; fail "Allrun -test failed"; }

flux=postProcessing/outlet/0/outlet.dat
[ -f "$flux" ] || fail "no $flux"
discharged="$(awk '!/^#/ { c = $2 } END { print c + 0 }' "$flux")"
echo "particles discharged: $discharged"
[ "$discharged" -gt 10 ] || fail "fewer than 10 particles left the hopper"
echo "PASS"
