#!/usr/bin/env python3
"""How much one run says: the ice resistance over repeated runs of one
set-up (README, "How much one run says").

Usage: repeats.py [-out DIR] RUN [RUN ...]

Each RUN is a finished ./Allrun folder (its ice/case.info and
postProcessing/summary.txt and iceSteady.dat) of the same set-up that
differs only in -seed: the same size, speed, draft, porosity, shape,
coupling and end time (the block count and the built porosity change a
little with the seed). The runs' ice resistances are independent draws of
the same random process (other blocks in other places), so

  ensemble mean    the plain mean of the runs' ice resistances
  s                their standard deviation between runs (n - 1)
  s / sqrt(n)      the standard error of the ensemble mean
  within-run       the mean of the runs' own batch-means standard errors:
                   the noise inside one run's window

s against the within-run error says whether one run's error bar covers
what another run of the same set-up gives: s well above it means that the
run-to-run spread (whether the channel jams, where the blocks were) is not
in one run's error bar. A run counts as jammed when its ice-load trend
over the window is more than two of its standard errors above zero
(iceSteady.dat).

Writes DIR/repeats.dat (one row per run, then the ensemble rows; plain
columns) and DIR/repeats.png (each run's ice resistance with its error bar,
the ensemble mean with s and s/sqrt(n)). DIR default: postProcessing.
"""
import math
import os
import re
import sys

# case.info entries that may differ between repeats: the seed and what it
# changes in the built channel
VARYING = {"seed", "blocks", "porosity"}


def fail(msg):
    sys.exit(f"repeats.py: {msg}")


def caseInfo(run):
    path = os.path.join(run, "ice", "case.info")
    if not os.path.isfile(path):
        fail(f"{run}: no {path} (expected a finished ./Allrun folder)")
    out = {}
    for line in open(path):
        parts = line.split(None, 1)
        if len(parts) == 2:
            out[parts[0]] = parts[1].strip()
    out.setdefault("seed", "1")     # runs from before -seed had seed 1
    return out


def summary(run):
    path = os.path.join(run, "postProcessing", "summary.txt")
    if not os.path.isfile(path):
        fail(f"{run}: no {path} (postProcess.py writes it at the end of ./Allrun)")
    rows, passed = {}, None
    for line in open(path):
        w = line.split()
        if len(w) >= 3 and w[0] in ("openWater", "total", "iceLoad", "fluid", "iceResistance"):
            rows[w[0]] = (float(w[1]), float(w[2]))
        if line.startswith("all checks passed"):
            passed = True
        elif line.startswith("SOME CHECKS FAILED"):
            passed = False
    if "iceResistance" not in rows:
        fail(f"{path}: no 'iceResistance mean stdError' row")
    return rows, passed


def iceLoadTrend(run):
    """(slope, its standard error) [N/s] of the ice load over the window,
    from iceSteady.dat's '# window' line; None if absent"""
    path = os.path.join(run, "postProcessing", "iceSteady.dat")
    if not os.path.isfile(path):
        return None
    for line in open(path):
        if line.startswith("# window"):
            m = re.search(r"ice load trend over \d+ batch means ([-+0-9.eE]+) \+- ([0-9.eE+-]+)", line)
            if m:
                return float(m.group(1)), float(m.group(2))
    return None


