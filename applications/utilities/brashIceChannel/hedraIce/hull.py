"""iceHull: a parametric ice-going bow, or the seed report's dummy hull, as an STL.

Hull frame: x forward from the transom (x = 0), y to port, z up from the keel
(z = 0); waterline z = T, deck z = D (depth).  Vertical flat transom of beam
B_t, an aft body tapering linearly in plan from B to B_t over
L_aft = L - L_PAR - L_BOW, the parallel mid-body (vertical sides), and the bow.

Bow (xi = distance ahead of the end of the mid-body, eta = 2|y|/B):
    waterline  xi = L_BOW g(eta),  g = sqrt((1 - eta)(1 + k eta)),  -1 < k <= 1
               (tangent to the mid-body side at eta = 1; a finite entrance
               angle at the stem for k < 1; k = 1 is the ellipse, the dummy
               hull's half circle for L_BOW = B/2)
    section at height z:  xi(eta, z) = L_BOW g(eta) + (z - T) c(eta)
    c(eta)     cubic, c(0) = cot phi1, c(1/2) = cot phi2, c(1) = 0, c'(0) = 0
so the stem (eta = 0) is raked at phi1 from the waterline and the buttock at
B/4 (eta = 1/2) at phi2, as in the FSICR definitions (fsicr.py), and the bow
joins the vertical mid-body at eta = 1.  k follows from the waterline angle
alpha at B/4: |g'(1/2)| = 1/sqrt(2 + k), so cot alpha = (2 L_BOW / B) / sqrt(2 + k),
i.e. k = (2 L_BOW tan(alpha) / B)^2 - 2, which must lie in (-1, 1]:
B/(2 L_BOW) < tan alpha <= sqrt(3) B/(2 L_BOW).

Volume (the integral of that surface; int_0^1 c = (cot phi1 + 4 cot phi2)/6):
    V = D [ L_aft (B + B_t)/2 + L_PAR B ]
      + B [ D L_BOW Ig + (D^2/2 - T D) (cot phi1 + 4 cot phi2) / 6 ],
    Ig = int_0^1 g(eta) d eta  (Gauss-Legendre in _int_g); the bow waterplane
    area is A_wf = B L_BOW Ig (FSICR's A_wf).
"""
import math
import os

from .foamDict import Dict

HULL_TYPES = ["parametric", "dummy"]


def _int_g(k):
    """int_0^1 sqrt((1 - e)(1 + k e)) de.  With e = 1 - u^2 the integrand
    2 u^2 sqrt(1 + k - k u^2) is smooth on [0, 1] (1 + k - k u^2 >= min(1, 1+k) > 0):
    64-point Gauss-Legendre is exact to round-off."""
    import numpy as np
    x, w = np.polynomial.legendre.leggauss(64)
    u = 0.5 * (x + 1)
    return float(0.5 * np.sum(w * 2 * u * u * np.sqrt(1 + k - k * u * u)))


