#!/usr/bin/env python3
"""Wet ball mill: a markdown table of the steady shoulder, toe and power of
the cases given, wet against the dry tutorial's reference run
(tutorials/demFoam/ballMill/reference/results.md) and the seed's values
(ballMill.md). Power: the balls' torque on the shell (chargeShape, every
DEM step), the fluid's (forces on the patch shell, every fluid step) and
their sum; steady means over the chargeShape's steadyStart to the end,
+- standard errors from 8 batch means (the sum's from the batch means of
the sum)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetMill import (batch_means, case_info, charge_means, charge_rows,  # noqa: E402
                     dry_reference, fluid_torque)

# ballMill.md: shoulder height, toe height [m], angles as printed [deg]
SEED = {"noLifters": {"dry": ("2.00", "0.72", "19.36", "214.16"), "wet": ("1.72", "1.08", "6.17", "197.35")},
        "lifters8": {"dry": ("2.62", "0.38", "51.84", "244.18"), "wet": ("2.37", "0.44", "39.40", "230.19")}}


def pm(v, e, d=2):
    if v is None or not math.isfinite(v):
        return "-"
    return "%.*f +- %.*f" % (d, v, d, e) if math.isfinite(e) else "%.*f" % (d, v)


def steady(case):
    info = case_info(case)
    omega = float(info["omega"])
    rows, col = charge_rows(case)
    m = charge_means(case)
    tEnd = rows[-1][0]
    # the chargeShape's steadyStart: the first sample of its means
    t0 = float(info["steadyStart"])
    balls = [(r[0], r[col["power"]]) for r in rows]
    fluid = [(t, -omega * T) for t, T in fluid_torque(case)]
    pb, eb, bb = batch_means(balls, t0, tEnd)
    pf, ef, bf = batch_means(fluid, t0, tEnd)
    tot = [a + b for a, b in zip(bb, bf)]
    pt = pb + pf
    et = (math.sqrt(sum((x - sum(tot) / len(tot)) ** 2 for x in tot) / (len(tot) - 1))
          / math.sqrt(len(tot))) if len(tot) > 1 else float("nan")
    return m, (pb, eb), (pf, ef), (pt, et), (t0, tEnd)


print("| mill | case | shoulder deg | toe deg | shoulder height m | toe height m "
      "| power balls kW | power fluid kW | power total kW | seed: shoulder h, toe h m "
      "| seed: angles as printed deg |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for case in sys.argv[1:]:
    d = dry_reference(case)
    s = SEED.get(case, {})
    if d:
        sd = s.get("dry", ("-",) * 4)
        print("| %s | dry (reference) | %s | %s | %s | %s | %s | - | %s | %s, %s | %s, %s |"
              % (case, pm(*d["shoulder"], d=1), pm(*d["toe"], d=1), pm(*d["shoulderHeight"]),
                 pm(*d["toeHeight"]), pm(*d["power"]), pm(*d["power"]), sd[0], sd[1], sd[2], sd[3]))
    m, b, f, t, (t0, t1) = steady(case)
    sw = s.get("wet", ("-",) * 4)

    def g(k, sc=1.0, dd=2):
        return pm(m[k][0] * sc, m[k][1] * sc, dd) if k in m else "-"
    print("| %s | wet | %s | %s | %s | %s | %s | %s | %s | %s, %s | %s, %s |"
          % (case, g("shoulder", dd=1), g("toe", dd=1), g("shoulderHeight"), g("toeHeight"),
             pm(b[0] / 1e3, b[1] / 1e3), pm(f[0] / 1e3, f[1] / 1e3, 3), pm(t[0] / 1e3, t[1] / 1e3),
             sw[0], sw[1], sw[2], sw[3]))
    if d and "shoulderHeight" in m:
        dsh = m["shoulderHeight"][0] - d["shoulderHeight"][0]
        esh = math.hypot(m["shoulderHeight"][1], d["shoulderHeight"][1])
        dto = m["toeHeight"][0] - d["toeHeight"][0]
        eto = math.hypot(m["toeHeight"][1], d["toeHeight"][1])
        dP = t[0] / 1e3 - d["power"][0]
        eP = math.hypot(t[1] / 1e3, d["power"][1])
        ss = (float(s["wet"][0]) - float(s["dry"][0]), float(s["wet"][1]) - float(s["dry"][1])) \
            if s else (float("nan"),) * 2
        print("| %s | wet - dry | %s | %s | %s | %s | - | - | %s | %+.2f, %+.2f | |"
              % (case, pm(m["shoulder"][0] - d["shoulder"][0], math.hypot(m["shoulder"][1], d["shoulder"][1]), 1),
                 pm(m["toe"][0] - d["toe"][0], math.hypot(m["toe"][1], d["toe"][1]), 1),
                 pm(dsh, esh, 3), pm(dto, eto, 3), pm(dP, eP), ss[0], ss[1]))
print()
print("Means over t = %g-%g s (+- standard errors from 8 batch means)." % (t0, t1))
