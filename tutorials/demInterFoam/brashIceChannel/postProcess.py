#!/usr/bin/env python3
"""brashIceChannel post-processing (Allrun): from openWater/ and ice/ writes

  postProcessing/resistance.dat   the resistance table: open water, with ice
                                  (total, the ice load on the hull, the
                                  fluid), ice resistance = total - open water,
                                  each steady mean with its standard error
                                  (the iceResistance function object's
                                  MSER-5 window and batch means), and the
                                  FSICR rule value at model scale
  postProcessing/checks.dat       the run's balances, PASS/FAIL with numbers
  resistance.png                  resistance against time, the steady means
                                  against the FSICR line
  postProcessing/iceHeights.dat   each block at the last written time: centre,
                                  the local free surface above it and its
                                  centre height against the free-floating
                                  height at that local surface
  postProcessing/surface.dat      the free-surface elevation map at that time
  iceField.png                    plan view at that time: the free-surface
                                  elevation (the bow wave) and the blocks,
                                  each against its floating height at the
                                  local surface

Usage: postProcess.py [-check]   (-check: exit 1 if a balance fails)

Checks (each a conservation law or a sign; the tolerances are the solvers'):
  1. water balance: int eps alpha dV plus the water out through inlet,
     outlet and atmosphere stays at its start value (MULES and the flux
     projection conserve it to the pressure solver's tolerance; 1e-5 of the
     water volume over the run)
  2. 0 <= alpha <= 1 (demInterFoam's waterVolume.dat): with ice to 1e-6
     (measured 1 + 4.7e-8 at -test); the open-water run has no particles,
     so it is interFoam's own bound (demInterFoam is interFoam to round-off
     there, validation.vofDamBreakInterFoam): the pressure solver's
     continuity residual (p_rgh to 1e-7) piles up in cells full of water
     beside the snapped hull, 1 + 4.9e-5 over the -test run's 0.4 s
     (2.3e-8 with p_rgh to 1e-11; 1 + 1.2e-4 measured at the default size
     before the outlet fix of docs/models.md): checked to 1e-3
  3. particle balance: inserted - removed = present at every step (the
     engine checks it and stops otherwise; here read back from
     particleBalance.dat)
  4. the ice reached the hull and pushes it downstream: the mean ice load
     along the flow over the run is positive, and the hull had contacts
  5. every resistance sample is finite
"""
import glob
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import demState  # noqa: E402
import waterBalance  # noqa: E402


def info(case):
    out = {}
    for l in open(os.path.join(case, "case.info")):
        k, v = l.split(None, 1)
        v = v.strip()
        try:
            out[k] = float(v)
        except ValueError:
            out[k] = v
    return out


def rows(path):
    return [[float(x) for x in l.split()] for l in open(path)
            if l.strip() and not l.startswith("#")]


def one_file(case, pattern):
    f = sorted(glob.glob(os.path.join(case, pattern)))
    if not f:
        sys.exit(f"postProcess.py: no {pattern} in {case} (did the run finish?)")
    return f


def resistance(case):
    """time series (dict of columns) and steady means {quantity: (mean, err, n, t0)}"""
    head = None
    data = []
    for f in one_file(case, "postProcessing/resistance/*/resistance.dat"):
        for l in open(f):
            if l.startswith("# time"):
                head = l[1:].split()
            elif l.strip() and not l.startswith("#"):
                data.append([float(x) for x in l.split()])
    cols = {k: [r[i] for r in data] for i, k in enumerate(head)}
    means = {}
    f = one_file(case, "postProcessing/resistance/*/resistanceMean.dat")[-1]
    for l in open(f):
        if l.strip() and not l.startswith("#"):
            w = l.split()
            means[w[0]] = (float(w[1]), float(w[2]), int(float(w[3])), float(w[4]))
    return cols, means


