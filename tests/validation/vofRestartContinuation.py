#!/usr/bin/env python3
"""demInterFoam: a run stopped and restarted continues bit for bit, in the
unresolved and the resolved coupling mode.

unresolved: tank 0.08 x 0.06 x 0.10 m open at the top (8 x 6 x 10 cells of
10 mm), water 0.05 m deep; two polyhedral cubes (H = 20 mm, 700 kg/m3), one
dropped from 10 mm above the surface (at the restart time it straddles the
free surface, bottom 2 mm under it, falling at ~0.4 m/s), one released 4 mm
above its draft; exactOverlap void fraction, Gidaspow + freeSurfacePressure,
dt 1 ms (DEM 1e-4 s), T = 0.1 s.
resolved: the cube of vofResolvedParallelAgreement.py (immersed boundary,
H = 8 dx, 500 kg/m3, released 0.1 H above its draft in a 20^3 tank open at
the top, directForcing penalised, nSubSamples 8), dt 1 ms, T = 0.04 s.
Fields ascii at 17 digits.
Run A: 0 -> T in one go. Run B: 0 -> T/2, then restarted from the T/2
folder (startFrom latestTime: the fields, the DEM state and, unresolved,
the fluid forces held for the next DEM advance and rAUcoupling; resolved,
the bodies' ibState) to T.
Compared at T: every file of the T folder (fields, <T>/polyDEM/*: the DEM
state with every number of positions, velocities, orientations, forces,
contact history) but uniform/ (the time's name and index), and the rows of
postProcessing (unresolved: demCloud summary.dat; resolved: ibForces
forces.dat; both: demInterFoam waterVolume.dat) after T/2.
Tolerance: bit-exact (identical data; the number of values that differ and
the largest relative difference are printed when they are not).
Before the fixes of 2026-12-02 (unresolved): the first step's particle
forces 15 % off (initCorrectPhi.H projected the restart's phi on
div(phi) = 0); then, with that fixed, p_rgh 9e-4 of its range off at T
(rAUcoupling started from 1).
"""
import glob
import math
import os
import re
import shutil
import time
import hedracase as hc
import vofcase as vc

results = []
num = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def set_control(c, end, write=None):
    p = os.path.join(c, "system/controlDict")
    txt = open(p).read()
    txt = re.sub(r"\nendTime [^;]*;", f"\nendTime {end};", txt)
    txt = re.sub(r"\nwritePrecision [^;]*;", "\nwritePrecision 17;", txt)
    if write is not None:
        txt = re.sub(r"\nwriteInterval [^;]*;", f"\nwriteInterval {write};", txt)
    open(p, "w").write(txt)


