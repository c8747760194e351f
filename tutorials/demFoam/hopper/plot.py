#!/usr/bin/env python3
"""Hopper tutorial: discharge mass and mass flow rate from the planeFlux
monitor 'outlet', compared with the Beverloo correlation.

Writes postProcessing/massFlowRate.png and prints the measured rate (slope of
a straight line fitted to the discharged mass between 20 % and 80 % of the
total discharged) next to Beverloo's estimate

    W = C rho_b sqrt(g) (D - k d)^(5/2)

(Beverloo, Leniger & van de Velde 1961, Chem. Eng. Sci. 15:260-269), with
C = 0.58, k = 1.5 (Nedderman 1992, Statics and kinematics of granular
materials) and bulk density rho_b = 0.6 rho_p.
"""
import glob
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

# Set-up (from constant/demProperties and makeGeometry.py)
D = 0.035           # orifice diameter [m]
g = 9.81
C, k = 0.58, 1.5
packing = 0.6


def entry(text, name):
    m = re.search(r"\b%s\s+([-+0-9.eE]+)\s*;" % name, text)
    return float(m.group(1)) if m else None


props = open("constant/demProperties").read()
# strip comments
props = re.sub(r"//.*", "", props)
props = re.sub(r"/\*.*?\*/", "", props, flags=re.S)
rho_p = entry(props, "density") or 2500.0
d = entry(props, "mean") or 5e-3
openTime = entry(props, "activeUntil") or 0.0

rows = []
for f in sorted(glob.glob("postProcessing/outlet/*/outlet.dat"),
                key=lambda p: float(p.split(os.sep)[-2])):
    for line in open(f):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(x) for x in line.split()])
if not rows:
    raise SystemExit("no postProcessing/outlet/*/outlet.dat: run ./Allrun first")
rows.sort()
t = [r[0] for r in rows]
mass = [r[2] for r in rows]
rate = [r[4] for r in rows]

W_beverloo = C * packing * rho_p * math.sqrt(g) * (D - k * d) ** 2.5

# Steady discharge: fit between 20 % and 80 % of the discharged mass
total = mass[-1]
sel = [i for i in range(len(t)) if 0.2 * total <= mass[i] <= 0.8 * total]
W_fit = None
if len(sel) >= 3:
    xs = [t[i] for i in sel]
    ys = [mass[i] for i in sel]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    W_fit = sxy / sxx
    b0 = my - W_fit * mx

fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
a1.plot(t, mass, "k-", label="discharged mass (planeFlux 'outlet')")
if W_fit is not None:
    xs = [t[sel[0]], t[sel[-1]]]
    a1.plot(xs, [W_fit * x + b0 for x in xs], "r--", lw=2,
            label="fit 20-80 %%: W = %.3f kg/s" % W_fit)
a1.axvline(openTime, color="grey", ls=":", label="orifice opened")
a1.set_ylabel("discharged mass [kg]")
a1.legend(loc="upper left")
a1.grid(alpha=0.3)

a2.plot(t, rate, "b-", lw=1, label="mass flow rate (0.1 s window)")
a2.axhline(W_beverloo, color="g", ls="--",
           label="Beverloo: %.3f kg/s (C=%.2f, k=%.1f)" % (W_beverloo, C, k))
if W_fit is not None:
    a2.axhline(W_fit, color="r", ls="--", label="measured: %.3f kg/s" % W_fit)
a2.axvline(openTime, color="grey", ls=":")
a2.set_xlabel("time [s]")
a2.set_ylabel("mass flow rate [kg/s]")
a2.legend(loc="lower right")
a2.grid(alpha=0.3)
fig.suptitle("Hopper discharge: D = %.0f mm, d = %.1f mm, D/d = %.1f"
             % (1e3 * D, 1e3 * d, D / d))
fig.tight_layout()
fig.savefig("postProcessing/massFlowRate.png", dpi=110)

print("discharged mass %.4f kg" % total)
print("Beverloo estimate W = %.4f kg/s" % W_beverloo)
if W_fit is not None:
    print("measured (20-80 %% fit) W = %.4f kg/s, ratio to Beverloo %.2f"
          % (W_fit, W_fit / W_beverloo))
print("wrote postProcessing/massFlowRate.png")
