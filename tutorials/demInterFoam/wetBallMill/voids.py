#!/usr/bin/env python3
"""Wet ball mill (run in a case folder, after `postProcess -func
writeCellVolumes -time <tCouple>`): where the slurry is, from the written
fields at t >= steadyStart. The charge's cells are those with a void
fraction below 0.75 (a solid fraction above 0.25; the bed's is ~0.6 and
the smoothing spreads it over about a cell). Per time: the slurry volume
int eps alpha dV, its part in the charge's cells, their void volume
int eps dV, and the fraction of those voids the slurry fills. Writes
postProcessing/voids.dat and prints the means."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetMill import case_info, internal_field  # noqa: E402

EPS_BED = 0.75


info = case_info(".")
t0 = float(info["steadyStart"])
V = internal_field(os.path.join(info["tCouple"], "V"))
rows = []
for d in sorted(os.listdir("."), key=lambda s: float(s) if re.fullmatch(r"[0-9.]+", s) else -1):
    if not re.fullmatch(r"[0-9.]+", d) or float(d) < t0 - 1e-9:
        continue
    pa, pe = os.path.join(d, "alpha.water"), os.path.join(d, "voidfraction")
    if not (os.path.isfile(pa) and os.path.isfile(pe)):
        continue
    a, e = internal_field(pa), internal_field(pe)
    if not isinstance(e, list):
        e = [e] * len(V)
    W = sum(ei * ai * vi for ei, ai, vi in zip(e, a, V))
    bed = [(ei, ai, vi) for ei, ai, vi in zip(e, a, V) if ei < EPS_BED]
    Wb = sum(ei * ai * vi for ei, ai, vi in bed)
    Vv = sum(ei * vi for ei, _, vi in bed)
    Vb = sum(vi for _, _, vi in bed)
    rows.append((float(d), W, Wb, Vv, Vb))
with open("postProcessing/voids.dat", "w") as f:
    f.write("# time slurry[m3] slurryInCharge[m3] chargeVoids[m3] chargeCells[m3]"
            f" (charge: cells with void fraction < {EPS_BED})\n")
    for r in rows:
        f.write("%g %.6g %.6g %.6g %.6g\n" % r)
if rows:
    n = len(rows)
    inBed = sum(r[2] / r[1] for r in rows) / n
    filled = sum(r[2] / r[3] for r in rows) / n
    print(f"{n} fields at t >= {t0:g} s: {100 * inBed:.1f} % of the slurry in the charge's cells,"
          f" filling {100 * filled:.1f} % of their voids (charge cells {sum(r[4] for r in rows) / n:.3f} m3,"
          f" voids {sum(r[3] for r in rows) / n:.3f} m3)")
