#!/usr/bin/env bash
# The particle function objects (src/demFunctionObjects) in system/controlDict
# of a demFoam run: 200 beads dropped from rest onto a floor.
#  - boundingBox: 200 particles in every row; until the first bead can touch
#    the floor (t < 0.019 s: the lowest bead starts 2 mm up) the centre of mass
#    falls freely, z_c(t) = z_c(0) - g t^2/2, which velocity Verlet integrates
#    exactly: checked to 1e-9 m;
#  - planeFlux through z = 0.02 (downwards): after settling (bed top below
#    the plane, checked) the net count equals the number of beads whose centre
#    started above the plane (from the initial state file), and the mass the
#    sum of their masses (to 1e-9 relative: the file has 10 digits);
#  - interval: the 'interval 0.01' rows are 0.01 s apart;
#  - the old place: a 'monitors' dictionary in constant/demProperties stops
#    the run with a FatalIOError naming the file, the entry and where the
#    monitors moved.
. "$(dirname "$0")/common.sh"

copyCase settlingSpheres
cat >> system/controlDict <<'EOD'
functions
{
    bed  { type boundingBox; libs (demFunctionObjects); }
    flux { type planeFlux; libs (demFunctionObjects); point (0 0 0.02); normal (0 0 -1); }
    slow { type boundingBox; libs (demFunctionObjects); interval 0.01; }
}
EOD
setEntry system/controlDict endTime 0.3
demFoam > log.demFoam 2>&1 || { tail -30 log.demFoam; fail "demFoam failed"; }

python3 - <<'PYEOF' || fail "function-object check failed"
import re
import sys
g = 9.81
def rows(p):
    return [[float(x) for x in l.split()] for l in open(p) if l.strip() and not l.startswith("#")]
bed = rows("postProcessing/bed/0/bed.dat")
flux = rows("postProcessing/flux/0/flux.dat")
slow = rows("postProcessing/slow/0/slow.dat")
ok = True
def check(what, good):
    global ok
    print(("ok   " if good else "FAIL ") + what)
    ok &= good
# columns: time n min(3) max(3) com(3) bedHeight
check(f"boundingBox: 200 particles in all {len(bed)} rows", all(int(r[1]) == 200 for r in bed))
t0, z0 = bed[0][0], bed[0][10]
check("first row at the start time", t0 == 0.0)
free = [r for r in bed if r[0] < 0.019]
err = max(abs(r[10] - (z0 - 0.5*g*r[0]**2)) for r in free)
check(f"free fall of the centre of mass over {len(free)} rows: max error {err:.2e} m <= 1e-9", err <= 1e-9 and len(free) >= 5)
top = bed[-1][9]
check(f"bed top at the end {top:.4f} m below the plane 0.02 m", top < 0.02)
# initial state: id type radius mass I(3) x y z ...
head, body = open("0/polyDEM/state").read().split("\ndata\n", 1)
nState = int(re.search(r"^particles (\d+)$", head, re.M).group(1))
lines = body.split("\n")[:nState]   # (the checksum line follows the records)
above = [l.split() for l in lines if l.strip() and float(l.split()[9]) > 0.02]
n, m = len(above), sum(float(l[3]) for l in above)
count, mass = flux[-1][1], flux[-1][2]
check(f"planeFlux count {count:.0f} = beads starting above the plane {n}", int(count) == n and n > 0)
# the file has 10 significant digits
check(f"planeFlux mass {mass:.9e} kg = {m:.9e} kg (1e-9 relative)", abs(mass - m) <= 1e-9*m)
dts = [b[0] - a[0] for a, b in zip(slow, slow[1:])]
check(f"interval rows 0.01 s apart ({len(slow)} rows)", len(slow) >= 25 and all(abs(d - 0.01) < 1e-9 for d in dts))
sys.exit(0 if ok else 1)
PYEOF

# The monitors' old place is refused with a message that says where they went
foamDictionary -entry monitors -set "{ bed { type boundingBox; } }" constant/demProperties >/dev/null \
    || fail "could not add monitors"
rm -rf 0.* [1-9]*
demFoam > log.old 2>&1 && fail "demFoam accepted 'monitors' in demProperties"
grep -q "FOAM FATAL IO ERROR" log.old || fail "no FatalIOError for 'monitors'"
grep -qF "constant/demProperties" log.old || fail "message does not name constant/demProperties"
grep -qF "Entry 'monitors'" log.old || fail "message does not name the entry"
grep -qF "system/controlDict" log.old || fail "message does not say where the monitors went"
echo "PASS"
