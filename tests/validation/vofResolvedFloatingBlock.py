#!/usr/bin/env python3
"""Floating block, resolved mode (demInterFoam couplingMode resolved: the
cube an immersed boundary with its true shape, directForcingIB penalised
interface, force from the stress on its surface with no Archimedes term).

Tank 0.05 x 0.05 x 0.05 m open to the atmosphere at the top, cells of
dx = 2.5 mm (20^3), water 0.025 m deep (the level on a cell face), a cube of
edge H = 0.02 m (8 dx), its faces off the cell faces, nSubSamples 8.

1. Hydrostatic rest: the cube at its Archimedes draft
       D = (rho_b - rho_a)/(rho_w - rho_a) H
   in water and air at rest, rho_b = 500.5 kg/m3 so that D = 10 mm = 4 dx
   exactly: the cube's faces then lie on the sub-sample points, the solid
   fraction holds the cube's volume exactly and the discrete equilibrium
   is D. (At 500 kg/m3, D = 9.99 mm, the sub-sampled solid fraction puts
   the bottom face up to dx/16 off: the cube then rises 74 um to its
   discrete draft in 0.2 s, 8.6 mm/s in the air beside it.) Run 0.2 s
   (dt 1 ms). Checked: the largest fluid speed of every step (from the
   Courant number, |U| = Co dx/dt) below 1e-3 sqrt(g dx) = 0.16 mm/s
   (sqrt(g dx): the speed of a surface wave one cell long), and the cube's
   vertical displacement below 1e-3 dx = 2.5 um (measured 2026-12-02:
   6e-9 m/s, 6e-15 m).
2. Released 10 % of H above its draft (densities 500 and 920 kg/m3; 700
   with -all), run 1 s (dt 1 ms; heave period about 0.2-0.27 s): the
   draft at the end (mean over the last 30 %) from the cube's bottom z_b
   and the mean water level, which the cube raises: with W the water
   volume outside the body, sum (1 - lambda) alpha V, and A the tank's
   area, d = (W/A - z_b)/(1 - H^2/A). Checked: |d - D|/D <= 3 %; the heave
   decays: the largest |z - z_end| in the last quarter of the run below
   50 % of that in the first quarter.
3. In the runs of 2., whose cube crosses the free surface up and down:
   0 <= alpha <= 1 on every step (to 1e-6: MULES's bound with the solver
   tolerance, no clipping), and the water outside the body W(t): max
   |W - W(0)| below 10 % of the cube's submerged volume. This is a bound,
   not conservation to the solvers' tolerance: W follows the heave
   (measured 2026-12-02: -6.6 % / -6.8 % of the submerged volume at the
   deepest point of the first heave at 500 / 920 kg/m3, back to -3.3 % as
   the cube rises; 0.4 % of the water in the tank), a known limit of the
   resolved mode (docs/models.md). Water entry (a cube dropped into the
   water) is not tested: there W falls by 46 % of the submerged volume
   (docs/models.md), an open defect.
About 1 min 45 s on one core in all (rest 0.2 s, two 1 s runs).
"""
import math
import os
import re
import sys
import hedracase as hc
import vofcase as vc

DX = 0.0025
LO, HI, N = (0.0, 0.0, 0.0), (0.05, 0.05, 0.05), (20, 20, 20)
LEVEL = 0.025
H = 0.02
A = (HI[0] - LO[0]) * (HI[1] - LO[1])
DT = 1e-3
G = 9.81
XC = (0.02537, 0.02468)      # off the cell centres and faces
UTOL = 1e-3 * math.sqrt(G * DX)
ZTOL = 1e-3 * DX
WTOL = 0.1
ATOL = 1e-6

COUPLING = """couplingMode resolved;
demBackend polyDEM;
internalFluid integrated;
directForcing
{
    interface penalised;
    nSubSamples 8;
}
"""


def make(name, rho_b, zb0, end, write):
    case = hc.workdir(name)
    vc.closed_tank(case, LO, HI, N, open_top=True)
    # Water outside the cube exactly (vofcase.water_field); the cells the
    # cube fills are set from the level by the solver (fillSolidCells)
    box = ((XC[0] - H / 2, XC[1] - H / 2, zb0), (XC[0] + H / 2, XC[1] + H / 2, zb0 + H))
    vc.water_field(case, LO, HI, N, LEVEL, [box])
    vc.vof_dicts(case, end, DT, write)
    vc.dem_blocks(case, 1e-4, rho_b, [(XC[0], XC[1], zb0 + H / 2)], (H, H, H), (LO, HI))
    hc.coupling(case, COUPLING)
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)
    return case


def read_forces(case):
    """(t, z, Uz) of postProcessing/ibForces/<t0>/forces.dat"""
    base = os.path.join(case, "postProcessing/ibForces")
    rows = []
    for t in sorted(os.listdir(base), key=float):
        for line in open(os.path.join(base, t, "forces.dat")):
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            rows.append((v[0], v[4], v[7]))
    return rows