def main():
    check = "-check" in sys.argv[1:]
    I = info("ice")
    ow_cols, ow = resistance("openWater")
    cols, m = resistance("ice")
    results = []

    def report(ok, text):
        results.append((ok, text))
        print(("PASS  " if ok else "FAIL  ") + text)

    # 1. water balance of each run
    for case in ("openWater", "ice"):
        Wb, _ = waterBalance.balance(case, I["dt"],
                                     fluxes=("water_inlet", "water_outlet", "water_atmosphere"))
        ref = Wb[0][3]
        drift = max(abs(r[3] - ref) for r in Wb) / ref
        report(drift <= 1e-5, f"{case}: water balance max |W + out - W(0)|/W(0) = {drift:.3g}"
               f" (W(0) = {ref:.6g} m3; tolerance 1e-5)")
    # 2. alpha bounds (demInterFoam's waterVolume.dat: t, W, alphaMin, alphaMax)
    for case in ("openWater", "ice"):
        W = []
        for f in one_file(case, "postProcessing/demInterFoam/*/waterVolume.dat"):
            W += rows(f)
        lo, hi = min(r[2] for r in W), max(r[3] for r in W)
        tol = 1e-3 if case == "openWater" else 1e-6
        report(lo >= -tol and hi <= 1 + tol,
               f"{case}: alpha in [{lo:.3g}, 1 + {hi - 1:.3g}] (tolerance {tol:g})")
    # 3. particle balance
    pb = []
    for f in one_file("ice", "postProcessing/*/*/particleBalance.dat"):
        head = None
        for l in open(f):
            if l.startswith("#") and "inserted" in l:
                head = l[1:].split()
            elif l.strip() and not l.startswith("#"):
                pb.append(dict(zip(head, [float(x) for x in l.split()])))
    bad = [r for r in pb if r["inserted"] - r["removed"] != r["particles"] or r["balance"] != 0]
    last = pb[-1]
    report(not bad, f"ice: particle balance inserted - removed = present at {len(pb)} steps"
           f" (last: {last['inserted']:.0f} - {last['removed']:.0f} = {last['particles']:.0f};"
           f" {last.get('inserted_inlet', 0):.0f} from the inflow, "
           f"{last.get('removed_downstream', 0):.0f} through the outlet)")
    # 3b. the inflow: blocks inserted upstream of the inlet entered the mesh
    #     (ids from the builder's count on are the inflow's)
    stl = demState.times("ice")[-1]
    parts = demState.read_state(os.path.join("ice", stl[1], "polyDEM", "state"))["particles"]
    new = [p for p in parts if p["id"] >= I["blocks"]]
    inside = [p for p in new if p["px"] > I["xmin"]]
    released = [p for p in new if p["px"] > I["xmin"] + 0.1]
    ahead = [p for p in parts if I["xmin"] < p["px"] < I["stemX"]]
    report(last.get("inserted_inlet", 0) > 0 and len(inside) > 0,
           f"ice: the inflow inserted {last.get('inserted_inlet', 0):.0f} blocks upstream of the inlet;"
           f" at t = {stl[0]:g} s {len(inside)} of them have their centre in the fluid mesh,"
           f" {len(released)} released; {len(ahead)} blocks between the inlet and the stem")
    # The first row (t = 0, before any DEM step) has no wall load yet
    keep = [i for i, s in enumerate(cols["iceSteps"]) if s > 0]
    cols = {k: [v[i] for i in keep] for k, v in cols.items()}
    keep = [i for i, s in enumerate(ow_cols["iceSteps"]) if s > 0]
    ow_cols = {k: [v[i] for i in keep] for k, v in ow_cols.items()}
    # 4. the ice load
    n = len(cols["time"])
    meanIce = sum(cols["Rice"]) / n
    contacts = max(cols["contacts"])
    report(meanIce > 0 and contacts > 0,
           f"ice: mean ice load along the flow {meanIce:.4g} N, up to {contacts:.0f} contacts")
    # 5. finite
    finite = all(math.isfinite(v) for c in (cols, ow_cols) for k in ("Rtotal", "Rice", "Rfluid")
                 for v in c[k])
    report(finite, "every resistance sample finite")

    # The table
    lam = 100.0
    os.makedirs("postProcessing", exist_ok=True)
    with open("postProcessing/resistance.dat", "w") as o:
        o.write(f"# brashIceChannel ({I['size']}): U {I['speed']:g} m/s, {I['blocks']:.0f} blocks,"
                f" porosity {I['porosity']:.3f}, ice {I['iceThickness']:g} m, cells {I['cell']:g} m,"
                f" CFD step {I['dt']:g} s, DEM step {I['dtDem']:g} s, k_v {I['stiffness']:g} N/m3\n")
        o.write("# quantity mean[N] stdError[N] samples windowStart[s]\n")
        for name, (src, key) in (("openWater", (ow, "Rtotal")), ("total", (m, "Rtotal")),
                                 ("iceLoad", (m, "Rice")), ("fluid", (m, "Rfluid")),
                                 ("iceResistance", (m, "RiceNet"))):
            v = src[key]
            o.write(f"{name} {v[0]:.6g} {v[1]:.3g} {v[2]} {v[3]:.4g}\n")
        o.write(f"fsicrModel {I['fsicrModel']:.6g} 0 0 0   # rule formula at 1:{lam:g}, not a validation\n")
    print(open("postProcessing/resistance.dat").read())
    with open("postProcessing/checks.dat", "w") as o:
        for ok, text in results:
            o.write(("PASS  " if ok else "FAIL  ") + text + "\n")

    plot(I, ow_cols, ow, cols, m)
    ok = all(r[0] for r in results)
    print("all checks passed" if ok else "SOME CHECKS FAILED")
    return 0 if ok or not check else 1


