#!/usr/bin/env bash
# 500 spheres (d = 4 mm) poured into a 40 x 40 mm box of plane walls come to
# rest within 1.5 s:
#   - final translational kinetic energy below 1e-6 N m g d: the energy of
#     every sphere moving at sqrt(2e-6 g d) ~ 0.3 mm/s, a millionth of the
#     potential energy of lifting the pile by one diameter: a pile at rest,
#     not one still flowing or vibrating (it reaches ~1e-11 J, the floor is
#     1.6e-9 J). Rotational energy is printed, not tested: a sphere touching
#     only the floor can keep spinning about the vertical, since the contact
#     and rolling models have no twisting (spin) resistance (~1e-8 J here).
#   - no particle outside the box (centres inside by at least 0.9 radius:
#     overlaps with the walls stay well below a radius)
. "$(dirname "$0")/common.sh"

copyCase settledPile
demFoam > log.demFoam 2>&1 || { tail -30 log.demFoam; fail "demFoam failed"; }

last="$(foamListTimes -latestTime 2>/dev/null | tail -1)"
state="$last/polyDEM/state"
[ -f "$state" ] || fail "no state at the last time ($last)"

python3 - "$state" postProcessing/demFoam/0/summary.dat <<'PYEOF' || fail "pile check failed"
import sys
state, summary = sys.argv[1], sys.argv[2]
lines = open(state).read().split("\n")
n = int(next(l for l in lines if l.startswith("particles ")).split()[1])
data = lines.index("data") + 1
L, d, g = 0.04, 0.004, 9.81
bad = 0
mass = 0.0
for l in lines[data:data + n]:
    f = l.split()
    r, m = float(f[2]), float(f[3])
    x, y, z = map(float, f[7:10])
    mass += m
    if not (0.9 * r <= x <= L - 0.9 * r and 0.9 * r <= y <= L - 0.9 * r and z >= 0.9 * r):
        bad += 1
last = [l for l in open(summary) if not l.startswith("#")][-1].split()
t, count, ek = float(last[0]), int(last[2]), float(last[7])
erot = float(last[8])
floor = 1e-6 * mass * g * d
print("t = %g s: %d particles (%d in the state), translational kinetic energy "
      "%.3g J (rotational %.3g J), floor 1e-6 N m g d = %.3g J, outside the box: %d"
      % (t, count, n, ek, erot, floor, bad))
ok = n == 500 and count == 500 and bad == 0 and ek < floor
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
PYEOF
