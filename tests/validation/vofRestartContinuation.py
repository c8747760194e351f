#!/usr/bin/env python3
"""demInterFoam (unresolved mode): a run stopped and restarted continues bit
for bit.

Tank 0.08 x 0.06 x 0.10 m open at the top (8 x 6 x 10 cells of 10 mm),
water 0.05 m deep; two polyhedral cubes (H = 20 mm, 700 kg/m3), one dropped
from 10 mm above the surface (at the restart time it straddles the free
surface, bottom 2 mm under it, falling at ~0.4 m/s), one released 4 mm
above its draft; exactOverlap void
fraction, Gidaspow + freeSurfacePressure, dt 1 ms (DEM 1e-4 s), ascii
fields at 17 digits.
Run A: 0 -> T = 0.1 s in one go. Run B: 0 -> T/2, then restarted from the
T/2 folder (startFrom latestTime: U, p_rgh, alpha.water, phi, the DEM state
and the fluid forces held for the next DEM advance) to T.
Compared at T: the DEM state (every number: positions, velocities,
orientations, forces, contact history), the fields alpha.water, U, p_rgh,
phi, voidfraction and the rows of postProcessing/demCloud summary.dat and
demInterFoam waterVolume.dat after T/2.
Tolerance: bit-exact (identical data; the largest relative difference is
printed when they are not).
"""
import glob
import math
import os
import re
import shutil
import hedracase as hc
import vofcase as vc

LO, HI, N = (0.0, 0.0, 0.0), (0.08, 0.06, 0.10), (8, 6, 10)
LEVEL, H, RHO = 0.05, 0.02, 700
DT, T = 1e-3, 0.1
D = (RHO - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H
BLOCKS = [(0.0247, 0.0312, LEVEL + 0.010 + H / 2),
          (0.0563, 0.0286, LEVEL - D + 0.004 + H / 2)]

case = hc.workdir("vofRestart")
vc.closed_tank(case, LO, HI, N, open_top=True)
boxes = [((c[0] - H / 2, c[1] - H / 2, c[2] - H / 2), (c[0] + H / 2, c[1] + H / 2, c[2] + H / 2))
         for c in BLOCKS]
vc.water_field(case, LO, HI, N, LEVEL, boxes)
vc.vof_dicts(case, T, DT, T / 2)
vc.dem_blocks(case, 1e-4, RHO, BLOCKS, (H, H, H), (LO, HI))
hc.coupling(case, """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
forceModels (Gidaspow freeSurfacePressure);
""")


def set_control(c, end):
    p = os.path.join(c, "system/controlDict")
    txt = open(p).read()
    txt = re.sub(r"\nendTime [^;]*;", f"\nendTime {end};", txt)
    txt = re.sub(r"\nwritePrecision [^;]*;", "\nwritePrecision 17;", txt)
    open(p, "w").write(txt)


set_control(case, T)
hc.run("blockMesh", case, "log.blockMesh")
caseB = case + "-np2"  # (removed with the case by hc.finish)
shutil.copytree(case, caseB)
hc.run("demInterFoam", case, "log.demInterFoam")
set_control(caseB, T / 2)
hc.run("demInterFoam", caseB, "log.part1")
set_control(caseB, T)
hc.run("demInterFoam", caseB, "log.part2")

results = []
log2 = open(os.path.join(caseB, "log.part2")).read()
ok = "restarting from" in log2 and f"Create time" in log2 and "Time = 0.051" in log2 \
    and "Time = 0.001\n" not in log2
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: part 2 restarted from the {T/2:g} folder (DEM state and forces)")

num = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def compare(label, fa, fb):
    a, b = open(fa).read(), open(fb).read()
    # the FoamFile header holds no data
    if "dimensions" in a:
        a, b = a[a.find("dimensions"):], b[b.find("dimensions"):]
    if a == b:
        print(f"PASS: {label}: identical ({len(num.findall(a))} numbers)")
        return True
    xa = [float(x) for x in num.findall(a)]
    xb = [float(x) for x in num.findall(b)]
    if len(xa) != len(xb):
        print(f"FAIL: {label}: different number of values ({len(xa)}, {len(xb)})")
        return False
    scale = max(max((abs(x) for x in xa), default=0.0), 1e-300)
    dev = max(abs(x - y) for x, y in zip(xa, xb))
    nd = sum(1 for x, y in zip(xa, xb) if x != y)
    print(f"FAIL: {label}: {nd} of {len(xa)} numbers differ, max |A - B| = {dev:.3g},"
          f" {dev/scale:.3g} of max |A| (bit-exact required)")
    return False


tT = f"{T:g}"
results.append(compare(f"DEM state at {tT} s", os.path.join(case, tT, "polyDEM/state"),
                       os.path.join(caseB, tT, "polyDEM/state")))
for f in ("alpha.water", "U", "p_rgh", "phi", "voidfraction"):
    results.append(compare(f"field {f} at {tT} s", os.path.join(case, tT, f),
                           os.path.join(caseB, tT, f)))


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


for label, pattern in (("summary.dat", "postProcessing/demCloud/*/summary.dat"),
                       ("waterVolume.dat", "postProcessing/demInterFoam/*/waterVolume.dat")):
    ra = rows_after(glob.glob(os.path.join(case, pattern)), T / 2)
    rb = rows_after(glob.glob(os.path.join(caseB, pattern)), T / 2)
    # the time column may differ in the last digits: a restart starts from
    # the folder's name, the unbroken run from the sum of its time steps
    same = len(ra) == len(rb) == round(T / 2 / DT) and all(
        abs(float(x[0]) - float(y[0])) < 1e-12 and x[1:] == y[1:] for x, y in zip(ra, rb))
    results.append(same)
    if same:
        print(f"PASS: {label}: the {len(ra)} rows after {T/2:g} s identical")
    else:
        dev = max((abs(float(p) - float(q)) for x, y in zip(ra, rb) for p, q in zip(x[1:], y[1:])),
                  default=float("nan"))
        print(f"FAIL: {label}: rows after {T/2:g} s differ ({len(ra)}, {len(rb)} rows; max difference {dev:.3g})")


def read_z(path):
    lines = open(path).read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    return {int(l.split()[0]): float(l.split()[9]) for l in lines[i + 1:i + 1 + n]}


z0 = read_z(os.path.join(case, "0/polyDEM/state"))
zh = read_z(os.path.join(case, f"{T/2:g}/polyDEM/state"))
zT = read_z(os.path.join(case, tT, "polyDEM/state"))
moved = max(abs(zT[i] - zh[i]) for i in zT)
ok = moved > 1e-3
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the blocks moved after the restart (max |dz| {moved*1e3:.3f} mm"
      f" between {T/2:g} and {tT} s; > 1 mm); z [mm] at 0 / {T/2:g} / {tT}: "
      + "; ".join(f"{z0[i]*1e3:.2f} / {zh[i]*1e3:.2f} / {zT[i]*1e3:.2f}" for i in sorted(z0)))
hc.finish(results)
