#!/usr/bin/env python3
"""Drafts of the floating blocks against Archimedes (floatingBlocks tutorial).

Usage: draft.py CASE [-check TOL]

Reads CASE/blocks.dat (makeCase.py: tank, level, each block's size and
density), the DEM state of every write time (CASE/<t>/polyDEM/state:
position and orientation quaternion of each block) and the water volume
W = int eps alpha dV (CASE/postProcessing/demInterFoam/0/waterVolume.dat).

At each write time:
  - every block is its box (edges a, b, c along body x, y, z) placed by its
    position and quaternion; its submerged volume below a horizontal plane
    z = h is the box clipped by the plane (exact, any orientation);
  - the free-surface level h is the mean level that holds the water: the
    fluid below h, A h - sum_i V_sub,i(h), equals W (A the tank's area;
    solved by bisection);
  - f_i = V_sub,i(h) / V_i against Archimedes f_A,i = (rho_b - rho_a) /
    (rho_w - rho_a);
  - the draft error delta_i: the distance the block would have to move
    down (delta > 0: it floats too high) for V_sub,i(h + delta) = f_A,i V_i,
    given as delta_i / H_i, H_i the block's vertical extent (for a level
    box, delta/H = f_A - f).
Writes CASE/postProcessing/draft/draft.dat (plain columns, one row per
write time: t h, then per block f f_A delta/H z_centre tilt[deg]) and
CASE/postProcessing/draft/draft.png (gnuplot).

At rest: the mean over the last quarter of the run of each block's f and
delta/H, and the spread (max - min) of delta/H over that window, which
says whether the block is at rest there. -check TOL: exit 1 unless every
block's |mean delta/H| <= TOL (the issue's 3 % of H: -check 0.03).
"""
import glob
import math
import os
import subprocess
import sys


def read_blocks(case):
    blocks, info = [], {}
    with open(os.path.join(case, "blocks.dat")) as f:
        for line in f:
            v = line.split()
            if not v or v[0].startswith("#"):
                continue
            if v[0] in ("tank", "level", "dx", "rho"):
                info[v[0]] = [float(x) for x in v[1:]]
            else:
                blocks.append(dict(id=int(v[0]), name=v[1], size=[float(x) for x in v[2:5]],
                                   rho=float(v[5])))
    return info, blocks


def read_state(path):
    """{id: (position, quaternion w x y z)} of a polyDEM ascii state."""
    with open(path) as f:
        lines = f.read().split("\n")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    i = lines.index("data")
    out = {}
    for l in lines[i + 1:i + 1 + n]:
        v = l.split()
        out[int(v[0])] = ([float(x) for x in v[7:10]], [float(x) for x in v[10:14]])
    return out


def rotation(q):
    w, x, y, z = q
    s = 1.0 / (w * w + x * x + y * y + z * z)
    return [[1 - 2 * s * (y * y + z * z), 2 * s * (x * y - w * z), 2 * s * (x * z + w * y)],
            [2 * s * (x * y + w * z), 1 - 2 * s * (x * x + z * z), 2 * s * (y * z - w * x)],
            [2 * s * (x * z - w * y), 2 * s * (y * z + w * x), 1 - 2 * s * (x * x + y * y)]]


def box_faces(size, pos, q):
    """The six faces of the box as lists of world points, each ordered
    counter-clockwise seen from outside."""
    R = rotation(q)
    def pt(s):
        b = [s[k] * size[k] / 2 for k in range(3)]
        return [pos[i] + sum(R[i][k] * b[k] for k in range(3)) for i in range(3)]
    faces = []
    for axis in range(3):
        for sign in (-1, 1):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            corners = []
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                s = [0, 0, 0]
                s[axis], s[u], s[v] = sign, a, b
                corners.append(pt(s))
            # (u, v, axis) is right-handed: this order faces +axis
            faces.append(corners if sign > 0 else corners[::-1])
    return faces


def clip_below(poly, h):
    """Part of a planar polygon with z <= h (Sutherland-Hodgman)."""
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        pin, qin = p[2] <= h, q[2] <= h
        if pin:
            out.append(p)
        if pin != qin:
            t = (h - p[2]) / (q[2] - p[2])
            out.append([p[k] + t * (q[k] - p[k]) for k in range(3)])
    return out


