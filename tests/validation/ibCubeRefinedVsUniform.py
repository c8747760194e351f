#!/usr/bin/env python3
"""Dynamic refinement around an angular body gives the uniform mesh's answer.

The fixed cube of ib/fixedCube (demIbFoam, face-on, Re = 20 on the edge,
a/5 cells at the body) run twice: on a base mesh of a/2.5 refined one level
around the cube by dynamicRefineFvMesh (ibRefinement), and on the uniform
a/5 mesh of the whole domain. Near the body the two meshes are the same,
so the drag must agree; what refinement may change is only the far field
(coarser there) and the refinement band's hanging faces.

Tolerance: C_d of the refined run within 1 % of the uniform run's (issue
18, item 5). The cell counts and run times are printed (the cost is
recorded in docs/performance.md).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.join(HERE, "ib", "fixedCube")
TOL = 0.01


def count_cells(case):
    """Cells of the last mesh written (a refined mesh goes to the time
    folders), from the owner file's note."""
    owners = [os.path.join(case, "constant/polyMesh/owner")]
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0]
    if times:
        owners.insert(0, os.path.join(case, max(times, key=float), "polyMesh/owner"))
    for owner in owners:
        if os.path.exists(owner):
            m = re.search(r"nCells:\s*(\d+)", open(owner, errors="replace").read(2000))
            if m:
                return int(m.group(1))
    return None


def run(tag, extra):
    base = os.environ.get("HEDRA_TEST_TMP", tempfile.gettempdir())
    tmp = tempfile.mkdtemp(prefix=f"hedra-cubeRefine-{tag}-", dir=base)
    case = os.path.join(tmp, "fixedCube")
    shutil.copytree(SRC, case, ignore=shutil.ignore_patterns("[1-9]*", "postProcessing", "log.*"))
    t0 = time.time()
    r = subprocess.run(["./Allrun", "-n", "5", "-re", "20"] + extra, cwd=case,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=900)
    wall = time.time() - t0
    out = r.stdout
    m = re.search(r"C_d = ([-0-9.eE+]+)", out)
    cells = count_cells(case)
    if r.returncode != 0 or m is None:
        print(out)
        sys.exit(f"FAIL: the {tag} run failed (case kept in {case})")
    print(f"{tag}: C_d = {m.group(1)}, {wall:.0f} s wall"
          + (f", {cells} cells at the end" if cells else ""))
    return float(m.group(1)), tmp, wall, cells


cdRefined, tmpR, wallR, cellsR = run("refined", [])
cdUniform, tmpU, wallU, cellsU = run("uniform", ["-levels", "0"])
# The cost (bench/ibRefinement/run reads this line)
print(f"cost: uniform / refined wall time {wallU / wallR:.2f}"
      + (f", cells {cellsU} / {cellsR} = {cellsU / cellsR:.2f}" if cellsR and cellsU else ""))
diff = cdRefined / cdUniform - 1
ok = abs(diff) <= TOL
print(f"{'PASS' if ok else 'FAIL'}: C_d refined {cdRefined:.4f} against uniform {cdUniform:.4f}:"
      f" {100 * diff:+.2f} % (tolerance {100 * TOL:.0f} %)")
if ok and not os.environ.get("HEDRA_KEEP"):
    shutil.rmtree(tmpR, ignore_errors=True)
    shutil.rmtree(tmpU, ignore_errors=True)
sys.exit(0 if ok else 1)
