#!/usr/bin/env python3
"""Fuzz test of Hedra's input dictionaries: mutate demProperties,
couplingProperties and ibProperties of small cases and check that every
mutated run ends in one of two acceptable ways:

  - a clean stop: non-zero exit, a 'FOAM FATAL (IO) ERROR' whose message
    names the dictionary (or, for a stop during the run, the particle or
    body), no signal, no stack trace;
  - a run to the end: exit 0, no 'nan'/'inf' in the log, and finite numbers
    in every summary file (DEM energies, coupling summary, IB forces).

Never acceptable: a signal (SIGFPE, SIGSEGV), a stack trace, a hang (the
per-case timeout), a NaN, or exit 0 after a misspelled key or a value of
the wrong type (those must be refused: a misspelled optional key would
leave its default in force without a word).

Mutations (drawn with a fixed seed from every entry of the dictionary,
walked as a tree): delete the entry; misspell its key (one letter dropped,
doubled or swapped); give a word where a number is expected and a number
where a word is expected; a scalar where a vector is expected; out-of-range
and extreme numbers (0, -1, -1e300, 1e300, 1e-300, and the value times
-1, 1e6 and 1e-6). Base cases (reduced run lengths: a few steps):
  demFoam       200 spheres settling (tests/cases/settlingSpheres)
  demFoam       polyhedral rocks settling (tests/cases/settlingRocks)
  demPimpleFoam one sphere in a 2x2x2 box (as validation.badInput)
  demIbFoam     one polyDEM sphere in a 6x6x6 box

Usage: fuzzInputs.py [--shard K/N] [--cases N (400)] [--seed S (2026)]
The summary line gives the counts by outcome.
"""
import argparse
import copy
import math
import os
import random
import re
import shutil
import subprocess
import sys

import hedracase as hc

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "..", "cases")
TIMEOUT = 30


# --------------------------------------------------------------------------
# A small OpenFOAM dictionary reader/writer: entries 'key tokens;' and
# 'key { ... }'; lists '( ... )' kept as token strings. Comments dropped.

def tokenize(text):
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.findall(r'"[^"]*"|[{}();]|[^\s{}();]+', text)


class Sub(list):
    """A sub-dictionary: a list of [key, value] entries."""


def parse(tokens, i=0):
    """Sub of [key, value]; value is a list of tokens or a Sub."""
    entries = Sub()
    while i < len(tokens):
        t = tokens[i]
        if t == "}":
            return entries, i + 1
        key = t
        i += 1
        if i < len(tokens) and tokens[i] == "{":
            sub, i = parse(tokens, i + 1)
            entries.append([key, sub])
            continue
        value, depth = [], 0
        while i < len(tokens):
            t = tokens[i]
            if t == "(":
                depth += 1
            elif t == ")":
                depth -= 1
            elif t == "{" and depth > 0:
                # a list of dictionaries: keep as tokens up to the matching brace
                depth += 1
            elif t == "}" and depth > 0:
                depth -= 1
            elif t == ";" and depth == 0:
                i += 1
                break
            value.append(t)
            i += 1
        entries.append([key, value])
    return entries, i


def write(entries, indent=0):
    pad = "    " * indent
    out = []
    for key, value in entries:
        if isinstance(value, Sub):
            out.append(f"{pad}{key}\n{pad}{{\n{write(value, indent + 1)}{pad}}}\n")
        else:
            out.append(f"{pad}{key} {' '.join(value)};\n")
    return "".join(out)


def is_dict(value):
    return isinstance(value, Sub)


def leaves(entries, path=()):
    """Paths (tuples of indices) of every entry, sub-dictionaries too."""
    for k, (key, value) in enumerate(entries):
        if key == "FoamFile":
            continue
        p = path + (k,)
        yield p
        if is_dict(value):
            yield from leaves(value, p)


def at(entries, path):
    e = entries
    for k in path[:-1]:
        e = e[k][1]
    return e, path[-1]


def name_of(entries, path):
    names, e = [], entries
    for k in path:
        names.append(e[k][0])
        e = e[k][1]
    return "/".join(names)


NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def mutations(entries, rng):
    """(description, mutated tree, mustFail) for one random entry."""
    path = rng.choice(list(leaves(entries)))
    holder, k = at(entries, path)
    key, value = holder[k]
    name = name_of(entries, path)
    out = []

    def variant(desc, change, mustFail=False):
        tree = copy.deepcopy(entries)
        h, j = at(tree, path)
        change(h, j)
        out.append((f"{name}: {desc}", tree, mustFail))

    variant("deleted", lambda h, j: h.pop(j))
    if len(key) > 3 and not key.startswith("#") and key != "default":
        s = list(key)
        m = rng.randrange(len(s))
        kind = rng.choice(["drop", "double", "swap"])
        if kind == "drop":
            bad = key[:m] + key[m + 1:]
        elif kind == "double":
            bad = key[:m] + key[m] + key[m:]
        else:
            m = min(m, len(s) - 2)
            s[m], s[m + 1] = s[m + 1], s[m]
            bad = "".join(s)
        if bad != key:
            def rename(h, j, bad=bad):
                h[j][0] = bad
            # A misspelled entry must be refused: except where the keys
            # are user names (materials, particleTypes, walls, insertions,
            # interaction pairs, force-model coefficient dictionaries that
            # are free to be unused) -- their misspelling is another name
            userName = len(path) >= 2 and name.split("/")[0] in (
                "materials", "particleTypes", "walls", "insertion",
                "interactions", "shapes")
            userName = userName and len(path) == 2
            variant(f"key misspelled as '{bad}'", rename, mustFail=not userName)
    if not is_dict(value) and value:
        toks = value
        if len(toks) == 1 and NUMBER.match(toks[0]):
            x = float(toks[0])
            variant("a word for a number", lambda h, j: h.__setitem__(j, [h[j][0], ["banana"]]),
                    mustFail=True)
            for v in ["0", "-1", "-1e300", "1e300", "1e-300",
                      repr(-x), repr(x * 1e6), repr(x * 1e-6)]:
                variant(f"value {v}", lambda h, j, v=v: h.__setitem__(j, [h[j][0], [v]]))
            variant("a vector for a scalar",
                    lambda h, j: h.__setitem__(j, [h[j][0], ["(", "1", "2", "3", ")"]]),
                    mustFail=True)
        elif len(toks) == 1 and re.match(r"^[A-Za-z]\w*$", toks[0]) and toks[0] not in (
                "true", "false", "yes", "no", "on", "off"):
            variant("a number for a word", lambda h, j: h.__setitem__(j, [h[j][0], ["42"]]),
                    mustFail=True)
            variant("an unknown word", lambda h, j: h.__setitem__(j, [h[j][0], ["zzzUnknown"]]))
        elif toks[0] == "(" and toks[-1] == ")" and all(NUMBER.match(t) for t in toks[1:-1]):
            variant("a scalar for a vector", lambda h, j: h.__setitem__(j, [h[j][0], ["1"]]),
                    mustFail=True)
            big = ["("] + ["1e300"] * (len(toks) - 2) + [")"]
            variant("huge components", lambda h, j: h.__setitem__(j, [h[j][0], big]))
            nan = ["("] + ["-1"] * (len(toks) - 2) + [")"]
            variant("negative components", lambda h, j: h.__setitem__(j, [h[j][0], nan]))
    return out


# --------------------------------------------------------------------------
# Base cases

def header(obj):
    return ("FoamFile { version 2.0; format ascii; class dictionary; "
            f"object {obj}; }}\n")


def shorten_control(case, endTime, deltaT):
    cd = os.path.join(case, "system/controlDict")
    t = open(cd).read()
    t = re.sub(r"\bendTime\s+[^;]+;", f"endTime {endTime};", t)
    t = re.sub(r"\bdeltaT\s+[^;]+;", f"deltaT {deltaT};", t)
    t = re.sub(r"\bwriteInterval\s+[^;]+;", f"writeInterval {endTime};", t)
    t = re.sub(r"\bwriteControl\s+[^;]+;", "writeControl runTime;", t)
    open(cd, "w").write(t)


def base_demFoam(name, src, endTime, deltaT):
    case = hc.workdir(f"fuzz-{name}")
    shutil.rmtree(case)
    shutil.copytree(os.path.join(CASES, src), case)
    shorten_control(case, endTime, deltaT)
    return dict(name=name, case=case, app="demFoam",
                dicts=["constant/demProperties"])


