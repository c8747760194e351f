#!/usr/bin/python3
"""CTest iceChannel.studySpeedLaw: the speed-sweep analysis of the brash-ice
study (tutorials/demInterFoam/brashIceChannel/study.py, speed_law and
sweep_table) against cases worked by hand.

1. Exact power law R = 2 U^1.5 at U = 0.3, 0.5, 0.74, 1.0 m/s with 10 %
   standard errors (sigma of ln R = 0.1 at every speed): n = 1.5 and
   a = 2 N to 1e-12. Standard error of n = 1/sqrt(S_xx) with
   S_xx = sum (ln U - mean)^2 / 0.1^2:
     ln U = -1.2039728, -0.6931472, -0.3011051, 0; mean -0.5495563
     deviations^2 = 0.4282610, 0.0206183, 0.0617280, 0.3020121; sum 0.8126194
     S_xx = 81.26194, se = 1/9.014541 = 0.1109319 (tolerance 1e-6 relative).
2. Two speeds off the law (R(0.5) x 1.2, R(1.0) / 1.2, same 10 % errors):
   the reduced chi-square exceeds 1, so se is scaled by sqrt(chi2/dof);
   checked against a direct weighted fit written out here in full.
3. A negative mean at one speed: left out of the fit (3 points remain).
4. The table's coefficients at U = 0.74 m/s, R = 3.44 N, B 0.2 m, H 0.1 m,
   rho_i 920, rho_w 1010, L 1.2 m:
     R/(rho_i g B H^2) = 3.44 / (920 x 9.81 x 0.2 x 0.01) = 3.44 / 18.0504 = 0.190578
     R/(0.5 rho_w U^2 B H) = 3.44 / (0.5 x 1010 x 0.5476 x 0.02) = 3.44 / 5.53076 = 0.621976
     Fn_L = 0.74 / sqrt(9.81 x 1.2) = 0.74 / 3.430977 = 0.215682
   (the table prints 3 decimals: 0.191, 0.622, 0.216).
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tutorials", "demInterFoam", "brashIceChannel"))
import study  # noqa: E402

fails = []


def check(name, got, want, tol):
    ok = abs(got - want) <= tol * max(1.0, abs(want))
    print(f"{'PASS' if ok else 'FAIL'}: {name} = {got:.10g} (expected {want:.10g}, tolerance {tol:g})")
    if not ok:
        fails.append(name)


def row(U, R, e):
    return dict(U=U, RiceNet=(R, e), openWater=(10.0, 0.2), rhoI=920.0, rhoW=1010.0,
                B=0.2, H=0.1, L=1.2, t0=6.0, t1=20.0)


speeds = (0.3, 0.5, 0.74, 1.0)
exact = [row(U, 2 * U ** 1.5, 0.2 * U ** 1.5) for U in speeds]
f = study.speed_law(exact)
check("1. n", f["n"], 1.5, 1e-12)
check("1. a [N]", f["a"], 2.0, 1e-12)
check("1. standard error of n", f["se"], 0.1109319, 1e-6)

off = [row(U, 2 * U ** 1.5 * m, 0.2 * U ** 1.5 * m) for U, m in zip(speeds, (1, 1.2, 1, 1 / 1.2))]
f = study.speed_law(off)
x = [math.log(U) for U in speeds]
y = [math.log(r["RiceNet"][0]) for r in off]
# equal weights (sigma of ln R = 0.1 everywhere): ordinary least squares
xm, ym = sum(x) / 4, sum(y) / 4
sxx = sum((xi - xm) ** 2 for xi in x)
n = sum((xi - xm) * (yi - ym) for xi, yi in zip(x, y)) / sxx
res = [yi - (ym - n * xm) - n * xi for xi, yi in zip(x, y)]
chi2 = sum(r * r for r in res) / 0.01
check("2. n", f["n"], n, 1e-12)
check("2. chi-square", f["chi2"], chi2, 1e-10)
check("2. standard error of n (scaled)", f["se"],
      math.sqrt(0.01 / sxx) * math.sqrt(chi2 / 2), 1e-10)
if not chi2 / 2 > 1:
    fails.append("2. case does not exercise the scaling")

neg = list(exact)
neg[1] = row(0.5, -0.4, 0.3)
f = study.speed_law(neg)
check("3. points used", f["points"], 3, 0)
check("3. n", f["n"], 1.5, 1e-12)

table = "\n".join(study.sweep_table([row(0.74, 3.44, 0.58)], None))
for want in ("| 0.216 |", "| 0.191 +- ", "| 0.622 +- "):
    ok = want in table
    print(f"{'PASS' if ok else 'FAIL'}: 4. the table holds '{want.strip()}'")
    if not ok:
        fails.append("4. " + want)
if "No power law fitted" not in table:
    fails.append("4. no-fit sentence")

if fails:
    print("FAILED:", ", ".join(fails))
    sys.exit(1)
print("all checks passed")
