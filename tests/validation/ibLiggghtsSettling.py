#!/usr/bin/env python3
"""demIbFoam with the LIGGGHTS back end against polyDEM.

The resolved settling sphere (tests/validation/ib/settlingSphere: glass
sphere d = 4 mm, rho_p 2500, in water-like fluid nu 1e-4, rho 1000, 20 x 20
x 40 mm box, d/dx = 4, direct-forcing IB with internal-fluid inertia) to
t = 0.05 s, released at rest from (10, 10, 30) mm, the DEM once polyDEM
(demProperties, list insertion) and once LIGGGHTS (ibProperties:
demBackend liggghts; the same Hertz-Mindlin sphere, floor and gravity in
constant/liggghts/in.liggghts). No contact: the DEM integrates gravity and
the IB force and torque (hdtorque) held over the 100 sub-steps, with
velocity Verlet in both.
Checked: the sphere's position and velocity in postProcessing/ibForces at
every step agree, max |dx| / displacement and max |dU| / |U| below 1e-9
(forces.dat holds 8 digits, writePrecision 8: measured equal in all of
them); so gravity (fix gravity), the mass and the IB force and torque reach
both DEMs alike.
"""
import math
import os
import re
import shutil
import hedracase as hc
import liggghtscase as lc

os.environ.setdefault("OMP_NUM_THREADS", "1")
T1 = 0.05
centre = (0.01, 0.01, 0.03)
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingSphere")


def make_case(name):
    case = hc.workdir(f"ibLiggghts-{name}")
    shutil.rmtree(case)
    shutil.copytree(src, case)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    p = os.path.join(case, "system/controlDict")
    txt = open(p).read()
    txt = re.sub(r"endTime\s+[^;]*;", f"endTime {T1};", txt)
    txt = re.sub(r"writeInterval\s+[^;]*;", f"writeInterval {T1};", txt)
    open(p, "w").write(txt)
    return case


poly = make_case("polyDEM")
p = os.path.join(poly, "constant/demProperties")
txt = open(p).read()
i = txt.index("insertion")
txt = txt[:i] + f"""insertion
{{
    one
    {{
        type list; particleType bead;
        particles ( {{ position ({centre[0]} {centre[1]} {centre[2]}); velocity (0 0 0); }} );
    }}
}}
output {{ format ascii; vtk false; }}
"""
open(p, "w").write(txt)

lig = make_case("liggghts")
os.remove(os.path.join(lig, "constant/demProperties"))
lc.script(lig, ((0, 0, 0), (0.02, 0.02, 0.04)), 1e-5, 2500, 4e-3, [centre], floor_z=0.0,
          couple_every=100)
p = os.path.join(lig, "constant/ibProperties")
txt = open(p).read().replace("demBackend polyDEM;", lc.coupling_lines())
open(p, "w").write(txt)

for case in (poly, lig):
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demIbFoam", case, "log.demIbFoam")


def track(case):
    import glob
    f = glob.glob(os.path.join(case, "postProcessing/ibForces/*/forces.dat"))[0]
    rows = [l.split() for l in open(f) if not l.startswith("#") and l.strip()]
    return {round(float(r[0]), 9): ([float(x) for x in r[2:5]], [float(x) for x in r[5:8]])
            for r in rows}


a, b = track(poly), track(lig)
results = []
common = sorted(set(a) & set(b))
ok = len(common) == len(a) == len(b) and len(common) >= 50
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: {len(common)} common steps")
x0 = centre
worstX = worstU = 0.0
for t in common:
    (xa, ua), (xb, ub) = a[t], b[t]
    disp = math.dist(xa, x0)
    if disp > 0:
        worstX = max(worstX, math.dist(xa, xb) / disp)
    if math.hypot(*ua) > 0:
        worstU = max(worstU, math.dist(ua, ub) / math.hypot(*ua))
xa, ua = a[common[-1]]
print(f"at t = {common[-1]}: polyDEM z {xa[2]:.9g} w {ua[2]:.9g};"
      f" LIGGGHTS z {b[common[-1]][0][2]:.9g} w {b[common[-1]][1][2]:.9g}")
for label, v in (("max |dx| / displacement", worstX), ("max |dU| / |U|", worstU)):
    ok = v < 1e-9
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: LIGGGHTS vs polyDEM: {label} = {v:.3g} (< 1e-9)")
hc.finish(results)
