#!/usr/bin/env python3
"""Ball mill speed sweep (run by ./speedSweep): the steady shoulder, toe and
power of the cases sweep/<noLifters|liftersN>_<fraction>/ (chargeShape means,
postProcessing/charge/*/chargeMean.dat) next to Morrell's charge-shape
correlations and C-model net power (millCorrelations.py, where the
citation is). Writes OUT.dat (plain columns), OUT.png and a markdown table
on standard output.

Usage: speedSweep.py [SWEEPDIR [OUT]] (default sweep speedSweep)
"""
import glob
import math
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import millCorrelations as mc
from tabulate import means  # noqa: E402  (mean, error, samples) per quantity

# The tutorial's mill (chargeNumbers.py): D, slice length, filling, bed solid
# fraction, ball density
D, L, J, SOLID, RHO = 3.0, 0.2, 0.35, 0.6, 7200.0
RHO_C = SOLID * RHO


def wallTime(case):
    try:
        text = open(case + "/runTime").read()
    except OSError:
        return float("nan")
    w = re.search(r"wall time (\d+) s", text)
    return float(w.group(1)) if w else float("nan")


def ballSizes(case):
    text = open(case + "/constant/demProperties").read()
    lo = [float(x) for x in re.findall(r"\bmin\s+([0-9.eE+-]+)\s*;", text)]
    hi = [float(x) for x in re.findall(r"\bmax\s+([0-9.eE+-]+)\s*;", text)]
    return min(lo), max(hi)


def rpmOf(case):
    text = open(case + "/constant/demProperties").read()
    return float(re.search(r"\brpm\s+([0-9.eE+-]+)\s*;", text).group(1))


sweep = sys.argv[1] if len(sys.argv) > 1 else "sweep"
out = sys.argv[2] if len(sys.argv) > 2 else "speedSweep"
rows = []
for case in sorted(glob.glob(os.path.join(sweep, "*_*"))):
    name, frac = os.path.basename(case).rsplit("_", 1)
    lifters = 0 if name == "noLifters" else int(name.replace("lifters", ""))
    m = means(case)
    if "shoulder" not in m:
        print("%s: no steady means (not run, or not finished)" % case, file=sys.stderr)
        continue
    rpm = rpmOf(case)
    phi = rpm / mc.criticalRpm(D)
    rows.append(dict(
        lifters=lifters, phi=phi, rpm=rpm,
        shoulder=m["shoulder"][:2], toe=m["toe"][:2],
        power=(m["power"][0] / 1e3, m["power"][1] / 1e3),
        powerGravity=(m["powerGravity"][0] / 1e3, m["powerGravity"][1] / 1e3),
        n=m["shoulder"][2],
        mShoulder=math.degrees(mc.shoulderAngle(phi, J)),
        mToe=math.degrees(mc.toeAngle(phi, J)),
        mPower=mc.netPower(D, L, J, phi, RHO_C) / 1e3,
        mPowerDEM=mc.netPower(D, L, J, phi, RHO_C, shoulder=math.radians(m["shoulder"][0]),
                              toe=math.radians(m["toe"][0])) / 1e3,
        wall=wallTime(case), balls=ballSizes(case)))
if not rows:
    raise SystemExit("speedSweep.py: no finished cases under %s/" % sweep)
rows.sort(key=lambda r: (r["lifters"], r["phi"]))

with open(out + ".dat", "w") as f:
    f.write("# Dry ball mill speed sweep (tutorials/demFoam/ballMill, ./speedSweep, cases %s/): "
            "D %g m, slice %g m, J %g, charge density %g kg/m^3\n" % (sweep, D, L, J, RHO_C))
    f.write("# angles [deg] from the horizontal on the rising side, positive in the sense "
            "of rotation (chargeShape); errors: standard errors of the steady means "
            "(batch means); power per slice [kW]\n")
    f.write("# Morrell: charge-shape correlations and C-model net power "
            "(millCorrelations.py)\n")
    f.write("# lifters phi rpm shoulder shoulderErr toe toeErr power powerErr powerGravity "
            "powerGravityErr samples morrellShoulder morrellToe morrellPower "
            "morrellPowerAtDEMAngles demFoamWall_s\n")
    for r in rows:
        f.write("%d %.4f %.4f %.3f %.3f %.3f %.3f %.4f %.4f %.4f %.4f %d %.3f %.3f %.4f %.4f %.0f\n"
                % (r["lifters"], r["phi"], r["rpm"], r["shoulder"][0], r["shoulder"][1],
                   r["toe"][0], r["toe"][1], r["power"][0], r["power"][1],
                   r["powerGravity"][0], r["powerGravity"][1], r["n"],
                   r["mShoulder"], r["mToe"], r["mPower"], r["mPowerDEM"], r["wall"]))

