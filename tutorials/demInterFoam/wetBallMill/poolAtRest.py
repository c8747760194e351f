#!/usr/bin/env python3
"""Reproducer of why the wet mill does not run (README, "Status"): the
slurry pool of the wet mill (11.88 % of the shell, no balls, no rotation:
static mesh, shell at rest) should stay at rest; on the mill's fluid meshes
it does not, in interFoam v1912 itself as in demInterFoam.

    python3 poolAtRest.py [--mesh snappy|ogrid] [--solver interFoam|demInterFoam]
                          [--velocityCorrection reconstruct|gradient|gaussBalance]
                          [--airNu 1.48e-5] [--endTime 0.2] [--keep]

The control, --mesh box: the same pool in the uncut Cartesian background
(3.2 m square, 0.1 m cells, the surface inside a row of cells) stays at
rest (largest |U| ~1e-6 m/s).

Writes the case with makeCase.py (static mesh, shell at rest) into a
temporary folder, sets the pool (setAlphaField), runs the solver and prints
the largest |U| in the slurry (alpha > 0.5) and in the air every 0.05 s.
A pool at rest should give round-off (the same pool in an axis-aligned
Cartesian box: 1e-6 m/s). Exit 1 when the slurry's largest |U| exceeds
1e-2 m/s or the solver fails (so it is a check that fails today).
Needs the OpenFOAM environment (source etc/bashrc)."""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from wetMill import internal_field  # noqa: E402
DRY = os.path.join(HERE, "..", "..", "demFoam", "ballMill")

p = argparse.ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("--mesh", choices=("snappy", "ogrid", "box"), default="snappy",
               help="box: the snappy mesh's Cartesian background, uncut (the control)")
p.add_argument("--solver", choices=("interFoam", "demInterFoam"), default="interFoam")
p.add_argument("--velocityCorrection", choices=("reconstruct", "gradient", "gaussBalance"), default=None,
               help="demInterFoam only (default: makeCase.py's, gaussBalance)")
p.add_argument("--airNu", type=float, default=1.48e-5)
p.add_argument("--endTime", type=float, default=0.2)
p.add_argument("--keep", action="store_true", help="keep the case folder")
args = p.parse_args()

case = tempfile.mkdtemp(prefix="hedra-poolAtRest-")
log = open(os.path.join(case, "log.poolAtRest"), "w")


def run(cmd, check=True):
    r = subprocess.run(cmd, cwd=case, shell=True, stdout=log, stderr=subprocess.STDOUT)
    if check and r.returncode != 0:
        print(f"failed: {cmd} (see {case})")
        sys.exit(1)
    return r.returncode


run(f"python3 {os.path.join(HERE, 'makeCase.py')} --mesh {'ogrid' if args.mesh == 'ogrid' else 'snappy'}"
    " --meshMotion static"
    f" --tCouple 0 --endTime {args.endTime} --writeInterval 0.05 --airNu {args.airNu} --rpm 0")
os.makedirs(os.path.join(case, "constant", "triSurface"), exist_ok=True)
shutil.copy(os.path.join(DRY, "constant", "demProperties"), os.path.join(case, "constant"))
run("foamDictionary -entry insertion -set '{}' constant/demProperties")
run(f"python3 {os.path.join(DRY, 'makeGeometry.py')} --lifters 0")
run("foamDictionary -entry functions -set '{}' system/controlDict")
if args.mesh == "box":
    # the background as the fluid domain: its side walls are the 'shell'
    run("sed -i 's/    box {/    shell {/; s/{ type patch; faces/{ type empty; faces/' system/blockMeshDict")
run("blockMesh")
if args.mesh == "snappy":
    run("snappyHexMesh -overwrite")
    run("sed -i '/^    \\(front\\|back\\)$/,/^    }/ s/type            patch;/type            empty;/'"
        " constant/polyMesh/boundary")
# the pool of the empty mill: 11.88 % of the circle
R = 1.5
A = 4.2 / (math.pi * R * R * 5.0) * math.pi * R * R
lo, hi = -R, R
for _ in range(100):
    h = 0.5 * (lo + hi)
    seg = R * R * math.acos(-h / R) + h * math.sqrt(R * R - h * h)   # area below y = h
    lo, hi = (h, hi) if seg < A else (lo, h)
with open(os.path.join(case, "system", "setAlphaFieldDict"), "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object setAlphaFieldDict; }\n"
            f"field alpha.water; type plane; origin (0 {h:.9g} 0); direction (0 1 0);\n")
run("setAlphaField")
if args.solver == "interFoam":
    os.remove(os.path.join(case, "constant", "couplingProperties"))
    run("sed -i 's/^application .*/application interFoam;/' system/controlDict")
elif args.velocityCorrection:
    run(f"foamDictionary -entry PIMPLE/velocityCorrection -set {args.velocityCorrection} system/fvSolution")
rc = run(f"{args.solver} > log.{args.solver} 2>&1", check=False)
print(f"{args.solver} on the {args.mesh} mesh, pool level y = {h:.4f} m, air nu {args.airNu:g}:"
      f" exit {rc}")
worst = 0.0
samples = 0
times = sorted((d for d in os.listdir(case) if re.fullmatch(r"[0-9.e-]+", d) and float(d) > 0), key=float)
for t in times:
    U = internal_field(os.path.join(case, t, "U"), 3)
    a = internal_field(os.path.join(case, t, "alpha.water"))
    if not (isinstance(U, list) and isinstance(a, list)):
        continue
    samples += 1
    sp = [math.sqrt(sum(c * c for c in u)) for u in U]
    w = max((s for s, x in zip(sp, a) if x > 0.5), default=0.0)
    air = max((s for s, x in zip(sp, a) if x <= 0.5), default=0.0)
    worst = max(worst, w)
    print(f"  t = {t:>5} s: largest |U| slurry {w:9.3g} m/s, air {air:9.3g} m/s")
ok = rc == 0 and worst <= 1e-2 and samples > 0
print(("PASS" if ok else "FAIL") + f": the pool at rest (slurry |U| <= 1e-2 m/s) in {samples} written"
      f" fields (at least one; writeInterval 0.05 s); case {case}")
if not args.keep and ok:
    shutil.rmtree(case)
sys.exit(0 if ok else 1)