class Hull:
    def __init__(self, L, B, T, D, Lpar, Lbow, phi1, phi2, alpha, Bt=None, k=None,
                 err=None):
        err = err or (lambda key, msg: (_ for _ in ()).throw(ValueError(f"{key}: {msg}")))
        self.L, self.B, self.T, self.D = L, B, T, D
        self.Lpar, self.Lbow = Lpar, Lbow
        self.phi1, self.phi2, self.alpha = phi1, phi2, alpha
        self.Bt = B if Bt is None else Bt
        self.Laft = L - Lpar - Lbow
        if self.Laft < -1e-12 * L:
            err("length", f"length {L} < parallelMidbodyLength + bowLength = {Lpar + Lbow}")
        if self.Laft < 1e-9 * L:
            self.Laft = 0.0
        if self.Laft == 0 and abs(self.Bt - B) > 1e-12 * B:
            err("transomBeam", "a transom beam other than the beam needs an aft body "
                "(length > parallelMidbodyLength + bowLength)")
        if T > D:
            err("draft", f"draft {T} is more than the depth {D}")
        if k is None:
            k = (2 * Lbow * math.tan(math.radians(alpha)) / B) ** 2 - 2
            if not -1 < k <= 1 + 1e-9:
                lo = math.degrees(math.atan(B / (2 * Lbow)))
                hi = math.degrees(math.atan(math.sqrt(3) * B / (2 * Lbow)))
                err("waterlineAngle", f"alpha = {alpha} deg: this bow (B {B}, L_BOW {Lbow}) "
                    f"needs {lo:.3f} < alpha <= {hi:.3f} deg (a waterline tangent to the "
                    "mid-body, convex, with k = (2 L_BOW tan alpha / B)^2 - 2 in (-1, 1])")
            k = min(k, 1.0)
        self.k = k
        self.Ig = _int_g(k)
        self.c0 = 1 / math.tan(math.radians(phi1))
        self.ch = 1 / math.tan(math.radians(phi2))
        self.xj = self.Laft + Lpar
        # the bow must stay ahead of the mid-body at every height
        for z in (0.0, D):
            for i in range(1, 400):
                eta = i / 400
                if self.xi(eta, z) < 0:
                    err("stemAngle", f"the bow section at z = {z} crosses into the "
                        "mid-body: stem/bow angles too small for this draft and depth")
                if self.xi(eta, z) > self.xi(eta - 1 / 400, z) + 1e-12:
                    err("bowAngle", f"the bow section at z = {z} is not monotone: "
                        "angles phi1, phi2 too different")

    def c(self, eta):
        # cubic c0 + a e^2 + b e^3 with c(1/2) = ch, c(1) = 0, c'(0) = 0
        a = 8 * self.ch - 7 * self.c0
        b = 6 * self.c0 - 8 * self.ch
        return self.c0 + a * eta * eta + b * eta ** 3

    def xi(self, eta, z):
        base = self.Lbow * math.sqrt(max(0.0, (1 - eta) * (1 + self.k * eta)))
        return base + (z - self.T) * self.c(eta)

    def volume(self):
        B, D, T = self.B, self.D, self.T
        return (D * (self.Laft * (B + self.Bt) / 2 + self.Lpar * B)
                + B * (D * self.Lbow * self.Ig
                       + (D * D / 2 - T * D) * (self.c0 + 4 * self.ch) / 6))

    def bow_waterplane_area(self):
        return self.B * self.Lbow * self.Ig

    def stem_x(self, z):
        return self.xj + self.xi(0.0, z)

    def chain(self, z, n_bow):
        """(x, half-breadth) from the transom to the stem at height z."""
        pts = [(0.0, self.Bt / 2)]
        if self.Laft > 0:
            pts.append((self.Laft, self.B / 2))
        if self.Lpar > 0:
            pts.append((self.xj, self.B / 2))
        for i in range(n_bow, -1, -1):
            sp = i / n_bow  # eta = 1 - (1 - s)^2: even steps in xi at the shoulder
            if i == n_bow and (self.Lpar > 0 or self.Laft > 0):
                continue  # the joint is the mid-body's last point
            eta = 1 - (1 - sp) ** 2
            pts.append((self.xj + self.xi(eta, z), 0.5 * self.B * eta))
        return pts

    def triangles(self, n_bow=96, n_levels=8):
        """Closed, outward-oriented triangulation (list of 3 points)."""
        levels = [self.D * k / n_levels for k in range(n_levels + 1)]
        polys = []
        for z in levels:
            ch = self.chain(z, n_bow)
            n = len(ch) - 1  # stem index
            poly = ([(x, -y, z) for x, y in ch] + [(x, y, z) for x, y in ch[n - 1::-1]])
            polys.append((poly, n))
        tris = []
        for k in range(n_levels):
            lo, hi = polys[k][0], polys[k + 1][0]
            N = len(lo)
            for i in range(N):
                j = (i + 1) % N
                tris.append((lo[i], lo[j], hi[j]))
                tris.append((lo[i], hi[j], hi[i]))
        for (poly, n), top in ((polys[0], False), (polys[-1], True)):
            N = len(poly)
            S = poly[:n + 1]
            P = [poly[(N - i) % N] for i in range(n + 1)]  # P[i] mirrors S[i]; P[n] = S[n]
            for i in range(n):
                quad = [(S[i], S[i + 1], P[i + 1]), (S[i], P[i + 1], P[i])]
                for t in quad:
                    if t[1] == t[2] or t[0] == t[1] or t[0] == t[2]:
                        continue
                    tris.append(t if top else (t[0], t[2], t[1]))
        return tris


def write_stl(path, tris, name="hull", transform=None):
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for t in tris:
            p = [transform(v) if transform else v for v in t]
            a = [p[1][i] - p[0][i] for i in range(3)]
            b = [p[2][i] - p[0][i] for i in range(3)]
            nrm = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
            ln = math.sqrt(sum(x * x for x in nrm)) or 1.0
            f.write(f"  facet normal {nrm[0] / ln:.9g} {nrm[1] / ln:.9g} {nrm[2] / ln:.9g}\n"
                    "    outer loop\n")
            for v in p:
                f.write(f"      vertex {v[0]:.15g} {v[1]:.15g} {v[2]:.15g}\n")
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")


