#!/usr/bin/python3
"""CTest iceChannel.repeatRuns: repeated runs of the brash-ice tutorial
(tutorials/demInterFoam/brashIceChannel: makeCase.py -seed, Allrun -seed
-openWater, repeats.py) against cases worked by hand.

1. makeCase.py: no -seed is -seed 1 (the same files); -seed 2 places other
   blocks (brashIce/insertion differs) and the inflow's seed is 8 (the
   builder's + 6); -seed 0 and -seed x are refused naming the option.
2. repeats.py on three made-up runs (ice resistance 10 +- 2, 20 +- 4,
   60 +- 12 N; ice-load trends -1 +- 3, +5 +- 3, +30 +- 10 N/s):
     mean = 30; deviations -20, -10, 30; squares 400 + 100 + 900 = 1400;
     s = sqrt(1400 / 2) = 26.45751311; s / sqrt(3) = 15.27525232;
     within-run error = (2 + 4 + 12) / 3 = 6; s / within = 4.409585518;
     jammed (trend > 2 standard errors): the third only (30 > 20; 5 < 6).
3. repeats.py refuses: runs of another set-up (its speed), two runs with
   the same seed, a run without its summary, a single run.
4. Allrun -openWater DIR refuses an open-water run of another size and a
   folder that is not a finished open-water run, before running anything.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TUTORIAL = os.path.join(HERE, "..", "..", "tutorials", "demInterFoam", "brashIceChannel")
PY = sys.executable
fails = []


def report(name, ok, detail=""):
    print(f"{'PASS' if ok else 'FAIL'}: {name}{': ' + detail if detail else ''}")
    if not ok:
        fails.append(name)


def check(name, got, want, tol):
    report(name, abs(got - want) <= tol * max(1.0, abs(want)),
           f"{got:.10g} (expected {want:.10g}, tolerance {tol:g})")


def run(args, cwd):
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True)


work = tempfile.mkdtemp(prefix="hedra_repeatRuns_")
# the tutorial's folder and ../common, as Allrun expects them
tut = os.path.join(work, "brashIceChannel")
shutil.copytree(TUTORIAL, tut, ignore=shutil.ignore_patterns("openWater", "ice", "postProcessing",
                                                             "__pycache__", "reference"))
shutil.copytree(os.path.join(TUTORIAL, "..", "common"), os.path.join(work, "common"))

# 1. makeCase.py -seed
cases = {}
for name, opts in (("none", []), ("one", ["-seed", "1"]), ("two", ["-seed", "2"])):
    r = run([PY, "makeCase.py", "-test", "-dir", f"c_{name}"] + opts, tut)
    report(f"1. makeCase.py -test {' '.join(opts) or '(no -seed)'} runs", r.returncode == 0,
           (r.stdout + r.stderr).strip().splitlines()[-1] if (r.stdout + r.stderr).strip() else "")
    cases[name] = os.path.join(tut, f"c_{name}")


def read(case, rel):
    with open(os.path.join(case, rel)) as f:
        return f.read()


same = all(read(cases["none"], rel) == read(cases["one"], rel)
           for rel in ("constant/brashIce/insertion", "constant/demProperties"))
report("1. no -seed writes what -seed 1 writes (insertion, demProperties)", same)
report("1. -seed 2 places other blocks (constant/brashIce/insertion differs)",
       read(cases["one"], "constant/brashIce/insertion") != read(cases["two"], "constant/brashIce/insertion"))
seeds = {k: re.findall(r"^\s*seed\s+(\d+);", read(cases[k], "constant/demProperties"), re.M) for k in ("one", "two")}
report("1. the inflow's seed is the builder's + 6 (7 and 8)", seeds["one"] == ["7"] and seeds["two"] == ["8"],
       f"{seeds}")
for bad in ("0", "x"):
    r = run([PY, "makeCase.py", "-test", "-dir", "c_bad", "-seed", bad], tut)
    report(f"1. -seed {bad} refused naming the option", r.returncode != 0
           and f"-seed '{bad}': expected a whole number >= 1" in r.stderr, r.stderr.strip())

# 2. repeats.py against the hand-worked case
INFO = """size default
openWater 0
speed 0.74
hullDraft 0.25
end 3.0
shape cuboid
couplingDirection twoWay
blocks {blocks}
porosity {porosity}
seed {seed}
"""


def fakeRun(name, seed, R, e, trend, speed="0.74", summary=True):
    d = os.path.join(work, "runs", name)
    os.makedirs(os.path.join(d, "ice"))
    os.makedirs(os.path.join(d, "postProcessing"))
    with open(os.path.join(d, "ice", "case.info"), "w") as f:
        f.write(INFO.format(blocks=118 + seed, porosity=0.35 + 0.001 * seed, seed=seed)
                .replace("speed 0.74", f"speed {speed}"))
    if summary:
        with open(os.path.join(d, "postProcessing", "summary.txt"), "w") as f:
            f.write("# quantity mean[N] stdError[N] samples windowStart[s]\n"
                    "openWater 11.0 0.7 400 1.3\n"
                    f"total {R + 11.0} {e} 500 0.9\n"
                    f"iceLoad {R} {e} 500 0.9\n"
                    "fluid 11.0 1.0 500 0.9\n"
                    f"iceResistance {R} {e} 500 0.9\n"
                    "all checks passed\n")
    with open(os.path.join(d, "postProcessing", "iceSteady.dat"), "w") as f:
        f.write("# t n_ahead\n0 120\n"
                f"# window from 0.9 s to 3.000 s (9 states): blocks ahead trend +1.00 +- 1.00 /s "
                f"(mean 120.0); ice load trend over 10 batch means {trend[0]:+.2f} +- {trend[1]:.2f} N/s\n")
    return d


r1 = fakeRun("r1", 1, 10.0, 2.0, (-1.0, 3.0))
r2 = fakeRun("r2", 2, 20.0, 4.0, (5.0, 3.0))
r3 = fakeRun("r3", 3, 60.0, 12.0, (30.0, 10.0))
out = os.path.join(work, "repeatsOut")
r = run([PY, os.path.join(tut, "repeats.py"), "-out", out, r1, r2, r3], work)
report("2. repeats.py runs", r.returncode == 0, r.stderr.strip())
dat = open(os.path.join(out, "repeats.dat")).read() if os.path.isfile(os.path.join(out, "repeats.dat")) else ""
m = re.search(r"# ensemble iceResistance: mean (\S+) N, s (\S+) N, s/sqrt\(n\) (\S+) N, "
              r"within-run error (\S+) N, s/within (\S+), n (\d+)", dat)
report("2. repeats.dat has the ensemble line", m is not None, dat.strip().splitlines()[-3] if dat else "no file")
if m:
    check("2. mean", float(m.group(1)), 30.0, 1e-4)
    check("2. s", float(m.group(2)), 26.45751311, 1e-4)
    check("2. s/sqrt(n)", float(m.group(3)), 15.27525232, 1e-4)
    check("2. within-run error", float(m.group(4)), 6.0, 1e-4)
    check("2. s/within", float(m.group(5)), 4.409585518, 1e-3)
    report("2. n = 3", m.group(6) == "3")
rows = [l.split() for l in dat.splitlines() if l and not l.startswith("#")]
report("2. jammed: the third run only", [row[8] for row in rows] == ["0", "0", "1"], f"{[row[8] for row in rows]}")
report("2. repeats.png written", os.path.isfile(os.path.join(out, "repeats.png")))

# 3. refusals
other = fakeRun("other", 4, 15.0, 3.0, (0.0, 1.0), speed="0.5")
dup = fakeRun("dup", 2, 15.0, 3.0, (0.0, 1.0))
nosum = fakeRun("nosum", 5, 15.0, 3.0, (0.0, 1.0), summary=False)
for name, args, what in (("another set-up", [r1, other], "its speed (0.5) is not"),
                         ("the same seed twice", [r1, r2, dup], "the same seed"),
                         ("a run without its summary", [r1, nosum], "summary.txt"),
                         ("a single run", [r1], "at least two runs")):
    r = run([PY, os.path.join(tut, "repeats.py"), "-out", out] + args, work)
    report(f"3. refuses {name}", r.returncode != 0 and what in r.stderr, r.stderr.strip())

# 4. Allrun -openWater refusals (the check runs makeCase.py only)
ow = os.path.join(work, "owDefault")
os.makedirs(ow)
shutil.copy(os.path.join(cases["one"], "case.info"), os.path.join(ow, "case.info"))
with open(os.path.join(ow, "case.info")) as f:
    txt = f.read().replace("openWater 0", "openWater 1").replace("size test", "size default")
with open(os.path.join(ow, "case.info"), "w") as f:
    f.write(txt)
with open(os.path.join(ow, "runTime"), "w") as f:
    f.write("1\n")
env = dict(os.environ, HEDRA_DIR=os.path.abspath(os.path.join(HERE, "..", "..")))
for name, target, what in (("an open-water run of another size", ow, "its size (default) is not this run's (test)"),
                           ("a folder that is no finished run", work, "expected a finished open-water run")):
    r = subprocess.run(["./Allrun", "-test", "-openWater", target], cwd=tut, capture_output=True,
                       text=True, env=env, timeout=120)
    report(f"4. Allrun -openWater refuses {name}", r.returncode != 0 and what in r.stdout + r.stderr,
           (r.stdout + r.stderr).strip().splitlines()[-1] if (r.stdout + r.stderr).strip() else "")
report("4. nothing was run (no ice/ folder)", not os.path.isdir(os.path.join(tut, "ice")))

shutil.rmtree(work, ignore_errors=True)
print(f"{'ALL PASSED' if not fails else 'FAILED: ' + ', '.join(fails)}")
sys.exit(1 if fails else 0)
