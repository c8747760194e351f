#!/usr/bin/env python3
"""Resolved mode on a refining mesh (demInterFoam couplingMode resolved,
dynamicRefineFvMesh on the field ibRefinement: ibRefinementIndicator marks
the cells within 'band' of each body's bounding sphere, and with
refinement { freeSurface yes; } the interface cells too).

A cube of edge H = 0.02 m, 500 kg/m3, released 10 % of H above its
Archimedes draft in a tank 0.1 x 0.1 x 0.05 m open at the top, water
0.025 m deep (the floating block of vofResolvedFloatingBlock.py in a tank
twice as wide, so that the refined region is a part of it), 0.5 s
(two heave periods; -full: 1 s), on three meshes:
  uniform     dx = 2.5 mm everywhere (40 x 40 x 20 cells);
  body only   a base mesh of 5 mm refined one level (2.5 mm) within
              band = 5 mm of the cube's bounding sphere, merged where it
              has left; the cube starts on the base mesh and is wrapped in
              the first step;
  body and    the same, and along the whole free surface;
  surface
  body and    the same, the free surface only within surfaceBand = 10 mm
  surface     of the cube's bounding sphere (the waves the heave sends
  near it     over the rest of the tank stay on the base mesh).
Checked, for each refined run against the uniform one (both have the same
cells at the body; what differs is the far field and the mesh changes):
1. the submerged volume (from the cube's position and orientation and the
   water outside it, vofcase.submerged_from_water) differs by at most 5 %
   of the heave's first amplitude on every step, and its mean over the
   last 30 % by at most 1 % of Archimedes' volume (before the old fluid
   fraction took the re-sampling of the body in the first step's
   refinement, resolvedTopoChange.H: 26 % and 1.6 %);
2. all three means within 3 % of Archimedes (as the floating block);
3. the water balance W + out = W0 on every step to 1e-8 of the water
   (the first step's re-sampling of the cube, 1.2e-8 m3, is before W0:
   waterVolume.dat's first row is the end of the first step), alpha in
   [0, 1] to 1e-6;
4. the body-only mesh holds at most 35 % of the uniform mesh's cells, the
   body-and-surface mesh at least the 20 x 20 interface cells split more
   and at most 60 %, the mesh with the surface near the body fewer than
   the whole surface's and more than the body's alone; the body-only
   mesh and the one with the surface near it change in at most 20 % of the
   steps (the heaving cube moves little: without the kept band of
   ibRefinementIndicator the band's edge changed in every step).
5. The body-only case serial against two ranks (the cube on the split
   plane), 0.05 s: centre within 1e-4 of the displacement, water within
   1e-10.
Prints the wall times and their ratios (bench/vofResolvedRefinement).
About 6 min on one core.
"""
import math
import os
import re
import sys
import time
import hedracase as hc
import vofcase as vc

H = 0.02
LO, HI = (0.0, 0.0, 0.0), (0.1, 0.1, 0.05)
NU = (40, 40, 20)          # uniform 2.5 mm
NB = (20, 20, 10)          # base 5 mm, refined one level around the cube
LEVEL = 0.025
A = (HI[0] - LO[0]) * (HI[1] - LO[1])
XY = (0.05037, 0.04968)    # off the cell centres and faces of both meshes
DT = 1e-3
END = 0.5 if "-full" not in sys.argv else 1.0
RHO_B = 500.0
BAND = 5e-3
SBAND = 1e-2
WTOL = 1e-8
ATOL = 1e-6

