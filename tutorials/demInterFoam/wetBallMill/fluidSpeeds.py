#!/usr/bin/env python3
"""Wet ball mill (run in a case folder): the fluid's speeds in the written
fields of the wet run, slurry (alpha > 0.5) and air apart: mean, 95th
percentile and largest |U| [m/s], and the cells above 5 m/s (slurry) and
10 m/s (air). The shell moves at 2.36 m/s; the air's parasitic currents
show here (README, "Numerics"). Writes postProcessing/fluidSpeeds.dat."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetMill import case_info, internal_field  # noqa: E402


def pct(v, q):
    v = sorted(v)
    return v[min(len(v) - 1, int(q * (len(v) - 1) + 0.5))] if v else float("nan")


t0 = float(case_info(".")["tCouple"])
out = []
for d in sorted((d for d in os.listdir(".") if re.fullmatch(r"[0-9.]+", d) and float(d) > t0 + 1e-9),
                key=float):
    if not (os.path.isfile(os.path.join(d, "U")) and os.path.isfile(os.path.join(d, "alpha.water"))):
        continue
    U, a = internal_field(os.path.join(d, "U"), 3), internal_field(os.path.join(d, "alpha.water"))
    if not (isinstance(U, list) and isinstance(a, list)):
        continue
    sp = [sum(c * c for c in u) ** 0.5 for u in U]
    w = [s for s, x in zip(sp, a) if x > 0.5]
    g = [s for s, x in zip(sp, a) if x <= 0.5]
    row = (float(d), sum(w) / len(w), pct(w, 0.95), max(w), sum(1 for s in w if s > 5),
           sum(g) / len(g), pct(g, 0.95), max(g), sum(1 for s in g if s > 10))
    out.append(row)
    print("t %5g  slurry mean %.2f p95 %.2f max %.1f (>5 m/s: %d cells)   air mean %.2f p95 %.2f"
          " max %.1f (>10 m/s: %d cells)" % row)
with open("postProcessing/fluidSpeeds.dat", "w") as f:
    f.write("# time slurryMean slurryP95 slurryMax slurryCellsOver5 airMean airP95 airMax airCellsOver10 [m/s]\n")
    for r in out:
        f.write(" ".join("%.6g" % x for x in r) + "\n")