def submerged(faces, h):
    """Volume of the convex polyhedron below z = h: divergence theorem with
    the apex on the plane, so the cap (in the plane) adds nothing."""
    vol = 0.0
    # one apex for every face: the centre of the box projected on the plane
    n = sum(len(f) for f in faces)
    o = [sum(p[0] for f in faces for p in f) / n, sum(p[1] for f in faces for p in f) / n, h]
    for f in faces:
        c = clip_below(f, h)
        if len(c) < 3:
            continue
        a = [c[0][k] - o[k] for k in range(3)]
        for j in range(1, len(c) - 1):
            b = [c[j][k] - o[k] for k in range(3)]
            d = [c[j + 1][k] - o[k] for k in range(3)]
            vol += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
                    + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6.0
    return vol


def bisect(fun, lo, hi, n=200):
    flo = fun(lo)
    for _ in range(n):
        mid = 0.5 * (lo + hi)
        fm = fun(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
        if hi - lo < 1e-14:
            break
    return 0.5 * (lo + hi)


def water_volumes(case):
    rows = []
    for path in sorted(glob.glob(os.path.join(case, "postProcessing/demInterFoam/*/waterVolume.dat"))):
        with open(path) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    v = line.split()
                    rows.append((float(v[0]), float(v[1])))
    return sorted(rows)


def whole_periods(t, x):
    """Indices of the samples between the first and the last upward
    crossing of x through its mean in the window (a whole number of heave
    periods), and that number; all samples when there are fewer than two
    crossings."""
    m = sum(x) / len(x)
    for _ in range(2):
        up = [j for j in range(1, len(x)) if x[j - 1] < m <= x[j]]
        if len(up) < 2:
            return list(range(len(x))), 0
        sel = list(range(up[0], up[-1]))
        m = sum(x[j] for j in sel) / len(sel)
    return sel, len(up) - 1


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    case = args[0]
    tol = float(args[args.index("-check") + 1]) if "-check" in args else None
    info, blocks = read_blocks(case)
    Lx, Ly, Lz = info["tank"]
    A = Lx * Ly
    rho_w, rho_a = info["rho"]
    water = water_volumes(case)
    if not water:
        sys.exit(f"draft.py: no {case}/postProcessing/demInterFoam/*/waterVolume.dat")

    def W_at(t):
        return min(water, key=lambda r: abs(r[0] - t))[1]

    times = []
    for d in glob.glob(os.path.join(case, "*", "polyDEM", "state")):
        name = d.split(os.sep)[-3]
        try:
            times.append((float(name), d))
        except ValueError:
            pass
    times.sort()
    rows = []
    for t, path in times:
        if t == 0:
            continue
        st = read_state(path)
        geo = []
        for b in blocks:
            pos, q = st[b["id"]]
            F = box_faces(b["size"], pos, q)
            zs = [p[2] for f in F for p in f]
            R = rotation(q)
            # tilt: angle of the body z axis (edge c) from the vertical
            tilt = math.degrees(math.acos(max(-1.0, min(1.0, abs(R[2][2])))))
            geo.append((F, min(zs), max(zs), pos[2], tilt))
        W = W_at(t)
        h = bisect(lambda h: A * h - sum(submerged(g[0], h) for g in geo) - W, 0.0, Lz)
        row = [t, h]
        for b, (F, zmin, zmax, zc, tilt) in zip(blocks, geo):
            V = b["size"][0] * b["size"][1] * b["size"][2]
            f = submerged(F, h) / V
            fA = (b["rho"] - rho_a) / (rho_w - rho_a)
            H = zmax - zmin
            # delta: V_sub(h + delta) = fA V, within the block's extent
            delta = bisect(lambda x: submerged(F, h + x) - fA * V, zmin - h, zmax - h)
            row += [f, fA, delta / H, zc, tilt]
        rows.append(row)
    out = os.path.join(case, "postProcessing/draft")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "draft.dat"), "w") as f:
        f.write("# floatingBlocks: level h from the water volume; per block: submerged fraction f,"
                " Archimedes f_A = (rho_b - rho_a)/(rho_w - rho_a), draft error delta/H"
                " (delta > 0: floats too high), centre z [m], tilt of edge c from vertical [deg]\n")
        f.write("# t h " + " ".join(f"f_{b['name']} fA_{b['name']} dH_{b['name']} z_{b['name']} tilt_{b['name']}"
                                   for b in blocks) + "\n")
        for r in rows:
            f.write(" ".join(f"{x:.9g}" for x in r) + "\n")

    tEnd = rows[-1][0]
    win = [r for r in rows if r[0] >= 0.75 * tEnd]
    print(f"floatingBlocks: {len(rows)} write times to t = {tEnd:g} s; at rest = mean over"
          f" t >= {win[0][0]:g} s ({len(win)} write times); level h {sum(r[1] for r in win)/len(win)*1e3:.2f} mm")
    print(f"  {'block':8s} {'rho':>5s} {'f_A':>7s} {'f':>7s} {'delta/H':>8s} {'spread':>7s} {'tilt':>6s} {'periods':>7s}")
    ok = True
    summary = []
    for i, b in enumerate(blocks):
        k = 2 + 5 * i
        fA = win[0][k + 1]
        # the heave goes on (waves in the tank): average over whole periods
        sel, periods = whole_periods([r[0] for r in win], [r[k + 2] for r in win])
        f = sum(win[j][k] for j in sel) / len(sel)
        dH = sum(win[j][k + 2] for j in sel) / len(sel)
        spread = max(r[k + 2] for r in win) - min(r[k + 2] for r in win)
        tilt = sum(r[k + 4] for r in win) / len(win)
        good = tol is None or abs(dH) <= tol
        ok = ok and good
        summary.append((b, f, fA, dH, spread, tilt, periods))
        mark = "" if tol is None else ("  PASS" if good else "  FAIL")
        print(f"  {b['name']:8s} {b['rho']:5g} {fA:7.4f} {f:7.4f} {100*dH:+7.2f}% {100*spread:6.2f}% {tilt:5.1f}d {periods:7d}{mark}")
    if tol is not None:
        print(f"{'PASS' if ok else 'FAIL'}: |mean delta/H| <= {100*tol:g} % of H for every block"
              f" (mean over the last quarter, t >= {win[0][0]:g} s)")
    with open(os.path.join(out, "rest.dat"), "w") as f:
        f.write(f"# at rest: mean over t >= {win[0][0]:g} s; spread = max - min of delta/H there\n")
        f.write("# block rho_b f_A f delta/H spread tilt[deg] heave periods averaged over\n")
        for b, fm, fA, dH, spread, tilt, periods in summary:
            f.write(f"{b['name']} {b['rho']:g} {fA:.6f} {fm:.6f} {dH:.6f} {spread:.6f} {tilt:.3f} {periods}\n")

    plot(out, blocks)
    sys.exit(0 if ok else 1)