def read_vector_field(path):
    """internalField of an ASCII volVectorField (nonuniform)."""
    txt = open(path).read()
    i = txt.index("internalField")
    head, body = txt[i:].split("(", 1)
    n = int(head.split()[-1])
    vals = body.replace("(", " ").replace(")", " ").split(None, 3 * n)[:3 * n]
    return [tuple(float(v) for v in vals[3 * k:3 * k + 3]) for k in range(n)]


def surface_map(case, time, I):
    """The free-surface elevation z_s(x, y) on the background mesh's columns
    (base cells of the blockMesh, I['cell'] square): z_min + sum(alpha V) /
    A over the column's cells, alpha being the water fraction of the fluid
    (inside a block it is the level's, so the block's own displacement does
    not count). Columns cut by the hull (cells removed: sum V below the full
    column's) are None. Needs the ASCII alpha.water and the cell centres and
    volumes (postProcess -func writeCellCentres, writeCellVolumes)."""
    d = os.path.join(case, time)
    C = read_vector_field(os.path.join(d, "C"))
    V, _ = demState.read_scalar_field(os.path.join(d, "V"))
    a, _ = demState.read_scalar_field(os.path.join(d, "alpha.water"))
    h = I["cell"]
    nx = round((I["xmax"] - I["xmin"]) / h)
    ny = round((I["ymax"] - I["ymin"]) / h)
    H = I["zmax"] - I["zmin"]
    vol = [[0.0] * ny for _ in range(nx)]
    wat = [[0.0] * ny for _ in range(nx)]
    for c, v, al in zip(C, V, a):
        i = min(nx - 1, max(0, int((c[0] - I["xmin"]) / h)))
        j = min(ny - 1, max(0, int((c[1] - I["ymin"]) / h)))
        vol[i][j] += v
        wat[i][j] += al * v
    A = h * h
    zs = [[(I["zmin"] + wat[i][j] / A) if vol[i][j] > (1 - 1e-6) * A * H else None
           for j in range(ny)] for i in range(nx)]
    return zs, h


