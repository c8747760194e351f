#!/usr/bin/env python3
"""demIbFoam: serial and 2-rank runs agree.

The settling-sphere case (tests/validation/ib/settlingSphere: one glass
sphere, d = 4 mm, in a 20 x 20 x 40 mm box, d/dx = 4, demBackend polyDEM) to
t = 0.05 s, serial and decomposed in two (simple (2 1 1): the split plane
x = 10 mm goes through the sphere, whose centre starts 0.07 mm from it), with
the linear solvers converged to 1e-12 so that what is compared is the
coupling, not the solver tolerance. In parallel the DEM runs once on the
master; each rank sums the IB force of its own cells and the parts are
summed over the ranks; the bodies are sent to every rank.
Checks: the DEM state is written once, in the case folder (<t>/polyDEM, not
processor0/<t>/polyDEM); the sphere straddles the processor boundary; the
particle position at 0.05 s agrees to 1e-6 relative (|x_par - x_ser| over
the displacement, and over |x_ser|); the velocity is printed.
"""
import math
import os
import re
import shutil
import hedracase as hc

os.environ.setdefault("OMP_NUM_THREADS", "1")

T1 = 0.05
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingSphere")
case = hc.workdir("ibParallel")
shutil.rmtree(case)
shutil.copytree(src, case)
shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))

p = os.path.join(case, "system/controlDict")
txt = open(p).read()
txt = re.sub(r"endTime\s+[^;]*;", f"endTime {T1};", txt)
txt = re.sub(r"writeInterval\s+[^;]*;", f"writeInterval {T1};", txt)
open(p, "w").write(txt)
p = os.path.join(case, "system/fvSolution")
txt = re.sub(r"tolerance\s+[^;]*;\s*relTol\s+[^;]*;", "tolerance 1e-12; relTol 0;", open(p).read())
open(p, "w").write(txt)
hc.foamfile(os.path.join(case, "system/decomposeParDict"), "decomposeParDict", """
numberOfSubdomains 2;
method simple;
simpleCoeffs { n (2 1 1); delta 0.001; }
""")
hc.run("blockMesh", case, "log.blockMesh")
par = case + "-np2"
shutil.copytree(case, par)
hc.run("demIbFoam", case, "log.demIbFoam")
hc.run("decomposePar", par, "log.decomposePar")
hc.run("mpirun -np 2 demIbFoam -parallel", par, "log.demIbFoam")


def read_state(path):
    lines = open(path).read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    return {int(l.split()[0]): (tuple(float(x) for x in l.split()[7:10]),
                                tuple(float(x) for x in l.split()[14:17]),
                                float(l.split()[2]))
            for l in lines[i + 1:i + 1 + n]}


t1 = f"{T1:g}"
results = []
ok = (os.path.isfile(os.path.join(par, t1, "polyDEM/state"))
      and os.path.isfile(os.path.join(par, t1, "polyDEM/ibState"))
      and not os.path.exists(os.path.join(par, "processor0", t1, "polyDEM"))
      and not os.path.exists(os.path.join(par, "processor1", t1, "polyDEM")))
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the parallel run wrote the DEM state once, in {t1}/polyDEM"
      " (none under processor*/)")

s0 = read_state(os.path.join(case, "0/polyDEM/state"))
s = read_state(os.path.join(case, t1, "polyDEM/state"))
q = read_state(os.path.join(par, t1, "polyDEM/state"))
ok = sorted(s) == sorted(q) and len(s) == 1
results.append(ok)
(i,) = list(s)
x0, x, xp = s0[i][0], s[i][0], q[i][0]
r = s[i][2]
ok = abs(x0[0] - 0.01) < r and abs(x[0] - 0.01) < r
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the sphere (r = {r*1e3:g} mm) straddles the processor boundary"
      f" x = 10 mm: centre x {x0[0]*1e3:.4f} mm at 0, {x[0]*1e3:.4f} mm at {t1} s")
disp = math.dist(x, x0)
dev = math.dist(x, xp)
print(f"displacement {disp*1e3:.4f} mm; serial U_p {s[i][1]}, parallel {q[i][1]}")
for label, v in (("|x_par - x_ser| / displacement", dev / disp),
                 ("|x_par - x_ser| / |x_ser|", dev / math.hypot(*x))):
    ok = v < 1e-6
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label} = {v:.3g} (< 1e-6)")
dU = math.dist(s[i][1], q[i][1]) / math.hypot(*s[i][1])
print(f"|U_par - U_ser| / |U_ser| = {dU:.3g}")
hc.finish(results)
