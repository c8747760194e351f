#!/usr/bin/env python3
"""The wet ball mill tutorial's Allrun refuses bad options before anything
runs: exit 2, a message naming the option, and no case folder made.

Checked: -seed not a whole number >= 1 (0, x, missing), -mill not noLifters
or lifters8, -cells outside 0.01..1 m or not a number, -fluidStep not a
whole number of DEM steps (1e-4 s) or zero, and an unknown option. Allrun
checks its options before it looks for the dry tutorial, so the copy here
needs nothing beside it.
"""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.join(HERE, "..", "..", "tutorials", "demInterFoam", "wetBallMill")

BAD = [["-seed", "0"], ["-seed", "x"], ["-seed"], ["-mill", "four"], ["-cells", "0"],
       ["-cells", "abc"], ["-fluidStep", "1.5e-4"], ["-fluidStep", "0"], ["-lifters", "8"]]

base = os.environ.get("HEDRA_TEST_TMP", tempfile.gettempdir())
tmp = tempfile.mkdtemp(prefix="hedra-millOptions-", dir=base)
case = os.path.join(tmp, "wetBallMill")
shutil.copytree(SRC, case, ignore=shutil.ignore_patterns("noLifters", "lifters8", "reference"))
failed = 0
for args in BAD:
    r = subprocess.run(["./Allrun"] + args, cwd=case, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=60)
    made = [c for c in ("noLifters", "lifters8") if os.path.exists(os.path.join(case, c))]
    ok = r.returncode == 2 and args[0] in r.stdout and not made
    print(("refused: " if ok else "FAIL: ") + "Allrun " + " ".join(args)
          + f": rc {r.returncode}: {r.stdout.strip()}" + (f"; made {made}" if made else ""))
    failed += not ok
shutil.rmtree(tmp)
sys.exit(1 if failed else 0)