def dummy_hull(diameter=0.2, length=1.2, depth=0.5, draft=0.25):
    """Seed report: half-cylinder bow of the beam's diameter on a rectangular
    body with vertical sides; length overall includes the bow's radius.  The
    report gives no draft: half the depth (0.25 m) unless told otherwise."""
    R = diameter / 2
    return Hull(L=length, B=diameter, T=draft, D=depth, Lpar=length - R, Lbow=R,
                phi1=90.0, phi2=90.0, alpha=60.0, k=1.0)


HULL_KEYS = {"parametric": ["type", "length", "beam", "draft", "depth",
                            "parallelMidbodyLength", "bowLength", "stemAngle", "bowAngle",
                            "waterlineAngle", "transomBeam"],
             "dummy": ["type", "diameter", "length", "depth", "draft"]}


def hull_from_dict(d):
    """d: the `hull` sub-dictionary."""
    t = d.get("type", str, choices=HULL_TYPES)
    d.check_keys(HULL_KEYS[t])
    pos = dict(min=0, strict_min=True)
    if t == "dummy":
        return dummy_hull(d.get("diameter", float, default=0.2, **pos),
                          d.get("length", float, default=1.2, **pos),
                          d.get("depth", float, default=0.5, **pos),
                          d.get("draft", float, default=0.25, **pos))
    ang = dict(min=1.0, max=90.0)
    return Hull(L=d.get("length", float, **pos), B=d.get("beam", float, **pos),
                T=d.get("draft", float, **pos), D=d.get("depth", float, **pos),
                Lpar=d.get("parallelMidbodyLength", float, min=0),
                Lbow=d.get("bowLength", float, **pos),
                phi1=d.get("stemAngle", float, **ang), phi2=d.get("bowAngle", float, **ang),
                alpha=d.get("waterlineAngle", float, **ang),
                Bt=d.get("transomBeam", float, default=-1.0) if "transomBeam" in d else None,
                err=d.error)


def placement(hull, d):
    """Transform hull frame -> case frame: the stem at the waterline goes to
    `stem` (default (0 0 T): hull frame), the bow towards bowDirection +x | -x."""
    d.check_keys(["stem", "bowDirection"])
    s = d.get("stem", "vector", default=[hull.stem_x(hull.T), 0.0, hull.T])
    sign = {"+x": 1.0, "-x": -1.0}[d.get("bowDirection", str, default="+x",
                                         choices=["+x", "-x"])]
    xs = hull.stem_x(hull.T)

    def tf(v):  # a turn by 0 or 180 deg about z keeps the outward orientation
        return (s[0] + sign * (v[0] - xs), s[1] + sign * v[1], s[2] + (v[2] - hull.T))
    return tf


def main(argv=None):
    import argparse
    p = argparse.ArgumentParser(description="Write an ice-going hull STL (docs/brashIce.md)")
    p.add_argument("-case", default=".")
    p.add_argument("-dict", default="system/iceHullDict")
    a = p.parse_args(argv)
    dfile = a.dict if os.path.isabs(a.dict) else os.path.join(a.case, a.dict)
    d = Dict.read(dfile)
    d.check_keys(["hull", "placement", "resolution", "file", "fsicr"])  # fsicr: read by fsicr
    hull = hull_from_dict(d.sub("hull"))
    res = d.sub("resolution") if "resolution" in d else None
    if res is not None:
        res.check_keys(["bowPoints", "levels"])
    nb = res.get("bowPoints", int, default=96, min=4) if res else 96
    nl = res.get("levels", int, default=8, min=1) if res else 8
    tf = placement(hull, d.sub("placement") if "placement" in d else _empty(dfile))
    out = os.path.join(a.case, d.get("file", str, default="constant/triSurface/hull.stl"))
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    write_stl(out, hull.triangles(nb, nl), "hull", tf)
    print(f"iceHull: wrote {out}: volume {hull.volume():.6g} m3 (analytic), bow waterplane "
          f"area A_wf {hull.bow_waterplane_area():.6g} m2, waterline shape k {hull.k:.4f}")
    return 0


def _empty(f):
    e = Dict(f, "placement")
    return e
