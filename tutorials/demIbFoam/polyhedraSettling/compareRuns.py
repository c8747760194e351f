#!/usr/bin/env python3
"""Compare the refined runs (postProcessing/table.dat, written by
plotSettling.py --table) with the uniform-mesh runs of 2026-11-23 (the table
in README.md's section "Uniform mesh, d/dx 5 and 7"), case by case:
terminal velocity and maximum velocity, and their differences.

Usage: python3 compareRuns.py [SUFFIX]
       python3 compareRuns.py --pair SUFFIX
  SUFFIX  compare refined cases NAME+SUFFIX (e.g. _n10_r2) with the uniform
          cases of the same NAME (default: no suffix, the default matrix)
  --pair  compare NAME+SUFFIX with NAME, both from table.dat (e.g. the
          refined d/dx 10 runs _n10_r2 with the refined default d/dx 5)
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
pair = "--pair" in sys.argv
args = [a for a in sys.argv[1:] if a != "--pair"]
suffix = args[0] if args else ""

readme = open(os.path.join(here, "README.md")).read()
sec = readme[readme.index("### Uniform mesh, d/dx 5 and 7"):]
uni = {}
for line in sec.splitlines():
    m = re.match(r"\| (A[0-9.]+C[0-9]+[HV](?:_n7)?) \|", line)
    if m:
        c = [x.strip() for x in line.strip("|").split("|")]
        uni[m.group(1)] = (float(c[8].split()[0]), float(c[10].split()[0]), float(c[4]))

ref = {}
tab = os.path.join(here, "postProcessing", "table.dat")
for line in open(tab):
    if line.startswith("#"):
        head = line[1:].split()
        continue
    r = dict(zip(head, line.split()))
    ref[r["case"]] = (float(r["wTerminal"]), float(r["wMax"]), float(r["d/dx"]))

first, second = ("NAME", "NAME%s" % suffix) if pair else ("uniform", "refined")
print("| case | d/dx %s | d/dx %s (near body) | terminal w %s / %s [m/s] | difference |"
      " max w %s / %s [m/s] | difference |" % (first, second, first, second, first, second))
print("|---|---|---|---|---|---|---|")
dH, dV = [], []
base = ref if pair else uni
for name in sorted(base):
    if "_" in name:
        continue
    if name + suffix not in ref:
        continue
    u, r = base[name], ref[name + suffix]
    dt, dm = 100 * (r[0] / u[0] - 1), 100 * (r[1] / u[1] - 1)
    (dH if name.endswith("H") else dV).append((dt, dm))
    print("| %s | %g | %g | %.4f / %.4f | %+.1f %% | %.4f / %.4f | %+.1f %% |"
          % (name + suffix, u[2], r[2], u[0], r[0], dt, u[1], r[1], dm))
for lab, d in (("horizontal", dH), ("vertical", dV)):
    if d:
        print("%s: terminal w differs by %+.1f ... %+.1f %%, max w by %+.1f ... %+.1f %%"
              % (lab, min(x[0] for x in d), max(x[0] for x in d), min(x[1] for x in d),
                 max(x[1] for x in d)))
