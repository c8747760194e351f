#!/usr/bin/env python3
"""Is the ice ahead of the bow steady? (brashIceChannel, README "Steady state")

Usage: iceSteady.py [CASE] [-window T0]     (CASE default ice; T0 default: the
                                             iceResistance MSER-5 window start)

From CASE's written states (<time>/polyDEM/state), its particleBalance.dat and
resistance.dat, writes to postProcessing/ (of the current folder):

  iceSteady.dat   per written time: the blocks with their centre between the
                  inlet and the stem (count, plan area), the ice's plan
                  coverage and mean drift in bands ahead of the bow, the ice
                  area flux past the hull (the two gaps), the released
                  blocks in contact with a kinematic one of the approach
                  region and the contact force on them along the flow (the
                  approach region acting as a piston); then the inflow's
                  and the outlet's area fluxes per second from the particle
                  balance, the ice load's plain means per second, and over
                  the window the trend (least-squares slope with its
                  standard error) of the blocks ahead and of the ice load
  iceSteady.png   blocks ahead of the stem, drift per band and the ice load
                  against time

The flux balance (all in m^2/s of ice plan area): the inflow delivers
c U W (c its plan coverage, U the towing speed, W the channel's width);
what passes the hull goes through its two gaps (W - B wide), q_gap =
sum(A_i u_i) / L over the blocks beside the hull (centre in x from 0.3 m aft
of the stem to the hull's end, |y| > B/2, L that length). Plan area of a
block: its mass / (rho_ice t), exact for the flat cuboids.
"""
import glob
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import demState  # noqa: E402

RHO_ICE = 920.0


def info(case):
    out = {}
    for l in open(os.path.join(case, "case.info")):
        k, v = l.split(None, 1)
        try:
            out[k] = float(v)
        except ValueError:
            out[k] = v.strip()
    return out


def table(pattern, marker):
    head, data = None, []
    for f in sorted(glob.glob(pattern)):
        for l in open(f):
            if l.startswith("#") and marker in l:
                head = l[1:].split()
            elif l.strip() and not l.startswith("#"):
                data.append([float(x) for x in l.split()])
    if head is None:
        sys.exit(f"iceSteady.py: no {pattern}")
    return {k: [r[i] for r in data] for i, k in enumerate(head)}


def slope(t, y):
    """least-squares slope and its standard error (independent residuals)"""
    n = len(t)
    if n < 3:
        return float("nan"), float("nan")
    tm, ym = sum(t) / n, sum(y) / n
    sxx = sum((a - tm) ** 2 for a in t)
    b = sum((a - tm) * (c - ym) for a, c in zip(t, y)) / sxx
    res = sum((c - ym - b * (a - tm)) ** 2 for a, c in zip(t, y))
    return b, (res / (n - 2) / sxx) ** 0.5