def base_demPimpleFoam():
    case = hc.workdir("fuzz-pimple")
    hc.block_mesh(case, (0, 0, 0), (0.02, 0.02, 0.02), (2, 2, 2),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.003, 1e-3, 1)
    hc.schemes_solution(case)
    hc.transport(case, 1e-6, 1000)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    hc.dem_properties(case, 1e-5, 2500, 2e-3, {"floor": ((0, 0, 0), (0, 0, 1))},
                      hc.random_fill("one", 3, (0.005, 0.005, 0.005), (0.015, 0.015, 0.015)))
    hc.coupling(case, """formulation setI;
momentumCoupling implicit;
fluidVelocity cell;
locateModel hinted;
voidFractionModel divided;
dividedCoeffs { nShells 2; alphaMin 0.3; }
smoothingModel none;
forceModels (DiFelice pressureGradient viscousStress);
DiFeliceCoeffs { alphaMax 1; }
""")
    hc.run("blockMesh", case, "log.blockMesh")
    return dict(name="pimple", case=case, app="demPimpleFoam",
                dicts=["constant/couplingProperties", "constant/demProperties"])


def base_demIbFoam():
    case = hc.workdir("fuzz-ib")
    hc.block_mesh(case, (0, 0, 0), (0.03, 0.03, 0.03), (6, 6, 6),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.003, 1e-3, 1)
    ibSrc = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingSphere", "system")
    for f in ("fvSchemes", "fvSolution"):
        shutil.copy(os.path.join(ibSrc, f), os.path.join(case, "system", f))
    hc.foamfile(os.path.join(case, "constant/transportProperties"), "transportProperties",
                "nu 1e-5;\nrho 1000;\n")
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type zeroGradient;"})
    hc.dem_properties(case, 1e-4, 2500, 0.012, {"floor": ((0, 0, 0), (0, 0, 1))},
                      """    one
    {
        type list; particleType beads;
        particles ( { position (0.015 0.015 0.015); velocity (0 0 -0.01); } );
    }""")
    hc.foamfile(os.path.join(case, "constant/ibProperties"), "ibProperties", """demBackend polyDEM;
internalFluid integrated;
directForcing
{
    nSubSamples 4; pressureCorrection true; nCorrections 1;
    interface penalised; integralForcing true; integralThreshold 0.5;
}
lubrication { model none; }
""")
    hc.run("blockMesh", case, "log.blockMesh")
    return dict(name="ib", case=case, app="demIbFoam",
                dicts=["constant/ibProperties", "constant/demProperties"])


# --------------------------------------------------------------------------
# One run and its verdict

FATAL = re.compile(r"FOAM FATAL (IO )?ERROR")
BAD_NUMBER = re.compile(r"(?<![A-Za-z_])(-?nan|-?inf)(?![A-Za-z_])", re.I)


def finite_files(case):
    """Every number in the summary files is finite: (ok, the bad file)."""
    for sub in ("postProcessing/demFoam", "postProcessing/demCloud", "postProcessing/ibForces"):
        base = os.path.join(case, sub)
        if not os.path.isdir(base):
            continue
        for root, _, files in os.walk(base):
            for f in files:
                if not f.endswith(".dat"):
                    continue
                for line in open(os.path.join(root, f)):
                    if line.startswith("#"):
                        continue
                    for x in line.split():
                        try:
                            if not math.isfinite(float(x)):
                                return False, os.path.join(root, f)
                        except ValueError:
                            pass
    return True, ""


