#!/usr/bin/env bash
# A restart is checked (docs/demProperties.md, "Restart"): demFoam runs to
# t = 0.01 s (written), the state or the input is then damaged, and the
# restart must stop (non-zero exit, FOAM FATAL IO ERROR naming the file and
# the entry) instead of running on:
#
#   reorderedTypes   particleTypes (beads marbles) -> (marbles beads)
#   changedShape     the cube edge of settlingRocks 3 mm -> 3.2 mm
#   changedDigit     one digit of the ASCII state's data changed
#   flippedBit       one bit of the binary state's data flipped
#   deletedState     0.01/polyDEM/state deleted (then freshStart true: runs)
#   deletedFolder    0.01/polyDEM deleted (uniform/time says 0.01 was written)
#
#   demFoam_restartChecks.sh <kind>
. "$(dirname "$0")/common.sh"

kind="$1"
props=constant/demProperties
t1=0.01
marbles="{ shape sphere; material steel; diameter 3e-3; }"
beads="{ shape sphere; material glass; diameter 4e-3; }"

if [ "$kind" = changedShape ]
then
    copyCase settlingRocks
else
    copyCase settlingSpheres
fi
setEntry system/controlDict endTime $t1
setEntry system/controlDict writeInterval $t1
case "$kind" in
reorderedTypes) setEntry $props particleTypes/marbles "$marbles" ;;
flippedBit)     setEntry $props output "{ format binary; }" ;;
esac

demFoam > log.demFoam.1 2>&1 || { tail -30 log.demFoam.1; fail "demFoam (to $t1) failed"; }
state=$t1/polyDEM/state
[ -f "$state" ] || fail "no $state"
tail -c 26 "$state" | grep -aq "^checksum [0-9a-f]\{16\}$" || fail "$state does not end with a checksum line"

case "$kind" in
reorderedTypes)
    grep -aq "^type beads " "$state" && grep -aq "^type marbles " "$state" \
        || fail "$state does not record the types beads and marbles"
    foamDictionary -entry particleTypes/beads -remove $props > /dev/null
    setEntry $props particleTypes/beads "$beads"     # now after marbles
    expectFile="$props"; expectAlso="particleTypes" ;;
changedShape)
    setEntry $props particleTypes/cubes/geometry/edge 3.2e-3
    expectFile="$props"; expectAlso="particleTypes/cubes" ;;
changedDigit)
    python3 - "$state" <<'PYEOF' || fail "could not change a digit"
import sys
t = open(sys.argv[1]).read()
i = t.index("\ndata\n") + 6
i = t.index(".", i) + 3   # a digit of the first particle's radius (0.00dd...)
t = t[:i] + ("8" if t[i] == "7" else "7") + t[i + 1:]
open(sys.argv[1], "w").write(t)
PYEOF
    expectFile="$state"; expectAlso="checksum mismatch" ;;
flippedBit)
    python3 - "$state" <<'PYEOF' || fail "could not flip a bit"
import sys
b = bytearray(open(sys.argv[1], "rb").read())
i = b.index(b"data\n") + 5 + 16 + 8 + 3   # a byte of the first particle's mass
b[i] ^= 0x10
open(sys.argv[1], "wb").write(bytes(b))
PYEOF
    expectFile="$state"; expectAlso="checksum mismatch" ;;
deletedState)
    rm "$state"
    expectFile="$state"; expectAlso="freshStart" ;;
deletedFolder)
    rm -r "$t1/polyDEM"
    expectFile="$state"; expectAlso="freshStart" ;;
*)
    fail "unknown restart-check kind '$kind'" ;;
esac

setEntry system/controlDict endTime 0.012
demFoam > log.demFoam.2 2>&1
rc=$?
sed -n '/FOAM FATAL/,/FOAM exiting/p' log.demFoam.2

[ "$rc" -ne 0 ] || fail "demFoam restarted with exit 0 from a damaged restart ($kind)"
grep -q "FOAM FATAL IO ERROR" log.demFoam.2 || { tail -20 log.demFoam.2; fail "no FOAM FATAL IO ERROR ($kind)"; }
grep -q "$expectFile" log.demFoam.2 || fail "the message does not name $expectFile ($kind)"
grep -q "$expectAlso" log.demFoam.2 || fail "the message does not say '$expectAlso' ($kind)"
grep -q "$state" log.demFoam.2 || fail "the message does not name the state $state ($kind)"
echo "PASS: the restart stopped with a FatalIOError naming $expectFile ($kind)"

if [ "$kind" = deletedState ]
then
    # Asked for: new particles at the restart time
    setEntry $props freshStart true
    setEntry system/controlDict writeInterval 0.002
    demFoam > log.demFoam.3 2>&1 || { tail -30 log.demFoam.3; fail "demFoam with freshStart true failed"; }
    grep -q "freshStart true: new particles" log.demFoam.3 || fail "freshStart true did not start afresh"
    grep -q "DEM: 200 particles" log.demFoam.3 || fail "freshStart true did not insert the 200 beads"
    [ -f 0.012/polyDEM/state ] || fail "freshStart run wrote no 0.012/polyDEM/state"
    echo "PASS: with freshStart true the run starts afresh at $t1"
fi
exit 0
