#!/usr/bin/env python3
"""Drafting, kissing and tumbling of two spheres against Glowinski et al. (2001).

Usage: plotDrafting.py [--check TOL | --checkKiss TOL] [--kissGap G]

Reads postProcessing/ibForces/*/forces.dat (demIbFoam: one row per sphere
and step), writes postProcessing/drafting/spheres.dat
    t [s], z_lead, w_lead, z_follow, w_follow [m, m/s], x_lead, x_follow [m],
    gap/d
(lead: the sphere that starts lower) and drafting.png: the vertical
displacements and velocities of both spheres against the digitised
reference, and the gap. Prints
  kiss time:   the first time the surface gap falls below G d (default
               0.02 d = 33 um: at or in contact; the mesh resolves no gap
               below about a cell, 0.2 d), and the time of the follower's
               peak downward velocity;
  tumble time: the first time the follower is below the leader (the
               vertical positions cross).
--check TOL: exit status 1 when the kiss time (gap) is further than TOL
(fraction) from the reference interval 0.155-0.16 s, or the tumble time
further than TOL from 0.25 s, or when the positions cross only after a
sphere reached the bottom (that is not a tumble). --checkKiss TOL: the kiss
time only.

Reference (/work/shared/reference/glowinskiDKT.md; cgs there): the
following sphere peaks at about -0.182 m/s near t = 0.155 s, the kiss is
at 0.155-0.16 s, the vertical positions cross near t = 0.25 s. The
digitised z curves start the spheres 0.49 cm apart (this case: 0.34 cm),
so their displacements are plotted, to compare shapes, not absolute z.
"""
import glob
import os
import sys

d = 1.67e-3
kissRef = (0.155, 0.16)
tumbleRef = 0.25
wPeakRef = (-0.182, 0.155)
# digitised reference: t [s], z follower [cm], z leader [cm]
ref = [(0, 4.994, 4.503), (0.05, 4.774, 4.269), (0.10, 4.263, 3.759),
       (0.15, 3.483, 3.171), (0.175, 3.071, 2.828), (0.20, 2.686, 2.458),
       (0.225, 2.274, 2.137), (0.249, 1.956, 1.955)]

args = sys.argv[1:]
tol = float(args[args.index("--check") + 1]) if "--check" in args else None
kissOnly = "--checkKiss" in args
if kissOnly:
    tol = float(args[args.index("--checkKiss") + 1])
kissGap = float(args[args.index("--kissGap") + 1]) if "--kissGap" in args else 0.02

files = sorted(glob.glob("postProcessing/ibForces/*/forces.dat"))
if not files:
    sys.exit("no postProcessing/ibForces/*/forces.dat: run ./Allrun first")
rows = {}
for fn in files:
    for line in open(fn):
        if line.startswith("#") or not line.strip():
            continue
        w = line.split()
        rows.setdefault(float(w[0]), {})[int(w[1])] = [float(x) for x in w[2:8]]
t = sorted(k for k in rows if len(rows[k]) == 2)
if len(t) < 2:
    sys.exit("fewer than two rows with both spheres in the forces files")
ids = sorted(rows[t[0]])
lead, follow = sorted(ids, key=lambda i: rows[t[0]][i][2])   # lower first


def col(i, k):
    return [rows[x][i][k] for x in t]


zL, wL, xL = col(lead, 2), col(lead, 5), col(lead, 0)
zF, wF, xF = col(follow, 2), col(follow, 5), col(follow, 0)
yL, yF = col(lead, 1), col(follow, 1)
gap = [(((xF[k] - xL[k])**2 + (yF[k] - yL[k])**2 + (zF[k] - zL[k])**2)**0.5 - d) / d
       for k in range(len(t))]

os.makedirs("postProcessing/drafting", exist_ok=True)
with open("postProcessing/drafting/spheres.dat", "w") as f:
    f.write("# drafting-kissing-tumbling: t [s], z_lead [m], w_lead [m/s], "
            "z_follow [m], w_follow [m/s], x_lead [m], x_follow [m], gap/d\n")
    for k in range(len(t)):
        f.write("%g %.7e %.6e %.7e %.6e %.7e %.7e %.5f\n"
                % (t[k], zL[k], wL[k], zF[k], wF[k], xL[k], xF[k], gap[k]))

tKiss = next((t[k] for k in range(len(t)) if gap[k] < kissGap), None)
# the follower's velocity peak before the tumble
kT = next((k for k in range(len(t)) if zF[k] < zL[k]), None)
tTumble = None
if kT is not None:
    # linear interpolation of the crossing
    a, b = zF[kT - 1] - zL[kT - 1], zF[kT] - zL[kT]
    tTumble = t[kT - 1] + (t[kT] - t[kT - 1]) * a / (a - b)
