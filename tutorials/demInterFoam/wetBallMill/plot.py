#!/usr/bin/env python3
"""Wet ball mill (run in a case folder): the chargeShape monitor 'charge'
(dry filling and wet run), the power from the balls' torque on the shell
and from the fluid's (forces 'fluidForces'), the slurry volume and alpha
bounds (waterVolume.dat), and the steady shoulder and toe on the shell,
with the dry tutorial's steady values when its reference table is there.
Writes postProcessing/chargeShape.png and postProcessing/fluidPower.dat
(time, fluid torque T.a [N m], fluid power -omega T.a [W])."""
import glob
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetMill import charge_rows, charge_means, fluid_torque, water_rows, dry_reference, case_info  # noqa: E402

info = case_info(".")
omega = float(info["omega"])
tCouple = float(info["tCouple"])
rows, col = charge_rows(".")
means = charge_means(".")
ft = fluid_torque(".")
with open("postProcessing/fluidPower.dat", "w") as f:
    f.write("# time fluidTorque[N m] (T.a, a = +z) fluidPower[W] (-omega T.a)\n")
    for t, T in ft:
        f.write("%.6g %.9g %.9g\n" % (t, T, -omega * T))
water = water_rows(".")

t = [r[0] for r in rows]
fig, ax = plt.subplots(2, 2, figsize=(13, 9))
a = ax[0][0]
a.plot(t, [r[col["shoulder"]] for r in rows], "b-", lw=0.8, label="shoulder")
a.plot(t, [r[col["toe"]] for r in rows], "r-", lw=0.8, label="toe")
a.axvline(tCouple, color="0.5", ls="--", lw=0.8)
a.text(tCouple, 280, " slurry in", fontsize=8, color="0.4")
a.set_xlabel("time [s]")
a.set_ylabel("angle from the rising-side horizontal [deg]")
a.set_ylim(-10, 300)
a.grid(alpha=0.3)
a.legend(loc="center right")

a = ax[0][1]
a.plot(t, [r[col["power"]] / 1e3 for r in rows], "k-", lw=0.6,
       label="balls: -omega T (shell torque, mean per sample)")
a.plot(t, [r[col["powerGravity"]] / 1e3 for r in rows], "g-", lw=0.8,
       label="M g xc omega (charge's centre of mass)")
if ft:
    a.plot([p[0] for p in ft], [-omega * p[1] / 1e3 for p in ft], "m-", lw=0.4,
           label="fluid on the shell: -omega T (every step)")
a.axvline(tCouple, color="0.5", ls="--", lw=0.8)
a.set_xlabel("time [s]")
a.set_ylabel("power [kW]")
a.grid(alpha=0.3)
a.legend(loc="lower right", fontsize=8)

a = ax[1][0]
if water:
    w0 = water[0][1]
    a.plot([r[0] for r in water], [(r[1] - w0) / w0 for r in water], "b-", lw=0.8,
           label="slurry volume int eps alpha dV: relative change")
    a.plot([r[0] for r in water], [min(r[2], 0.0) for r in water], "g-", lw=0.8,
           label="min alpha (when < 0)")
    a.plot([r[0] for r in water], [max(r[3] - 1.0, 0.0) for r in water], "r-", lw=0.8,
           label="max alpha - 1 (when > 0)")
    a.set_title("slurry %.6f m3 at t = %g s" % (w0, water[0][0]), fontsize=9)
a.set_xlabel("time [s]")
a.grid(alpha=0.3)
a.legend(loc="best", fontsize=8)

R = float(info["R"])
a = ax[1][1]
th = [2 * math.pi * k / 200 for k in range(201)]
a.plot([R * math.cos(x) for x in th], [R * math.sin(x) for x in th], "k-", lw=1)
a.axhline(0, color="0.7", lw=0.5)
dry = dry_reference(os.path.basename(os.getcwd()))
for name, c in (("shoulder", "b"), ("toe", "r")):
    if name in means and math.isfinite(means[name][0]):
        th0 = math.radians(means[name][0])
        a.plot([0, R * math.cos(th0)], [0, R * math.sin(th0)], c + "-", lw=2,
               label="wet %s %.1f +- %.1f deg" % ((name,) + means[name]))
    if dry and name in dry:
        th0 = math.radians(dry[name][0])
        a.plot([0, R * math.cos(th0)], [0, R * math.sin(th0)], c + ":", lw=1.5,
               label="dry %s %.1f deg" % (name, dry[name][0]))
if "power" in means:
    a.set_title("steady, wet: balls %.2f +- %.2f kW" % (means["power"][0] / 1e3,
                                                       means["power"][1] / 1e3), fontsize=9)
a.annotate("rotation", xy=(1.1, -1.1), xytext=(0.4, -1.35), arrowprops=dict(arrowstyle="->"))
a.set_aspect("equal")
a.set_xlim(-1.7, 1.7)
a.set_ylim(-1.7, 1.7)
a.set_xlabel("x, rising side to the right [m]")
a.legend(loc="upper left", fontsize=8)
fig.suptitle("wet mill, " + os.path.basename(os.getcwd()))
fig.tight_layout()
fig.savefig("postProcessing/chargeShape.png", dpi=100)
print("wrote postProcessing/chargeShape.png")
