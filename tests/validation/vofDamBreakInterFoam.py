#!/usr/bin/env python3
"""demInterFoam without particles reproduces interFoam (OpenFOAM v1912) on
OpenFOAM's damBreak tutorial (tutorials/multiphase/interFoam/laminar/
damBreak/damBreak, 2D, 2268 cells, adjustable time step, MULES with
MULESCorr, surface tension), run to t = 0.3 s (written in
binary at full precision).

With eps = 1 every operation of demInterFoam is interFoam's (products
with exactly 1, sums with exactly 0), so the two runs agree to round-off.
Tolerance: max |difference| of alpha.water, U, p_rgh at t = 0.3 below
1e-10 of each field's range, and the same number of time steps (the
time step adapts to the Courant number, so any difference would show).
"""
import os
import re
import shutil
import struct
import sys
import hedracase as hc
import vofcase as vc

SRC = os.path.join(os.environ.get("HEDRA_CACHE", os.path.expanduser("~/.cache/hedra")),
                   "openfoam-v1912-src/tutorials/multiphase/interFoam/laminar/damBreak/damBreak")
END = "0.3"


def prepare(case, app):
    shutil.rmtree(case)
    shutil.copytree(SRC, case)
    cd = os.path.join(case, "system/controlDict")
    txt = open(cd).read()
    txt = re.sub(r"application\s+\w+;", f"application {app};", txt)
    txt = re.sub(r"endTime\s+[\d.]+;", f"endTime {END};", txt)
    txt = re.sub(r"writeInterval\s+[\d.]+;", f"writeInterval {END};", txt)
    txt = re.sub(r"writeFormat\s+\w+;", "writeFormat binary;", txt)
    txt = re.sub(r"writePrecision\s+\d+;", "writePrecision 17;", txt)
    txt = re.sub(r"runTimeModifiable\s+\w+;", "runTimeModifiable false;", txt)
    txt = txt.replace('#sinclude   "sampling"', "")
    open(cd, "w").write(txt)
    shutil.copy(os.path.join(case, "0/alpha.water.orig"), os.path.join(case, "0/alpha.water"))
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("setFields", case, "log.setFields")


def read_binary(path):
    """internalField of a binary OpenFOAM field: list of floats."""
    data = open(path, "rb").read()
    i = data.index(b"internalField")
    m = re.compile(rb"nonuniform\s+List<(\w+)>\s+(\d+)\s*\(").search(data, i)
    kind, n = m.group(1), int(m.group(2))
    width = {b"scalar": 1, b"vector": 3}[kind]
    start = m.end()
    return struct.unpack(f"<{n * width}d", data[start:start + 8 * n * width])


def steps(log):
    return len(re.findall(r"^Time = ", open(log).read(), re.M))


results = []
ref = hc.workdir("damBreak-interFoam")
new = hc.workdir("damBreak-demInterFoam")
prepare(ref, "interFoam")
prepare(new, "demInterFoam")
vc.coupling_without_particles(new, (0, 1, 0))
hc.run("interFoam", ref, "log.interFoam")
hc.run("demInterFoam", new, "log.demInterFoam")

nRef, nNew = steps(os.path.join(ref, "log.interFoam")), steps(os.path.join(new, "log.demInterFoam"))
ok = nRef == nNew
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: time steps to t = {END}: interFoam {nRef}, demInterFoam {nNew}")
for field in ("alpha.water", "U", "p_rgh"):
    a = read_binary(os.path.join(ref, END, field))
    b = read_binary(os.path.join(new, END, field))
    rng = max(a) - min(a) or 1.0
    diff = max(abs(x - y) for x, y in zip(a, b)) if len(a) == len(b) else float("inf")
    ok = diff <= 1e-10 * rng
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {field} at t = {END}: max |demInterFoam - interFoam| ="
          f" {diff:.3g} (field range {rng:.4g}; tolerance 1e-10 of the range)")
hc.finish(results)
