#!/usr/bin/env python3
"""Rock pile vs sphere pile: surface profiles, fitted flanks and angles of
repose (pileAngle.py) in postProcessing/pileProfiles.png; the angles also in
postProcessing/angles.dat.

    python3 plot.py [rocksCase] [spheresCase] [plateRadius]
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from pileAngle import analyse

rocks = sys.argv[1] if len(sys.argv) > 1 else "rocks"
spheres = sys.argv[2] if len(sys.argv) > 2 else "spheres"
R = float(sys.argv[3]) if len(sys.argv) > 3 else 0.03
rolling = sys.argv[4] if len(sys.argv) > 4 else "spheresRolling"

fig, ax = plt.subplots(figsize=(8, 4.5))
lines = []
for case, label, colour in ((rocks, "rocks (10 shapes, 20 faces)", "tab:brown"),
                            (spheres, "spheres of equal volume", "tab:blue"),
                            (rolling, "spheres + rolling resistance 0.3", "tab:green")):
    if not os.path.isdir(case):
        continue
    res = analyse(case, R)
    if res["n"] < 20:
        ax.plot([], [], "o", color=colour, label="%s: no pile (all rolled off)" % label)
        lines.append("%s %s %.2f %.2f\n" % (case, res["kind"], 0.0, 0.0))
        continue
    # every surface point, mirrored radius, faint
    rr = [math.hypot(x, y) for x, y, z in res["points"]]
    zz = [z for x, y, z in res["points"]]
    ax.plot([1e3*r for r in rr], [1e3*z for z in zz], ".", ms=1, color=colour, alpha=0.15)
    ax.plot([1e3*r for r in res["r"]], [1e3*h for h in res["h"]], "o-", color=colour,
            label="%s: surface (median of 8 sectors)" % label)
    r0, r1 = res["fitRange"][0], res["r"][-1]
    ax.plot([1e3*r0, 1e3*r1], [1e3*(res["a"] + res["b"]*r0), 1e3*(res["a"] + res["b"]*r1)],
            "--", color="k", lw=1)
    ax.text(1e3*r1, 1e3*(res["a"] + res["b"]*r1) + 1.5, "%.1f°" % res["angle"],
            color=colour, fontsize=12)
    lines.append("%s %s %.2f %.2f\n" % (case, res["kind"], res["angle"], res["spread"]))

ax.axvline(1e3*R, color="grey", lw=1, ls=":")
ax.set_xlim(0, 1e3*R*1.15)
ax.set_ylim(bottom=0)
ax.set_xlabel("distance from the plate centre r [mm]")
ax.set_ylabel("surface height [mm]")
ax.set_title("Angle of repose on a %g mm plate (dashed: flank fitted outside the shoulder)"
             % (2e3*R), fontsize=10)
ax.set_aspect("equal")
ax.legend(fontsize=8, loc="upper right")
fig.tight_layout()
os.makedirs("postProcessing", exist_ok=True)
fig.savefig("postProcessing/pileProfiles.png", dpi=130)
with open("postProcessing/angles.dat", "w") as f:
    f.write("# case kind angle[deg] sectorStd[deg]\n")
    f.writelines(lines)
print("".join(lines), end="")
print("wrote postProcessing/pileProfiles.png")
