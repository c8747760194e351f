#!/usr/bin/env python3
"""A coupled run stopped and restarted continues as if unbroken.

30 glass spheres settle in water (DiFelice + pressureGradient, divided).
Run A: 0 -> 0.04 s in one go. Run B: 0 -> 0.02 s, then restarted from the
0.02 folder (DEM state + fluidForces written by demCloud, U, p, phi) to
0.04 s. Compared: particle positions at 0.04 s, matched by id.
Tolerance: max |x_A - x_B| < 1e-9 x max displacement.
"""
import math
import os
import shutil
import hedracase as hc

case = hc.workdir("restart")
hc.block_mesh(case, (0, 0, 0), (0.02, 0.02, 0.04), (8, 8, 16),
              {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
hc.control_dict(case, 0.04, 1e-3, 0.02)
hc.schemes_solution(case, pTol=1e-12, pRelTol=0)
hc.transport(case, 1e-6, 1000)
hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
hc.dem_properties(case, 1e-5, 2500, 1e-3, {"floor": ((0, 0, 0), (0, 0, 1))},
                  hc.random_fill("cloud", 30, (0.003, 0.003, 0.021), (0.017, 0.017, 0.03)))
hc.coupling(case, "voidFractionModel divided;\nforceModels (DiFelice pressureGradient);\n")
hc.run("blockMesh", case, "log.blockMesh")
caseB = case + "-np2"  # (removed with the case by hc.finish)
shutil.copytree(case, caseB)
hc.run("demPimpleFoam", case, "log.demPimpleFoam")


def set_end(c, t):
    p = os.path.join(c, "system/controlDict")
    txt = open(p).read()
    import re
    open(p, "w").write(re.sub(r"\nendTime [^;]*;", f"\nendTime {t};", txt))


set_end(caseB, 0.02)
hc.run("demPimpleFoam", caseB, "log.part1")
set_end(caseB, 0.04)
hc.run("demPimpleFoam", caseB, "log.part2")


def read_state(path):
    lines = open(path).read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    return {int(l.split()[0]): tuple(float(x) for x in l.split()[7:10])
            for l in lines[i + 1:i + 1 + n]}


a = read_state(os.path.join(case, "0.04/polyDEM/state"))
b = read_state(os.path.join(caseB, "0.04/polyDEM/state"))
s0 = read_state(os.path.join(case, "0/polyDEM/state"))
results = []
log2 = open(os.path.join(caseB, "log.part2")).read()
ok = "fluid forces of the restart read" in log2 and "restarting from" in log2
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: part 2 restarted from the 0.02 state and forces")
disp = max(math.dist(a[i], s0[i]) for i in a)
dev = max(math.dist(a[i], b[i]) for i in a)
ok = sorted(a) == sorted(b) and dev < 1e-9 * disp
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: max |x_A - x_B| = {dev:.3g} m, max displacement {disp:.3g} m (ratio < 1e-9)")
hc.finish(results)
