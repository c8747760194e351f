#!/usr/bin/env python3
"""A body several cells across turns with the fluid (demPimpleFoam,
semi-resolved: exactOverlap void fraction, `solidVelocity rigidBody`).

With `solidVelocity rigidBody` the drag of each of a particle's cells acts on
the solid's velocity there, Up + omega x (x_c - x_p), so a body spanning
cells feels the torque of the fluid's rotation across it and drives the
fluid of its cells round when it turns (docs/models.md). With the default
(`centre`) the drag acts on the centre's velocity in every cell and nothing
turns a body.

Case: plane Couette flow, gamma = 1/s (walls at y = +-60 mm moving at
+-60 mm/s, cyclic in x and z, 80 mm periods), a viscous fluid (nu 1e-3 m2/s,
rho 1000), a neutrally buoyant body centred on a cell vertex on the centre
plane (its cells symmetric in x and y), drag Gidaspow, no gravity; the
fluid starts with the Couette profile. Coupling step 1e-4 s: the drag and
its torque are explicit on the particle, and beta/m of a body at alphaMin
in this viscous fluid is ~4e3 /s.
  - a cube of edge a = 15 mm (3 cells of 5 mm; Re = gamma a^2/nu = 0.23);
  - a sphere of the same volume (d = 18.6 mm, 3.7 cells).

Reference: a sphere, and any body with cubic symmetry (its resistance
tensors are isotropic, with no coupling between strain and rotation), free
in a simple shear in Stokes flow turns at half the vorticity,
omega_z = -gamma/2 (Jeffery 1922; Happel & Brenner 1965, ch. 5). The walls
(4 a away) and the periodic images (5.3 a) change it little.

Checked (tolerances): serial and `mpirun -np 2` (split through the cube,
y = 0) give the cube's omega_z at 0.05 s to 1e-6 relative (measured 6e-11);
omega_z over the last 0.1 s of 0.3 s within 5 % of
-gamma/2 (the body is 3-4 cells across, and the drag of its part-filled
cells drives the fluid there only in part: measured -3.0 % for the sphere,
+1.8 % for the cube); the centre stays put (drift < 1 % of a). With
`centre` (printed, not checked) the body does not turn.
Before the turning part of the drag source went in at the cells
(demExchangeFields::rotationSource), it went through the face fluxes with
the rest and reached the fluid half a cell outside the body: the sphere
turned at -0.80 gamma.
"""
import math
import os
import shutil

import hedracase as hc
import vofcase as vc  # noqa: F401 (puts tutorials/demInterFoam/common on the path)
import demState

NOG = (0.0, 0.0, 0.0)
DX, H, L = 0.005, 0.06, 0.08
GAMMA, NU, RHO, A = 1.0, 1e-3, 1000.0, 0.015
END = 0.3


def run(shape, solid, end=END, parallel=False):
    case = hc.workdir(f"solidRotation-{shape}-{solid}")
    n = (round(L / DX), round(2 * H / DX), round(L / DX))
    hc.couette_case(case, H, L, n, GAMMA, NU, RHO)
    hc.control_dict(case, end, 1e-4, 0.025)
    c = (L / 2, 0.0, L / 2)   # a cell vertex: the body's cells symmetric in x and y
    d = A * (6 / math.pi) ** (1 / 3) if shape == "sphere" else A
    hc.dem_properties(case, 1e-4, RHO, d, {"floor": ((0, -H, 0), (0, 1, 0))},
                      f"""    one
    {{
        type list; particleType beads;
        particles ( {{ position ({c[0]} {c[1]} {c[2]}); }} );
    }}""", gravity=NOG)
    if shape == "cube":
        t = open(f"{case}/constant/demProperties").read()
        t = t.replace("contactModel { law hertzMindlin; rolling none; }",
                      "contactModel { law overlapVolume; volumetricStiffness 1e6; rolling none; }")
        t = t.replace(f"beads {{ shape sphere; material mat; diameter {d}; }}",
                      f"beads {{ shape polyhedron; material mat; geometry {{ type cube; edge {A}; }} }}")
        open(f"{case}/constant/demProperties", "w").write(t)
    hc.coupling(case, f"""formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
solidVelocity {solid};
forceModels (Gidaspow);
""")
    hc.run("blockMesh", case, "log.blockMesh")
    if parallel:
        # Two ranks split at y = 0, through the body
        hc.foamfile(os.path.join(case, "system/decomposeParDict"), "decomposeParDict",
                    "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 2 1); }\n")
        shutil.copytree(case, case + "-np2")
        case = case + "-np2"
        hc.run("decomposePar", case, "log.decomposePar")
        hc.run("mpirun -np 2 demPimpleFoam -parallel", case, "log.demPimpleFoam")
    else:
        hc.run("demPimpleFoam", case, "log.demPimpleFoam")
    series = []
    for tt, dd in demState.times(case):
        p = demState.read_state(os.path.join(case, dd, "polyDEM", "state"))["particles"][0]
        series.append((tt, p["wz"], (p["px"] - c[0], p["py"] - c[1], p["pz"] - c[2])))
    return series


results = []
w1, wp = (run("cube", "rigidBody", end=0.05, parallel=p)[-1][1] for p in (False, True))
ok = abs(wp - w1) <= 1e-6 * abs(w1) and w1 != 0
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: cube, rigidBody: omega_z at 0.05 s serial {w1:.12g},"
      f" mpirun -np 2 {wp:.12g} (relative difference {abs(wp - w1) / abs(w1):.2g}, tolerance 1e-6)")
ref = -0.5 * GAMMA
print(f"Re = gamma a^2/nu = {GAMMA * A * A / NU:.3g}; reference omega_z = -gamma/2 = {ref:g} 1/s")
for shape in ("cube", "sphere"):
    series = run(shape, "rigidBody")
    late = [w for t, w, _ in series if t >= END - 0.1 - 1e-9]
    print(f"{shape}, rigidBody: omega_z(t) = " + ", ".join(f"{t:g}: {w:.4f}" for t, w, _ in series[::4]))
    hc.check(f"{shape}, rigidBody: omega_z of the free body in simple shear [1/s]",
             sum(late) / len(late), ref, 0.05, results)
    drift = max(max(abs(x) for x in dx) for _, _, dx in series)
    ok = drift < 0.01 * A
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {shape}: the centre stays put: largest drift {drift:.3g} m"
          f" (< {0.01 * A:g})")

series = run("cube", "centre", end=0.05)
print(f"cube, centre (the default, not checked): omega_z at {series[-1][0]:g} s = {series[-1][1]:.3g} 1/s")
hc.finish(results)
