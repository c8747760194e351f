#!/usr/bin/env python3
"""Wet ball mill, checks of a run (Allrun -test; CTest
validation.vof.wetBallMillTutorial): for each case given
  - the run reached its end time (the last waterVolume.dat row);
  - the slurry volume int eps alpha dV stays within 1e-6 (relative) of its
    value at the first step of the wet run (closed drum: nothing leaves);
  - alpha stays in [-1e-6, 1 + 1e-6];
  - the chargeShape samples of the wet run are finite (shoulder, toe,
    power) and no ball is lost.
Exit 1 when a check fails."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wetMill import case_info, charge_rows, water_rows  # noqa: E402

ok = True


def check(cond, text):
    global ok
    print(("PASS: " if cond else "FAIL: ") + text)
    ok = ok and cond


for case in sys.argv[1:]:
    info = case_info(case)
    w = water_rows(case)
    if not w:
        check(False, f"{case}: no waterVolume.dat")
        continue
    tEnd = float(info["endTime"])
    check(abs(w[-1][0] - tEnd) < 1e-6, f"{case}: the wet run reached t = {w[-1][0]:g} s (end {tEnd:g} s)")
    w0 = w[0][1]
    drift = max(abs(r[1] - w0) for r in w) / w0
    check(drift <= 1e-6, f"{case}: slurry volume {w0:.6f} m3, largest relative change {drift:.2e} (tolerance 1e-6)")
    amin = min(r[2] for r in w)
    amax = max(r[3] for r in w)
    check(amin >= -1e-6 and amax <= 1 + 1e-6,
          f"{case}: alpha in [{amin:.2e}, 1 + {amax - 1:.2e}] (tolerance 1e-6)")
    check(all(r[5] == w[0][5] for r in w), f"{case}: {int(w[0][5])} balls throughout")
    rows, col = charge_rows(case)
    wet = [r for r in rows if r[0] > float(info["tCouple"]) + 1e-9]
    fin = wet and all(math.isfinite(r[col[k]]) for r in wet for k in ("shoulder", "toe", "power"))
    check(bool(fin), f"{case}: {len(wet)} chargeShape samples of the wet run, shoulder, toe and power finite")
sys.exit(0 if ok else 1)