def plot(out, blocks):
    p1 = ", ".join(f"'draft.dat' u 1:{3 + 5*i} w l lw 2 lc {i+1} t '{b['name']} f',"
                   f" '' u 1:{4 + 5*i} w l dt 2 lc {i+1} notitle"
                   for i, b in enumerate(blocks))
    p2 = ", ".join(f"'draft.dat' u 1:(100*${5 + 5*i}) w l lw 2 lc {i+1} t '{b['name']}'"
                   for i, b in enumerate(blocks))
    script = f"""set terminal pngcairo size 1000,800 noenhanced
set output 'draft.png'
set multiplot layout 2,1
set grid
set key outside right
set ylabel 'submerged fraction V_sub/V'
set title 'floatingBlocks (demInterFoam): submerged fraction (solid) vs Archimedes rho_b/rho_w (dashed)'
plot {p1}
set title 'draft error delta/H (delta > 0: floats too high); band: 3 % of H'
set xlabel 't [s]'
set ylabel 'delta / H [%]'
set yrange [-15:15]
plot 3 w l lc rgb 'gray' dt 3 notitle, -3 w l lc rgb 'gray' dt 3 notitle, {p2}
unset multiplot
"""
    try:
        subprocess.run(["gnuplot"], input=script, text=True, check=True, cwd=out,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"gnuplot failed ({e}): no PNG")


main()
