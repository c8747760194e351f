#!/usr/bin/python3
"""CTest iceChannel.hullGenerator: iceHull writes a closed, outward-oriented STL
whose volume is the analytic volume of the hull it describes.

Checked independently of the generator (the STL is parsed here):
  * closed 2-manifold: every edge is used by exactly two triangles, once in
    each direction (consistent orientation);
  * outward: the signed volume (divergence theorem, sum of det(a, b, c)/6) is
    positive and every triangle normal of the flat deck points up (+z);
  * volume: the dummy hull (half-cylinder bow) against
        V = (L - R) B D + pi R^2 D / 2
    and a parametric bow against the volume integral of its surface
    (docs/brashIce.md), int g by scipy's adaptive quadrature to 1e-13, k from
    the waterline angle alpha at B/4 found here by brentq on |dx/dy| = cot alpha
    with g' differentiated by hand.
    Tolerance: the polygonal waterline (n chords of a smooth curve) loses
    O(n^-2) of the area: at 192 bow points the relative error must be below
    2e-4, and halving the points must raise it by 3x-5x (second order):
    a wrong formula or a missing face cannot pass both.
"""
import math
import os
import subprocess
import sys
import tempfile
from collections import Counter

from scipy.integrate import quad
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "..", "applications", "utilities", "brashIceChannel", "iceHull")


def read_stl(path):
    tris, cur = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "vertex":
                cur.append(tuple(float(x) for x in w[1:4]))
                if len(cur) == 3:
                    tris.append(tuple(cur))
                    cur = []
    return tris


def check_closed(tris):
    key = lambda p: tuple(round(x, 10) for x in p)
    directed = Counter()
    for t in tris:
        for i in range(3):
            directed[(key(t[i]), key(t[(i + 1) % 3]))] += 1
    bad = [e for e, c in directed.items() if c != 1 or directed.get((e[1], e[0]), 0) != 1]
    return len(bad)


def signed_volume(tris):
    v = 0.0
    for a, b, c in tris:
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
              + a[2] * (b[0] * c[1] - b[1] * c[0]))
    return v / 6


def deck_normals_up(tris, zdeck):
    ok = True
    for a, b, c in tris:
        if all(abs(p[2] - zdeck) < 1e-9 for p in (a, b, c)):
            nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            ok &= nz > 0
    return ok


def run(case, hull, bow_points, placement=""):
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    with open(os.path.join(case, "system", "iceHullDict"), "w") as f:
        f.write(f"hull {{ {hull} }}\nresolution {{ bowPoints {bow_points}; levels 6; }}\n"
                f"{placement}\n")
    subprocess.run([TOOL, "-case", case], check=True, stdout=subprocess.DEVNULL)
    return read_stl(os.path.join(case, "constant", "triSurface", "hull.stl"))


def main():
    fails = []
    tmp = tempfile.mkdtemp(prefix="iceHull", dir=os.environ.get("HEDRA_TEST_TMP"))
    # 1. the seed report's dummy hull: D = 0.2 (R = 0.1), L = 1.2, depth 0.5
    R, L, D = 0.1, 1.2, 0.5
    V_dummy = (L - R) * 2 * R * D + math.pi * R * R * D / 2
    # 2. a parametric ice-going bow (full scale): m from cot(alpha) = 2 Lbow/B f(m)
    Lp, B, T, Dp, Lpar, Lbow, phi1, phi2, alpha = 150.0, 24.0, 9.0, 14.0, 70.0, 40.0, 30.0, 45.0, 22.0
    # waterline x = Lbow g(eta), y = eta B/2, g = sqrt((1-eta)(1+k eta));
    # dg/deta = (k - 1 - 2 k eta) / (2 g); at B/4 (eta = 1/2) |dx/dy| = cot(alpha)
    g = lambda e, k: math.sqrt((1 - e) * (1 + k * e))
    slope = lambda k: Lbow * abs((k - 1 - k) / (2 * g(0.5, k))) / (B / 2)
    k = brentq(lambda k: slope(k) - 1 / math.tan(math.radians(alpha)), -0.999, 1.0, xtol=1e-15)
    cot1, cot2 = 1 / math.tan(math.radians(phi1)), 1 / math.tan(math.radians(phi2))
    # eta = 1 - u^2 takes the square-root end point out: g deta = 2 u^2 sqrt(1 + k - k u^2) du
    Ig = quad(lambda u: 2 * u * u * math.sqrt(1 + k - k * u * u), 0, 1, epsabs=1e-13, epsrel=1e-12)[0]
    # c(eta): cubic with c(0) = cot1, c(1/2) = cot2, c(1) = 0, c'(0) = 0 -> its mean
    cmean = quad(lambda e: cot1 + (8 * cot2 - 7 * cot1) * e * e + (6 * cot1 - 8 * cot2) * e ** 3, 0, 1)[0]
    V_param = (Dp * (Lp - Lpar - Lbow) * B + Dp * Lpar * B
               + B * (Dp * Lbow * Ig + (Dp ** 2 / 2 - T * Dp) * cmean))
    param = (f"type parametric; length {Lp}; beam {B}; draft {T}; depth {Dp}; "
             f"parallelMidbodyLength {Lpar}; bowLength {Lbow}; stemAngle {phi1}; "
             f"bowAngle {phi2}; waterlineAngle {alpha};")
    cases = [("dummy", "type dummy;", V_dummy, D,
              "placement { stem (3 0 2.5); bowDirection -x; }", 2.5 + D / 2),
             ("parametric", param, V_param, Dp, "", Dp)]
    for name, hull, V, depth, place, zdeck in cases:
        errs = []
        for n in (96, 192):
            tris = run(os.path.join(tmp, f"{name}{n}"), hull, n, place)
            nbad = check_closed(tris)
            vol = signed_volume(tris)
            err = abs(vol - V) / V
            errs.append(err)
            print(f"{name:10s} bowPoints {n:4d}: {len(tris)} triangles, {nbad} bad edges, "
                  f"volume {vol:.8g} (analytic {V:.8g}), rel. error {err:.3e}, "
                  f"deck normals up {deck_normals_up(tris, zdeck)}")
            if nbad:
                fails.append(f"{name}: {nbad} edges not shared by two opposite triangles")
            if vol <= 0:
                fails.append(f"{name}: inward orientation (signed volume {vol})")
            if not deck_normals_up(tris, zdeck):
                fails.append(f"{name}: a deck triangle points down")
        if errs[1] > 2e-4:
            fails.append(f"{name}: volume error {errs[1]:.3e} > 2e-4")
        ratio = errs[0] / errs[1]
        print(f"{name:10s} error ratio 96 -> 192 points: {ratio:.3f} (second order: 4)")
        if not 3.0 <= ratio <= 5.0:
            fails.append(f"{name}: error ratio {ratio:.3f} not second order (3..5)")
    for f_ in fails:
        print("FAIL:", f_)
    print("hullGenerator:", "FAILED" if fails else "passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