def judge(base, mutated_dict, desc, mustFail, text, workroot, index):
    case = os.path.join(workroot, f"{base['name']}-{index:03d}")
    shutil.copytree(base["case"], case, ignore=shutil.ignore_patterns("log.*", "processor*"))
    for t in os.listdir(case):
        # only the 0 folder: no time folders of earlier runs
        if re.match(r"^[0-9.e+-]+$", t) and float(t) > 0:
            shutil.rmtree(os.path.join(case, t))
    open(os.path.join(case, mutated_dict), "w").write(text)
    log = os.path.join(case, "log")
    try:
        with open(log, "w") as f:
            r = subprocess.run([base["app"]], cwd=case, stdout=f, stderr=subprocess.STDOUT,
                               timeout=TIMEOUT)
        rc = r.returncode
    except subprocess.TimeoutExpired:
        return "hang", f"no end within {TIMEOUT} s"
    out = open(log, errors="replace").read()
    dictName = os.path.basename(mutated_dict)
    if rc < 0 or rc >= 128:
        return "signal", f"exit {rc}"
    # (not "Floating point exception": OpenFOAM's banner names the trap)
    if "printStack" in out or "sigSegv" in out or "sigFpe::sigHandler" in out:
        return "signal", "stack trace in the log"
    if rc != 0:
        m = FATAL.search(out)
        if not m:
            return "unclean", f"exit {rc} without a FOAM FATAL message"
        msg = out[m.start():m.start() + 3000]
        names = (dictName in msg or "controlDict" in msg or "particle" in msg.lower()
                 or "body" in msg.lower() or "demProperties" in msg)
        if not names:
            return "unnamed", "the message names no file, particle or body"
        return "refused", ""
    # Ran to the end
    if mustFail:
        return "accepted", "exit 0 for input that must be refused"
    if BAD_NUMBER.search(out):
        return "nan", "nan/inf in the log"
    ok, bad = finite_files(case)
    if not ok:
        return "nan", f"non-finite number in {bad}"
    return "ran", ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shard", default="1/1")
    ap.add_argument("--cases", type=int, default=400)
    ap.add_argument("--seed", type=int, default=2026)
    args = ap.parse_args()
    shard, nShards = (int(x) for x in args.shard.split("/"))

    bases = [
        lambda: base_demFoam("spheres", "settlingSpheres", 0.004, 0.002),
        lambda: base_demFoam("rocks", "settlingRocks", 0.004, 0.002),
        base_demPimpleFoam,
        base_demIbFoam,
    ]
    rng = random.Random(args.seed)
    # The whole list of mutations is drawn for all shards alike, then split
    plan = []
    perBase = args.cases // len(bases)
    drawn = {}
    for b in range(len(bases)):
        drawn[b] = []
    # Draw per base with the dictionary text of the base's files; the base
    # cases are built lazily (only the ones this shard needs)
    built = {}

    def base(b):
        if b not in built:
            built[b] = bases[b]()
        return built[b]

    for b in range(len(bases)):
        dicts = None
        while len(drawn[b]) < perBase:
            if dicts is None:
                bb = base(b)
                dicts = [(d, parse(tokenize(open(os.path.join(bb["case"], d)).read()))[0])
                         for d in bb["dicts"]]
            # One variant of one random entry per case: many entries
            d, tree = dicts[rng.randrange(len(dicts))]
            desc, mutated, mustFail = rng.choice(mutations(tree, rng))
            drawn[b].append((d, desc, mustFail, mutated))
        for item in drawn[b]:
            plan.append((b,) + item)

    mine = [p for i, p in enumerate(plan) if i % nShards == shard - 1]
    workroot = hc.workdir(f"fuzz-runs-{shard}")
    counts = {}
    failures = []
    # The unmutated bases must run, or every verdict below means nothing
    for b in sorted({p[0] for p in mine}):
        bb = base(b)
        d = bb["dicts"][0]
        verdict, why = judge(bb, d, "unchanged", False,
                             open(os.path.join(bb["case"], d)).read(), workroot, 999)
        ok = verdict == "ran"
        print(f"{'PASS' if ok else 'FAIL'}: [{bb['name']}] unchanged base case -> {verdict}"
              + (f" ({why})" if why else ""), flush=True)
        if not ok:
            failures.append(f"base case {bb['name']} does not run: {verdict} ({why})")
        else:
            shutil.rmtree(os.path.join(workroot, f"{bb['name']}-999"), ignore_errors=True)
    for i, (b, d, desc, mustFail, tree) in enumerate(mine):
        bb = base(b)
        text = write(tree)
        verdict, why = judge(bb, d, desc, mustFail, text, workroot, i)
        counts[verdict] = counts.get(verdict, 0) + 1
        good = verdict in ("refused", "ran")
        if not good:
            failures.append(f"{bb['app']} {d} {desc}: {verdict} ({why}); case {workroot}/{bb['name']}-{i:03d}")
        print(f"{'PASS' if good else 'FAIL'}: [{bb['name']}] {d}: {desc} -> {verdict}"
              + (f" ({why})" if why else ""), flush=True)
        if good:
            shutil.rmtree(os.path.join(workroot, f"{bb['name']}-{i:03d}"), ignore_errors=True)
    for f in failures:
        print("FAIL:", f)
    print("summary: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items()))
          + f"; {len(mine)} cases (shard {shard}/{nShards}, seed {args.seed})")
    hc.finish([not failures])


if __name__ == "__main__":
    main()
