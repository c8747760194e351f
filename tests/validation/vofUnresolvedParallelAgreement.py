#!/usr/bin/env python3
"""Unresolved mode in parallel (demInterFoam couplingMode unresolved): serial
and `mpirun -np 2` agree.

Tank 0.12 x 0.06 x 0.10 m open at the top (12 x 6 x 10 cells of 10 mm),
water 0.05 m deep; three polyhedral cubes (H = 20 mm = 2 dx, 700 kg/m3),
exactOverlap void fraction, Gidaspow + freeSurfacePressure, dt 1 ms (DEM
1e-4 s), to 0.2 s:
  - A, centred on x = 0.0603 m: the split plane x = 0.06 m of the two ranks
    (simple (2 1 1)) cuts it; dropped from 15 mm above the surface, it
    falls into the water (crosses both the processor boundary and the free
    surface);
  - B, straddling the surface on rank 0, released 4 mm above its draft;
  - C, on rank 1, dropped from 25 mm above the surface.
The DEM runs once, on the master; each rank computes the void-fraction
weights, the averages at the particles and the forces of its cells, summed
over the ranks (Pstream); the solvers at 1e-12.
Checked (tolerances):
  - the set-up: A's x-extent spans the split plane over the run, and A
    crossed the free surface (bottom above the level at 0, its centre below
    it at the end);
  - every particle's position (DEM state <t>/polyDEM/state, 17 digits,
    matched by id) at t = 0.1 and 0.2 s: max |x_1 - x_2| <= 1e-6 x the
    largest displacement; velocity: max |v_1 - v_2| <= 1e-6 x the largest
    speed (the cubes do not rotate here: no contact and no fluid torque);
  - the water volume int eps alpha dV at the end (waterVolume.dat): 1e-10
    relative.
"""
import math
import os
import shutil
import time
import hedracase as hc
import vofcase as vc

LO, HI, N = (0.0, 0.0, 0.0), (0.12, 0.06, 0.10), (12, 6, 10)
LEVEL, H, RHO = 0.05, 0.02, 700
DT, END, WRITE = 1e-3, 0.2, 0.1
XSPLIT = 0.06
D = (RHO - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H      # Archimedes draft
BLOCKS = {
    "A": (0.0603, 0.0312, LEVEL + 0.015 + H / 2),
    "B": (0.0287, 0.0296, LEVEL - D + 0.004 + H / 2),
    "C": (0.0921, 0.0304, LEVEL + 0.025 + H / 2),
}

case = hc.workdir("vofUnresolvedParallel")
vc.closed_tank(case, LO, HI, N, open_top=True)
boxes = [((c[0] - H / 2, c[1] - H / 2, c[2] - H / 2), (c[0] + H / 2, c[1] + H / 2, c[2] + H / 2))
         for c in BLOCKS.values()]
vc.water_field(case, LO, HI, N, LEVEL, boxes)
vc.vof_dicts(case, END, DT, WRITE)
vc.dem_blocks(case, 1e-4, RHO, list(BLOCKS.values()), (H, H, H), (LO, HI))
hc.coupling(case, """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
forceModels (Gidaspow freeSurfacePressure);
""")
hc.foamfile(os.path.join(case, "system/decomposeParDict"), "decomposeParDict", """
numberOfSubdomains 2;
method simple;
simpleCoeffs { n (2 1 1); delta 0.001; }
""")
hc.run("blockMesh", case, "log.blockMesh")
par = case + "-np2"
shutil.copytree(case, par)
t0 = time.time()
hc.run("demInterFoam", case, "log.demInterFoam")
t1 = time.time()
hc.run("decomposePar", par, "log.decomposePar")
hc.run("mpirun -np 2 demInterFoam -parallel", par, "log.demInterFoam")
t2 = time.time()
print(f"info: serial {t1 - t0:.0f} s, 2 ranks {t2 - t1:.0f} s")


def read_state(path):
    """id -> (position, velocity) of a DEM state file (ascii)."""
    lines = open(path).read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    out = {}
    for l in lines[i + 1:i + 1 + n]:
        v = l.split()
        f = [float(x) for x in v[2:]]
        out[int(v[0])] = (tuple(f[5:8]), tuple(f[12:15]))
    return out


def state(c, t):
    # the parallel run's DEM state is written by the master in the case's
    # own time folder (the DEM is not decomposed)
    for p in (os.path.join(c, t, "polyDEM/state"), os.path.join(c, "processor0", t, "polyDEM/state")):
        if os.path.isfile(p):
            return read_state(p)
    raise SystemExit(f"FAILED: no DEM state for t = {t} in {c}")


results = []
s0 = state(case, "0")
# Which id is block A: the one that starts nearest its centre
idA = min(s0, key=lambda i: math.dist(s0[i][0], BLOCKS["A"]))

# The set-up does what it is meant to: A spans the split plane and crosses the surface
xs = []
for t in (f"{WRITE:g}", f"{END:g}"):
    a = state(case, t)[idA][0]
    xs.append(a)
spans = all(p[0] - H / 2 < XSPLIT < p[0] + H / 2 for p in [s0[idA][0]] + xs)
crossed = s0[idA][0][2] - H / 2 > LEVEL and xs[-1][2] < LEVEL
ok = spans and crossed
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: block A spans the split plane x = {XSPLIT} m (x = "
      + ", ".join(f"{p[0]*1e3:.2f}" for p in [s0[idA][0]] + xs) + " mm at 0, 0.1, 0.2 s) and crossed the"
      f" free surface (bottom {1e3*(s0[idA][0][2] - H/2):.1f} mm at 0, centre {1e3*xs[-1][2]:.2f} mm at"
      f" {END:g} s; level {LEVEL*1e3:.0f} mm)")

for t in (f"{WRITE:g}", f"{END:g}"):
    a, b = state(case, t), state(par, t)
    ok = sorted(a) == sorted(b) and len(a) == len(BLOCKS)
    results.append(ok)
    if not ok:
        print(f"FAIL: t = {t}: particle ids differ ({sorted(a)} vs {sorted(b)})")
        continue
    disp = max(math.dist(a[i][0], s0[i][0]) for i in a)
    dx = max(math.dist(a[i][0], b[i][0]) for i in a)
    vmax = max(math.hypot(*a[i][1]) for i in a)
    dv = max(math.dist(a[i][1], b[i][1]) for i in a)
    for label, err, scale in (("position", dx, disp), ("velocity", dv, vmax)):
        ok = err <= 1e-6 * scale and scale > 0
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: t = {t} s, {label}: serial vs 2 ranks differ by {err:.3g},"
              f" {err / scale if scale > 0 else 0:.3g} of the largest {'displacement' if label == 'position' else 'value'}"
              f" {scale:.4g} (tolerance 1e-6)")

wa, wb = vc.read_water(case)[-1][1], vc.read_water(par)[-1][1]
rel = abs(wb - wa) / wa
ok = rel <= 1e-10
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: water volume int eps alpha dV at {END:g} s: serial {wa:.12g},"
      f" 2 ranks {wb:.12g} m3 (relative {rel:.3g}, tolerance 1e-10)")
hc.finish(results)