D = (RHO_B - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H
ZB0 = LEVEL - D + 0.1 * H
VARCH = D * H * H


def run(name, n, refinement, end, ranks=1):
    t0 = time.time()
    case = vc.resolved_cube(name, RHO_B, XY, ZB0, H, LO, HI, n, LEVEL, end, DT, end,
                            refinement=refinement, ranks=ranks)
    return case, time.time() - t0


def cells(case, n):
    """Cell counts after each refinement step (log), or the uniform count."""
    log = open(os.path.join(case, "log.demInterFoam")).read()
    counts = [int(m) for m in re.findall(r"Refined from \d+ to (\d+) cells", log)]
    counts += [int(m) for m in re.findall(r"Unrefined from \d+ to (\d+) cells", log)]
    return counts or [n[0] * n[1] * n[2]]


def submerged(case):
    rows = vc.read_ib_forces(case)
    water = vc.read_water(case)
    return [(r[0], vc.submerged_from_water(r[3], r[4], (H, H, H), w[1], A)[1])
            for r, w in zip(rows, water)]


def water_checks(label, case, results):
    water = vc.read_water(case)
    W0 = water[0][1]
    out, drift = 0.0, 0.0
    for r in water:
        out += r[6] if len(r) > 6 else 0.0
        drift = max(drift, abs(r[1] + out - W0))
    aMin = min(r[2] for r in water)
    aMax = max(r[3] for r in water)
    for ok, msg in [
        (drift <= WTOL * W0,
         f"{label}: water balance max |W + out - W0| = {drift:.3g} m3 = {drift/W0:.3g} of the"
         f" water (tolerance {WTOL:g})"),
        (aMin >= -ATOL and aMax <= 1 + ATOL,
         f"{label}: alpha in [{aMin:.3g}, 1 + {aMax - 1:.3g}] (tolerance {ATOL:g})"),
    ]:
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {msg}")


def compare(label, su, sr, results):
    """The refined run against the uniform one: submerged volume on every
    step (against the heave's first amplitude) and its late mean; both
    means against Archimedes."""
    n = min(len(su), len(sr))
    ok = n > 0 and abs(su[n - 1][0] - END) < 0.5 * DT and abs(sr[n - 1][0] - END) < 0.5 * DT
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label}: both runs reached t = {END} s ({len(su)} and {len(sr)} steps)")
    first = max(abs(v - VARCH) for _, v in su[: n // 4]) if n else 0.0
    diff = max(abs(a[1] - b[1]) for a, b in zip(su, sr)) if n else float("inf")
    means = [vc.late_mean([v for _, v in s]) for s in (su, sr)]
    d = (means[1] - means[0]) / VARCH
    checks = [
        (n > 0 and diff <= 0.05 * first,
         f"{label} vs uniform: largest difference of the submerged volume {diff/H**2*1e3:.3g} mm x"
         f" H^2 = {100*diff/first if first else 0:.2f} % of the heave's first amplitude"
         f" {first/H**2*1e3:.3g} mm (tolerance 5 %)"),
        (abs(d) <= 0.01,
         f"{label} - uniform mean submerged volume over the last 30 % {100*d:+.3f} % of"
         f" Archimedes' (tolerance 1 %)"),
    ]
    for name, V in (("uniform", means[0]), (label, means[1])):
        err = (V - VARCH) / VARCH
        checks.append((abs(err) <= 0.03,
                       f"{name}: mean submerged volume over the last 30 % {V/VARCH:.4f} of"
                       f" Archimedes' (error {100*err:+.2f} %, tolerance 3 %)"))
    for ok, msg in checks:
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {msg}")


results = []
uni, tUni = run("vofResolvedUniform", NU, None, END)
fs, tFs = run("vofResolvedRefinedSurface", NB, f"band {BAND}; freeSurface yes;", END)
near, tNear = run("vofResolvedRefinedSurfaceBand", NB,
                  f"band {BAND}; freeSurface yes; surfaceBand {SBAND};", END)
ref, tRef = run("vofResolvedRefined", NB, f"band {BAND};", END)
su, sf, sn, sr = submerged(uni), submerged(fs), submerged(near), submerged(ref)
compare("refined (body and free surface)", su, sf, results)
compare("refined (body and the surface near it)", su, sn, results)
compare("refined (body only)", su, sr, results)
water_checks("uniform", uni, results)
water_checks("refined (body and free surface)", fs, results)
water_checks("refined (body and the surface near it)", near, results)
water_checks("refined (body only)", ref, results)
cu, cf, cr = cells(uni, NU)[0], max(cells(fs, NB)), max(cells(ref, NB))
cn = max(cells(near, NB))
ok = cr <= 0.35 * cu
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: refined (body only) mesh at most {cr} cells against {cu}"
      f" uniform ({100*cr/cu:.1f} %, tolerance 35 %)")
extra = 7 * NB[0] * NB[1]
ok = cf >= cr + extra and cf <= 0.6 * cu
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: freeSurface yes: at most {cf} cells against {cr} for the body"
      f" alone (at least {extra} more: the 20 x 20 interface cells split) and {cu} uniform"
      f" ({100*cf/cu:.1f} %, tolerance 60 %)")
