#!/usr/bin/env python3
"""Rotating drum tutorial: dynamic angle of repose against time from the
reposeAngle monitor 'angle'. Writes postProcessing/reposeAngle.png and prints
the mean angle over the steady part (t >= steadyFrom, default 1 s).
"""
import glob
import math
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

steadyFrom = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0

rows = []
for f in sorted(glob.glob("postProcessing/angle/*/angle.dat"),
                key=lambda p: float(p.split(os.sep)[-2])):
    for line in open(f):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(x) for x in line.split()])
if not rows:
    raise SystemExit("no postProcessing/angle/*/angle.dat: run ./Allrun first")
rows.sort()
t = [r[0] for r in rows]
angle = [r[2] for r in rows]

props = re.sub(r"//.*", "", open("constant/demProperties").read())
m = re.search(r"\brpm\s+([-+0-9.eE]+)\s*;", props)
rpm = float(m.group(1)) if m else 10.0
R = 0.05
omega = rpm * 2 * math.pi / 60
Fr = omega ** 2 * R / 9.81

steady = [a for ti, a in zip(t, angle) if ti >= steadyFrom]
fig, ax = plt.subplots(figsize=(7, 4.5))
ax.plot(t, angle, "k-", lw=1, label="dynamic angle of repose (monitor 'angle')")
ax.axhspan(25, 35, color="g", alpha=0.12, label="rolling regime, expected 25-35 deg")
if steady:
    mean = sum(steady) / len(steady)
    sd = math.sqrt(sum((a - mean) ** 2 for a in steady) / len(steady))
    ax.axhline(mean, color="r", ls="--",
               label="mean for t >= %g s: %.1f +- %.1f deg" % (steadyFrom, mean, sd))
ax.set_xlabel("time [s]")
ax.set_ylabel("angle [deg]")
ax.set_ylim(0, 50)
ax.grid(alpha=0.3)
ax.legend(loc="lower right")
ax.set_title("Rotating drum, %g rpm, Fr = %.1e" % (rpm, Fr))
fig.tight_layout()
fig.savefig("postProcessing/reposeAngle.png", dpi=110)
print("Froude number %.2e" % Fr)
if steady:
    print("mean dynamic angle of repose for t >= %g s: %.1f deg (sd %.1f)"
          % (steadyFrom, mean, sd))
print("wrote postProcessing/reposeAngle.png")
