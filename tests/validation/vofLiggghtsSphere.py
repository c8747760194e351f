#!/usr/bin/env python3
"""demInterFoam (unresolved, free surface) with the LIGGGHTS back end
against polyDEM.

vofWaterVolume.py's closed tank (0.06 x 0.06 x 0.08 m, 5 mm cells, water
0.04 m deep) with one glass sphere (d = 2 mm, 2500 kg/m3) released at rest
in the air at (30, 30, 60) mm: it falls through the free surface into the
water (SchillerNaumann + freeSurfacePressure, divided void fraction, setI)
to t = 0.15 s, the DEM once polyDEM (demProperties, list insertion) and
once LIGGGHTS (couplingProperties: demBackend liggghts; the same sphere,
floor and gravity in constant/liggghts/in.liggghts). No contact.
Checked: the sphere crossed the surface (z < 0.04 m at the end); its
velocity and position at every step (summary.dat, 12 digits) agree,
max |dUp| / |Up| and max |dxp| / displacement below 1e-9.
"""
import math
import hedracase as hc
import liggghtscase as lc
import vofcase as vc

LO, HI, N = (0.0, 0.0, 0.0), (0.06, 0.06, 0.08), (12, 12, 16)
LEVEL = 0.04
centre = (0.03, 0.03, 0.06)
COUPLING = """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel divided;
smoothingModel none;
forceModels (SchillerNaumann freeSurfacePressure);
"""


def make_case(name, backend):
    case = hc.workdir(f"vofLiggghts-{name}")
    vc.closed_tank(case, LO, HI, N)
    vc.water_field(case, LO, HI, N, LEVEL)
    vc.vof_dicts(case, 0.15, 5e-4, 1)
    if backend == "polyDEM":
        hc.dem_properties(case, 1e-5, 2500, 2e-3, {"floor": ((0, 0, 0), (0, 0, 1))},
                          f"""    one
    {{
        type list; particleType beads;
        particles ( {{ position ({centre[0]} {centre[1]} {centre[2]}); velocity (0 0 0); }} );
    }}""", E=5e6)
        hc.coupling(case, COUPLING)
    else:
        lc.script(case, (LO, HI), 1e-5, 2500, 2e-3, [centre], floor_z=0.0, E=5e6,
                  couple_every=50)
        hc.coupling(case, COUPLING + lc.coupling_lines())
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", timeout=1200)
    return {round(r[0], 9): r for r in hc.read_summary(case)}


a = make_case("polyDEM", "polyDEM")
b = make_case("liggghts", "liggghts")
results = []
common = sorted(set(a) & set(b))
ok = len(common) == len(a) == len(b) and len(common) > 100
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: {len(common)} common steps")
zEnd = b[common[-1]][hc.COLS["xp"]][2]
ok = zEnd < LEVEL
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: LIGGGHTS sphere at z = {zEnd:.5f} m at the end (< surface {LEVEL} m)")
worstU = worstX = 0.0
for t in common:
    ua, ub = a[t][hc.COLS["Up"]], b[t][hc.COLS["Up"]]
    xa, xb = a[t][hc.COLS["xp"]], b[t][hc.COLS["xp"]]
    if math.hypot(*ua) > 0:
        worstU = max(worstU, math.dist(ua, ub) / math.hypot(*ua))
    if math.dist(xa, centre) > 0:
        worstX = max(worstX, math.dist(xa, xb) / math.dist(xa, centre))
for label, v in (("max |dUp| / |Up|", worstU), ("max |dxp| / displacement", worstX)):
    ok = v < 1e-9
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: LIGGGHTS vs polyDEM: {label} = {v:.3g} (< 1e-9)")
hc.finish(results)
