#!/usr/bin/env python3
"""The brash-ice study (README "The study"): runs the matrix of ice runs,
each with the open-water run of the same hull at the same speed, and
tabulates their steady means.

Usage: study.py [-test] [-runs "NAME ..."] [-endTime T] [-window T0]
                [-openWaterEndTime T] [-porosity P] [-np N] [-dir DIR]
                [-part openWater | ice] [-tabulate]

Runs (NAME: the ice run's makeCase.py options):
  polyhedra        cuboid blocks, two-way coupling, 0.74 m/s
  spheres          -shape sphere (each block as the sphere of its volume)
  spheresRolling   -shape sphere -rollingFriction 0.5
  oneWay           cuboids, -oneWay (drag and buoyancy on the ice only)
  U0.3 U0.5 U1.0   cuboids at 0.3, 0.5, 1.0 m/s (with polyhedra at 0.74:
                   the speed sweep)
Defaults: all runs; the default channel at -porosity 0.8; means over the
window from -window 6 s at the report's 0.74 m/s, and at another speed U
from 6 s x 0.74/U: the window opens when the hull has passed the same
length of channel (4.4 m), so a slow run is not averaged over its filling
(the ice ahead of the bow takes a time ~ 1/U to build up). Each ice run
goes to its window start + 14 s (20 s at 0.74 m/s, 28.8 s at 0.3 m/s)
unless -endTime T sets one end for all. The open-water runs go as long as
the ice runs of their speed (-openWaterEndTime sets another end) and their
mean is taken over the same window: the open-water force on this hull
drifts over tens of seconds (README, "One-way against two-way"), so a mean
over an earlier, shorter window would bias the ice resistance.
-test: the CTest-size channel (-test of makeCase.py) and its porosity,
0.4 s, window from 0.2 s: checks that the study runs, not physics.
-np N: each run's fluid on N ranks (decomposePar, mpirun).
-part openWater | ice: only the open-water runs of the named runs' speeds,
or only the ice runs (their open water made before or alongside, e.g. on
another core); then the table of those found.
-tabulate: no runs; tabulate those found in DIR.

Each ice run is DIR/<NAME>/ice with DIR/<NAME>/openWater a link to the
open-water run at its speed, DIR/openWater_U<speed> (run once per speed).
The means come from iceSteady.py (10 batch means over the window, the
standard error of the mean from them; the trends of the blocks ahead of
the stem and of the ice load over the window say whether it is steady);
ice resistance = total - open water, both over the window, the errors
added in quadrature.

Writes DIR/study.dat (one row per run, plain columns), DIR/study.md (the
table and the differences the study asks about, for the README; for the
speed sweep, the ice resistance with R/(rho_i g B H^2) and R/(0.5 rho_w U^2
B H) and a power law R = a U^n fitted over the speeds) and
DIR/resistanceSpeed.png (ice resistance against towing speed, with the fit).
DIR default: study (study-test with -test).
"""
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from iceSteady import batch_mean  # noqa: E402

U_REF = 0.74        # the report's towing speed [m/s]: -window is given there
WINDOW_LENGTH = 14  # default run length after the window start [s]


def window_start(window, U):
    """The window start at speed U: the same length of channel passed as in
    -window seconds at U_REF."""
    return window * U_REF / U


RUNS = {
    "polyhedra": (0.74, []),
    "spheres": (0.74, ["-shape", "sphere"]),
    "spheresRolling": (0.74, ["-shape", "sphere", "-rollingFriction", "0.5"]),
    "oneWay": (0.74, ["-oneWay"]),
    "U0.3": (0.3, []),
    "U0.5": (0.5, []),
    "U1.0": (1.0, []),
}


def fail(msg):
    sys.exit(f"study.py: {msg}")