# the first time a sphere is within 0.05 d of the bottom (z = 0): a
# crossing after that is the follower rolling off the leader on the floor,
# not a tumble in the fluid
tBottom = next((t[k] for k in range(len(t)) if min(zL[k], zF[k]) < 0.55 * d), None)
freeTumble = tTumble is not None and (tBottom is None or tTumble < tBottom)
# the follower's peak speed of the drafting: before the kiss (5 ms after it
# at most), else before the tumble
kEnd = kT if kT is not None else len(t)
if tKiss is not None:
    kEnd = min(kEnd, next((k for k in range(len(t)) if t[k] > tKiss + 0.005), len(t)))
kPeak = min(range(kEnd), key=lambda k: wF[k])
gapMin = min(range(len(t)), key=lambda k: gap[k])


def dev(x, lo, hi):
    """Relative distance of x from the interval [lo, hi] (0 inside)."""
    if x is None:
        return float("inf")
    mid = 0.5 * (lo + hi)
    return max(lo - x, x - hi, 0.0) / mid


print("drafting: spheres start %.2f d apart (centres), end at t = %g s"
      % ((zF[0] - zL[0]) / d, t[-1]))
print("  kiss (gap < %g d): %s; reference %g-%g s: %s"
      % (kissGap, ("t = %.4f s" % tKiss) if tKiss else "not reached",
         kissRef[0], kissRef[1],
         ("%+.1f %%" % (100 * dev(tKiss, *kissRef) * (1 if tKiss > kissRef[1] else -1)))
         if tKiss else "-"))
print("  smallest gap %.4f d at t = %.4f s" % (gap[gapMin], t[gapMin]))
print("  follower's peak velocity %.4f m/s at t = %.4f s (gap %.3f d); reference "
      "about %.3f m/s at %.3f s" % (wF[kPeak], t[kPeak], gap[kPeak], *wPeakRef))
print("  tumble (vertical positions cross): %s; reference %g s: %s"
      % (("t = %.4f s" % tTumble) if tTumble else "not reached", tumbleRef,
         ("%+.1f %%" % (100 * (tTumble / tumbleRef - 1))) if tTumble else "-"))
if tBottom is not None:
    print("  a sphere reaches the bottom (gap < 0.05 d) at t = %.4f s%s"
          % (tBottom, "" if freeTumble else
             ": no tumble in the fluid before that%s"
             % ((", the positions cross at %.4f s on the floor" % tTumble)
                if tTumble else "")))
print("  lateral separation at the end: %.3f d" % (abs(xF[-1] - xL[-1]) / d))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    ms = 1000
    ax[0].plot(t, [ms * (z - zF[0]) for z in zF], "r-", label="following (upper)")
    ax[0].plot(t, [ms * (z - zL[0]) for z in zL], "b-", label="leading (lower)")
    ax[0].plot([r[0] for r in ref], [10 * (r[1] - ref[0][1]) for r in ref], "rs",
               mfc="none", label="Glowinski et al. 2001, following")
    ax[0].plot([r[0] for r in ref], [10 * (r[2] - ref[0][2]) for r in ref], "bo",
               mfc="none", label="Glowinski et al. 2001, leading")
    ax[0].set_ylabel("z - z(0) [mm]")
    ax[0].set_title("displacement (reference starts 4.9 mm apart, here 3.4)",
                    fontsize=9)
    ax[1].plot(t, wF, "r-", label="following")
    ax[1].plot(t, wL, "b-", label="leading")
    # reference velocities: differences of the digitised z
    for j, c in ((1, "rs"), (2, "bo")):
        ax[1].plot([0.5 * (ref[i][0] + ref[i + 1][0]) for i in range(len(ref) - 1)],
                   [0.01 * (ref[i + 1][j] - ref[i][j]) / (ref[i + 1][0] - ref[i][0])
                    for i in range(len(ref) - 1)], c, mfc="none")
    ax[1].plot([wPeakRef[1]], [wPeakRef[0]], "k*", ms=10,
               label="reference follower peak")
    ax[1].set_ylabel("w [m/s]")
    ax[1].set_title("vertical velocity (symbols: differences of the reference z)",
                    fontsize=9)
    ax[2].plot(t, gap, "k-", label="gap / d")
    ax[2].plot(t, [(z2 - z1) / d for z1, z2 in zip(zL, zF)], "g--",
               label="(z_follow - z_lead) / d")
    ax[2].axhline(0, color="0.5", lw=0.5)
    ax[2].set_ylabel("/ d")
    ax[2].set_title("gap and vertical separation", fontsize=9)
    for a in ax:
        a.axvspan(*kissRef, color="orange", alpha=0.3)
        a.axvline(tumbleRef, color="purple", ls=":")
        if tKiss:
            a.axvline(tKiss, color="orange", ls="--")
        if freeTumble:
            a.axvline(tTumble, color="purple", ls="--")
        a.set_xlabel("t [s]")
    ax[0].plot([], [], color="orange", lw=6, alpha=0.3, label="reference kiss")
    ax[0].plot([], [], color="purple", ls=":", label="reference tumble")
    ax[0].plot([], [], color="k", ls="--", label="kiss / tumble here")
    ax[0].legend(fontsize=7)
    ax[1].legend(fontsize=7)
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("drafting.png", dpi=100)
    print("wrote drafting.png, postProcessing/drafting/spheres.dat")
