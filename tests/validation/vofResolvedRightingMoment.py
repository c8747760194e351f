#!/usr/bin/env python3
"""Hydrostatic righting moment in demInterFoam's resolved mode (the body an
immersed boundary with its true shape; force and torque from the stress on
its surface, hydrostatics included, no Archimedes term added).

Theory: the hydrostatic pressure on the submerged part of a body acts at
its centroid B, so about the centre of mass C the fluid's torque is
    T = (B - C) x (rho_w - rho_a) g V_sub e_z
(the air's share folded in: C is the centroid of the whole), with B and
V_sub from the box clipped exactly by the plane z = level
(vofcase.submerged_box_centroid). In the solver it is the moment of the
weight of the fluid inside the body, taken out with that weight
(ibParticles::evolve, - S x g), and it holds exactly if the body the fluid
sees has the true volume and centroid: directForcing's solidFraction exact
(the default for polyhedra since 2026-12-06).

Tank 0.08 x 0.08 x 0.05 m open at the top, water 0.025 m deep (on a cell
face), directForcing penalised (nSubSamples 8 where sub-sampled). alpha at
t = 0: the water fraction of each cell's fluid outside the body (8^3
sub-samples in the cells the body and the level both cut), so that the
surface is flat.

1. A flat box of 40 x 40 x 10 mm (an ice floe's shape), 500 kg/m3, heeled
   10 deg about x at its Archimedes volume (GZ = 4.27 mm; wall-sided:
   sin(phi) (GM + BM tan^2(phi)/2), GM = B^2/(12 s D) - D (1 - s)/2 =
   24.2 mm), in water and air at rest, dx = 2.5 mm (4 cells thick) and
   1.25 mm (2.5 mm only with -quick), open and closed surface: on the first
   step (the fluid still at rest) the torque handed to the DEM (forces.dat
   TDx) and the vertical force FDz within 1e-6 of the theory and of the
   weight (the level on a cell face, nothing is approximate but round-off:
   measured 2e-12 and 3e-13 relative). Printed (INFO) with solidFraction
   subSampled: +0.31 %, 4.5e-6 N m about y.
2. A 20 mm cube of 875 kg/m3 (GM = 0.65 mm), upright, faces off the grid:
   the horizontal torque below 1e-3 of its righting moment at 1 deg
   (measured 8e-18 N m). Printed (INFO) with solidFraction subSampled:
   4e-6 N m, the righting moment at 5.1 deg: the sub-sampled faces shift
   the centroid of the body the fluid sees by 57 um (0.023 dx).
3. The floe released (dx 2.5 mm, open surface, 0.25 s): the heel comes back
   through upright before 0.1 s (the hydrostatic quarter period with the
   box's own inertia is 0.038 s; the fluid's inertia makes it longer:
   measured 0.057 s) and the first swing past upright stays below 0.9 of
   the 10 deg (measured 6.5 deg: the fluid damps the roll). No published
   roll decay of such a floe is checked against; in this narrow tank the
   roll settles near +-3.5 deg by 0.3-0.6 s (the waves it makes come back
   from the walls).
Before 2026-12-06 the torque handed to the DEM lacked the moment of the
weight of the fluid inside the body (ibParticles::evolve took out that
weight, - M g, but not its moment): 1e-18 N m in 1., which failed.
About 2 min on one core.
"""
import math
import os
import sys

import hedracase as hc
import vofcase as vc

LO, HI = (0.0, 0.0, 0.0), (0.08, 0.08, 0.05)
LEVEL = 0.025
XC = (0.04037, 0.03968)      # off the cell centres and faces
G = 9.81
DT = 1e-3
RELEASE_END = 0.25
TORQUE_TOL = 1e-6
FORCE_TOL = 1e-6


