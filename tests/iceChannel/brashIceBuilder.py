#!/usr/bin/python3
"""CTest iceChannel.brashIceBuilder: brashIceChannel's channel against its input.

Everything is checked from what the tool WROTE (constant/brashIce/insertion,
particleTypes, the block STLs), rebuilt here independently of the builder:
world vertices = position + R(orientation) x body vertices, R = Rz(c) Ry(b)
Rx(a) (docs/demProperties.md), body vertices of `box` = the engine's sorted
box, of `stl` = the file's points.

Case A: cuboids, log-normal sizes in 6 classes, one layer (H = t = 0.1 m),
        porosity 0.5, 3 m x 2 m.
Case B: random convex plates (3 shapes per class), a table of sizes with
        frequencies, block thickness 0.05 m in a profile 0.1 m at the
        centreline to 0.2 m at the edges (stacked blocks), porosity 0.6.
Case C: as A with `packing lattice` (rows, headings within +-5 deg) at
        porosity 0.3, which random addition cannot reach.
Case D: as A with `shape { type sphere; }` at porosity 0.8: each block as
        the sphere of its volume. Checked: (1) no two spheres closer than
        the sum of their radii (centre distances), all inside the channel in
        plan; (2) porosity by volume as in 2 below; (3) each sphere's
        submerged cap pi h^2 (3R - h)/3 (h = z_w - bottom) equal to
        (rho_i/rho_w) of its volume to 1e-9 relative; (4) the diameters:
        pi d^3/6 = D_k^2 t with D_k the class sizes of 5 below (F(D_k) =
        (k + 1/2)/N to 1e-7); (5) the same spheres with a thickness profile
        are refused naming the entry 'shape'.
Checks and tolerances:
  1. no two blocks intersect: for every pair closer than the sum of their
     bounding radii, the LP  max s  s.t.  A1 x <= b1 - s, A2 x <= b2 - s  (the
     two hulls' face planes, scipy ConvexHull + linprog) must give s <= 1e-9 m
     (s > 0 is a point inside both by s); all vertices inside the channel.
  2. porosity: n = 1 - sum V / (L int H dy) within one largest block volume
     of the target: |n - n_target| <= V_max / V_layer (blocks are whole).
  3. draft: case A every block's bottom at z_w - (rho_i/rho_w) t and top at
     z_w + (1 - rho_i/rho_w) t to 1e-9 m (its own Archimedes balance);
     case B the layer's: sum over blocks of plan area x submerged depth
     = (rho_i/rho_w) sum V to 1e-9 relative.
  4. thickness: case A top - bottom = 0.1 m for every block; case B every
     block lies inside the local slab of H(y) (shifted by the layer's draft
     correction dz read from the summary, |dz| <= t) at every vertex; the
     achieved thickness (top - bottom) in 10 bins across lies between
     H - 2t (at most two missing layers) and the largest H under the bin's blocks.
  5. size distribution: class sizes are the medians of equal-probability
     classes of the truncated log-normal (scipy.stats, independent CDF):
     F(D_k) = (k + 1/2)/N to 1e-7 (D_k read back from the hull volumes); class counts against the class
     probabilities (case A: 1/N; case B: the table's) by a chi-square test at
     p = 0.001 (chi2.sf > 0.001); and a one-sample Kolmogorov-Smirnov distance
     of the sizes against the continuous log-normal below 1.63/sqrt(n) + 1/(2N)
     (p = 0.01 critical value plus the largest CDF step of the classes).
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from scipy import stats
from scipy.optimize import linprog
from scipy.spatial import ConvexHull

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "..", "applications", "utilities", "brashIceChannel",
                    "brashIceChannel")
RHO_I, RHO_W, ZW = 920.0, 1010.0, 2.5
R = RHO_I / RHO_W

CASE_A = """
channel { origin (0 -1); length 3; width 2; waterLevel 2.5; }
thickness { type uniform; value 0.1; }
blockThickness 0.1;
sizeDistribution { type logNormal; median 0.1; sigma 0.3; min 0.05; max 0.2; }
sizeClasses 6;
shape { type cuboid; aspectRatio 0.8; }
porosity 0.5;
seed 3;
iceDensity 920;
waterDensity 1010;
"""
CASE_C = """
channel { origin (0 -1); length 3; width 2; waterLevel 2.5; }
thickness { type uniform; value 0.1; }
blockThickness 0.1;
sizeDistribution { type logNormal; median 0.1; sigma 0.3; min 0.05; max 0.2; }
sizeClasses 6;
shape { type cuboid; aspectRatio 0.8; }
packing lattice;
yawSpread 5;
porosity 0.3;
seed 4;
iceDensity 920;
waterDensity 1010;
"""
CASE_B = """
channel { origin (1 -0.75); length 2; width 1.5; waterLevel 2.5; }
thickness { type profile; points ((0 0.1) (0.5 0.1) (1 0.2)); }
blockThickness 0.05;
sizeDistribution { type table; sizes ((0.08 0.3) (0.12 0.5) (0.18 0.2)); }
shape { type plate; corners 7; elongation 0.7; shapes 3; }
porosity 0.6;
seed 5;
iceDensity 920;
waterDensity 1010;
"""


def rot(e):
    a, b, c = np.radians(e)
    Rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    Ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
    Rz = np.array([[np.cos(c), -np.sin(c), 0], [np.sin(c), np.cos(c), 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def body_vertices(case, geo):
    m = re.search(r"type box; size \(([^)]*)\)", geo)
    if m:
        s = sorted((float(x) for x in m.group(1).split()), reverse=True)  # engine: x longest
        return np.array([[sx * s[0] / 2, sy * s[1] / 2, sz * s[2] / 2]
                         for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    f = re.search(r'type stl; file "([^"]+)"', geo).group(1)
    pts = []
    with open(os.path.join(case, "constant", "triSurface", f)) as fh:
        for line in fh:
            w = line.split()
            if w and w[0] == "vertex":
                pts.append([float(x) for x in w[1:4]])
    P = np.unique(np.round(np.array(pts), 14), axis=0)
    return P  # the file is in the body frame (centroid at the origin)


def insertion_lists(case):
    """(particle type, text) of each list the tool wrote to brashIce/insertion."""
    with open(os.path.join(case, "constant", "brashIce", "insertion")) as f:
        txt = f.read()
    return [(re.search(r"particleType\s+(\w+);", body).group(1), body)
            for name, body in re.findall(r"\n(\w+)\n\{(.*?)\n\}", txt, re.S)
            if name != "FoamFile"]


def read_case(case):
    with open(os.path.join(case, "constant", "brashIce", "particleTypes")) as f:
        types = dict(re.findall(r"\n(\w+)\n\{[^{}]*geometry\s*\{ ([^}]*) \}", f.read()))
    blocks = []
    for ptype, body in insertion_lists(case):
        V = body_vertices(case, types[ptype])
        for pos, ori in re.findall(r"position \(([^)]*)\); orientation \(([^)]*)\);", body):
            p = np.array([float(x) for x in pos.split()])
            Rm = rot([float(x) for x in ori.split()])
            W = p + V @ Rm.T
            blocks.append(dict(type=ptype, pos=p, W=W, hull=ConvexHull(W),
                               r=np.max(np.linalg.norm(W - p, axis=1))))
    summ = {}
    with open(os.path.join(case, "postProcessing", "brashIceChannel", "summary.dat")) as f:
        for line in f:
            k, v = line.split()
            summ[k] = float(v)
    return blocks, summ


def max_depth(h1, h2):
    """Largest s with a point at distance >= s inside both hulls (s <= 0: disjoint)."""
    A = np.vstack([h1.equations[:, :3], h2.equations[:, :3]])
    b = -np.concatenate([h1.equations[:, 3], h2.equations[:, 3]])
    # unit normals (ConvexHull equations are normalised): A x + s <= b
    Aub = np.hstack([A, np.ones((A.shape[0], 1))])
    res = linprog([0, 0, 0, -1], A_ub=Aub, b_ub=b, bounds=[(None, None)] * 3 + [(None, 1)],
                  method="highs")
    return -res.fun if res.status == 0 else -1.0


def volume_plan(b):
    h = b["hull"]
    zspan = b["W"][:, 2].max() - b["W"][:, 2].min()
    return h.volume, h.volume / zspan


def run(text, fails, tag, hprofile, t, distr_check):
    case = tempfile.mkdtemp(prefix="brashIce" + tag, dir=os.environ.get("HEDRA_TEST_TMP"))
    os.makedirs(os.path.join(case, "system"))
    with open(os.path.join(case, "system", "brashIceChannelDict"), "w") as f:
        f.write(text)
    subprocess.run([TOOL, "-case", case], check=True)
    blocks, summ = read_case(case)
    n = len(blocks)
    print(f"[{tag}] {n} blocks read back from {case}")
    # 1. overlaps (independent LP) and inside the channel
    m = re.search(r"origin \(([^)]*)\); length (\S+); width (\S+);", text)
    x0, y0 = (float(v) for v in m.group(1).split())
    L, Wd = float(m.group(2)), float(m.group(3).rstrip(";"))
    pos = np.array([b["pos"] for b in blocks])
    worst, pairs = -1.0, 0
    for i in range(n):
        d = np.linalg.norm(pos[i + 1:] - pos[i], axis=1)
        for j in np.nonzero(d < np.array([blocks[i]["r"] + blocks[k]["r"]
                                          for k in range(i + 1, n)]))[0] + i + 1:
            pairs += 1
            worst = max(worst, max_depth(blocks[i]["hull"], blocks[j]["hull"]))
    allW = np.vstack([b["W"] for b in blocks])
    inside = (allW[:, 0].min() >= x0 - 1e-9 and allW[:, 0].max() <= x0 + L + 1e-9
              and allW[:, 1].min() >= y0 - 1e-9 and allW[:, 1].max() <= y0 + Wd + 1e-9)
    print(f"[{tag}] overlap: {pairs} close pairs, deepest common point {worst:.3e} m "
          f"(must be <= 1e-9); inside the channel: {inside}")
    if worst > 1e-9:
        fails.append(f"{tag}: blocks intersect by {worst:.3e} m")
    if not inside:
        fails.append(f"{tag}: a block reaches outside the channel")
    # 2. porosity
    vols = np.array([volume_plan(b)[0] for b in blocks])
    areas = np.array([volume_plan(b)[1] for b in blocks])
    eta = np.linspace(0, 1, 200001)
    Hint = np.trapz([hprofile(e) for e in eta], eta) * Wd  # int H dy
    Vl = L * Hint
    por = 1 - vols.sum() / Vl
    target = float(re.search(r"porosity (\S+);", text).group(1))
    tol = vols.max() / Vl
    print(f"[{tag}] porosity {por:.5f} target {target} tolerance {tol:.5f} "
          f"(tool says {summ['porosity']:.5f}, {int(summ['notPlaced'])} not placed)")
    if abs(por - target) > tol:
        fails.append(f"{tag}: porosity {por:.5f} against {target} (tolerance {tol:.5f})")
    # 3. + 4. draft and thickness
    zb = np.array([b["W"][:, 2].min() for b in blocks])
    zt = np.array([b["W"][:, 2].max() for b in blocks])
    sub = np.clip(ZW - zb, 0, zt - zb)
    bal = (areas * sub).sum() / (R * vols.sum()) - 1
    print(f"[{tag}] layer buoyancy/weight - 1 = {bal:.2e} (tolerance 1e-9)")
    if abs(bal) > 1e-9:
        fails.append(f"{tag}: submerged ice volume / (r V) - 1 = {bal:.3e}")
    if hprofile(0) == hprofile(1) == t:
        e1 = np.max(np.abs(zb - (ZW - R * t)))
        e2 = np.max(np.abs(zt - (ZW + (1 - R) * t)))
        print(f"[{tag}] one layer: bottom - (z_w - r t) max {e1:.2e} m, "
              f"top - (z_w + (1-r) t) max {e2:.2e} m; draft r t = {R * t:.6f} m")
        if max(e1, e2) > 1e-9:
            fails.append(f"{tag}: a block is not at its hydrostatic draft ({max(e1, e2):.3e} m)")
    else:
        dz = summ["layerShift"]
        yc = y0 + Wd / 2
        worst_s = 0.0
        for b in blocks:
            for v in b["W"]:
                H = hprofile(abs(v[1] - yc) / (Wd / 2))
                lo, hi = ZW - R * H + dz, ZW + (1 - R) * H + dz
                worst_s = max(worst_s, lo - v[2], v[2] - hi)
        print(f"[{tag}] layer shift dz {dz:.4e} m; worst vertex outside the local slab "
              f"{worst_s:.2e} m (tolerance 1e-9)")
        if worst_s > 1e-9 or abs(dz) > t:
            fails.append(f"{tag}: a block outside its slab by {worst_s:.3e} m (dz {dz})")
        # thickness reached: in 10 bins across, top - bottom of the blocks
        edges = np.linspace(y0, y0 + Wd, 11)
        for k in range(10):
            sel = (pos[:, 1] >= edges[k]) & (pos[:, 1] < edges[k + 1])
            if sel.any():
                yc_ = 0.5 * (edges[k] + edges[k + 1])
                Hin = hprofile(abs(yc_ - yc) / (Wd / 2))
                Ha = zt[sel].max() - zb[sel].min()
                print(f"[{tag}]   y {yc_ - yc:+.3f}: H input {Hin:.3f} achieved {Ha:.3f}")
                # upper bound: the largest H under any block of the bin (centre in
                # the bin, reaching out by at most the largest bounding radius)
                rmax = max(b["r"] for b in blocks)
                ys = np.linspace(edges[k] - rmax, edges[k + 1] + rmax, 201)
                Hup = max(hprofile(min(1.0, abs(y - yc) / (Wd / 2))) for y in ys)
                if not (Hin - 2 * t - 1e-9 <= Ha <= Hup + 1e-9):
                    fails.append(f"{tag}: thickness {Ha:.3f} at y {yc_ - yc:+.3f} against {Hin:.3f}")
    # 5. size distribution
    D = np.sqrt(areas)
    distr_check(D, n, fails, tag)
    return blocks


def check_lognormal(D, n, fails, tag):
    N = 6
    lo, hi, med, sig = 0.05, 0.2, 0.1, 0.3
    dist = stats.lognorm(s=sig, scale=med)
    F = lambda x: (dist.cdf(x) - dist.cdf(lo)) / (dist.cdf(hi) - dist.cdf(lo))
    classes = np.unique(np.round(D, 7))
    classes = np.array([D[np.abs(D - c) < 1e-6].mean() for c in classes])
    Fk = F(classes)
    want = (np.arange(N) + 0.5) / N
    print(f"[{tag}] class sizes {np.round(classes, 5)}; F(D_k) {np.round(Fk, 9)}")
    if len(classes) != N or np.max(np.abs(Fk - want)) > 1e-7:
        fails.append(f"{tag}: class sizes are not the medians of equal-probability classes")
    counts = np.array([np.sum(np.abs(D - c) < 1e-7) for c in classes])
    chi = stats.chisquare(counts, np.full(N, n / N))
    print(f"[{tag}] class counts {counts}, chi-square p = {chi.pvalue:.3f} (> 0.001)")
    if chi.pvalue < 1e-3:
        fails.append(f"{tag}: class counts fail the chi-square test (p {chi.pvalue:.2e})")
    ks = stats.kstest(D, F).statistic
    crit = 1.63 / math.sqrt(n) + 1 / (2 * N)
    print(f"[{tag}] KS distance to the continuous log-normal {ks:.4f} (< {crit:.4f})")
    if ks > crit:
        fails.append(f"{tag}: KS distance {ks:.4f} > {crit:.4f}")


def check_table(D, n, fails, tag):
    sizes, freq = np.array([0.08, 0.12, 0.18]), np.array([0.3, 0.5, 0.2])
    counts = np.array([np.sum(np.abs(D - s) < 1e-7) for s in sizes])
    chi = stats.chisquare(counts, freq * n)
    print(f"[{tag}] table counts {counts} of {n} (expected {np.round(freq * n, 1)}), "
          f"chi-square p = {chi.pvalue:.3f} (> 0.001)")
    if counts.sum() != n:
        fails.append(f"{tag}: a block size is not in the table")
    if chi.pvalue < 1e-3:
        fails.append(f"{tag}: table counts fail the chi-square test (p {chi.pvalue:.2e})")


CASE_D = CASE_A.replace("shape { type cuboid; aspectRatio 0.8; }", "shape { type sphere; }") \
    .replace("porosity 0.5;", "porosity 0.8;")


def run_spheres(fails, tag="D"):
    case = tempfile.mkdtemp(prefix="brashIce" + tag, dir=os.environ.get("HEDRA_TEST_TMP"))
    os.makedirs(os.path.join(case, "system"))
    with open(os.path.join(case, "system", "brashIceChannelDict"), "w") as f:
        f.write(CASE_D)
    subprocess.run([TOOL, "-case", case], check=True)
    with open(os.path.join(case, "constant", "brashIce", "particleTypes")) as f:
        diam = {n: float(d) for n, d in
                re.findall(r"\n(\w+)\n\{\s*shape\s+sphere;[^{}]*?diameter\s+(\S+);", f.read())}
    spheres = []
    for ptype, body in insertion_lists(case):
        d = diam[ptype]
        for pos in re.findall(r"\{ position \(([^)]*)\); \}", body):
            spheres.append((np.array([float(x) for x in pos.split()]), 0.5 * d))
    n = len(spheres)
    print(f"[{tag}] {n} spheres read back from {case}, diameters {sorted(round(2 * r, 5) for r in set(r for _, r in spheres))}")
    if n == 0 or len(diam) == 0:
        fails.append(f"{tag}: no spheres written")
        return
    # 1. no overlap, inside the channel
    P = np.array([p for p, _ in spheres])
    R_ = np.array([r for _, r in spheres])
    worst = -np.inf
    for i in range(n):
        dist = np.linalg.norm(P[i + 1:] - P[i], axis=1) - (R_[i + 1:] + R_[i])
        if dist.size:
            worst = max(worst, -dist.min())
    inside = (np.all(P[:, 0] - R_ >= -1e-9) and np.all(P[:, 0] + R_ <= 3 + 1e-9)
              and np.all(P[:, 1] - R_ >= -1 - 1e-9) and np.all(P[:, 1] + R_ <= 1 + 1e-9))
    print(f"[{tag}] deepest sphere overlap {worst:.3e} m (must be <= 0); inside: {inside}")
    if worst > 0:
        fails.append(f"{tag}: spheres overlap by {worst:.3e} m")
    if not inside:
        fails.append(f"{tag}: a sphere reaches outside the channel")
    # 2. porosity by volume
    V = 4 / 3 * np.pi * R_ ** 3
    Vl = 3 * 2 * 0.1
    por = 1 - V.sum() / Vl
    tol = V.max() / Vl
    print(f"[{tag}] porosity {por:.5f} target 0.8 tolerance {tol:.5f}")
    if abs(por - 0.8) > tol:
        fails.append(f"{tag}: porosity {por:.5f} against 0.8 (tolerance {tol:.5f})")
    # 3. each sphere at its own draft
    h = ZW - (P[:, 2] - R_)
    cap = np.pi * h * h * (3 * R_ - h) / 3
    err = np.max(np.abs(cap / (R * V) - 1))
    print(f"[{tag}] submerged cap / (r V) - 1: max {err:.2e} (tolerance 1e-9)")
    if err > 1e-9:
        fails.append(f"{tag}: a sphere is not at its own draft ({err:.3e})")
    # 4. the diameters are the volumes of the class blocks (log-normal medians)
    N, t = 6, 0.1
    dist = stats.lognorm(s=0.3, scale=0.1)
    F = lambda x: (dist.cdf(x) - dist.cdf(0.05)) / (dist.cdf(0.2) - dist.cdf(0.05))
    D = np.sort([np.sqrt(np.pi * d ** 3 / 6 / t) for d in diam.values()])
    Fk = F(D)
    want = (np.arange(N) + 0.5) / N
    print(f"[{tag}] block sizes of the sphere volumes {np.round(D, 5)}; F(D_k) {np.round(Fk, 9)}")
    if len(D) != N or np.max(np.abs(Fk - want)) > 1e-7:
        fails.append(f"{tag}: sphere volumes are not the class blocks' volumes")
    # 5. spheres float in one layer: a thickness profile is refused
    bad = CASE_D.replace("thickness { type uniform; value 0.1; }",
                         "thickness { type profile; points ((0 0.1) (1 0.2)); }")
    with open(os.path.join(case, "system", "brashIceChannelDict"), "w") as f:
        f.write(bad)
    r = subprocess.run([TOOL, "-case", case], capture_output=True, text=True)
    msg = r.stdout + r.stderr
    ok = r.returncode != 0 and "shape" in msg and "brashIceChannelDict" in msg
    print(f"[{tag}] spheres with a thickness profile: exit {r.returncode}, "
          f"names the file and 'shape': {ok}")
    if not ok:
        fails.append(f"{tag}: spheres with a thickness profile not refused clearly: {msg[-300:]}")


def main():
    fails = []
    which = sys.argv[1:] or ["A", "B", "C", "D"]
    if "A" in which:
        run(CASE_A, fails, "A", lambda e: 0.1, 0.1, check_lognormal)
    if "C" in which:
        run(CASE_C, fails, "C", lambda e: 0.1, 0.1, check_lognormal)
    if "B" in which:
        prof = lambda e: float(np.interp(e, [0, 0.5, 1], [0.1, 0.1, 0.2]))
        run(CASE_B, fails, "B", prof, 0.05, check_table)
    if "D" in which:
        run_spheres(fails)
    for f_ in fails:
        print("FAIL:", f_)
    print("brashIceBuilder:", "FAILED" if fails else "passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
