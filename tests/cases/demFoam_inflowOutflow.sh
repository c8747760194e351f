#!/usr/bin/env bash
# Ice inflow and outflow keep an exact particle bookkeeping, through a
# restart (case iceChannel: blocks drift at 0.5 m/s from an inflow region,
# kept at a solid fraction, into an outlet box that removes them).
# Checked, on every line of postProcessing/demFoam/<start>/particleBalance.dat
# of every run: inserted - removed = particles (recomputed here from the
# columns, not the file's own balance column); at the end: blocks were
# removed by the outlet (none by the domain), more were inserted after the
# first fill, the counters of <t>/polyDEM/particleBalance match the state's
# particle count; a run restarted at 0.8 s ends with the one-go run's
# counters and a byte-identical state.
. "$(dirname "$0")/common.sh"

# stateCount STATE: the particle count of a polyDEM state file
stateCount()
{
    awk '$1 == "particles" { print $2; exit }' "$1"
}

copyCase iceChannel
mv "$testDir/iceChannel" "$testDir/oneGo"
cd "$testDir/oneGo" || fail "no case"
demFoam > log.demFoam 2>&1 || { tail -30 log.demFoam; fail "demFoam (one go) failed"; }
one=postProcessing/demFoam/0/particleBalance.dat
checkBalance $one
removedOut=$(lastValue $one removed_downstream)
removedDom=$(lastValue $one removed_domain)
inserted=$(lastValue $one inserted_inlet)
firstFill=$(awk '!/^#/ && $4 > 0 { print $4; exit }' $one)
echo "one go: inserted $inserted (first fill $firstFill), removed by the outlet $removedOut, by the domain $removedDom, present $(lastValue $one particles)"
[ "$removedOut" -gt 0 ] || fail "the outlet removed no block"
[ "$removedDom" -eq 0 ] || fail "the domain removed $removedDom blocks (all should leave by the outlet)"
[ "$inserted" -gt "$firstFill" ] || fail "no block inserted after the first fill ($inserted)"
n=$(stateCount 1.6/polyDEM/state)
[ -n "$n" ] || fail "no particle count in 1.6/polyDEM/state"
[ "$n" -eq "$(lastValue $one particles)" ] || fail "state has $n particles, the balance $(lastValue $one particles)"
grep -q "^particles $n\$" 1.6/polyDEM/particleBalance || fail "1.6/polyDEM/particleBalance does not count $n particles"
grep -q "^removed downstream $removedOut " 1.6/polyDEM/particleBalance || fail "1.6/polyDEM/particleBalance: removed downstream is not $removedOut"

copyCase iceChannel
mv "$testDir/iceChannel" "$testDir/restarted"
cd "$testDir/restarted" || fail "no case"
setEntry system/controlDict endTime 0.8
demFoam > log.demFoam.1 2>&1 || { tail -30 log.demFoam.1; fail "demFoam (to 0.8) failed"; }
setEntry system/controlDict endTime 1.6
demFoam > log.demFoam.2 2>&1 || { tail -30 log.demFoam.2; fail "demFoam (restart) failed"; }
grep -q "restarting from" log.demFoam.2 || fail "the second run did not restart"
checkBalance postProcessing/demFoam/0/particleBalance.dat
two=postProcessing/demFoam/0.8/particleBalance.dat
checkBalance $two
for c in particles inserted removed inserted_inlet removed_downstream removed_domain
do
    a=$(lastValue "$testDir/oneGo/$one" $c); b=$(lastValue $two $c)
    [ "$a" = "$b" ] || fail "restarted run ends with $c = $b, the one-go run with $a"
done
echo "PASS: bookkeeping exact in every line of 3 runs; restart continues the counters"

compareStates "$testDir/oneGo/1.6/polyDEM/state" "$testDir/restarted/1.6/polyDEM/state" "state at t = 1.6 s"