print("| lifters | phi | rpm | shoulder deg | Morrell | diff | toe deg | Morrell | diff "
      "| power kW / slice | Morrell C | diff | C-model at DEM angles | demFoam s |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %d | %.2f | %.2f | %.1f +- %.1f | %.1f | %+.1f | %.1f +- %.1f | %.1f | %+.1f "
          "| %.2f +- %.2f | %.2f | %+.0f %% | %.2f | %.0f |"
          % (r["lifters"], r["phi"], r["rpm"], r["shoulder"][0], r["shoulder"][1],
             r["mShoulder"], r["shoulder"][0] - r["mShoulder"],
             r["toe"][0], r["toe"][1], r["mToe"], r["toe"][0] - r["mToe"],
             r["power"][0], r["power"][1], r["mPower"],
             100 * (r["power"][0] / r["mPower"] - 1), r["mPowerDEM"], r["wall"]))

phis = [0.5 + 0.005 * k for k in range(91)]
fig, ax = plt.subplots(1, 3, figsize=(17, 5))
ax[0].plot(phis, [math.degrees(mc.shoulderAngle(p, J)) for p in phis], "b-",
           label="Morrell's correlation (J = %.2f)" % J)
ax[1].plot(phis, [math.degrees(mc.toeAngle(p, J)) for p in phis], "r-",
           label="Morrell's correlation (J = %.2f)" % J)
ax[2].plot(phis, [mc.netPower(D, L, J, p, RHO_C) / 1e3 for p in phis], "g-",
           label="Morrell C-model net power")
marks = {0: "o", 8: "s"}
for lifters in sorted(set(r["lifters"] for r in rows)):
    sel = [r for r in rows if r["lifters"] == lifters]
    lab = "DEM, no lifters" if lifters == 0 else "DEM, %d lifters" % lifters
    mk = marks.get(lifters, "^")
    x = [r["phi"] for r in sel]
    for a, key, colour in ((ax[0], "shoulder", "b"), (ax[1], "toe", "r"), (ax[2], "power", "k")):
        a.errorbar(x, [r[key][0] for r in sel], yerr=[r[key][1] for r in sel], fmt=mk,
                   color=colour, mfc="none" if lifters else colour, capsize=3,
                   label=lab + (", shell torque" if key == "power" else ""))
sizes = sorted(set(r["balls"] for r in rows))
ballText = ", ".join("%g-%g mm" % (1e3 * a, 1e3 * b) for a, b in sizes)
for a in ax:
    a.set_xlabel("fraction of critical speed (N_c = 42.3/sqrt(D) = %.2f rpm)"
                 % mc.criticalRpm(D))
    a.grid(alpha=0.3)
    a.legend(fontsize=8)
ax[0].set_ylabel("shoulder: angle above the rising-side horizontal [deg]")
ax[0].set_title("Shoulder (D %g m, J %.2f, dry, balls %s)" % (D, J, ballText), fontsize=10)
ax[1].set_ylabel("toe: angle from the rising-side horizontal [deg]\n(180 + degrees below "
                 "the falling-side horizontal)")
ax[1].set_title("Toe (same angle convention as chargeShape)", fontsize=10)
ax[2].set_ylabel("power per %g m slice [kW]" % L)
ax[2].set_title("Power draw (charge density %g kg/m^3)" % RHO_C, fontsize=10)
lo, hi = ax[2].get_ylim()
sec = ax[2].twinx()
sec.set_ylim(lo / L, hi / L)
sec.set_ylabel("power per metre of mill [kW/m]")
fig.tight_layout()
fig.savefig(out + ".png", dpi=110)
print("wrote %s.dat, %s.png (%d cases)" % (out, out, len(rows)), file=sys.stderr)