class Body:
    """A box of edges 'size' and density rho, heeled phi degrees about x,
    at its Archimedes volume below LEVEL, centred at XC."""

    def __init__(self, size, rho, phi):
        self.size, self.rho, self.phi = size, rho, phi
        a = math.radians(phi)
        self.q = (math.cos(a / 2), math.sin(a / 2), 0.0, 0.0)
        self.V = size[0] * size[1] * size[2]
        self.s = (rho - vc.RHO_A) / (vc.RHO_W - vc.RHO_A)
        lo, hi = LEVEL - 0.02, LEVEL + 0.02
        for _ in range(100):
            zc = 0.5 * (lo + hi)
            if vc.submerged_box_volume((XC[0], XC[1], zc), self.q, size, LEVEL) > self.s * self.V:
                lo = zc
            else:
                hi = zc
        self.centre = (XC[0], XC[1], 0.5 * (lo + hi))
        self.R = vc._rotation(self.q)

    def inside(self, p):
        d = [p[i] - self.centre[i] for i in range(3)]
        b = [sum(self.R[i][j] * d[i] for i in range(3)) for j in range(3)]   # R^T d
        return all(abs(b[j]) <= 0.5 * self.size[j] for j in range(3))

    def hydrostatic_torque(self):
        """(T_x, T_y) of (B - C) x (rho_w - rho_a) g V_sub e_z, and GZ."""
        Vsub = vc.submerged_box_volume(self.centre, self.q, self.size, LEVEL)
        B = vc.submerged_box_centroid(self.centre, self.q, self.size, LEVEL)
        Fb = (vc.RHO_W - vc.RHO_A) * G * Vsub
        return ((B[1] - self.centre[1]) * Fb, -(B[0] - self.centre[0]) * Fb,
                -(B[1] - self.centre[1]))

    def righting_stiffness(self):
        """(rho_w - rho_a) g V_sub GM [N m/rad] about x, wall-sided."""
        BM = self.size[1] ** 2 / (12 * self.s * self.size[2])
        GM = BM - self.size[2] * (1 - self.s) / 2
        return (vc.RHO_W - vc.RHO_A) * G * self.s * self.V * GM, GM


FLOE = Body((0.04, 0.04, 0.01), 500.0, 10.0)
# A cube of the same 20 mm as vofResolvedFloatingBlock's rest case, upright,
# its faces off the grid (s = 0.875: stable, GM = 0.65 mm)
CUBE = Body((0.02, 0.02, 0.02), vc.RHO_A + (vc.RHO_W - vc.RHO_A) * 0.875, 0.0)


def water_field(case, n, body):
    """alpha.water: the flat level's fraction in every cell, and in the
    cells that both the box and the level cut the water fraction of the
    cell's fluid outside the box (8^3 sub-samples)."""
    dx = [(HI[k] - LO[k]) / n[k] for k in range(3)]
    ext = [sum(abs(body.R[i][j]) * 0.5 * body.size[j] for j in range(3)) for i in range(3)]
    c = body.centre
    vals = []
    m = 8
    for k in range(n[2]):
        z0 = LO[2] + k * dx[2]
        below = min(max((LEVEL - z0) / dx[2], 0.0), 1.0)
        for j in range(n[1]):
            y0 = LO[1] + j * dx[1]
            for i in range(n[0]):
                x0 = LO[0] + i * dx[0]
                a = below
                cut = 0.0 < below < 1.0 and all(
                    c0 < c[d] + ext[d] and c0 + dx[d] > c[d] - ext[d]
                    for d, c0 in enumerate((x0, y0, z0)))
                if cut:
                    fluid = water = 0
                    for a1 in range(m):
                        for b1 in range(m):
                            for c1 in range(m):
                                p = (x0 + (a1 + 0.5) * dx[0] / m, y0 + (b1 + 0.5) * dx[1] / m,
                                     z0 + (c1 + 0.5) * dx[2] / m)
                                if not body.inside(p):
                                    fluid += 1
                                    water += p[2] < LEVEL
                    a = water / fluid if fluid else below
                vals.append(a)
    text = ("dimensions [0 0 0 0 0 0 0];\ninternalField nonuniform List<scalar>\n"
            f"{len(vals)}\n(\n" + "\n".join(f"{v:.17g}" for v in vals) + "\n);\n"
            "boundaryField\n{\n    walls { type zeroGradient; }\n"
            "    atmosphere { type inletOutlet; inletValue uniform 0; value uniform 0; }\n}\n")
    hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water", text, cls="volScalarField")


def run(body, dx, closed=False, fraction="exact", end=3 * DT, write=3 * DT):
    """Run demInterFoam on the body at rest in the tank; the rows of
    forces.dat."""
    n = tuple(int(round((HI[k] - LO[k]) / dx)) for k in range(3))
    case = hc.workdir(f"resolvedRighting-{body.size[2]*1e3:g}mm-{dx*1e3:g}mm-"
                      f"{'closed' if closed else 'open'}-{fraction}")
    vc.closed_tank(case, LO, HI, n, open_top=True)
    water_field(case, n, body)
    vc.vof_dicts(case, end, DT, write, limiterIter=20)
    vc.dem_blocks(case, 1e-4, body.rho, [body.centre], body.size, (LO, HI),
                  orientations=[(body.phi, 0, 0)])
    extra = f"\n    solidFraction {fraction};" + ("\n    closedSurface true;" if closed else "")
    hc.coupling(case, vc.RESOLVED_CUBE_COUPLING.replace(
        "interface penalised;", "interface penalised;" + extra))
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)
    base = os.path.join(case, "postProcessing/ibForces")
    rows = []
    for t in sorted(os.listdir(base), key=float):
        for line in open(os.path.join(base, t, "forces.dat")):
            if line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    return rows


