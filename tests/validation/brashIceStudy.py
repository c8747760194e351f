#!/usr/bin/env python3
"""The brash-ice study script (tutorials/demInterFoam/brashIceChannel/
study.py) at the CTest size: open water, the polyhedra run (two-way) and the
one-way run, 0.4 s each, in a temporary copy of the tutorial.

Checked:
  - study.dat holds one row per run with finite means;
  - one-way: the fluid force on the hull equals the open-water run's at
    every common time step (tolerance 0: the water does not see the ice, so
    its flow is the open-water flow bit for bit);
  - one-way: the ice touched the hull (contacts > 0 in some sample) and the
    ice load is positive over the window;
  - two-way: the fluid force on the hull differs from the open water's
    (max difference > 1e-3 of it: the comparison can tell the two apart).
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
results = []


def check(label, ok, detail):
    print(f"{'PASS' if ok else 'FAIL'}: {label}: {detail}")
    results.append(ok)


tmp = tempfile.mkdtemp(prefix="hedra-brashIceStudy-")
shutil.copytree(os.path.join(ROOT, "tutorials/demInterFoam/common"),
                os.path.join(tmp, "demInterFoam/common"))
shutil.copytree(os.path.join(ROOT, "tutorials/demInterFoam/brashIceChannel"),
                os.path.join(tmp, "demInterFoam/brashIceChannel"),
                ignore=shutil.ignore_patterns("study", "study-test", "reference"))
tut = os.path.join(tmp, "demInterFoam/brashIceChannel")
r = subprocess.run(["/usr/bin/python3", "study.py", "-test", "-runs", "polyhedra oneWay"],
                   cwd=tut, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
print(r.stdout[-4000:])
if r.returncode != 0:
    sys.exit(f"FAILED: study.py exit {r.returncode}; case folders kept in {tmp}")
top = os.path.join(tut, "study-test")

rows = [l.split() for l in open(os.path.join(top, "study.dat")) if not l.startswith("#")]
names = [w[0] for w in rows]
finite = all(math.isfinite(float(x)) for w in rows for x in w[9:])
check("study.dat rows", names == ["polyhedra", "oneWay"] and finite,
      f"runs {names}, all means finite: {finite}")


sys.path.insert(0, tut)
from study import resistance_series  # noqa: E402


def series(case):
    """time -> (Rfluid, Rice, contacts) of an iceResistance resistance.dat."""
    return resistance_series(case, ["Rfluid", "Rice", "contacts"])


ow = series(os.path.join(top, "openWater_U0.74"))
one = series(os.path.join(top, "oneWay/ice"))
two = series(os.path.join(top, "polyhedra/ice"))
common = sorted(set(ow) & set(one))
d1 = max(abs(one[t][0] - ow[t][0]) for t in common)
check("one-way: fluid force on the hull = open water's", len(common) > 50 and d1 == 0,
      f"max difference {d1:g} N over {len(common)} common samples")
contacts = max((one[t][2] for t in common if math.isfinite(one[t][2])), default=0)
iceLoad = float(rows[names.index("oneWay")][9])
check("one-way: the ice reaches the hull", contacts > 0 and iceLoad > 0,
      f"most contacts {contacts:g}, window ice load {iceLoad:.3g} N")
common2 = sorted(set(ow) & set(two))
scale = max(abs(ow[t][0]) for t in common2)
d2 = max(abs(two[t][0] - ow[t][0]) for t in common2)
check("two-way: fluid force on the hull differs from open water's", d2 > 1e-3 * scale,
      f"max difference {d2:.3g} N (open water up to {scale:.3g} N)")

if all(results):
    shutil.rmtree(tmp, ignore_errors=True)
    sys.exit(0)
print(f"case folders kept in {tmp}")
sys.exit(1)
