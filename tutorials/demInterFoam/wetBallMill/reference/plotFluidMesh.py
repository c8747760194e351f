#!/usr/bin/env python3
"""The wet mill on two fluid meshes, standing and turning (README, "Mesh
motion"): reads fluidMesh_2026-12-07.dat and plots shoulder, power and the
fluid's net work rate on the balls against the fluid's cell size
(fluidMesh_2026-12-07.png). The fluid can only give the balls what the
balls and the shell gave it, and the shell gives it 5-16 W, so a net work
rate on the balls above ~0 is an energy source of the numerics: the grey
band marks the physical side."""
import os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
stem = os.path.join(here, "fluidMesh_2026-12-07")
rows = {}
for line in open(stem + ".dat"):
    if line.startswith("#") or not line.strip():
        continue
    f = line.split()
    rows.setdefault((f[0], f[1]), []).append([float(x) for x in f[2:]])

fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
quantities = [(1, "shoulder angle [deg]"), (5, "power draw [kW]"),
              (7, "fluid's net work rate on the balls [kW]")]
style = {"static": ("o", "--", "standing mesh, turning wall"), "rotating": ("s", "-", "mesh turning with the shell")}
colour = {"noLifters": "C0", "lifters8": "C3"}
for (mill, motion), data in sorted(rows.items()):
    data.sort(key=lambda r: -r[0])
    h = [r[0] for r in data]
    marker, ls, label = style[motion]
    for a, (k, name) in zip(ax, quantities):
        a.errorbar(h, [r[k] for r in data], [r[k + 1] for r in data], marker=marker, ls=ls,
                   color=colour[mill], label=f"{mill}, {label}", capsize=3)
        a.set_ylabel(name)
for a in ax:
    a.set_xlabel("fluid cell size [m]")
    a.set_xlim(0.107, 0.06)
    a.set_xticks([0.1, 0.067])
ax[2].axhspan(-3.5, 0.016, color="0.9", zorder=0)
ax[2].axhline(0, color="k", lw=0.8)
ax[2].set_ylim(-3.0, 3.6)
ax[2].text(0.104, -2.85, "below: energy the balls give the fluid", fontsize=8)
ax[0].legend(fontsize=7)
ax[0].set_title("shoulder (seed 1)", fontsize=9)
ax[1].set_title("power (balls' torque on the shell)", fontsize=9)
ax[2].set_title("fluid's work on the balls (chargeMean.dat)", fontsize=9)
fig.tight_layout()
fig.savefig(stem + ".png", dpi=110)