results = []

# 1. The heeled floe: the first step's torque against the hydrostatic moment
Tx, _, GZ = FLOE.hydrostatic_torque()
weight = FLOE.rho * FLOE.V * G
sizes = (0.0025,) if "-quick" in sys.argv else (0.0025, 0.00125)
for dx in sizes:
    for closed in (False, True):
        rows = run(FLOE, dx, closed)
        TDx, FDz = rows[0][27], rows[0][26]
        label = f"floe, dx {dx*1e3:g} mm, {'closed' if closed else 'open'} surface"
        err = TDx / Tx - 1
        ok = abs(err) <= TORQUE_TOL
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {label}: torque about x {TDx:.8g} N m vs hydrostatic"
              f" {Tx:.8g} N m (GZ {GZ*1e3:.3f} mm; error {100*err:+.2g} %, tolerance"
              f" {100*TORQUE_TOL:g} %)")
        err = FDz / weight - 1
        ok = abs(err) <= FORCE_TOL
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {label}: vertical force {FDz:.8g} N vs the weight"
              f" {weight:.8g} N (error {100*err:+.2g} %, tolerance {100*FORCE_TOL:g} %)")
        print("      torque about x on the next steps (the body starts to turn; the"
              " fluid's reaction comes in): " + ", ".join(f"{r[27]:.5g}" for r in rows[1:]))
rows = run(FLOE, 0.0025, fraction="subSampled")
print(f"INFO: floe, dx 2.5 mm, solidFraction subSampled (nSubSamples 8): torque about x"
      f" {rows[0][27]:.8g} N m ({100*(rows[0][27]/Tx - 1):+.2f} %), about y {rows[0][28]:.3g} N m,"
      f" vertical force {100*(rows[0][26]/weight - 1):+.3f} % of the weight")

# 2. The upright cube, faces off the grid: no moment
K, GM = CUBE.righting_stiffness()
bound = 1e-3 * K * math.radians(1.0)
rows = run(CUBE, 0.0025)
Th = math.hypot(rows[0][27], rows[0][28])
ok = Th < bound
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: upright cube (875 kg/m3, GM {GM*1e3:.2f} mm), faces off the grid:"
      f" horizontal torque {Th:.3g} N m (< 1e-3 of its righting moment at 1 deg, {bound:.3g} N m)")
rows = run(CUBE, 0.0025, fraction="subSampled")
Th = math.hypot(rows[0][27], rows[0][28])
print(f"INFO: upright cube, solidFraction subSampled (nSubSamples 8): horizontal torque {Th:.3g} N m"
      f" = the righting moment at {math.degrees(Th / K):.2f} deg")

# 3. Released: the heel must come back through upright and overshoot less
# than it started (the fluid damps the roll: waves, vortices)
rows = run(FLOE, 0.0025, end=RELEASE_END, write=RELEASE_END)
heels = []
for r in rows:
    R = vc._rotation(r[20:24])
    heels.append((r[0], math.degrees(math.atan2(-R[1][2], R[2][2]))))
zeros = [t0 + (t1 - t0) * p0 / (p0 - p1)
         for (t0, p0), (t1, p1) in zip(heels, heels[1:]) if p0 > 0 >= p1 or p0 < 0 <= p1]
first = zeros[0] if zeros else None
# Quarter period with the hydrostatic stiffness and the box's own inertia
# only, I = m (B^2 + D^2)/12
I = FLOE.rho * FLOE.V * (FLOE.size[1] ** 2 + FLOE.size[2] ** 2) / 12
T_QUARTER = 0.5 * math.pi * math.sqrt(I / FLOE.righting_stiffness()[0])
ok = first is not None and first < 0.1
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: floe released at {FLOE.phi:g} deg (dx 2.5 mm, open surface):"
      f" back through upright at {'never' if first is None else f'{first:.4f} s'} (< 0.1 s; the"
      f" hydrostatic quarter period without the fluid's inertia is {T_QUARTER:.4f} s)")
swing = [p for t, p in heels if zeros and zeros[0] <= t <= (zeros[1] if len(zeros) > 1 else t)]
over = max((abs(p) for p in swing), default=FLOE.phi)
ok = len(zeros) > 1 and over < 0.9 * FLOE.phi
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: released: the first swing past upright reaches {over:.2f} deg"
      f" (< 0.9 x {FLOE.phi:g}: the roll is damped), {len(zeros)} zero crossings by {RELEASE_END} s"
      + (f"; half periods {', '.join(f'{b - a:.3f}' for a, b in zip(zeros, zeros[1:]))} s"
         if len(zeros) > 1 else ""))
hc.finish(results)
