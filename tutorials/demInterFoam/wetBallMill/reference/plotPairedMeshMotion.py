#!/usr/bin/env python3
"""Paired repeats of the wet lifters8 mill (README, "Mesh motion"): for each
seed of the dry fill, the standing mesh with the turning shell wall (the
default until 2026-12-07) and the mesh turning with the shell (-rotating), both from
`./Allrun -mill lifters8 -seed N [-rotating]`. Reads
pairedMeshMotion_lifters8_2026-12-07.dat (the numbers of each run's
results.md, and the energy flows of its chargeMean.dat: the fluid's work
rate on the balls, the contacts' dissipation), prints the paired
differences with their standard errors and plots
pairedMeshMotion_lifters8_2026-12-07.png."""
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
stem = os.path.join(here, "pairedMeshMotion_lifters8_2026-12-07")
r = np.loadtxt(stem + ".dat")
seed, sh_s, toe_s, p_s, se_s, sh_r, toe_r, p_r, se_r, ext_s, dis_s, ext_r, dis_r = r.T


def paired(name, a, b, unit):
    d = b - a
    se = d.std(ddof=1) / len(d) ** 0.5
    print("%-26s rotating - standing: %+.3f +- %.3f %s (t %.1f, %d pairs)"
          % (name, d.mean(), se, unit, d.mean() / se, len(d)))


paired("power", p_s, p_r, "kW")
print("         relative: %+.2f %%" % (100 * (p_r - p_s).mean() / p_s.mean()))
paired("shoulder", sh_s, sh_r, "deg")
paired("toe", toe_s, toe_r, "deg")
paired("fluid's work on the balls", ext_s, ext_r, "kW")
paired("contact dissipation", dis_s, dis_r, "kW")
print("power between seeds: s %.3f kW (standing), %.3f kW (rotating); runs' own s.e. %.3f kW"
      % (p_s.std(ddof=1), p_r.std(ddof=1), np.r_[se_s, se_r].mean()))

fig, ax = plt.subplots(1, 3, figsize=(15, 4))
ax[0].errorbar(seed - 0.08, p_s, se_s, fmt="o", label="standing mesh, turning wall (default)")
ax[0].errorbar(seed + 0.08, p_r, se_r, fmt="s", label="mesh turning with the shell (-rotating)")
ax[0].set_xlabel("seed of the dry fill")
ax[0].set_ylabel("power draw, steady mean [kW]")
ax[0].set_ylim(17.0, 18.35)
ax[0].legend(fontsize=8, loc="lower right")
ax[0].set_title("lifters8, wet: power per seed (error bars: s.e. of the mean)", fontsize=9)
ax[1].plot(seed - 0.08, sh_s, "o", label="shoulder, standing")
ax[1].plot(seed + 0.08, sh_r, "s", label="shoulder, rotating")
ax[1].set_xlabel("seed of the dry fill")
ax[1].set_ylabel("shoulder angle [deg]")
ax[1].legend(fontsize=8)
ax[1].set_title("shoulder per seed", fontsize=9)
ax[2].plot(seed - 0.08, -ext_s, "o", color="C0", label="fluid's work on the balls, standing")
ax[2].plot(seed + 0.08, -ext_r, "s", color="C1", label="fluid's work on the balls, rotating")
ax[2].plot(seed - 0.08, dis_s - 14.0, "o", mfc="none", color="C0", label="contact dissipation - 14 kW, standing")
ax[2].plot(seed + 0.08, dis_r - 14.0, "s", mfc="none", color="C1", label="contact dissipation - 14 kW, rotating")
ax[2].set_xlabel("seed of the dry fill")
ax[2].set_ylabel("[kW]")
ax[2].set_ylim(1.0, 3.6)
ax[2].legend(fontsize=7, loc="upper right")
ax[2].set_title("where the power goes (chargeMean.dat, 6-16 s)", fontsize=9)
fig.tight_layout()
fig.savefig(stem + ".png", dpi=110)