def plot(I, ow_cols, ow, cols, m):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("No plots: python3-matplotlib missing")
        return
    fig, ax = plt.subplots(1, 2, figsize=(13, 4.8), gridspec_kw=dict(width_ratios=[2.2, 1]))
    t = cols["time"]
    ax[0].plot(ow_cols["time"], ow_cols["Rtotal"], color="0.5", lw=1, label="open water (no ice)")
    ax[0].plot(t, cols["Rtotal"], color="C0", lw=1, label="with ice: total")
    ax[0].plot(t, cols["Rice"], color="C3", lw=0.8, alpha=0.8, label="with ice: ice load on the hull")
    ax[0].plot(t, cols["Rfluid"], color="C2", lw=0.8, alpha=0.8, label="with ice: fluid")
    tw = m["Rtotal"][3]
    ax[0].axvspan(tw, t[-1], color="C0", alpha=0.08, label=f"steady window (MSER-5) from {tw:.2f} s")
    ax[0].axhline(I["fsicrModel"], color="k", ls="--", lw=1, label="FSICR rule formula (1:100)")
    # The start (the impulsive start of the flow, the first impacts) reaches
    # far beyond the steady level: scale to the steady window
    inwin = [v for tt, v in zip(t, cols["Rtotal"]) if tt >= tw] + \
        [v for tt, v in zip(t, cols["Rice"]) if tt >= tw] + [I["fsicrModel"], ow["Rtotal"][0]]
    lo, hi = min(inwin), max(inwin)
    ax[0].set_ylim(min(0, lo) - 0.1 * (hi - lo), hi + 0.3 * (hi - lo))
    ax[0].set_xlabel("time [s]")
    ax[0].set_ylabel("force along the flow [N]")
    ax[0].set_title(f"Dummy hull in brash ice, U = {I['speed']:g} m/s, {I['blocks']:.0f} blocks")
    ax[0].legend(fontsize=7, loc="upper left")
    names = ["open water", "total", "ice load", "fluid", "ice resistance\n(total - open water)",
             "FSICR\nrule formula"]
    vals = [ow["Rtotal"], m["Rtotal"], m["Rice"], m["Rfluid"], m["RiceNet"], (I["fsicrModel"], 0)]
    ax[1].bar(range(len(vals)), [v[0] for v in vals], yerr=[2 * v[1] for v in vals], capsize=3,
              color=["0.6", "C0", "C3", "C2", "C1", "k"])
    ax[1].set_xticks(range(len(vals)))
    ax[1].set_xticklabels(names, fontsize=7)
    ax[1].set_ylabel("steady mean [N] (bars: 2 standard errors)")
    fig.tight_layout()
    fig.savefig("resistance.png", dpi=110)
    plt.close(fig)

    # Plan view at the last written time: the free-surface elevation and
    # the blocks, each against its free-floating (Archimedes) height at the
    # local surface, z_s - r t + t/2 (pushed down by the hull: negative)
    last = demState.times("ice")[-1]
    st = demState.read_state(os.path.join("ice", last[1], "polyDEM", "state"))
    zs, h = surface_map("ice", last[1], I)
    zw, t_i, r = I["waterLevel"], I["iceThickness"], 920.0 / I["rhoWater"]
    blocks = []
    for p in st["particles"]:
        i = min(len(zs) - 1, max(0, int((p["px"] - I["xmin"]) / h)))
        j = min(len(zs[0]) - 1, max(0, int((p["py"] - I["ymin"]) / h)))
        z_local = zs[i][j] if zs[i][j] is not None else zw
        blocks.append((p["px"], p["py"], p["pz"], z_local, p["pz"] - (z_local - r * t_i + 0.5 * t_i)))
    with open("postProcessing/iceHeights.dat", "w") as o:
        o.write(f"# t = {last[0]:g} s; z_s: free surface over the block's mesh column; "
                "dz: centre - (z_s - r t + t/2)\n# x y z z_s dz\n")
        for b in blocks:
            o.write(" ".join(f"{v:.6g}" for v in b) + "\n")
    with open("postProcessing/surface.dat", "w") as o:
        o.write(f"# t = {last[0]:g} s; free-surface elevation z_s - z_w [m] per mesh column "
                f"(x, y of its centre; hull columns left out)\n# x y elevation\n")
        for i, col in enumerate(zs):
            for j, z in enumerate(col):
                if z is not None:
                    o.write(f"{I['xmin'] + (i + 0.5) * h:.6g} {I['ymin'] + (j + 0.5) * h:.6g} "
                            f"{z - zw:.6g}\n")
    if blocks:
        dz = [b[4] for b in blocks]
        el = [b[3] - zw for b in blocks]
        print(f"iceField: at t = {last[0]:g} s the surface over the blocks is {sum(el)/len(el):+.4f} m "
              f"(mean; {min(el):+.4f} .. {max(el):+.4f}) from the still level; the blocks sit "
              f"{sum(dz)/len(dz):+.4f} m (mean; {min(dz):+.4f} .. {max(dz):+.4f}) from their floating "
              "height at that local surface")
    ny, nx = len(zs[0]), len(zs)
    import numpy as np
    E = np.array([[np.nan if zs[i][j] is None else zs[i][j] - zw for i in range(nx)]
                  for j in range(ny)])
    ext = max(0.01, float(np.nanmax(np.abs(E))))
    fig, ax = plt.subplots(2, 1, figsize=(12, 2 * (12 * (I["ymax"] - I["ymin"]) /
                                                   (I["xmax"] - I["xmin"]) + 1.2)))
    pc = ax[0].pcolormesh(np.linspace(I["xmin"], I["xmax"], nx + 1),
                          np.linspace(I["ymin"], I["ymax"], ny + 1),
                          E, cmap="RdBu_r", vmin=-ext, vmax=ext, shading="flat")
    fig.colorbar(pc, ax=ax[0], label="free surface - still level [m]", shrink=0.8)
    ax[0].scatter([b[0] for b in blocks], [b[1] for b in blocks], s=30, marker="s",
                  facecolors="none", edgecolors="k", lw=0.8)
    ax[0].set_title(f"Free-surface elevation at t = {last[0]:g} s (mesh columns; the blocks' "
                    "centres as squares)")
    sc = ax[1].scatter([b[0] for b in blocks], [b[1] for b in blocks], c=[b[4] for b in blocks],
                       s=40, marker="s", cmap="coolwarm_r", vmin=-0.5 * t_i, vmax=0.5 * t_i)
    fig.colorbar(sc, ax=ax[1], label="centre - floating height\nat the local surface [m]",
                 shrink=0.8)
    ax[1].set_title(f"Ice at t = {last[0]:g} s ({len(blocks)} blocks; hull 1 cm below the "
                    "waterline in black)")
    # (just below the waterline: the STL has a vertex ring at the waterline)
    hull = waterline("ice/constant/triSurface/hull.stl", zw - 0.01)
    for a_ in ax:
        for (a, b) in hull:
            a_.plot([a[0], b[0]], [a[1], b[1]], color="k", lw=1.2)
        a_.set_xlim(I["xmin"], I["xmax"])
        a_.set_ylim(I["ymin"], I["ymax"])
        a_.set_aspect("equal")
        a_.set_ylabel("y [m]")
    ax[1].set_xlabel("x [m] (flow +x)")
    fig.tight_layout()
    fig.savefig("iceField.png", dpi=100)
    plt.close(fig)


def waterline(stl, z):
    """Segments of the STL's section by the plane at height z."""
    segs = []
    try:
        tri = []
        for l in open(stl):
            w = l.split()
            if w and w[0] == "vertex":
                tri.append(tuple(float(x) for x in w[1:4]))
                if len(tri) == 3:
                    pts = []
                    for i in range(3):
                        a, b = tri[i], tri[(i + 1) % 3]
                        if (a[2] - z) * (b[2] - z) < 0:
                            s = (z - a[2]) / (b[2] - a[2])
                            pts.append((a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])))
                    if len(pts) == 2:
                        segs.append(tuple(pts))
                    tri = []
    except OSError:
        return []
    return segs


sys.exit(main())