def python():
    """python3 with numpy, scipy, matplotlib (Debian's if the first lacks them)."""
    r = subprocess.run([sys.executable, "-c", "import numpy, scipy, matplotlib"],
                       capture_output=True)
    return sys.executable if r.returncode == 0 else "/usr/bin/python3"


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, shell=True)
    if r.returncode != 0:
        fail(f"'{cmd}' failed in {cwd} (see {os.path.join(cwd, log)})")


def run_case(case, make_opts, np_):
    """makeCase.py, the mesh and demInterFoam, as Allrun's runCase."""
    parent, name = os.path.split(case)
    if os.path.exists(case):
        shutil.rmtree(case)
    sh(f"{python()} {HERE}/makeCase.py {' '.join(make_opts)} -dir {name}", parent,
       f"log.makeCase.{name}")
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    for app in ("surfaceFeatureExtract", "blockMesh", "snappyHexMesh -overwrite",
                "checkMesh", "setFields"):
        sh(app, case, "log." + app.split()[0])
    t0 = os.times()
    if np_ > 1:
        sh(f"foamDictionary -entry numberOfSubdomains -set {np_} system/decomposeParDict",
           case, "log.foamDictionary")
        sh(f"foamDictionary -entry coeffs/n -set '({np_} 1 1)' system/decomposeParDict",
           case, "log.foamDictionary")
        sh("decomposePar", case, "log.decomposePar")
        sh(f"mpirun -np {np_} demInterFoam -parallel", case, "log.demInterFoam")
        sh("reconstructPar -latestTime", case, "log.reconstructPar")
    else:
        sh("demInterFoam", case, "log.demInterFoam")
    t1 = os.times()
    with open(os.path.join(case, "runTime"), "w") as f:
        f.write(f"{t1.elapsed - t0.elapsed:.0f}\n")


def info(case):
    d = {}
    for line in open(os.path.join(case, "case.info")):
        k, _, v = line.strip().partition(" ")
        d[k] = v
    return d


def cpu_time(case):
    """demInterFoam's last ExecutionTime [s] (rank 0) and the simulated time
    it reached (a run stopped early is tabulated over what it ran)."""
    t, reached = float("nan"), 0.0
    for line in open(os.path.join(case, "log.demInterFoam")):
        if line.startswith("ExecutionTime"):
            t = float(line.split()[2])
        elif line.startswith("Time = "):
            reached = float(line.split()[2])
    return t, reached


def steady_means(rundir, window):
    """iceSteady.py over the window: {quantity: (mean, stdError)}, trends."""
    sh(f"{python()} {HERE}/iceSteady.py ice -window {window:g}", rundir, "log.iceSteady")
    txt = open(os.path.join(rundir, "postProcessing", "iceSteady.dat")).read()
    means = {}
    for m in re.finditer(r"^#M (\w+) (\S+) \+- (\S+) N \((\d+) samples from (\S+) s", txt, re.M):
        means[m.group(1)] = (float(m.group(2)), float(m.group(3)), int(m.group(4)))
    w = re.search(r"^# window from (\S+) s to (\S+) s .*blocks ahead trend (\S+) \+- (\S+) /s"
                  r" \(mean (\S+)\); ice load trend over 10 batch means (\S+) \+- (\S+) N/s",
                  txt, re.M)
    if not means or not w:
        fail(f"no window means in {rundir}/postProcessing/iceSteady.dat")
    trends = dict(t0=float(w.group(1)), t1=float(w.group(2)),
                  nTrend=(float(w.group(3)), float(w.group(4))), nAhead=float(w.group(5)),
                  RTrend=(float(w.group(6)), float(w.group(7))))
    return means, trends


def resistance_series(case, names):
    """time -> tuple of the named columns of a case's iceResistance
    postProcessing/resistance/0/resistance.dat."""
    path = os.path.join(case, "postProcessing", "resistance", "0", "resistance.dat")
    cols, d = None, {}
    for line in open(path):
        if line.startswith("# time"):
            cols = line[1:].split()
            continue
        if line.startswith("#") or not line.strip():
            continue
        w = line.split()
        d[round(float(w[0]), 9)] = tuple(float(w[cols.index(n)]) for n in names)
    return d


