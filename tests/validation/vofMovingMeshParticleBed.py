#!/usr/bin/env python3
"""A bed of particles held in place in still water stays still when the
mesh turns through it (issue 16: the wet mill's balls on a rotating mesh).

The case: demInterFoam, unresolved coupling (exactOverlap void fraction,
Schiller-Naumann drag), in a 2D drum of radius R = 0.05 m (the O-grid of
validation.vofRotatingDrumSpinUp, 1024 cells, 5 mm thick), full of water,
gravity on, the shell a wall at rest (noSlip). A bed of 87 spheres of
3 mm diameter on a 5 mm lattice in the lower half is held in place
(demBackend fixed: the particles neither move nor take the fluid's force),
so the void fraction is a fixed field in space: 0.59-1 in the cells.
The whole mesh turns as a solid body at 15 rpm (the seed mill's speed;
dynamicMotionSolverFvMesh, solidBody, rotatingMotion): in 0.3 s each cell
of the bed sweeps 27 degrees, 6-21 mm, one to four lattice spacings, so
the void fraction of every cell of the bed changes all the time.

The particles see the cell velocity (fluidVelocity cell): the default,
the velocity reconstructed from the face fluxes, is unstable on this
O-grid with particles held in place, on a static mesh too (|U| 5e2 m/s
after 6 steps), for the reason interFoam's own velocity reconstruction
diverges on it (validation.vofRotatingDrumSpinUp).

Exact solution: the water stays at rest (no-slip walls at rest, uniform
density, hydrostatic pressure), alpha stays 1. On the moving mesh the
volume-averaged equations must use the flux relative to the cells
phi - epsf meshPhi and, in the pressure equation, ddt(eps) -
div(epsf meshPhi) (createCoupling.H, pEqn.H). Taking interFoam's
phi - meshPhi instead makes each face of the bed sweep a volume
(1 - epsf) meshPhi of fluid that is not there, and the water moves.

Checks:
  - the largest |U| in the drum, at t = 0.1, 0.2 and 0.3 s, below 1e-3
    of the mesh speed Omega R (the bed's apparent flow through the cells
    is 0.2-0.9 Omega R);
  - the same case on a static mesh stays at rest to the same tolerance
    (the case itself is a rest state: hydrostatics and the held bed);
  - alpha within [0, 1] to 1e-6 and the water volume int eps alpha dV
    constant to 1e-10 relative (waterVolume.dat).
"""
import math
import os

import hedracase as hc
import vofcase as vc

R = 0.05
OMEGA = 15 * 2 * math.pi / 60
N, M = 16, 12
C = 0.4 * R
DZ = 0.005
DT = 1e-3
T_END = 0.3
T_CHECK = (0.1, 0.2, 0.3)
D_P = 0.003
SPACING = 0.005


def bed():
    """Sphere centres: a square lattice in the lower half of the drum, a
    particle diameter clear of the shell."""
    pts = []
    k = int(R / SPACING)
    for i in range(-k, k + 1):
        for j in range(-k, 0):
            x, y = i * SPACING, j * SPACING - 0.5 * SPACING
            if math.hypot(x, y) <= R - 2 * D_P and y <= -0.01:
                pts.append((x, y, 0.5 * DZ))
    return pts


def write_case(case, omega):
    vc.drum_mesh(case, R, N, M, C, DZ)
    vc.rotating_mesh(case, omega)
    vc.vof_dicts(case, T_END, DT, 0.05, pTol=1e-10)
    sides = "    frontAndBack { type empty; }\n"
    hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water",
                "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 1;\n"
                "boundaryField\n{\n    shell { type zeroGradient; }\n" + sides + "}\n",
                cls="volScalarField")
    hc.foamfile(os.path.join(case, "0/U"), "U",
                "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
                "boundaryField\n{\n    shell { type noSlip; }\n" + sides + "}\n",
                cls="volVectorField")
    hc.foamfile(os.path.join(case, "0/p_rgh"), "p_rgh",
                "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
                "boundaryField\n{\n    shell { type fixedFluxPressure; value uniform 0; }\n"
                + sides + "}\n", cls="volScalarField")
    fvs = os.path.join(case, "system/fvSolution")
    txt = open(fvs).read()
    # velocityCorrection gradient: interFoam's reconstruct diverges from rest
    # on this O-grid (validation.vofRotatingDrumSpinUp)
    txt = txt.replace("PIMPLE\n{", "PIMPLE\n{\n    correctPhi yes;\n    moveMeshOuterCorrectors no;"
                      "\n    velocityCorrection gradient;")
    open(fvs, "w").write(txt)
    bodies = "\n".join(
        f"    {{ shape sphere; radius {0.5 * D_P}; position ({x:.6g} {y:.6g} {z:.6g});"
        f" velocity (0 0 0); omega (0 0 0); }}" for x, y, z in bed())
    hc.coupling(case, f"""couplingMode unresolved;
demBackend fixed;
bodies
(
{bodies}
);
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
forceModels (SchillerNaumann);
fluidVelocity cell;
""")
    g = os.path.join(case, "constant/g")
    hc.foamfile(g, "g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n",
                cls="uniformDimensionedVectorField")


def largest_speed(case, t):
    _, U = vc.internal_field(os.path.join(case, f"{t:g}", "U"), 3)
    return max(math.sqrt(U[i] ** 2 + U[i + 1] ** 2 + U[i + 2] ** 2)
               for i in range(0, len(U), 3))


def eps_range(case, t):
    _, e = vc.internal_field(os.path.join(case, f"{t:g}", "voidfraction"), 1)
    return min(e), max(e)


results = []
scale = OMEGA * R
print(f"{len(bed())} spheres of {1000 * D_P:g} mm; mesh speed Omega R = {scale:.4f} m/s")
for label, omega in (("rotating mesh", OMEGA), ("static mesh", None)):
    case = hc.workdir("movingMeshBed" if omega else "staticMeshBed")
    write_case(case, omega)
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", timeout=900)
    emin, emax = eps_range(case, T_END)
    print(f"{label}: void fraction {emin:.3f} - {emax:.3f} at {T_END:g} s")
    for t in T_CHECK:
        u = largest_speed(case, t)
        ok = u <= 1e-3 * scale
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {label}, t = {t:4.2f} s: largest |U| "
              f"{u:.3e} m/s = {u / scale:.2e} Omega R (tolerance 1e-3)")
    rows = vc.read_water(case)
    amin = min(row[2] for row in rows)
    amax = max(row[3] for row in rows)
    ok = amin >= -1e-6 and amax <= 1 + 1e-6
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label}: alpha in [{amin:.3e}, 1 + {amax - 1:.3e}]"
          f" (tolerance 1e-6)")
    w0 = rows[0][1]
    dw = max(abs(row[1] - w0) for row in rows) / w0
    ok = dw <= 1e-10
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label}: water volume constant to {dw:.2e}"
          f" relative (tolerance 1e-10)")
    if os.environ.get("HEDRA_KEEP"):
        print("case folder:", case)
hc.finish(results)
