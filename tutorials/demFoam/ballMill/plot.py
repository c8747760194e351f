#!/usr/bin/env python3
"""Ball mill tutorial (run in a case folder): the chargeShape monitor
'charge' against time, and the steady means on a sketch of the shell.
Writes postProcessing/chargeShape.png.
"""
import glob
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = []
for f in sorted(glob.glob("postProcessing/charge/*/charge.dat"),
                key=lambda p: float(p.split(os.sep)[-2])):
    for line in open(f):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(x) for x in line.split()])
if not rows:
    raise SystemExit("no postProcessing/charge/*/charge.dat: run ./Allrun first")
rows.sort()
col = {n: k for k, n in enumerate(
    "time shoulder toe toeBelow shoulderHeight toeHeight M xc yc wallTorque "
    "gravityTorque power powerGravity wallSteps dissipation wallWorkRate externalWorkRate energy".split())}


def series(name):
    return [r[col[name]] for r in rows]


means = {}
for f in glob.glob("postProcessing/charge/*/chargeMean.dat"):
    for line in open(f):
        if line.startswith("#") or not line.strip():
            continue
        q, m, e, n = line.split()
        means[q.split("[")[0]] = (float(m), float(e))

t = series("time")
fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
ax[0].plot(t, series("shoulder"), "b-", lw=0.8, label="shoulder")
ax[0].plot(t, series("toe"), "r-", lw=0.8, label="toe")
ax[0].set_xlabel("time [s]")
ax[0].set_ylabel("angle from the rising-side horizontal [deg]")
ax[0].set_ylim(-10, 300)
ax[0].grid(alpha=0.3)
ax[0].legend(loc="center right")

ax[1].plot(t, [p / 1e3 for p in series("power")], "k-", lw=0.6,
           label="P = -omega T (shell torque, mean per sample)")
ax[1].plot(t, [p / 1e3 for p in series("powerGravity")], "g-", lw=1,
           label="M g xc omega (charge's centre of mass)")
ax[1].set_xlabel("time [s]")
ax[1].set_ylabel("power [kW]")
ax[1].grid(alpha=0.3)
ax[1].legend(loc="lower right", fontsize=8)

# The shell and the steady shoulder/toe
R = 1.5
th = [2 * math.pi * k / 200 for k in range(201)]
ax[2].plot([R * math.cos(a) for a in th], [R * math.sin(a) for a in th], "k-", lw=1)
ax[2].axhline(0, color="0.7", lw=0.5)
title = []
for name, c in (("shoulder", "b"), ("toe", "r")):
    if name in means and math.isfinite(means[name][0]):
        a = math.radians(means[name][0])
        ax[2].plot([0, R * math.cos(a)], [0, R * math.sin(a)], c + "-", lw=2,
                   label="%s %.1f +- %.1f deg" % ((name,) + means[name]))
if "xc" in means:
    ax[2].plot([means["xc"][0]], [means["yc"][0]], "ko",
               label="centre of mass (%.3f, %.3f) m" % (means["xc"][0], means["yc"][0]))
if "power" in means:
    ax[2].set_title("steady: P = %.2f +- %.2f kW (%.2f kW from M g xc omega)"
                    % (means["power"][0] / 1e3, means["power"][1] / 1e3,
                       means.get("powerGravity", (float("nan"),))[0] / 1e3), fontsize=9)
ax[2].annotate("rotation", xy=(1.1, -1.1), xytext=(0.4, -1.35),
               arrowprops=dict(arrowstyle="->"))
ax[2].set_aspect("equal")
ax[2].set_xlim(-1.7, 1.7)
ax[2].set_ylim(-1.7, 1.7)
ax[2].set_xlabel("x, rising side to the right [m]")
ax[2].legend(loc="upper left", fontsize=8)
fig.suptitle(os.path.basename(os.getcwd()))
fig.tight_layout()
os.makedirs("postProcessing", exist_ok=True)
fig.savefig("postProcessing/chargeShape.png", dpi=110)
print("wrote postProcessing/chargeShape.png")
for k in ("shoulder", "toe", "toeBelow", "shoulderHeight", "toeHeight", "power", "powerGravity"):
    if k in means:
        print("%-15s %.4g +- %.2g" % (k, means[k][0], means[k][1]))