def draft(rho_b):
    return (rho_b - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H


results = []

# 1. Hydrostatic rest (D = 4 dx exactly)
RHO_REST = vc.RHO_A + (vc.RHO_W - vc.RHO_A) * 0.5
D = draft(RHO_REST)
case = make("vofResolvedRest", RHO_REST, LEVEL - D, 0.2, 0.2)
log = open(os.path.join(case, "log.demInterFoam")).read()
Co = [float(m) for m in re.findall(r"^Courant Number mean: \S+ max: (\S+)", log, re.M)]
spurious = max(Co) * DX / DT
ok = spurious < UTOL
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: rest: spurious fluid velocity max |U| {spurious:.3g} m/s"
      f" (tolerance 1e-3 sqrt(g dx) = {UTOL:.3g} m/s)")
rows = read_forces(case)
dz = max(abs(r[1] - rows[0][1]) for r in rows)
ok = dz < ZTOL
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: rest: largest vertical displacement of the cube {dz:.3g} m"
      f" (tolerance 1e-3 dx = {ZTOL:.3g} m; final {rows[-1][1] - rows[0][1]:+.3g} m)")

# 2., 3. Released off the draft
END = 1.0
densities = (500, 700, 920) if "-all" in sys.argv else (500, 920)
table, cases = [], []
for rho_b in densities:
    D = draft(rho_b)
    zb0 = LEVEL - D + 0.1 * H
    case = make(f"vofResolvedFloat-{rho_b}", rho_b, zb0, END, END)
    rows = read_forces(case)
    water = vc.read_water(case)
    W0 = water[0][1]
    W = water[-1][1]
    z = [r[1] for r in rows]
    n = len(z)
    zEnd = sum(z[int(0.7 * n):]) / len(z[int(0.7 * n):])
    d = (W / A - (zEnd - H / 2)) / (1 - H * H / A)
    err = (d - D) / D
    ok = abs(err) <= 0.03
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: rho_b = {rho_b}: draft {d*1e3:.3f} mm vs Archimedes"
          f" {D*1e3:.3f} mm (error {100*err:+.2f} %, tolerance 3 %)")
    first = max(abs(v - zEnd) for v in z[: n // 4])
    last = max(abs(v - zEnd) for v in z[3 * n // 4:])
    ok = last < 0.5 * first
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: rho_b = {rho_b}: heave amplitude {first*1e3:.3g} mm"
          f" (first quarter) -> {last*1e3:.3g} mm (last quarter; < 50 %)")
    Vsub = H * H * D
    drift = max(abs(r[1] - W0) for r in water)
    ok = drift <= WTOL * Vsub
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: rho_b = {rho_b}: water outside the body max |W - W0|"
          f" = {drift:.3g} m3 = {drift/Vsub:.3g} of the submerged volume (tolerance {WTOL:g};"
          f" final {(W - W0)/Vsub:+.3g})")
    aMin = min(r[2] for r in water)
    aMax = max(r[3] for r in water)
    ok = aMin >= -ATOL and aMax <= 1 + ATOL
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: rho_b = {rho_b}: alpha in [{aMin:.3g}, 1 + {aMax - 1:.3g}]"
          f" over the run (tolerance {ATOL:g})")
    table.append((rho_b, D, d, err, first, last, drift / Vsub))
    # Heave and water volume as plain columns in the case (kept with
    # HEDRA_KEEP, or when a check fails)
    with open(os.path.join(case, "postProcessing/heave.dat"), "w") as f:
        f.write("# t z_centre Uz waterOutside\n")
        for (t, zz, uz), wr in zip(rows, water):
            f.write(f"{t} {zz} {uz} {wr[1]}\n")
    cases.append((rho_b, case))

# Plot (case folder of each run: postProcessing/heave.png), if matplotlib is there
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for rho_b, c in cases:
        t, zc, wv = [], [], []
        for line in open(os.path.join(c, "postProcessing/heave.dat")):
            if line.startswith("#"):
                continue
            v = [float(x) for x in line.split()]
            t.append(v[0]); zc.append(v[1]); wv.append(v[3])
        D = draft(rho_b)
        fig, ax = plt.subplots(2, 1, sharex=True, figsize=(6, 5))
        ax[0].plot(t, [1e3 * (z - H / 2) for z in zc], label="bottom of the cube")
        ax[0].set_ylabel("z_b [mm]")
        ax[0].set_title(f"resolved floating cube, {rho_b} kg/m3 (Archimedes draft {1e3*D:.2f} mm)")
        ax[1].plot(t, [(w - wv[0]) / (H * H * D) for w in wv])
        ax[1].set_ylabel("(W - W0)/V_sub")
        ax[1].set_xlabel("t [s]")
        fig.tight_layout()
        fig.savefig(os.path.join(c, "postProcessing/heave.png"), dpi=90)
        plt.close(fig)
except ImportError:
    pass

print("\nrho_b  D_Archimedes[mm]  draft[mm]  error[%]  heave first/last [mm]  water drift/Vsub")
for rho_b, D, d, err, first, last, wd in table:
    print(f"  {rho_b:4g}  {D*1e3:8.3f}  {d*1e3:8.3f}  {100*err:+7.2f}  {first*1e3:.3g}/{last*1e3:.3g}"
          f"  {wd:.3g}")
hc.finish(results)