def unresolved_case():
    LO, HI, N = (0.0, 0.0, 0.0), (0.08, 0.06, 0.10), (8, 6, 10)
    LEVEL, H, RHO = 0.05, 0.02, 700
    D = (RHO - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H
    blocks = [(0.0247, 0.0312, LEVEL + 0.010 + H / 2),
              (0.0563, 0.0286, LEVEL - D + 0.004 + H / 2)]
    case = hc.workdir("vofRestart")
    vc.closed_tank(case, LO, HI, N, open_top=True)
    boxes = [((c[0] - H / 2, c[1] - H / 2, c[2] - H / 2), (c[0] + H / 2, c[1] + H / 2, c[2] + H / 2))
             for c in blocks]
    vc.water_field(case, LO, HI, N, LEVEL, boxes)
    vc.vof_dicts(case, 0.1, 1e-3, 0.05)
    vc.dem_blocks(case, 1e-4, RHO, blocks, (H, H, H), (LO, HI))
    hc.coupling(case, """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
forceModels (Gidaspow freeSurfacePressure);
""")
    return case, 0.1


def resolved_case():
    LO, HI, N = (0.0, 0.0, 0.0), (0.05, 0.05, 0.05), (20, 20, 20)
    LEVEL, H, RHO = 0.025, 0.02, 500
    XC = (0.02537, 0.02468)
    D = (RHO - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H
    zb0 = LEVEL - D + 0.1 * H
    case = hc.workdir("vofRestartResolved")
    vc.closed_tank(case, LO, HI, N, open_top=True)
    box = ((XC[0] - H / 2, XC[1] - H / 2, zb0), (XC[0] + H / 2, XC[1] + H / 2, zb0 + H))
    vc.water_field(case, LO, HI, N, LEVEL, [box])
    vc.vof_dicts(case, 0.04, 1e-3, 0.02)
    vc.dem_blocks(case, 1e-4, RHO, [(XC[0], XC[1], zb0 + H / 2)], (H, H, H), (LO, HI))
    hc.coupling(case, """couplingMode resolved;
demBackend polyDEM;
directForcing { interface penalised; nSubSamples 8; }
""")
    return case, 0.04


def compare(label, fa, fb):
    a, b = open(fa, errors="replace").read(), open(fb, errors="replace").read()
    # the FoamFile header holds no data
    if "dimensions" in a:
        a, b = a[a.find("dimensions"):], b[b.find("dimensions"):]
    if label == "phiIB":
        # Resolved mode: the projection potential of directForcingIB (zero,
        # not solved in demInterFoam) has p_rgh's patch types; its
        # totalPressure patch is built from the type with gamma 0 and read
        # back at the restart with gamma 1 (OpenFOAM v1912's default for
        # psi none, where gamma is not used): a coefficient, not data
        a, b = (re.sub(r"\n\s*gamma\s+[^;]*;", "", x) for x in (a, b))
    if a == b:
        return True, f"{label} ({len(num.findall(a))})"
    xa = [float(x) for x in num.findall(a)]
    xb = [float(x) for x in num.findall(b)]
    if len(xa) != len(xb):
        return False, f"{label}: different number of values ({len(xa)}, {len(xb)})"
    scale = max(max((abs(x) for x in xa), default=0.0), 1e-300)
    dev = max((abs(x - y) for x, y in zip(xa, xb)), default=0.0)
    nd = sum(1 for x, y in zip(xa, xb) if x != y)
    return False, (f"{label}: {nd} of {len(xa)} numbers differ, max |A - B| = {dev:.3g},"
                   f" {dev/scale:.3g} of max |A|")


def rows_after(files, after):
    out = []
    for fn in sorted(files):
        for line in open(fn):
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            if float(v[0]) > after + 1e-9:
                out.append(v)
    return out


for mode, make in (("unresolved", unresolved_case), ("resolved", resolved_case)):
    case, T = make()
    DT = 1e-3
    set_control(case, T)
    hc.run("blockMesh", case, "log.blockMesh")
    caseB = case + "-np2"  # (removed with the case by hc.finish)
    shutil.copytree(case, caseB)
    t0 = time.time()
    hc.run("demInterFoam", case, "log.demInterFoam")
    t1 = time.time()
    set_control(caseB, T / 2)
    hc.run("demInterFoam", caseB, "log.part1")
    set_control(caseB, T)
    hc.run("demInterFoam", caseB, "log.part2")
    t2 = time.time()
    print(f"info: {mode}: run A {t1 - t0:.1f} s, run B {t2 - t1:.1f} s")

    log2 = open(os.path.join(caseB, "log.part2")).read()
    restarted = "DEM: restarting from" in log2 and "Time = 0.001\n" not in log2 \
        and f"Create mesh for time = {T/2:g}" in log2
    if mode == "unresolved":
        restarted = restarted and "fluid forces of the restart read" in log2
    else:
        restarted = restarted and "restart state read from" in log2
    results.append(restarted)
    print(f"{'PASS' if restarted else 'FAIL'}: {mode}: part 2 restarted from the {T/2:g} folder"
          f" ({'DEM state and fluid forces' if mode == 'unresolved' else 'DEM state and ibState'})")

    tT = f"{T:g}"
    dA, dB = os.path.join(case, tT), os.path.join(caseB, tT)
    files = sorted(os.path.relpath(os.path.join(r, f), dA) for r, _, fs in os.walk(dA) for f in fs)
    files = [f for f in files if not f.startswith("uniform" + os.sep)]
    filesB = sorted(os.path.relpath(os.path.join(r, f), dB) for r, _, fs in os.walk(dB) for f in fs)
    filesB = [f for f in filesB if not f.startswith("uniform" + os.sep)]
    ok = files == filesB and "polyDEM/state" in files and "alpha.water" in files and "phi" in files
    same, diff = [], []
    if ok:
        for f in files:
            good, text = compare(f, os.path.join(dA, f), os.path.join(dB, f))
            (same if good else diff).append(text)
    ok = ok and not diff
    results.append(ok)
    if files != filesB:
        print(f"FAIL: {mode}: the {tT} folders hold different files ({files} / {filesB})")
    elif ok:
        print(f"PASS: {mode}: every file of the {tT} folder identical (values): " + ", ".join(same))
    else:
        print(f"FAIL: {mode}: at {tT} s, bit-exact required: " + "; ".join(diff))

    pp = [("waterVolume.dat", "postProcessing/demInterFoam/*/waterVolume.dat")]
    pp.append(("summary.dat", "postProcessing/demCloud/*/summary.dat") if mode == "unresolved"
              else ("ibForces forces.dat", "postProcessing/ibForces/*/forces.dat"))
    for label, pattern in pp:
        ra = rows_after(glob.glob(os.path.join(case, pattern)), T / 2)
        rb = rows_after(glob.glob(os.path.join(caseB, pattern)), T / 2)
        # the time column may differ in the last digits: a restart starts from
        # the folder's name, the unbroken run from the sum of its time steps
        same = len(ra) == len(rb) == round(T / 2 / DT) and all(
            abs(float(x[0]) - float(y[0])) < 1e-12 and x[1:] == y[1:] for x, y in zip(ra, rb))
        results.append(same)
        if same:
            print(f"PASS: {mode}: {label}: the {len(ra)} rows after {T/2:g} s identical")
        else:
            dev = max((abs(float(p) - float(q)) for x, y in zip(ra, rb) for p, q in zip(x[1:], y[1:])),
                      default=float("nan"))
            print(f"FAIL: {mode}: {label}: rows after {T/2:g} s differ ({len(ra)}, {len(rb)} rows;"
                  f" max difference {dev:.3g})")

    # The bodies moved over the second half (the comparison is not of a rest state)
    def read_z(path):
        lines = open(path).read().split("\n")
        i = lines.index("data")
        n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
        return {int(l.split()[0]): float(l.split()[9]) for l in lines[i + 1:i + 1 + n]}

    z0 = read_z(os.path.join(case, "0/polyDEM/state"))
    zh = read_z(os.path.join(case, f"{T/2:g}/polyDEM/state"))
    zT = read_z(os.path.join(case, tT, "polyDEM/state"))
    moved = max(abs(zT[i] - zh[i]) for i in zT)
    need = 1e-3 if mode == "unresolved" else 1e-4
    ok = moved > need
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {mode}: the blocks moved after the restart (max |dz|"
          f" {moved*1e3:.3f} mm between {T/2:g} and {tT} s; > {need*1e3:g} mm); z [mm] at 0 / {T/2:g} / {tT}: "
          + "; ".join(f"{z0[i]*1e3:.2f} / {zh[i]*1e3:.2f} / {zT[i]*1e3:.2f}" for i in sorted(z0)))
hc.finish(results)