def main():
    args, out = sys.argv[1:], "postProcessing"
    runs = []
    while args:
        a = args.pop(0)
        if a == "-out":
            if not args:
                fail("-out: expected a folder")
            out = args.pop(0)
        elif a.startswith("-"):
            fail(f"unknown option {a} (usage: repeats.py [-out DIR] RUN [RUN ...])")
        else:
            runs.append(a)
    if len(runs) < 2:
        fail("expected at least two runs (./Allrun folders of one set-up with different -seed)")

    infos = [caseInfo(r) for r in runs]
    ref = infos[0]
    for r, inf in zip(runs[1:], infos[1:]):
        for k in sorted(set(ref) | set(inf)):
            if k in VARYING:
                continue
            if ref.get(k) != inf.get(k):
                fail(f"{r}: its {k} ({inf.get(k)}) is not {runs[0]}'s ({ref.get(k)}): "
                     "expected repeats of one set-up that differ only in -seed")
    seeds = [inf["seed"] for inf in infos]
    if len(set(seeds)) != len(seeds):
        fail(f"two runs have the same seed ({' '.join(seeds)}): they are not independent")

    rows = []
    for r, inf in zip(runs, infos):
        s, passed = summary(r)
        trend = iceLoadTrend(r)
        jammed = trend is not None and trend[0] > 2 * trend[1]
        rows.append(dict(run=r, seed=int(inf["seed"]), blocks=int(inf["blocks"]),
                         R=s["iceResistance"], load=s.get("iceLoad", (math.nan, math.nan)),
                         trend=trend, jammed=jammed, passed=passed))
    n = len(rows)
    R = [row["R"][0] for row in rows]
    mean = sum(R) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in R) / (n - 1))
    sem = sd / math.sqrt(n)
    within = sum(row["R"][1] for row in rows) / n
    load = [row["load"][0] for row in rows]
    loadMean = sum(load) / n
    loadSd = math.sqrt(sum((x - loadMean) ** 2 for x in load) / (n - 1))

    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "repeats.dat"), "w") as f:
        f.write(f"# brashIceChannel repeats: {n} runs of size {ref.get('size')}, U {ref.get('speed')} m/s, "
                f"end {ref.get('end')} s, {ref.get('shape')}s, {ref.get('couplingDirection')}\n")
        f.write("# seed blocks iceResistance[N] stdError[N] iceLoad[N] stdError[N] "
                "iceLoadTrend[N/s] trendError[N/s] jammed checksPassed run\n")
        for row in rows:
            t = row["trend"] or (math.nan, math.nan)
            f.write(f"{row['seed']} {row['blocks']} {row['R'][0]:.4f} {row['R'][1]:.4f} "
                    f"{row['load'][0]:.4f} {row['load'][1]:.4f} {t[0]:.3f} {t[1]:.3f} "
                    f"{int(row['jammed'])} {'' if row['passed'] is None else int(row['passed'])} "
                    f"{row['run']}\n")
        f.write(f"# ensemble iceResistance: mean {mean:.4f} N, s {sd:.4f} N, s/sqrt(n) {sem:.4f} N, "
                f"within-run error {within:.4f} N, s/within {sd / within:.3f}, n {n}\n")
        f.write(f"# ensemble iceLoad: mean {loadMean:.4f} N, s {loadSd:.4f} N\n")
        f.write(f"# jammed: {sum(r['jammed'] for r in rows)} of {n}\n")
    print(open(os.path.join(out, "repeats.dat")).read(), end="")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("repeats.py: no matplotlib; repeats.png not written")
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    x = list(range(1, n + 1))
    for xi, row in zip(x, rows):
        ax.errorbar(xi, row["R"][0], yerr=row["R"][1], fmt="s" if row["jammed"] else "o",
                    color="C3" if row["jammed"] else "C0", capsize=4)
    ax.axhspan(mean - sd, mean + sd, color="C1", alpha=0.15, label=f"mean ± s ({mean:.1f} ± {sd:.1f} N)")
    ax.axhspan(mean - sem, mean + sem, color="C1", alpha=0.35, label=f"mean ± s/√n (± {sem:.1f} N)")
    ax.axhline(mean, color="C1")
    ax.plot([], [], "o", color="C0", label="run ± its batch-means error")
    if any(r["jammed"] for r in rows):
        ax.plot([], [], "s", color="C3", label="run that jammed (ice-load trend > 2 se)")
    ax.set_xticks(x)
    ax.set_xticklabels([f"seed {r['seed']}" for r in rows])
    ax.set_ylabel("ice resistance [N]")
    ax.set_title(f"brashIceChannel {ref.get('size')}: {n} repeats, {ref.get('end')} s each")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "repeats.png"), dpi=120)


if __name__ == "__main__":
    main()
