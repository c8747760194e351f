#!/usr/bin/env python3
"""Settling velocity of the ten Cate sphere against the experiment.

Usage: plotSettling.py CASE [--check TOL]

Reads postProcessing/ibForces/*/forces.dat (demIbFoam), writes
postProcessing/settling/CASE.dat (t [s], z [m], gap/d, w [m/s]) and
settling.png (w(t) and, for E1, the gap against the digitised experiment).

Reference numbers (ten Cate et al. 2002, Phys. Fluids 14:4012; see
/work/shared/reference/tenCate2002.md and README.md):
  E1: the digitised experimental curve, maximum |w| = 0.0383 m/s (t = 1.56 s)
  E2-E4: the maximum speed in the box is about 0.95 u_inf (ten Cate's
         lattice-Boltzmann simulations of the same boxes: 0.947-0.959 u_inf)
w_max: maximum of the settling velocity averaged over one cell crossing
(dx / 0.95 u_inf), as the coarse-mesh velocity oscillates with the cells.
--check TOL: exit status 1 when |w_max / reference - 1| > TOL.
"""
import glob
import os
import sys

d = 0.015
uInf = {"E1": 0.038, "E2": 0.060, "E3": 0.091, "E4": 0.128}
# E1, digitised experiment: (t s, w m/s) and (t s, gap/d)
expW = [(0.05, -0.0132), (0.12, -0.0222), (0.27, -0.0293), (0.54, -0.0351),
        (0.90, -0.0367), (1.56, -0.0383), (2.27, -0.0376), (2.94, -0.0364),
        (3.32, -0.0325), (3.60, -0.0216), (3.78, -0.0109), (4.07, -0.0026)]
expGap = [(0.08, 8.02), (0.59, 6.94), (1.20, 5.63), (1.72, 4.49), (2.31, 3.07),
          (2.94, 1.79), (3.32, 0.87), (3.66, 0.29), (4.11, 0.085)]

args = sys.argv[1:]
case = args[0] if args and not args[0].startswith("-") else "E4"
tol = float(args[args.index("--check") + 1]) if "--check" in args else None
if case == "E1":
    ref, refName = max(-w for _, w in expW), "experiment (digitised curve)"
else:
    ref, refName = 0.95 * uInf[case], "0.95 u_inf (box maximum, ten Cate 2002)"

files = sorted(glob.glob("postProcessing/ibForces/*/forces.dat"))
if not files:
    sys.exit("no postProcessing/ibForces/*/forces.dat: run ./Allrun first")
rows = {}
for fn in files:
    for line in open(fn):
        if line.startswith("#") or not line.strip():
            continue
        w = line.split()
        rows[float(w[0])] = (float(w[4]), float(w[7]))
t = sorted(rows)
z = [rows[x][0] for x in t]
w = [rows[x][1] for x in t]
gap = [(zz - d / 2) / d for zz in z]

os.makedirs("postProcessing/settling", exist_ok=True)
with open("postProcessing/settling/%s.dat" % case, "w") as f:
    f.write("# ten Cate (2002) %s: t [s], z [m], gap/d, w [m/s]\n" % case)
    for row in zip(t, z, gap, w):
        f.write("%g %.6e %.5f %.6e\n" % row)

# On a coarse mesh the velocity oscillates by a few per cent each time the
# sphere crosses a cell (the cells at least half inside switch); the
# maximum is taken of the velocity averaged over one cell crossing,
# window dx/(0.95 u_inf) (dx from the comment makeCase.py writes).
dx = None
try:
    for line in open("system/blockMeshDict"):
        if "(dx = " in line:
            dx = 1e-3 * float(line.split("(dx = ")[1].split()[0])
except OSError:
    pass
window = dx / (0.95 * uInf[case]) if dx else 0.0
wAvg = []
for i, ti in enumerate(t):
    v = [w[j] for j in range(len(t)) if abs(t[j] - ti) <= 0.5 * window + 1e-12]
    wAvg.append(sum(v) / len(v))