def mser5(x):
    """MSER-5 truncation (as steadyMean.C): the start index of the window"""
    b, m = 5, len(x) // 5
    if m < 2:
        return 0
    bm = [sum(x[j * b:(j + 1) * b]) / b for j in range(m)]
    best, bestv = 0, float("inf")
    for d in range(m // 2 + 1):
        n = m - d
        mu = sum(bm[d:]) / n
        v = sum((y - mu) ** 2 for y in bm[d:]) / (n * n)
        if v < bestv:
            best, bestv = d, v
    return best * b


def batch_mean(x, start, nb=10):
    """mean, batch-means standard error, lag-1 correlation of the batches
    (as steadyMean.C)"""
    n = len(x) - start
    mu = sum(x[start:]) / n
    bm = [sum(x[start + k * n // nb:start + (k + 1) * n // nb]) /
          (start + (k + 1) * n // nb - (start + k * n // nb)) for k in range(nb)]
    m = sum(bm) / nb
    var = sum((y - m) ** 2 for y in bm)
    cov = sum((bm[k] - m) * (bm[k - 1] - m) for k in range(1, nb))
    return mu, (var / (nb - 1) / nb) ** 0.5, cov / var if var > 0 else 0.0


def main():
    args = sys.argv[1:]
    case, t0 = "ice", None
    while args:
        a = args.pop(0)
        if a == "-window":
            t0 = float(args.pop(0))
        else:
            case = a
    I = info(case)
    if "hullBeam" not in I:
        sys.exit(f"iceSteady.py: {case}/case.info has no hullBeam (a case made before"
                 " makeCase.py wrote it): remake the case")
    U, W, t_ice = I["speed"], I["ymax"] - I["ymin"], I["iceThickness"]
    BEAM = I["hullBeam"]
    x0, xs, xe = I["xmin"], I["stemX"], I["hullEnd"]
    area = lambda p: p["mass"] / (RHO_ICE * t_ice)          # noqa: E731
    # bands ahead of the bow (from the release line, a bounding radius
    # past the inlet, to the stem)
    edges = [x0 + 0.1]
    while edges[-1] < xs - 1e-9:
        edges.append(min(xs, edges[-1] + 0.5))
    if len(edges) > 2 and edges[-1] - edges[-2] < 0.25:
        edges.pop(-2)
    bands = list(zip(edges[:-1], edges[1:]))
    gap0, gap1 = xs + 0.3, xe
    rows = []
    for t, d in demState.times(case):
        S = demState.read_state(os.path.join(case, d, "polyDEM", "state"))
        P = S["particles"]
        ahead = [p for p in P if x0 < p["px"] < xs]
        r = dict(t=t, n=len(ahead), A=sum(area(p) for p in ahead),
                 naft=len([p for p in P if xs <= p["px"] < I["xmax"]]))
        for k, (a, b) in enumerate(bands):
            B = [p for p in P if a <= p["px"] < b]
            r[f"c{k}"] = sum(area(p) for p in B) / ((b - a) * W)
            r[f"u{k}"] = (sum(p["vx"] * area(p) for p in B) / sum(area(p) for p in B)
                          if B else float("nan"))
        G = [p for p in P if gap0 < p["px"] < gap1 and abs(p["py"]) > 0.5 * BEAM]
        r["qgap"] = sum(area(p) * p["vx"] for p in G) / (gap1 - gap0)
        r["ugap"] = (sum(p["vx"] * area(p) for p in G) / sum(area(p) for p in G)
                     if G else float("nan"))
        r["cgap"] = sum(area(p) for p in G) / ((gap1 - gap0) * (W - BEAM))
        # the approach region as a piston: contacts of a kinematic block
        # (centre before the release line) with a released one, and the
        # contact force along the flow on those released blocks
        byId = {p["id"]: p for p in P}
        kin = lambda p: p["px"] < x0 + 0.1          # noqa: E731
        pushed = {}
        for a, b, _ in S["pairs"]:
            if a in byId and b in byId and kin(byId[a]) != kin(byId[b]):
                q = byId[b] if kin(byId[a]) else byId[a]
                pushed[q["id"]] = q
        r["piston"] = len(pushed)
        r["pistonF"] = sum(demState.contact_force(q)[0] for q in pushed.values()) \
            if "fext" in (P[0] if P else {}) else float("nan")
        rows.append(r)
    pb = table(os.path.join(case, "postProcessing", "*", "*", "particleBalance.dat"), "inserted")
    res = table(os.path.join(case, "postProcessing", "resistance", "*", "resistance.dat"), "time")
    # the series over restarts (a restart's first row repeats its start
    # time with no DEM steps): one row per time, DEM steps done
    byT = {}
    for i, s in enumerate(res["iceSteps"]):
        if s > 0:
            byT[round(res["time"][i], 9)] = i
    keep = [byT[k] for k in sorted(byT)]
    tr, Rice = [res["time"][i] for i in keep], [res["Rice"][i] for i in keep]
    Rtot, Rfl = [res["Rtotal"][i] for i in keep], [res["Rfluid"][i] for i in keep]
    meanf = glob.glob(os.path.join(case, "postProcessing", "resistance", "*", "resistanceMean.dat"))
    means = {}
    if meanf:
        for l in open(sorted(meanf)[-1]):
            if l.strip() and not l.startswith("#"):
                w = l.split()
                means[w[0]] = (float(w[1]), float(w[2]), int(float(w[3])), float(w[4]))
    # the steady window over the whole series (the function object's own
    # mean restarts with a restarted run): MSER-5 of Rtotal, as it does,
    # unless -window is given
    if t0 is not None and (not tr or tr[-1] < t0):
        sys.exit(f"iceSteady.py: -window {t0:g}: the window starts after the last"
                 f" sample of {case} ({tr[-1] if tr else 0:g} s); run longer or start"
                 " the window earlier")
    i0 = mser5(Rtot) if t0 is None else next(i for i, tt in enumerate(tr) if tt >= t0)
    t0 = tr[i0]
    ow = means.get("Rtotal", (0, 0))[0] - means.get("RiceNet", (0, 0))[0]
    # MSER-5 within the window: does the load still truncate a transient?
    i1 = i0 + mser5(Rtot[i0:])
    mserIn = (tr[i1],) + batch_mean(Rice, i1) + batch_mean([v - ow for v in Rtot], i1)
    means = {}
    for k, x in (("Rice", Rice), ("Rfluid", Rfl), ("Rtotal", Rtot),
                 ("RiceNet", [v - ow for v in Rtot])):
        mu, e, c = batch_mean(x, i0)
        means[k] = (mu, e, len(x) - i0, t0, c)
    tend = tr[-1]
    # fluxes per second from the particle balance (plan area per second)
    sec = []
    T = 0.0
    while T + 1.0 <= tend + 1e-9:
        def at(col, tt):
            i = min(range(len(pb["time"])), key=lambda j: abs(pb["time"][j] - tt))
            return pb[col][i]
        qin = (at("insertedMass_inlet", T + 1) - at("insertedMass_inlet", T)) / (RHO_ICE * t_ice)
        qout = (at("removedMass_downstream", T + 1) - at("removedMass_downstream", T)) / (RHO_ICE * t_ice)
        R = [v for tt, v in zip(tr, Rice) if T < tt <= T + 1]
        sec.append((T, T + 1, qin, qin / (U * W), qout, sum(R) / len(R) if R else float("nan")))
        T += 1.0
    win = [r for r in rows if r["t"] >= t0 - 1e-9]
    bn, bn_e = slope([r["t"] for r in win], [r["n"] for r in win])
    # the ice load's trend from 10 batch means over the window (the samples
    # are correlated; the batches much less)
    Rw = [(tt, v) for tt, v in zip(tr, Rice) if tt >= t0]
    nb = 10
    L = len(Rw) // nb
    bt = [sum(x[0] for x in Rw[k * L:(k + 1) * L]) / L for k in range(nb)] if L else []
    bv = [sum(x[1] for x in Rw[k * L:(k + 1) * L]) / L for k in range(nb)] if L else []
    bR, bR_e = slope(bt, bv)
    os.makedirs("postProcessing", exist_ok=True)
    out = "postProcessing/iceSteady.dat"
    with open(out, "w") as o:
        o.write(f"# brashIceChannel {case}: U {U:g} m/s, W {W:g} m, built porosity {I['porosity']:.3f};"
                f" ahead: centre in x = ({x0:g}, {xs:g}) m; bands from the release line;"
                f" gaps: x = ({gap0:g}, {gap1:g}) m, |y| > {0.5 * BEAM:g} m\n")
        o.write("# t n_ahead A_ahead[m2] n_aft(stem to outlet) " +
                " ".join(f"c[{a:.2f},{b:.2f}] u[{a:.2f},{b:.2f}]" for a, b in bands) +
                " c_gap u_gap q_gap[m2/s] pushed_by_approach F_push_x[N]\n")
        for r in rows:
            o.write(f"{r['t']:g} {r['n']} {r['A']:.4f} {r['naft']} " +
                    " ".join(f"{r[f'c{k}']:.3f} {r[f'u{k}']:.3f}" for k in range(len(bands))) +
                    f" {r['cgap']:.3f} {r['ugap']:.3f} {r['qgap']:.4f} {r['piston']} {r['pistonF']:.3g}\n")
        o.write("# per second: t0 t1 inflow[m2/s] inflow/(U W) (its plan coverage) "
                "outlet[m2/s] Rice_plainMean[N]\n")
        for s in sec:
            o.write("#S " + " ".join(f"{v:.4g}" for v in s) + "\n")
        o.write(f"# window from {t0:.3f} s to {tend:.3f} s ({len(win)} states):"
                f" blocks ahead trend {bn:+.2f} +- {bn_e:.2f} /s"
                f" (mean {sum(r['n'] for r in win) / max(1, len(win)):.1f});"
                f" ice load trend over 10 batch means {bR:+.2f} +- {bR_e:.2f} N/s\n")
        if "Rice" in means:
            o.write(f"# means over the window (from {t0:.3f} s: {'MSER-5 of Rtotal' if '-window' not in sys.argv else '-window'};"
                    f" 10 batch means; open water {ow:.4g} N from the function object's openWaterFile)\n")
            o.write(f"# MSER-5 of Rtotal within the window: from {mserIn[0]:.3f} s, Rice"
                    f" {mserIn[1]:.4g} +- {mserIn[2]:.3g} N, RiceNet {mserIn[4]:.4g} +- {mserIn[5]:.3g} N\n")
            for k in ("Rice", "Rfluid", "Rtotal", "RiceNet"):
                o.write(f"#M {k} {means[k][0]:.4g} +- {means[k][1]:.3g} N ({means[k][2]} samples"
                        f" from {means[k][3]:.3f} s, batch lag-1 correlation {means[k][4]:.2f})\n")
    print(open(out).read())
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return 0
    fig, ax = plt.subplots(3, 1, figsize=(9, 9.5), sharex=True)
    t = [r["t"] for r in rows]
    ax[0].plot(t, [r["n"] for r in rows], "o-", label="blocks ahead of the stem (centre)")
    ax0b = ax[0].twinx()
    ax0b.plot(t, [r["qgap"] for r in rows], "s--", color="C1", ms=3,
              label="ice area flux past the hull's gaps [m$^2$/s]")
    for s in sec:
        ax0b.plot([s[0], s[1]], [s[2], s[2]], color="C2", lw=2)
    ax0b.plot([], [], color="C2", lw=2, label="inflow's area flux [m$^2$/s] (per second)")
    ax0b.set_ylabel("ice area flux [m$^2$/s]")
    ax[0].set_ylabel("blocks")
    h1, l1 = ax[0].get_legend_handles_labels()
    h2, l2 = ax0b.get_legend_handles_labels()
    ax[0].legend(h1 + h2, l1 + l2, fontsize=7, loc="lower right")
    name = os.path.join(*os.path.normpath(os.path.abspath(case)).split(os.sep)[-2:])
    ax[0].set_title(f"{name}: built porosity {I['porosity']:.2f}, U = {U:g} m/s")
    for k, (a, b) in enumerate(bands):
        ax[1].plot(t, [r[f"u{k}"] for r in rows], "o-", ms=3, label=f"x in [{a:.1f}, {b:.1f}] m")
    ax[1].plot(t, [r["ugap"] for r in rows], "k--", ms=3, label="beside the hull (gaps)")
    ax[1].axhline(U, color="0.5", lw=0.8)
    ax[1].set_ylabel("ice drift along the flow [m/s]")
    ax[1].legend(fontsize=7, ncol=3)
    ax[2].plot(tr, Rice, color="C3", lw=0.4, alpha=0.6, label="ice load on the hull")
    n = max(1, int(0.25 / (tr[1] - tr[0])))
    run = [sum(Rice[max(0, i - n):i + 1]) / len(Rice[max(0, i - n):i + 1]) for i in range(len(Rice))]
    ax[2].plot(tr, run, color="k", lw=1, label="0.25 s running mean")
    if "Rice" in means:
        m, e = means["Rice"][0], means["Rice"][1]
        ax[2].axvspan(t0, tend, color="C0", alpha=0.08)
        ax[2].plot([t0, tend], [m, m], color="C0", lw=2,
                   label=f"mean over the window {m:.2f} $\\pm$ {e:.2f} N from {t0:.2f} s (steady only if the trends say so)")
    ax[2].set_ylim(min(0, min(run)) - 5, max(run) * 2 + 5)
    ax[2].set_ylabel("ice load along the flow [N]")
    ax[2].set_xlabel("time [s]")
    ax[2].legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig("iceSteady.png", dpi=100)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