def open_water_mean(ow, t0, t1):
    """The open-water run's total force on the hull over [t0, t1] (10 batch
    means): mean, standard error, and the window it covers."""
    series = resistance_series(ow, ["Rtotal"])
    t = [tt for tt in sorted(series)
         if t0 - 1e-9 <= tt <= t1 + 1e-9 and math.isfinite(series[tt][0])]
    x = [series[tt][0] for tt in t]
    if len(x) < 20:
        fail(f"{ow}: the open-water run has {len(x)} samples in the ice run's window"
             f" {t0:g}-{t1:g} s; run it as long as the ice run (-openWaterEndTime)")
    mu, se, _ = batch_mean(x, 0)
    return (mu, se), (t[0], t[-1])


def tabulate(top, names, window):
    rows = []
    for name in names:
        rundir = os.path.join(top, name)
        ice = os.path.join(rundir, "ice")
        if not os.path.isfile(os.path.join(ice, "log.demInterFoam")):
            print(f"study.py: {name}: no run in {ice}, left out of the table")
            continue
        I = info(ice)
        means, tr = steady_means(rundir, window_start(window, float(I["speed"])))
        ow, owWin = open_water_mean(os.path.join(rundir, "openWater"), tr["t0"], tr["t1"])
        cpu, reached = cpu_time(ice)
        rows.append(dict(
            name=name, U=float(I["speed"]), shape=I["shape"],
            rolling=float(I.get("rollingFriction", 0)),
            coupling=I.get("couplingDirection", "twoWay"), porosity=float(I["porosity"]),
            t0=tr["t0"], t1=tr["t1"], samples=means["Rice"][2],
            Rice=means["Rice"][:2], Rfluid=means["Rfluid"][:2], Rtotal=means["Rtotal"][:2],
            RiceNet=(means["Rtotal"][0] - ow[0], math.hypot(means["Rtotal"][1], ow[1])),
            openWater=ow, openWaterWindow=owWin,
            nAhead=tr["nAhead"], nTrend=tr["nTrend"], RTrend=tr["RTrend"],
            B=float(I["hullBeam"]), H=float(I["iceThickness"]),
            L=float(I["hullEnd"]) - float(I["stemX"]),
            rhoW=float(I["rhoWater"]), rhoI=float(I.get("rhoIce", 920.0)),
            cpuPerSecond=cpu / reached if reached > 0 else float("nan")))
    if not rows:
        fail(f"no runs to tabulate in {top}")

    with open(os.path.join(top, "study.dat"), "w") as f:
        f.write("# brashIceChannel study (study.py): window means, 10 batch means,"
                " +- the standard error of the mean\n")
        f.write("# name U[m/s] shape rollingFriction coupling porosity windowStart[s]"
                " windowEnd[s] samples Rice[N] se RfluidHull[N] se Rtotal[N] se"
                " openWaterSameWindow[N] se RiceNet[N] se blocksAhead blocksAheadTrend[1/s] se"
                " RiceTrend[N/s] se cpuPerSimulatedSecond[s]\n")
        for r in rows:
            f.write(f"{r['name']} {r['U']:g} {r['shape']} {r['rolling']:g} {r['coupling']}"
                    f" {r['porosity']:.4f} {r['t0']:.3f} {r['t1']:.3f} {r['samples']}"
                    f" {r['Rice'][0]:.5g} {r['Rice'][1]:.3g} {r['Rfluid'][0]:.5g} {r['Rfluid'][1]:.3g}"
                    f" {r['Rtotal'][0]:.5g} {r['Rtotal'][1]:.3g} {r['openWater'][0]:.5g}"
                    f" {r['openWater'][1]:.3g} {r['RiceNet'][0]:.5g} {r['RiceNet'][1]:.3g}"
                    f" {r['nAhead']:.1f} {r['nTrend'][0]:.3g} {r['nTrend'][1]:.3g}"
                    f" {r['RTrend'][0]:.3g} {r['RTrend'][1]:.3g} {r['cpuPerSecond']:.4g}\n")

    pm = lambda v: f"{v[0]:.2f} +- {v[1]:.2f}"  # noqa: E731
    md = ["| run | U [m/s] | blocks | coupling | window [s] | ice load on the hull [N]"
          " | fluid force on the hull [N] | open water [N] | **ice resistance** = total"
          " - open water [N] | ice load trend [N/s] | blocks ahead: mean, trend [1/s]"
          " | CPU per simulated s [s] |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        blocks = r["shape"] + (f", rolling {r['rolling']:g}" if r["rolling"] > 0 else "")
        md.append(f"| {r['name']} | {r['U']:g} | {blocks} | {r['coupling']} |"
                  f" {r['t0']:.1f}-{r['t1']:.1f} | {pm(r['Rice'])} | {pm(r['Rfluid'])} |"
                  f" {pm(r['openWater'])} | **{pm(r['RiceNet'])}** | {pm(r['RTrend'])} |"
                  f" {r['nAhead']:.1f}, {r['nTrend'][0]:+.2f} +- {r['nTrend'][1]:.2f} |"
                  f" {r['cpuPerSecond']:.0f} |")
    by = {r["name"]: r for r in rows}

    def diff(a, b, key):
        x, y = by[a][key], by[b][key]
        return x[0] - y[0], math.hypot(x[1], y[1])

    md.append("")
    md.append("Differences against `polyhedra` (the errors added in quadrature; the open-water"
              " mean is common to runs at one speed, so its error cancels in a difference of"
              " ice resistances at one speed and is left out there):")
    md.append("")
    md.append("| run | ice resistance [N] | ice load [N] | fluid force on the hull [N] |")
    md.append("|---|---|---|---|")
    for other in ("spheres", "spheresRolling", "oneWay"):
        if other in by and "polyhedra" in by:
            md.append(f"| {other} - polyhedra | {pm(diff(other, 'polyhedra', 'Rtotal'))} |"
                      f" {pm(diff(other, 'polyhedra', 'Rice'))} |"
                      f" {pm(diff(other, 'polyhedra', 'Rfluid'))} |")
    sweep = sorted((r for r in rows if r["shape"] == "cuboid" and r["coupling"] == "twoWay"
                    and r["rolling"] == 0), key=lambda r: r["U"])
    fit = speed_law(sweep) if len(sweep) >= 2 else None
    if len(sweep) >= 2:
        md += sweep_table(sweep, fit)
    open(os.path.join(top, "study.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md))

    if len(sweep) >= 2:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("study.py: no matplotlib; resistanceSpeed.png not written")
            return
        U = [r["U"] for r in sweep]
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.errorbar(U, [r["RiceNet"][0] for r in sweep], yerr=[r["RiceNet"][1] for r in sweep],
                    fmt="o-", capsize=3, label="ice resistance = total - open water")
        ax.errorbar(U, [r["Rice"][0] for r in sweep], yerr=[r["Rice"][1] for r in sweep],
                    fmt="s--", capsize=3, label="ice load on the hull (contacts)")
        ax.errorbar(U, [r["openWater"][0] for r in sweep],
                    yerr=[r["openWater"][1] for r in sweep], fmt="^:", capsize=3,
                    label="open-water resistance")
        if fit:
            uu = [min(U) + (max(U) - min(U)) * k / 50 for k in range(51)]
            ax.plot(uu, [fit["a"] * u ** fit["n"] for u in uu], "-", color="C0", alpha=0.4,
                    label=f"fit R_ice ~ U^n, n = {fit['n']:.2f} +- {fit['se']:.2f}")
        ax.set_xlabel("towing speed U [m/s]")
        ax.set_ylabel("force along the flow [N]")
        ax.set_title(f"brash-ice channel, cuboid blocks, porosity {sweep[0]['porosity']:.2f}"
                     "\n(means over the window +- standard error)", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(top, "resistanceSpeed.png"), dpi=120)
        print(f"study.py: {os.path.join(top, 'resistanceSpeed.png')}")


def speed_law(sweep):
    """Weighted least squares of ln R_ice = ln a + n ln U over the sweep
    (weights from the standard errors of the means): a, n and the standard
    error of n (scaled by the reduced chi-square when it exceeds 1). None when
    a mean is not positive or fewer than two speeds."""
    pts = [(math.log(r["U"]), math.log(r["RiceNet"][0]), r["RiceNet"][1] / r["RiceNet"][0])
           for r in sweep if r["RiceNet"][0] > 0 and r["RiceNet"][1] > 0]
    if len(pts) < 2 or len({p[0] for p in pts}) < 2:
        return None
    w = [1 / p[2] ** 2 for p in pts]
    sw = sum(w)
    xm = sum(wi * p[0] for wi, p in zip(w, pts)) / sw
    ym = sum(wi * p[1] for wi, p in zip(w, pts)) / sw
    sxx = sum(wi * (p[0] - xm) ** 2 for wi, p in zip(w, pts))
    n = sum(wi * (p[0] - xm) * (p[1] - ym) for wi, p in zip(w, pts)) / sxx
    lna = ym - n * xm
    se = math.sqrt(1 / sxx)
    dof = len(pts) - 2
    chi2 = sum(wi * (p[1] - lna - n * p[0]) ** 2 for wi, p in zip(w, pts))
    if dof > 0 and chi2 / dof > 1:
        se *= math.sqrt(chi2 / dof)
    return dict(a=math.exp(lna), n=n, se=se, chi2=chi2, dof=dof, points=len(pts))


def sweep_table(sweep, fit):
    """The speed sweep for study.md: the ice resistance against speed with
    two non-dimensional forms. C_static = R/(rho_i g B H^2), the scale of the
    rule formulas (buoyancy and friction of the ice; no speed), and C_dynamic
    = R/(0.5 rho_w U^2 B H), a dynamic-pressure scale. One of them staying
    constant over the sweep says which regime the ice is in (R independent
    of U, or R ~ U^2); the fitted exponent n says the same in one number."""
    g = 9.81
    md = ["", "Speed sweep (cuboids, two-way): B the hull's beam, H the ice thickness;"
          f" Fn_L = U/sqrt(g L) with the hull's length L = {sweep[0]['L']:g} m,"
          " Fn_H = U/sqrt(g H).", "",
          "| U [m/s] | Fn_L | Fn_H | window [s] | ice resistance [N] | R/(rho_i g B H^2)"
          " | R/(0.5 rho_w U^2 B H) | open water [N] | ice / open water |",
          "|---|---|---|---|---|---|---|---|---|"]
    for r in sweep:
        cs = r["rhoI"] * g * r["B"] * r["H"] ** 2
        cd = 0.5 * r["rhoW"] * r["U"] ** 2 * r["B"] * r["H"]
        R, e = r["RiceNet"]
        md.append(f"| {r['U']:g} | {r['U'] / math.sqrt(g * r['L']):.3f} |"
                  f" {r['U'] / math.sqrt(g * r['H']):.3f} | {r['t0']:.1f}-{r['t1']:.1f} |"
                  f" {R:.2f} +- {e:.2f} | {R / cs:.3f} +- {e / cs:.3f} |"
                  f" {R / cd:.3f} +- {e / cd:.3f} | {r['openWater'][0]:.2f} |"
                  f" {R / r['openWater'][0]:.2f} |")
    md.append("")
    if fit:
        md.append(f"Power law R_ice = a U^n fitted to {fit['points']} speeds (weighted by the"
                  f" standard errors): n = {fit['n']:.2f} +- {fit['se']:.2f}, a = {fit['a']:.2f} N"
                  f" at 1 m/s (chi-square {fit['chi2']:.2f} for {fit['dof']} degrees of freedom)."
                  " n = 0: speed-independent (the rule formula's regime); n = 2: the ice's"
                  " inertia and the dynamic pressure.")
    else:
        md.append("No power law fitted (a mean ice resistance not positive, or one speed).")
    return md


def main():
    args = sys.argv[1:]
    test, names, np_, only_tab, part = False, list(RUNS), 1, False, None
    end = window = owEnd = porosity = top = None

    def value(opt):
        if not args:
            fail(f"{opt}: expected a value")
        return args.pop(0)

    def number(opt, lo):
        v = value(opt)
        try:
            x = float(v)
        except ValueError:
            fail(f"{opt} '{v}': expected a number")
        if not x > lo:
            fail(f"{opt} {v}: expected a number > {lo:g}")
        return x

    while args:
        a = args.pop(0)
        if a == "-test":
            test = True
        elif a == "-runs":
            names = value(a).split()
            bad = [n for n in names if n not in RUNS]
            if bad:
                fail(f"-runs: unknown run(s) {' '.join(bad)}; valid: {' '.join(RUNS)}")
        elif a == "-endTime":
            end = number(a, 0)
        elif a == "-window":
            window = number(a, -1e-12)
        elif a == "-openWaterEndTime":
            owEnd = number(a, 0)
        elif a == "-porosity":
            porosity = number(a, 0)
            if porosity >= 1:
                fail(f"-porosity {porosity:g}: expected 0 < P < 1")
        elif a == "-np":
            np_ = int(number(a, 0))
        elif a == "-dir":
            top = value(a)
        elif a == "-part":
            part = value(a)
            if part not in ("openWater", "ice"):
                fail(f"-part {part}: expected openWater or ice")
        elif a == "-tabulate":
            only_tab = True
        elif a in ("-h", "-help", "--help"):
            print(__doc__)
            return
        else:
            fail(f"unknown option {a} (study.py -help)")
    window = window if window is not None else (0.2 if test else 6.0)

    def run_end(U):
        """The ice run's end at speed U: -endTime, else the window start + 14 s."""
        if end is not None:
            return end
        return 0.4 if test else round(window_start(window, U) + WINDOW_LENGTH, 1)

    for n in names:
        U = RUNS[n][0]
        if window_start(window, U) >= run_end(U):
            fail(f"-window {window:g}: at {U:g} m/s ({n}) the window starts at"
                 f" {window_start(window, U):g} s, not before the run's end {run_end(U):g} s"
                 f" (-endTime)")
    top = os.path.abspath(top or ("study-test" if test else "study"))
    os.makedirs(top, exist_ok=True)

    if not only_tab:
        size = ["-test"] if test else []
        poro = [] if (test and porosity is None) else ["-porosity", f"{porosity or 0.8:g}"]
        speeds = sorted({RUNS[n][0] for n in names})
        for U in (speeds if part != "ice" else []):
            ow = os.path.join(top, f"openWater_U{U:g}")
            print(f"study.py: open water at {U:g} m/s -> {ow}", flush=True)
            owT = owEnd if owEnd is not None else run_end(U)
            run_case(ow, size + ["-openWater", "-speed", f"{U:g}", "-endTime", f"{owT:g}"]
                     + poro, np_)
        for name in (names if part != "openWater" else []):
            U, opts = RUNS[name]
            rundir = os.path.join(top, name)
            os.makedirs(rundir, exist_ok=True)
            link = os.path.join(rundir, "openWater")
            if os.path.lexists(link):
                os.remove(link)
            os.symlink(os.path.join("..", f"openWater_U{U:g}"), link)
            print(f"study.py: {name} -> {rundir}/ice", flush=True)
            run_case(os.path.join(rundir, "ice"),
                     size + ["-speed", f"{U:g}", "-endTime", f"{run_end(U):g}", "-noOpenWaterFile"]
                     + poro + opts, np_)
    if part == "openWater":
        return
    tabulate(top, names, window)


if __name__ == "__main__":
    main()