iRaw = max(range(len(w)), key=lambda i: -w[i])
iMax = max(range(len(w)), key=lambda i: -wAvg[i])
wMax = -wAvg[iMax]
dev = wMax / ref - 1
print("%s: maximum settling velocity (averaged over a cell crossing, %.3f s) "
      "%.4f m/s at t = %.3f s (gap/d %.2f); reference %.4f m/s, %s: %+.1f %%; "
      "u_max/u_inf = %.3f"
      % (case, window, wMax, t[iMax], gap[iMax], ref, refName, 100 * dev,
         wMax / uInf[case]))
print("  largest instantaneous value %.4f m/s at t = %.3f s (%+.1f %%)"
      % (-w[iRaw], t[iRaw], 100 * (-w[iRaw] / ref - 1)))
if case == "E1":
    # velocity against the experiment at the experimental times
    for te, we in expW:
        if te <= t[-1]:
            wi = min(range(len(t)), key=lambda i: abs(t[i] - te))
            print("  t %.2f s: w %.4f (experiment %.4f)" % (te, w[wi], we))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    nPanel = 2 if case == "E1" else 1
    fig, ax = plt.subplots(1, nPanel, figsize=(5.5 * nPanel, 4))
    a = ax[0] if nPanel == 2 else ax
    a.plot(t, [-x for x in w], "b-", label="demIbFoam")
    if case == "E1":
        a.plot([p[0] for p in expW], [-p[1] for p in expW], "ko",
               label="experiment (ten Cate 2002)")
    else:
        a.axhspan(0.947 * uInf[case], 0.959 * uInf[case], color="0.8",
                  label="box maximum 0.947-0.959 u_inf (ten Cate 2002)")
        a.axhline(uInf[case], color="k", ls="--", label="u_inf")
    a.set_xlabel("t [s]")
    a.set_ylabel("settling velocity -w [m/s]")
    a.set_title("ten Cate sphere %s" % case)
    a.legend(loc="lower center")
    if nPanel == 2:
        ax[1].plot(t, gap, "b-", label="demIbFoam")
        ax[1].plot([p[0] for p in expGap], [p[1] for p in expGap], "ko",
                   label="experiment")
        ax[1].set_xlabel("t [s]")
        ax[1].set_ylabel("gap / d")
        ax[1].legend()
    fig.tight_layout()
    fig.savefig("settling.png", dpi=100)
    print("wrote settling.png, postProcessing/settling/%s.dat" % case)
except ImportError:
    # Fall back on gnuplot (Debian's gnuplot-nox)
    import shutil
    import subprocess
    if shutil.which("gnuplot"):
        with open("postProcessing/settling/experiment.dat", "w") as f:
            for te, we in expW:
                f.write("%g %g\n" % (te, -we))
        if case == "E1":
            refPlot = ("'postProcessing/settling/experiment.dat' u 1:2 w p pt 7 lc "
                       "rgb 'black' t 'experiment (ten Cate 2002)'")
        else:
            refPlot = ("%g w l lc rgb 'gray' lw 2 t '0.95 u_inf (box maximum, ten Cate 2002)', "
                       "%g w l dt 2 lc rgb 'black' t 'u_inf'" % (0.95 * uInf[case], uInf[case]))
        script = """set terminal pngcairo size 700,450 noenhanced
set output 'settling.png'
set xlabel 't [s]'
set ylabel 'settling velocity -w [m/s]'
set title 'ten Cate sphere %s'
set key bottom center
plot 'postProcessing/settling/%s.dat' u 1:(-$4) w l lw 2 lc rgb 'blue' t 'demIbFoam', %s
""" % (case, case, refPlot)
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        print("wrote settling.png (gnuplot), postProcessing/settling/%s.dat" % case)
    else:
        print("neither matplotlib nor gnuplot found: postProcessing/settling/%s.dat only"
              % case)

if tol is not None:
    ok = abs(dev) <= tol
    print("%s: |w_max/reference - 1| = %.1f %% %s %.1f %%"
          % ("PASS" if ok else "FAIL", 100 * abs(dev), "<=" if ok else ">", 100 * tol))
    sys.exit(0 if ok else 1)
