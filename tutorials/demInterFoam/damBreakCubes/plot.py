#!/usr/bin/env python3
"""damBreakCubes plot (postProcess.py's files): postProcessing/damBreakCubes.png
cube positions x(t), z(t); the front against Ritter's; snapshots of the stack."""
import math
import os
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

info = {k: v for k, v in (l.split() for l in open("case.info"))}
f = {k: float(v) for k, v in info.items() if k != "mode"}
rows = [[float(x) for x in l.split()] for l in open("postProcessing/cubePositions.dat")
        if l.strip() and not l.startswith("#")]
fr = [[float(x) for x in l.split()] for l in open("postProcessing/waterFront.dat")
      if l.strip() and not l.startswith("#")]
t = [r[0] for r in rows]
n = (len(rows[0]) - 1)//2
labels = ["bottom 1", "bottom 2", "bottom 3", "middle 1", "middle 2", "top"]

fig, ax = plt.subplots(2, 2, figsize=(11, 7.5))
for k in range(n):
    ax[0, 0].plot(t, [r[1 + 2*k] for r in rows], label=labels[k] if n == 6 else "cube %d" % k)
    ax[0, 1].plot(t, [r[2 + 2*k] for r in rows])
tArr = min([r[0] for r in fr if r[1] >= f["xStack"] - 2*f["a"]], default=None)
for a_ in (ax[0, 0], ax[0, 1]):
    if tArr is not None:
        a_.axvline(tArr, color="0.6", ls=":", label="front within 2a of the stack")
    a_.set_xlabel("t [s]")
    a_.grid(alpha=0.3)
ax[0, 0].set_ylabel("cube centre x [m]")
ax[0, 1].set_ylabel("cube centre z [m]")
ax[0, 0].legend(fontsize=8)
ax[0, 0].set_title("damBreakCubes (%s): %d cubes a = %g m, %g kg/m3, dx = %g m"
                   % (info["mode"], n, f["a"], f["rhoCube"], f["dx"]), fontsize=10)

h0 = f["h0"]
T = [r[4] for r in fr]
ax[1, 0].plot(T, [r[3] for r in fr], "o-", ms=3, label="front, alpha > 0.5 in the floor cells")
ax[1, 0].plot(T, [2*x for x in T], "k--", label="Ritter: (x - x0)/h0 = 2 t sqrt(g/h0)")
ax[1, 0].axhline((f["xStack"] - f["x0"])/h0, color="0.6", ls=":", label="stack")
ax[1, 0].set_xlabel("t sqrt(g/h0)")
ax[1, 0].set_ylabel("(x_front - x0)/h0")
ax[1, 0].set_ylim(0, (f["L"] - f["x0"])/h0 + 0.3)
ax[1, 0].legend(fontsize=8)
ax[1, 0].grid(alpha=0.3)

# Snapshots of the cube centres (squares of edge a, not rotated: the centres only)
pick = [0, len(rows)//2, len(rows) - 1]
for j, col in zip(pick, ("C0", "C1", "C2")):
    r = rows[j]
    for k in range(n):
        x, z = r[1 + 2*k], r[2 + 2*k]
        ax[1, 1].add_patch(plt.Rectangle((x - f["a"]/2, z - f["a"]/2), f["a"], f["a"], fill=False,
                                         ec=col, label="t = %g s" % r[0] if k == 0 else None))
ax[1, 1].set_xlim(f["xStack"] - 0.1, f["L"])
ax[1, 1].set_ylim(0, 0.35)
ax[1, 1].set_aspect("equal")
ax[1, 1].set_xlabel("x [m]")
ax[1, 1].set_ylabel("z [m]")
ax[1, 1].legend(fontsize=8)
ax[1, 1].set_title("cube centres (drawn unrotated)", fontsize=9)
fig.tight_layout()
fig.savefig("postProcessing/damBreakCubes.png", dpi=110)
print("wrote postProcessing/damBreakCubes.png")
