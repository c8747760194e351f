#!/usr/bin/env python3
"""Serial and 2-rank runs agree.

30 glass spheres (d = 1 mm) settle in water through the processor boundary
(decomposePar, simple (1 1 2): the split plane z = 20 mm is crossed by all
of them; particles on both sides and straddling it). The DEM runs on the
master; each rank computes the forces of the particles whose centre is in
its cells; weights and forces are summed with Pstream. Compared after
0.1 s: particle positions, matched by id.
Tolerance: max |x_parallel - x_serial| / max displacement < 1e-6
(and the same relative to |x_serial|).
"""
import math
import os
import shutil
import sys
import hedracase as hc

case = hc.workdir("parallel")
hc.block_mesh(case, (0, 0, 0), (0.02, 0.02, 0.04), (8, 8, 16),
              {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
hc.control_dict(case, 0.1, 1e-3, 0.1)
hc.schemes_solution(case, pTol=1e-12, pRelTol=0)
hc.transport(case, 1e-6, 1000)
hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
hc.dem_properties(case, 1e-5, 2500, 1e-3, {"floor": ((0, 0, 0), (0, 0, 1))},
                  hc.random_fill("cloud", 30, (0.003, 0.003, 0.021), (0.017, 0.017, 0.03)))
hc.coupling(case, """formulation setI;
voidFractionModel divided;
forceModels (DiFelice pressureGradient);
""")
hc.run("blockMesh", case, "log.blockMesh")
par = case + "-np2"
shutil.copytree(case, par)
hc.run("demPimpleFoam", case, "log.demPimpleFoam")
hc.run("decomposePar", par, "log.decomposePar")
hc.run("mpirun -np 2 demPimpleFoam -parallel", par, "log.demPimpleFoam")


def read_state(path):
    with open(path) as f:
        lines = f.read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    return {int(l.split()[0]): tuple(float(x) for x in l.split()[7:10])
            for l in lines[i + 1:i + 1 + n]}


s0 = read_state(os.path.join(case, "0/polyDEM/state"))
s = read_state(os.path.join(case, "0.1/polyDEM/state"))
p = read_state(os.path.join(par, "0.1/polyDEM/state"))  # the case folder, also in parallel
results = []
ok = sorted(s) == sorted(p)
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: same particle ids ({len(s)} serial, {len(p)} parallel)")
disp = max(math.dist(s[i], s0[i]) for i in s)
dev = max(math.dist(s[i], p[i]) for i in s if i in p)
rel = max(math.dist(s[i], p[i]) / math.hypot(*s[i]) for i in s if i in p)
crossed = sum(1 for i in s if (s0[i][2] - 0.02) * (s[i][2] - 0.02) < 0)
print(f"max displacement {disp:.4g} m; {crossed} particles crossed the processor boundary")
for label, v in (("max |dx| / max displacement", dev / disp), ("max |dx| / |x|", rel)):
    ok = v < 1e-6
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label} = {v:.3g} (< 1e-6)")
hc.finish(results)
