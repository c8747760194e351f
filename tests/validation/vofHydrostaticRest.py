#!/usr/bin/env python3
"""Hydrostatic rest (demInterFoam, unresolved mode): blocks at rest
straddling a flat free surface, each at its Archimedes draft
D = (rho_b - rho_a)/(rho_w - rho_a) H, in water and air at rest (tank open to the atmosphere at the top), stay at
rest, and so does the fluid.

Tank 0.16 x 0.16 x 0.12 m, cells of 0.01 m, surface at 0.07 m; four cubes:
H = 3 cells at 500 and 920 kg/m3 (cellWeights buoyancy), H = 0.7 cell at
500 and 920 kg/m3 (interfacePlane), far from each other and from the walls;
the initial alpha holds the water outside the blocks exactly. Run 0.3 s (dt 2 ms).

Checked (tolerances): each block's vertical displacement below 1 % of its
edge; the largest fluid velocity over the run (the spurious velocity,
printed) below 5 mm/s; the largest block velocity at the end below 5 mm/s.
"""
import os
import re
import hedracase as hc
import vofcase as vc

DX = 0.01
LO, HI, N = (0.0, 0.0, 0.0), (0.16, 0.16, 0.12), (16, 16, 12)
LEVEL = 0.07
END, DT = 0.3, 2e-3
blocks = [(3.0, 500, (0.0434, 0.0427)), (3.0, 920, (0.1167, 0.0433)),
          (0.7, 500, (0.0436, 0.1163)), (0.7, 920, (0.1164, 0.1168))]
results = []
case = hc.workdir("vofHydrostaticRest")
vc.closed_tank(case, LO, HI, N, open_top=True)
boxes, centres = [], []
for ratio, rho_b, (x, y) in blocks:
    H = ratio * DX
    D = (rho_b - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H
    boxes.append(((x - H / 2, y - H / 2, LEVEL - D), (x + H / 2, y + H / 2, LEVEL - D + H)))
    centres.append((x, y, LEVEL - D + H / 2))
vc.water_field(case, LO, HI, N, LEVEL, boxes)
vc.vof_dicts(case, END, DT, END)
# One DEM type per block (sizes and densities differ)
types, plist = "", ""
for k, ((ratio, rho_b, _), c) in enumerate(zip(blocks, centres)):
    H = ratio * DX
    types += (f"    b{k} {{ shape polyhedron; material m{k};"
              f" geometry {{ type box; size ({H} {H} {H}); }} }}\n")
    plist += (f"    i{k} {{ type list; particleType b{k}; particles"
              f" ( {{ position ({c[0]} {c[1]} {c[2]}); }} ); }}\n")
mats = "".join(f"    m{k} {{ youngsModulus 1e8; poissonsRatio 0.3; density {b[1]}; }}\n"
               for k, b in enumerate(blocks))
hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", f"""device cpu;
timeStep 1e-4;
gravity (0 0 -9.81);
contactModel {{ law overlapVolume; volumetricStiffness 1e6; tangentialStiffnessRatio 0.2857; }}
materials
{{
{mats}}}
interactions {{ default {{ restitution 0.3; friction 0.3; }} }}
particleTypes
{{
{types}}}
walls {{ floor {{ type plane; point (0 0 0); normal (0 0 1); material m0; }} }}
insertion
{{
{plist}}}
output {{ format ascii; vtk false; }}
""")
hc.coupling(case, """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
submergedVolume auto;
forceModels (SchillerNaumann freeSurfacePressure);
""")
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)

def read_state(t):
    """id -> (position, velocity) from <t>/polyDEM/state"""
    lines = open(os.path.join(case, t, "polyDEM/state")).read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    P = {}
    for l in lines[i + 1:i + 1 + n]:
        v = l.split()
        P[int(v[0])] = ([float(x) for x in v[7:10]], [float(x) for x in v[14:17]])
    return P


log = open(os.path.join(case, "log.demInterFoam")).read()
Co = [float(m) for m in re.findall(r"^Courant Number mean: \S+ max: (\S+)", log, re.M)]
# The largest fluid speed of the run from the Courant number, |U| = Co dx/dt
spurious = max(Co) * DX / DT
ok = spurious < 5e-3
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: spurious fluid velocity: max |U| over the run"
      f" {spurious*1e3:.3g} mm/s (from the largest Courant number; tolerance 5 mm/s)")
P0, P1 = read_state("0"), read_state(f"{END:g}")
for k, (ratio, rho_b, _) in enumerate(blocks):
    H = ratio * DX
    pid = sorted(P0)[k]
    dz = P1[pid][0][2] - P0[pid][0][2]
    ok = abs(dz) < 0.01 * H
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: block H = {ratio} dx, rho_b = {rho_b}: vertical"
          f" displacement {dz*1e6:+.3g} um (tolerance 1 % of H = {0.01*H*1e6:.3g} um)")
vmax = max(max(abs(x) for x in P1[pid][1]) for pid in P1)
ok = vmax < 5e-3
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: largest block velocity component at the end {vmax*1e3:.3g} mm/s"
      f" (tolerance 5 mm/s)")
hc.finish(results)
