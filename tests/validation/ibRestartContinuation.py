#!/usr/bin/env python3
"""demIbFoam: a resolved run stopped and restarted continues as if unbroken.

The settling-sphere case (tests/validation/ib/settlingSphere: one glass
sphere, d = 4 mm, in a 20 x 20 x 40 mm box, d/dx = 4, demBackend polyDEM,
internalFluid as the case sets it) with ascii fields at 17 digits.
Run A: 0 -> t1 in one go. Run B: 0 -> t0, then restarted from the t0 folder
(fields U p phi fIB phiIB, the DEM state <t0>/polyDEM/state and the
particles' carried state <t0>/polyDEM/ibState) to t1.
Compared at t1: the DEM state (positions, velocities, orientation, contact
history; every number), the fields U, p, phi and fIB, and the particle rows
of postProcessing/ibForces after t0.
Tolerance: bit-exact (identical files); the largest relative difference is
printed, and a difference above 1e-10 fails.
Then: the restart from t0 with <t0>/polyDEM/ibState deleted must stop with a
FatalError naming it.
"""
import glob
import os
import re
import shutil
import sys
import hedracase as hc

os.environ.setdefault("OMP_NUM_THREADS", "1")

T0, T1 = 0.03, 0.06
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingSphere")
case = hc.workdir("ibRestart")
shutil.rmtree(case)
shutil.copytree(src, case)
shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))


def set_control(c, end):
    p = os.path.join(c, "system/controlDict")
    txt = open(p).read()
    txt = re.sub(r"startFrom\s+\w+;", "startFrom latestTime;", txt)
    txt = re.sub(r"endTime\s+[^;]*;", f"endTime {end};", txt)
    txt = re.sub(r"writeInterval\s+[^;]*;", f"writeInterval {T0};", txt)
    txt = re.sub(r"writePrecision\s+[^;]*;", "writePrecision 17;", txt)
    open(p, "w").write(txt)


set_control(case, T1)
hc.run("blockMesh", case, "log.blockMesh")
caseB = case + "-np2"  # (removed with the case by hc.finish)
shutil.copytree(case, caseB)
hc.run("demIbFoam", case, "log.demIbFoam")
set_control(caseB, T0)
hc.run("demIbFoam", caseB, "log.part1")
set_control(caseB, T1)
hc.run("demIbFoam", caseB, "log.part2")

results = []
log2 = open(os.path.join(caseB, "log.part2")).read()
ok = "DEM: restarting from" in log2 and "restart state read from" in log2
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: part 2 restarted from the {T0} DEM state and ibState")

num = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def compare(label, fa, fb, skip_header=True):
    a, b = open(fa).read(), open(fb).read()
    if skip_header:  # FoamFile header holds no data
        a, b = a[a.find("dimensions"):] if "dimensions" in a else a, \
            b[b.find("dimensions"):] if "dimensions" in b else b
    if a == b:
        print(f"PASS: {label}: identical")
        return True
    xa = [float(x) for x in num.findall(a)]
    xb = [float(x) for x in num.findall(b)]
    if len(xa) != len(xb):
        print(f"FAIL: {label}: different number of values ({len(xa)}, {len(xb)})")
        return False
    scale = max(max((abs(x) for x in xa), default=0.0), 1e-300)
    dev = max(abs(x - y) for x, y in zip(xa, xb)) / scale
    ok = dev < 1e-10
    print(f"{'PASS' if ok else 'FAIL'}: {label}: max |A - B| / max |A| = {dev:.3g} (< 1e-10)")
    return ok


t1 = f"{T1:g}"
results.append(compare("DEM state at t1", os.path.join(case, t1, "polyDEM/state"),
                       os.path.join(caseB, t1, "polyDEM/state"), skip_header=False))
for f in ("U", "p", "phi", "fIB"):
    results.append(compare(f"field {f} at t1", os.path.join(case, t1, f),
                           os.path.join(caseB, t1, f)))


def rows(c, after):
    out = []
    for fn in sorted(glob.glob(os.path.join(c, "postProcessing/ibForces/*/forces.dat"))):
        for line in open(fn):
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            if v[0] > after + 1e-9:
                out.append(v)
    return out


ra, rb = rows(case, T0), rows(caseB, T0)
# (the time column may differ in the last digits: a restart starts from the
# folder's name, the unbroken run from the sum of its time steps)
ok = len(ra) == len(rb) and len(ra) > 0 and all(
    abs(x[0] - y[0]) < 1e-12 and x[1:] == y[1:] for x, y in zip(ra, rb))
results.append(ok)
zA = ra[-1][4] if ra else float("nan")
z0 = rows(case, -1)[0][4]
print(f"{'PASS' if ok else 'FAIL'}: ibForces rows after t0 identical ({len(ra)} rows; "
      f"sphere moved {1e3*(z0 - zA):.4f} mm down, w = {ra[-1][7] if ra else 0:.5g} m/s at t1)")

# A restart time written by demIbFoam without its ibState stops (it used to
# continue, not bit for bit): the restart from t0 again, ibState deleted
caseC = case + "-noIbState"
hc._workdirs.append(caseC)
shutil.copytree(caseB, caseC)
for t in glob.glob(os.path.join(caseC, "[0-9]*")):
    if os.path.basename(t) not in ("0", f"{T0:g}"):
        shutil.rmtree(t)
os.remove(os.path.join(caseC, f"{T0:g}", "polyDEM", "ibState"))
rc = hc.run("demIbFoam", caseC, "log.noIbState", check=False)
logC = open(os.path.join(caseC, "log.noIbState")).read()
ok = rc != 0 and "FOAM FATAL ERROR" in logC and f"{T0:g}/polyDEM/ibState" in logC
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: a restart from {T0:g} without polyDEM/ibState stops (exit {rc}) "
      "with a FatalError naming it")
hc.finish(results)
