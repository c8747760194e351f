#!/usr/bin/env python3
"""damBreakRockPile plots (from postProcess.py's files in postProcessing/):
  postProcessing/damBreakRockPile.png  rock displacement, fluid force, front
  postProcessing/contactNetwork.png    the contact network at three times
"""
import math
import os
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import demState as ds

info = {k: v for k, v in (l.split() for l in open("case.info"))}
f = {k: float(v) for k, v in info.items() if k not in ("mode", "coupling")}


def cols(path):
    rows = [[float(x) for x in l.split()] for l in open(path) if l.strip() and not l.startswith("#")]
    return list(zip(*rows))


D = cols("postProcessing/rockDisplacement.dat")
F = cols("postProcessing/fluidForce.dat")
W = cols("postProcessing/waterFront.dat")
fig, ax = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
ax[0].plot(D[0], D[1], label="mean |displacement|")
ax[0].plot(D[0], D[2], label="max |displacement|")
ax[0].plot(D[0], D[3], "--", label="mean x-displacement")
ax[0].set_ylabel("rock displacement [m]")
ax[0].legend()
ax[0].set_title("damBreakRockPile (%s): %d rocks, d_eq %g m"
                % (info["mode"], int(open("postProcessing/pile.dat").readline().split()[1]), f["d"]))
ax[1].plot(F[0], F[1], label="Fx")
ax[1].plot(F[0], F[3], label="Fz (with buoyancy)")
ax[1].set_ylabel("fluid force on the pile [N]")
ax[1].legend()
# (no Ritter line: the column is narrower than high, its reservoir is not
# the semi-infinite one of Ritter's solution; damBreakCubes checks that)
ax[2].plot(W[0], W[1], "o-", ms=3, label="water front (alpha > 0.5 on the floor)")
ax[2].axhspan(f["colX0"], f["colX1"], color="0.85", label="rock column footprint")
ax[2].set_ylabel("x [m]")
ax[2].set_xlabel("t - t_couple [s] (water released at 0)")
ax[2].legend(fontsize=8)
for a in ax:
    a.grid(alpha=0.3)
fig.tight_layout()
fig.savefig("postProcessing/damBreakRockPile.png", dpi=110)

# contact network
files = sorted((float(n[len("network_"):-4]), n) for n in os.listdir("postProcessing/contactNetwork")
               if n.startswith("network_"))
fig, ax = plt.subplots(len(files), 1, figsize=(10, 2.4*len(files)), sharex=True)
ax = ax if len(files) > 1 else [ax]
for a, (t, name) in zip(ax, files):
    s = None
    for tt2, d in ds.times("coupled"):
        if abs(tt2 - t) < 1e-9:
            s = ds.read_state(os.path.join("coupled", d, "polyDEM", "state"))
    ps = s["particles"]
    idx = {p["id"]: p for p in ps}
    cf = [math.sqrt(sum(c*c for c in ds.contact_force(p))) for p in ps]
    for a_, b_, _ in s["pairs"]:
        if a_ in idx and b_ in idx:
            a.plot([idx[a_]["px"], idx[b_]["px"]], [idx[a_]["pz"], idx[b_]["pz"]], "k-", lw=1)
    sc = a.scatter([p["px"] for p in ps], [p["pz"] for p in ps], c=cf, s=40, cmap="viridis",
                   vmin=0, zorder=3)
    fig.colorbar(sc, ax=a, label="|contact force| [N]")
    a.set_ylim(-0.02, 0.45)
    a.set_xlim(0.6, f["L"])
    a.set_ylabel("z [m]")
    a.set_title("t - t_couple = %.2f s: %d rock-rock pairs (lines), %d rock-wall contacts"
                % (t - f["tCouple"], len(s["pairs"]), len(s["walls"])), fontsize=9)
ax[-1].set_xlabel("x [m]")
fig.tight_layout()
fig.savefig("postProcessing/contactNetwork.png", dpi=110)
print("wrote postProcessing/damBreakRockPile.png, postProcessing/contactNetwork.png")
