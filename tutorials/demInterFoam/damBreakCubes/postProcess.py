#!/usr/bin/env python3
"""damBreakCubes post-processing and checks (Allrun): from case/ writes

  postProcessing/cubePositions.dat  t, then x z of every cube (by id)
  postProcessing/waterFront.dat     t, front x (furthest floor cell with
                                    alpha.water > 0.5), Ritter's front
  postProcessing/checks.dat         the checks below, PASS/FAIL with numbers
and exits 1 if a check fails.

Checks (tolerances, README "Checks"):
  1. water balance: int eps alpha dV plus the water that left through the
     open top (run-up on the downstream wall) equals the start:
     max |W + out - W0|/W0 <= 1e-5 (the continuity error the pressure
     tolerances allow; the solver conserves water to them, docs/models.md)
  2. alpha.water within [-1e-6, 1 + 1e-6] over the whole run
  3. cubes: count and mass rho a^3 (to 1e-9) unchanged, none left the domain
  4. front before it reaches the stack: x_f <= x0 + 2 sqrt(g h0) t + dx
     (Ritter's shallow-water front on a dry frictionless bed is an upper
     bound of the real front) and, at the last such write,
     x_f - x0 >= 0.5 x the Ritter distance (sanity bound, ours: a front at
     less than half Ritter's would mean the column is held back)
  5. the stack at rest until the front comes within 2 a of it (after the
     first 0.06 s in which it settles onto its contacts): every cube slower
     than 1 cm/s (0.3 % of the Ritter front speed) and the fluid force on
     the stack below 1 % of its weight (the air pushed ahead of the front
     pushes the stack too, more the closer the front: hence the 2 a)
  6. the stack is moved by the water: by the end the largest cube
     displacement exceeds a/2 (Ritter's depth at the stack,
     (2 sqrt(g h0) - (x - x0)/t)^2/(9 g), exceeds the cubes' floating draft
     0.8 a = 0.04 m from t = 0.4 s on, besides the drag of the surge)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import demState as ds

info = {k: v for k, v in (l.split() for l in open("case.info"))}
f = {k: float(v) for k, v in info.items() if k != "mode"}
g, h0, x0, dx, a = 9.81, f["h0"], f["x0"], f["dx"], f["a"]
c0 = math.sqrt(g*h0)
nx = int(f["nx"])
results = []
out = []


def report(ok, text):
    results.append(ok)
    line = ("PASS: " if ok else "FAIL: ") + text
    out.append(line)
    print(line)


T = ds.times("case")
states = [(t, ds.read_state(os.path.join("case", d, "polyDEM", "state"))) for t, d in T]
ids = sorted(p["id"] for p in states[0][1]["particles"])
with open("postProcessing/cubePositions.dat", "w") as o:
    o.write("# t [s], then x z [m] of the cubes " + " ".join(str(i) for i in ids) + "\n")
    for t, s in states:
        by = {p["id"]: p for p in s["particles"]}
        o.write("%.4f " % t + " ".join("%.6g %.6g" % (by[i]["px"], by[i]["pz"]) if i in by else "nan nan"
                                       for i in ids) + "\n")

front = []
for t, d in T:
    al, u = ds.read_scalar_field(os.path.join("case", d, "alpha.water"))
    xf = max([(i + 1)*dx for i in range(nx) if al[i] > 0.5], default=0.0)
    front.append((t, xf))
with open("postProcessing/waterFront.dat", "w") as o:
    o.write("# t [s]  front x [m]  Ritter x0 + 2 sqrt(g h0) t [m]  (x_f - x0)/h0  t sqrt(g/h0)\n")
    for t, xf in front:
        o.write("%.4f %.4f %.4f %.4f %.4f\n" % (t, xf, x0 + 2*c0*t, (xf - x0)/h0, t*c0/h0))

# 1, 2: water balance (volume + outflow through the open top) and bounds
import waterBalance as wb
Wb, W0 = wb.balance("case", f["dtCfd"])
drift = max(abs(r[3] - W0) for r in Wb)/W0
report(drift <= 1e-5, f"water balance: max |W + out - W0|/W0 = {drift:.3g} (W0 = {W0:.6g} m3;"
       f" tolerance 1e-5); left through the top by the end: {Wb[-1][2]:.3g} m3")
aMin, aMax = min(r[4] for r in Wb), max(r[5] for r in Wb)
report(aMin >= -1e-6 and aMax <= 1 + 1e-6,
       f"alpha.water bounds over the run: min {aMin:.3g}, max - 1 = {aMax - 1:.3g} (tolerance 1e-6)")

# 3: cubes
m0 = f["rhoCube"]*a**3
nOk = all(len(s["particles"]) == int(f["n"]) for t, s in states)
mErr = max(abs(p["mass"] - m0)/m0 for t, s in states for p in s["particles"])
rows = ds.read_summary("case")
nOut = max(r[2] for r in rows)
report(nOk and mErr <= 1e-9 and nOut == 0,
       f"cubes: {int(f['n'])} at every write: {nOk}; mass vs rho a^3 = {m0:.6g} kg: max rel. error"
       f" {mErr:.2g} (tolerance 1e-9); outside the domain: {int(nOut)}")

# 4: front before the stack
before = [(t, xf) for t, xf in front if t > 0 and xf < f["xStack"] - dx]
if not before:
    report(False, "front: no write before the front reaches the stack")
else:
    worst = max(before, key=lambda r: r[1] - (x0 + 2*c0*r[0]))
    report(all(xf <= x0 + 2*c0*t + dx for t, xf in before),
           f"front before the stack ({len(before)} writes to t = {before[-1][0]:g} s) within Ritter's"
           f" x0 + 2 sqrt(g h0) t + dx: closest at t = {worst[0]:g} s, x_f = {worst[1]:.3f} m vs"
           f" {x0 + 2*c0*worst[0]:.3f} m")
    t, xf = before[-1]
    ratio = (xf - x0)/(2*c0*t)
    report(ratio >= 0.5, f"front at t = {t:g} s: x_f - x0 = {xf - x0:.3f} m = {ratio:.3f} of Ritter's"
           f" {2*c0*t:.3f} m (sanity bound >= 0.5)")

# 5: at rest until the front comes within 2 a of the stack (the last write before)
iArr = min([i for i, (t, xf) in enumerate(front) if xf >= f["xStack"] - 2*a], default=len(front))
tArr = front[max(iArr - 1, 0)][0]
rest = [(t, s) for t, s in states if 0.06 <= t < tArr]
vmax = max((math.sqrt(p["vx"]**2 + p["vy"]**2 + p["vz"]**2) for t, s in rest for p in s["particles"]),
           default=float("nan"))
weight = f["n"]*m0*g
Fmax = max((math.sqrt(r[3]**2 + r[4]**2 + r[5]**2) for r in rows if 0.06 <= r[0] < tArr),
           default=float("nan"))
report(vmax < 0.01 and Fmax < 0.01*weight,
       f"stack at rest for 0.06 s <= t < {tArr:g} s (front within 2 a, {len(rest)} writes): max cube speed"
       f" {vmax:.3g} m/s (< 0.01), max |fluid force| {Fmax:.3g} N (< 1 % of the weight {weight:.3g} N)")

# 6: moved by the water
s0 = {p["id"]: p for p in states[0][1]["particles"]}
dmax = max(math.dist((p["px"], p["py"], p["pz"]), (s0[p["id"]]["px"], s0[p["id"]]["py"], s0[p["id"]]["pz"]))
           for p in states[-1][1]["particles"])
report(dmax > 0.5*a, f"stack moved by the flow: largest cube displacement at t = {states[-1][0]:g} s"
       f" {dmax:.3f} m (> a/2 = {0.5*a:g} m)")

with open("postProcessing/checks.dat", "w") as o:
    o.write("\n".join(out) + "\n")
ok = all(results)
print("all checks passed" if ok else "SOME CHECKS FAILED")
sys.exit(0 if ok else 1)