ok = cr < cn < cf
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: surfaceBand {SBAND}: at most {cn} cells, between the body"
      f" alone ({cr}) and the whole surface ({cf})")
# 5. Serial against two ranks (split in x through the cube), 0.05 s
END_PAR = 0.05
s1, _ = run("vofResolvedRefinedSerial", NB, f"band {BAND};", END_PAR)
s2, _ = run("vofResolvedRefinedNp2", NB, f"band {BAND};", END_PAR, ranks=2)
r1, r2 = vc.read_ib_forces(s1)[-1], vc.read_ib_forces(s2)[-1]
disp = abs(r1[1] - (ZB0 + H / 2))
err = max(abs(a - b) for a, b in zip(r1[3], r2[3]))
w1, w2 = vc.read_water(s1)[-1][1], vc.read_water(s2)[-1][1]
for ok, msg in [
    (disp > 0 and err <= 1e-4 * disp,
     f"serial vs 2 ranks at {END_PAR} s: cube centre differs by {err:.3g} m, {err/disp if disp else 0:.3g}"
     f" of its displacement {disp:.3g} m (tolerance 1e-4: the ranks refine their halves, and"
     f" the buffer layers at the processor faces may split a cell a step apart)"),
    (abs(w2 - w1) <= 1e-10 * w1,
     f"serial vs 2 ranks: water outside the body {w1:.12g} / {w2:.12g} m3 (relative"
     f" {abs(w2 - w1)/w1:.3g}, tolerance 1e-10)"),
]:
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {msg}")

steps = [len(cells(c, NB)) for c in (fs, ref, near)]
nSteps = int(round(END / DT))
print(f"INFO: mesh changes in {steps[0]} (body and surface), {steps[2]} (body and the surface"
      f" near it) of {nSteps} steps")
ok = steps[1] <= 0.2 * nSteps
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: refined (body only): {steps[1]} mesh changes in {nSteps}"
      f" steps (at most 20 %: the kept band of ibRefinementIndicator; without it the cells at"
      f" the band's edge were split and merged in every step)")
ok = steps[2] <= 0.2 * nSteps
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: refined (body and the surface near it): {steps[2]} mesh"
      f" changes in {nSteps} steps (at most 20 %, as the body alone: the surface within"
      f" surfaceBand moves with the cube's heave, the waves beyond it are not followed)")

with open(os.path.join(ref, "postProcessing/submerged.dat"), "w") as f:
    f.write("# t submergedVolume [m3]: uniform, refined (body and free surface),"
            " refined (body only), refined (body and the surface near it)\n")
    for a, b, e, g in zip(su, sf, sr, sn):
        f.write(f"{a[0]} {a[1]} {b[1]} {e[1]} {g[1]}\n")
print(f"\nwall time: uniform {tUni:.1f} s ({cu} cells), refined at the body and the surface"
      f" {tFs:.1f} s (at most {cf} cells), at the body and the surface near it {tNear:.1f} s"
      f" (at most {cn} cells), at the body only {tRef:.1f} s (at most {cr} cells)")
print(f"ratio uniform/refined (body and surface) wall time: {tUni/tFs:.3f}")
print(f"ratio uniform/refined (body and the surface near it) wall time: {tUni/tNear:.3f}")
print(f"ratio uniform/refined (body only) wall time: {tUni/tRef:.3f}")
hc.finish(results)