except ImportError:
    # Fall back on gnuplot (Debian's gnuplot-nox)
    import shutil
    import subprocess
    if shutil.which("gnuplot"):
        with open("postProcessing/drafting/reference.dat", "w") as f:
            f.write("# Glowinski et al. (2001), digitised: t [s], z_follow - z0, "
                    "z_lead - z0 [mm]\n")
            for r in ref:
                f.write("%g %g %g\n" % (r[0], 10 * (r[1] - ref[0][1]),
                                        10 * (r[2] - ref[0][2])))
        with open("postProcessing/drafting/referenceVelocity.dat", "w") as f:
            f.write("# differences of the digitised z: t [s], w_follow, w_lead [m/s]\n")
            for i in range(len(ref) - 1):
                h = ref[i + 1][0] - ref[i][0]
                f.write("%g %g %g\n" % (0.5 * (ref[i][0] + ref[i + 1][0]),
                                        0.01 * (ref[i + 1][1] - ref[i][1]) / h,
                                        0.01 * (ref[i + 1][2] - ref[i][2]) / h))
        marks = ("set object 1 rect from %g, graph 0 to %g, graph 1 behind "
                 "fc rgb 'orange' fs transparent solid 0.3 noborder\n"
                 "set arrow 1 from %g, graph 0 to %g, graph 1 nohead dt 3 lc rgb 'purple'\n"
                 % (kissRef[0], kissRef[1], tumbleRef, tumbleRef))
        if tKiss:
            marks += ("set arrow 2 from %g, graph 0 to %g, graph 1 nohead dt 2 "
                      "lc rgb 'orange'\n" % (tKiss, tKiss))
        if freeTumble:
            marks += ("set arrow 3 from %g, graph 0 to %g, graph 1 nohead dt 2 "
                      "lc rgb 'purple'\n" % (tTumble, tTumble))
        D = "'postProcessing/drafting/spheres.dat'"
        R = "'postProcessing/drafting/reference.dat'"
        V = "'postProcessing/drafting/referenceVelocity.dat'"
        script = """set terminal pngcairo size 1500,440 noenhanced font ',9'
set output 'drafting.png'
set multiplot layout 1,3
set xlabel 't [s]'
set xrange [0:%(tmax)g]
%(marks)s
set key bottom left
set title 'displacement (reference spheres start 4.9 mm apart, here 3.4 mm)'
set ylabel 'z - z(0) [mm]'
plot %(D)s u 1:(1000*($4-%(zF0).9g)) w l lw 2 lc rgb 'red' t 'following (upper)', \\
     %(D)s u 1:(1000*($2-%(zL0).9g)) w l lw 2 lc rgb 'blue' t 'leading (lower)', \\
     %(R)s u 1:2 w p pt 4 lc rgb 'red' t 'Glowinski et al. 2001, following', \\
     %(R)s u 1:3 w p pt 6 lc rgb 'blue' t 'Glowinski et al. 2001, leading'
set title 'vertical velocity (open symbols: differences of the reference z)'
set ylabel 'w [m/s]'
set yrange [-0.2:0.05]
set key bottom right
plot %(D)s u 1:5 w l lw 2 lc rgb 'red' t 'following', \\
     %(D)s u 1:3 w l lw 2 lc rgb 'blue' t 'leading', \\
     %(V)s u 1:2 w p pt 4 lc rgb 'red' notitle, \\
     %(V)s u 1:3 w p pt 6 lc rgb 'blue' notitle, \\
     '-' w p pt 3 ps 2 lc rgb 'black' t 'reference follower peak'
%(tp)g %(wp)g
e
set autoscale y
set title 'gap; shaded: reference kiss, dotted: reference tumble, dashed: here'
set ylabel '/ d'
set key top right
plot %(D)s u 1:8 w l lw 2 lc rgb 'black' t 'gap / d', \\
     %(D)s u 1:(($4-$2)/%(d)g) w l dt 2 lw 2 lc rgb 'dark-green' t '(z_follow - z_lead) / d', \\
     0 w l lc rgb 'gray' notitle
unset multiplot
""" % dict(marks=marks, D=D, R=R, V=V, zF0=zF[0], zL0=zL[0], tp=wPeakRef[1],
           wp=wPeakRef[0], d=d, tmax=max(t[-1], 0.26))
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        print("wrote drafting.png (gnuplot), postProcessing/drafting/spheres.dat")
    else:
        print("neither matplotlib nor gnuplot found: "
              "postProcessing/drafting/spheres.dat only")

if tol is not None:
    dK = dev(tKiss, *kissRef)
    dT = dev(tTumble if freeTumble else None, tumbleRef, tumbleRef)
    ok = dK <= tol and (kissOnly or dT <= tol)
    print("%s: kiss %.1f %%%s from the reference (tolerance %.1f %%)"
          % ("PASS" if ok else "FAIL", 100 * dK,
             "" if kissOnly else (", tumble %.1f %%" % (100 * dT) if freeTumble
                                  else ", no tumble in the fluid"), 100 * tol))
    sys.exit(0 if ok else 1)
