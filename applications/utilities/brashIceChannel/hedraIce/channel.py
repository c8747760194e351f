"""brashIceChannel: a floating brash-ice channel as a DEM `list` insertion.

Method (what the code does, and why):
  * The brash layer occupies, at cross-channel position y, the slab
        z_w - r H(y)  <=  z  <=  z_w + (1 - r) H(y),    r = rho_ice / rho_water,
    H(y) the user's thickness (uniform or a profile with thicker edges): a
    layer of any porosity floats with the fraction r of its ice submerged
    (Archimedes; the pores hold water below z_w and air above).
  * Target ice volume V = (1 - n) L int H dy, n the macro-porosity.  Block
    plan sizes D (D^2 = plan area) are drawn from the size distribution,
    discretised into `sizeClasses` classes of equal probability (class size =
    the median of the class), so that the engine needs one particle type per
    class (and shape): polyDEM stores a polyhedron per type and cannot scale a
    particle of a type (docs/demProperties.md: diameterDistribution is refused
    for polyhedra).  A `table` distribution uses its own sizes as classes.
    Blocks are drawn until their volume is closest to V.
  * Random sequential addition, largest first: random position and heading,
    lowest free height in the local slab (deposition; one layer when H equals
    the block thickness), accepted when the exact separating-axis test finds
    no other block within `gap` (convex.py).  A block that finds no place in
    `maxAttempts` tries is left out and counted: random addition jams near
    55 % plan coverage per layer (Feder 1980 for discs; about the same for
    squares), so a single layer cannot be made denser than porosity ~0.45.
  * `packing lattice` (denser, for porosities random addition cannot reach):
    rows of blocks, each at a heading within +-yawSpread (default 5 deg),
    jittered inside disjoint slots (see _lattice); uniform thickness of a
    whole number of block layers.  Coverage up to ~0.8 per layer at small
    yawSpread; the rows stay visible in the plan view.
  * Blocks lie flat: a single-layer block floats with draft r t exactly
    (bottom at z_w - r t).  Stacked layers are shifted as a whole so that the
    submerged ice volume equals r times the ice volume (the layer's draft).
  * `shape { type sphere; }`: the same blocks drawn and placed, each turned
    into the sphere of its volume (d^3 pi/6 = D^2 t): the spherical floes of
    the open codes, for a like-for-like comparison with the polyhedra (same
    ice volume per class, same porosity by volume). Placement in plan uses
    the regular 32-gon circumscribing the sphere's circle (never closer than
    `gap`); one layer only; each sphere floats at its own draft (the cap
    below z_w holds r of its volume).
"""
import math
import os
import random
from statistics import NormalDist

from . import convex
from .foamDict import Dict, fatal, header

DIST_TYPES = ["uniform", "normal", "logNormal", "table"]
SHAPE_TYPES = ["cuboid", "plate", "sphere"]
SPHERE_PLAN_SIDES = 32       # the polygon a sphere is placed with in plan


class SizeDistribution:
    """Plan size D [m] of a block (D^2 = plan area)."""

    def __init__(self, d):
        self.dict = d
        self.type = d.get("type", str, choices=DIST_TYPES)
        t = self.type
        keys = {"uniform": ["type", "min", "max"],
                "normal": ["type", "mean", "standardDeviation", "min", "max"],
                "logNormal": ["type", "median", "sigma", "min", "max"],
                "table": ["type", "sizes"]}[t]
        d.check_keys(keys)
        if t == "table":
            rows = d.get("sizes", "list", length=1)
            self.table = []
            for k, row in enumerate(rows):
                if (not isinstance(row, list) or len(row) != 2
                        or not all(isinstance(v, (int, float)) for v in row)
                        or row[0] <= 0 or row[1] < 0):
                    d.error("sizes", f"sizes[{k}] must be (size frequency) with size > 0 "
                            f"and frequency >= 0, not {row}")
                self.table.append((float(row[0]), float(row[1])))
            tot = sum(f for _, f in self.table)
            if tot <= 0:
                d.error("sizes", "the frequencies sum to zero")
            self.table = [(s, f / tot) for s, f in sorted(self.table)]
            self.lo, self.hi = self.table[0][0], self.table[-1][0]
            return
        self.lo = d.get("min", float, min=0, strict_min=True)
        self.hi = d.get("max", float, min=0, strict_min=True)
        if self.hi <= self.lo:
            d.error("max", f"max {self.hi} must be > min {self.lo}")
        if t == "normal":
            self.nd = NormalDist(d.get("mean", float, min=0, strict_min=True),
                                 d.get("standardDeviation", float, min=0, strict_min=True))
        elif t == "logNormal":
            self.nd = NormalDist(math.log(d.get("median", float, min=0, strict_min=True)),
                                 d.get("sigma", float, min=0, strict_min=True))
        if t in ("normal", "logNormal"):
            self.Flo = self.nd.cdf(self._u(self.lo))
            self.Fhi = self.nd.cdf(self._u(self.hi))
            if self.Fhi - self.Flo < 1e-9:
                d.error("min", "the range [min, max] holds no probability")

    def _u(self, x):
        return math.log(x) if self.type == "logNormal" else x

    def cdf(self, x):
        if self.type == "uniform":
            return min(1.0, max(0.0, (x - self.lo) / (self.hi - self.lo)))
        if self.type == "table":
            return sum(f for s, f in self.table if s <= x)
        if x <= self.lo:
            return 0.0
        if x >= self.hi:
            return 1.0
        return (self.nd.cdf(self._u(x)) - self.Flo) / (self.Fhi - self.Flo)

    def quantile(self, p):
        if self.type == "uniform":
            return self.lo + p * (self.hi - self.lo)
        u = self.nd.inv_cdf(self.Flo + p * (self.Fhi - self.Flo))
        return math.exp(u) if self.type == "logNormal" else u

    def classes(self, n):
        """[(size, probability)]: n classes of equal probability (table: its rows)."""
        if self.type == "table":
            return list(self.table)
        return [(self.quantile((k + 0.5) / n), 1.0 / n) for k in range(n)]


class Thickness:
    """H(y): uniform, or a profile of (|y| / half-width, H) points, linear between."""

    def __init__(self, d, half_width):
        self.type = d.get("type", str, choices=["uniform", "profile"])
        if self.type == "uniform":
            d.check_keys(["type", "value"])
            self.value = d.get("value", float, min=0, strict_min=True)
            self.points = [(0.0, self.value), (1.0, self.value)]
        else:
            d.check_keys(["type", "points"])
            rows = d.get("points", "list", length=2)
            pts = []
            for k, row in enumerate(rows):
                if (not isinstance(row, list) or len(row) != 2
                        or not all(isinstance(v, (int, float)) for v in row)):
                    d.error("points", f"points[{k}] must be (eta H), not {row}")
                pts.append((float(row[0]), float(row[1])))
            if pts[0][0] != 0 or pts[-1][0] != 1:
                d.error("points", "the profile must run from eta = |y|/(width/2) = 0 to 1")
            for k in range(1, len(pts)):
                if pts[k][0] <= pts[k - 1][0]:
                    d.error("points", f"points[{k}]: eta must increase")
            if min(h for _, h in pts) <= 0:
                d.error("points", "every thickness must be > 0")
            self.points = pts
        self.hw = half_width

    def __call__(self, y_rel):
        eta = min(1.0, abs(y_rel) / self.hw)
        p = self.points
        for k in range(1, len(p)):
            if eta <= p[k][0]:
                w = (eta - p[k - 1][0]) / (p[k][0] - p[k - 1][0])
                return p[k - 1][1] + w * (p[k][1] - p[k - 1][1])
        return p[-1][1]

    def integral(self):
        """int H dy over the width (exact for the piecewise-linear profile)."""
        p = self.points
        s = sum(0.5 * (p[k][1] + p[k - 1][1]) * (p[k][0] - p[k - 1][0])
                for k in range(1, len(p)))
        return 2 * self.hw * s

    def max(self):
        return max(h for _, h in self.points)

    def min(self):
        return min(h for _, h in self.points)


def _clip(poly, y, keep_above):
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        pin = (p[1] >= y) if keep_above else (p[1] <= y)
        qin = (q[1] >= y) if keep_above else (q[1] <= y)
        if pin:
            out.append(p)
        if pin != qin:
            w = (y - p[1]) / (q[1] - p[1])
            out.append((p[0] + w * (q[0] - p[0]), y))
    return out


def _strip_area(poly, ya, yb):
    """Area of a convex polygon between y = ya and y = yb (Sutherland-Hodgman)."""
    c = _clip(_clip(poly, ya, True), yb, False)
    n = len(c)
    return 0.5 * sum(c[i][0] * c[(i + 1) % n][1] - c[(i + 1) % n][0] * c[i][1]
                     for i in range(n)) if n >= 3 else 0.0


def random_plate(rng, corners, elongation):
    """A random convex polygon: `corners` points on an ellipse 1 : elongation at
    jittered angles (points on a convex curve are in convex position)."""
    th = sorted((2 * math.pi * (k + rng.uniform(-0.35, 0.35)) / corners) % (2 * math.pi)
                for k in range(corners))
    return [(math.cos(a), elongation * math.sin(a)) for a in th]


def scaled(plan, area):
    a, _, _ = convex.polygon_area_centroid(plan)
    s = math.sqrt(area / a)
    return [(s * x, s * y) for x, y in plan]


TOP_KEYS = ["channel", "thickness", "blockThickness", "sizeDistribution", "sizeClasses",
            "shape", "porosity", "seed", "iceDensity", "waterDensity", "gap",
            "maxAttempts", "particleTypePrefix", "material", "iceMaterial", "output",
            "packing", "yawSpread", "velocity"]


class Channel:
    def __init__(self, dict_file):
        d = Dict.read(dict_file)
        self.dict_file = dict_file
        d.check_keys(TOP_KEYS)
        c = d.sub("channel")
        c.check_keys(["origin", "length", "width", "waterLevel"])
        self.x0, self.y0 = c.get("origin", "list", length=2)[:2]
        if not all(isinstance(v, (int, float)) for v in (self.x0, self.y0)):
            c.error("origin", "origin must be (x y): the channel's corner at min x, min y")
        self.L = c.get("length", float, min=0, strict_min=True)
        self.W = c.get("width", float, min=0, strict_min=True)
        self.zw = c.get("waterLevel", float)
        self.yc = self.y0 + 0.5 * self.W
        self.H = Thickness(d.sub("thickness"), 0.5 * self.W)
        self.rho_i = d.get("iceDensity", float, min=0, strict_min=True)
        self.rho_w = d.get("waterDensity", float, min=0, strict_min=True)
        if self.rho_i >= self.rho_w:
            d.error("iceDensity", f"ice ({self.rho_i}) must be lighter than water "
                    f"({self.rho_w}) to float")
        self.r = self.rho_i / self.rho_w
        self.porosity = d.get("porosity", float, min=0, max=0.95)
        self.seed = d.get("seed", int, default=1)
        self.n_classes = d.get("sizeClasses", int, default=6, min=1, max=40)
        self.max_attempts = d.get("maxAttempts", int, default=3000, min=1)
        self.packing = d.get("packing", str, default="random", choices=["random", "lattice"])
        self.yaw_spread = math.radians(d.get("yawSpread", float, default=5.0, min=0, max=90))
        self.prefix = d.get("particleTypePrefix", str, default="ice")
        self.material = d.get("material", str, default="ice")
        self.sizes = SizeDistribution(d.sub("sizeDistribution"))
        s = d.sub("shape")
        self.shape_type = s.get("type", str, choices=SHAPE_TYPES)
        if self.shape_type == "cuboid":
            s.check_keys(["type", "aspectRatio"])
            self.aspect = s.get("aspectRatio", float, default=1.0, min=0.05, max=1.0)
            self.n_shapes = 1
            self.flatness = None
        elif self.shape_type == "sphere":
            s.check_keys(["type"])
            self.n_shapes = 1
            self.flatness = None
        else:
            s.check_keys(["type", "corners", "elongation", "shapes", "flatness"])
            self.corners = s.get("corners", int, default=7, min=3, max=30)
            self.elongation = s.get("elongation", float, default=0.7, min=0.1, max=1.0)
            self.n_shapes = s.get("shapes", int, default=3, min=1, max=20)
            self.flatness = s.get("flatness", float, default=None, min=0, strict_min=True) \
                if "flatness" in s else None
        if self.flatness is not None and "blockThickness" in d:
            d.error("blockThickness", "give either blockThickness or shape/flatness "
                    "(thickness = flatness x plan size), not both")
        if self.flatness is None:
            self.t_block = d.get("blockThickness", float, min=0, strict_min=True)
        else:
            self.t_block = None
        self.gap = d.get("gap", float, default=1e-3 * self.sizes.lo, min=0)
        if self.packing == "lattice":
            if self.flatness is not None:
                d.error("packing", "packing lattice needs one blockThickness (not flatness)")
            if self.H.min() != self.H.max():
                d.error("packing", "packing lattice needs a uniform thickness")
            nl = self.H.max() / self.t_block
            if abs(nl - round(nl)) > 1e-9 * nl or round(nl) < 1:
                d.error("packing", f"packing lattice: the thickness {self.H.max()} must be a "
                        f"whole number of block thicknesses {self.t_block}")
            self.n_layers = int(round(nl))
        if self.shape_type == "sphere" and not (
                self.H.min() == self.H.max()
                and abs(self.H.max() - self.t_block) <= 1e-12 * self.t_block):
            d.error("shape", "spheres float in one layer: give a uniform thickness equal to "
                    f"blockThickness ({self.t_block}), not {self.H.min()}..{self.H.max()}")
        self.classes = self.sizes.classes(self.n_classes)
        for k, (D, _) in enumerate(self.classes):
            t = self.thick(D)
            if t > self.H.max() * (1 + 1e-12):
                d.error("blockThickness" if self.flatness is None else "shape",
                        f"size class {k} ({D:.4g} m): block thickness {t:.4g} m is more "
                        f"than the largest ice thickness {self.H.max():.4g} m")
            if D > min(self.L, self.W):
                d.error("sizeDistribution", f"size class {k} ({D:.4g} m) does not fit "
                        "in the channel")
        # In a hull-fixed frame the ice drifts with the water: its initial velocity
        self.velocity = None
        if "velocity" in d:
            self.velocity = tuple(d.get("velocity", "vector"))
        self.ice_material = None
        if "iceMaterial" in d:
            m = d.sub("iceMaterial")
            m.check_keys(["youngsModulus", "poissonsRatio"])
            self.ice_material = (m.get("youngsModulus", float, min=0, strict_min=True),
                                 m.get("poissonsRatio", float, min=0, max=0.5))
        o = d.sub("output") if "output" in d else None
        if o is not None:
            o.check_keys(["include", "postProcessing"])
        self.out_include = o.get("include", str, default="constant/brashIce") if o \
            else "constant/brashIce"
        self.out_post = o.get("postProcessing", str, default="postProcessing/brashIceChannel") \
            if o else "postProcessing/brashIceChannel"

    def thick(self, D):
        return self.t_block if self.flatness is None else self.flatness * D

    # -- shapes ------------------------------------------------------------
    def make_shapes(self, rng):
        """self.shapes[k][s] = dict(plan (local, principal), t, P, name, kind)."""
        self.shapes = []
        for k, (D, _) in enumerate(self.classes):
            t = self.thick(D)
            row = []
            for s in range(self.n_shapes):
                sphere = None
                if self.shape_type == "cuboid":
                    a = D / math.sqrt(self.aspect)
                    b = D * math.sqrt(self.aspect)
                    plan = [(-a / 2, -b / 2), (a / 2, -b / 2), (a / 2, b / 2), (-a / 2, b / 2)]
                    size = (a, b, t)
                elif self.shape_type == "sphere":
                    sphere = (6 * D * D * t / math.pi) ** (1 / 3)   # the block's volume
                    n = SPHERE_PLAN_SIDES
                    rc = 0.5 * sphere / math.cos(math.pi / n)       # circumscribes the circle
                    plan = [(rc * math.cos(2 * math.pi * (k + 0.5) / n),
                             rc * math.sin(2 * math.pi * (k + 0.5) / n)) for k in range(n)]
                    size = None
                else:
                    plan = scaled(convex.principal_plan(
                        random_plate(rng, self.corners, self.elongation)), D * D)
                    size = None
                P = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] if sphere else \
                    convex.engine_frame(convex.prism_moments(plan, t))
                name = f"{self.prefix}C{k}" + (f"S{s}" if self.n_shapes > 1 else "")
                row.append(dict(plan=plan, t=t, P=P, name=name, size=size, D=D, sphere=sphere))
            self.shapes.append(row)

    # -- placement ---------------------------------------------------------
    def slab(self, y):
        h = self.H(y - self.yc)
        return self.zw - self.r * h, self.zw + (1 - self.r) * h

    def build(self):
        rng = random.Random(self.seed)
        self.make_shapes(rng)
        V_layer = self.L * self.H.integral()
        V_target = (1 - self.porosity) * V_layer
        probs = [p for _, p in self.classes]
        cum = [sum(probs[:k + 1]) for k in range(len(probs))]
        drawn, V = [], 0.0
        while True:
            u = rng.random()
            k = next((i for i, c in enumerate(cum) if u <= c), len(cum) - 1)
            D = self.classes[k][0]
            v = D * D * self.thick(D)
            if V + v > V_target and (V + v - V_target) > (V_target - V):
                break
            drawn.append(k)
            V += v
            if V >= V_target:
                break
        self.V_layer, self.V_target = V_layer, V_target
        drawn.sort(key=lambda k: -self.classes[k][0])
        cell = 2 * max(max(math.hypot(x, y) for x, y in sh["plan"])
                       for row in self.shapes for sh in row) + self.gap
        grid = {}
        placed, failed = [], []
        if self.packing == "lattice":
            placed, failed = self._lattice(rng, drawn)
        else:
            for k in drawn:
                b = self._place(rng, k, grid, cell, placed)
                (placed if b is not None else failed).append(b if b is not None else k)
        self.blocks, self.failed = placed, failed
        if self.shape_type == "sphere":
            self._float_spheres()
        else:
            self._float_layer()

    def _place(self, rng, k, grid, cell, placed):
        row = self.shapes[k]
        for _ in range(self.max_attempts):
            s = rng.randrange(len(row))
            sh = row[s]
            yaw = rng.uniform(0, math.pi)
            cx = rng.uniform(self.x0, self.x0 + self.L)
            cy = rng.uniform(self.y0, self.y0 + self.W)
            b = convex.Block(sh["plan"], cx, cy, yaw, 0.0, sh["t"], k, s)
            xs = [p[0] for p in b.plan]
            ys = [p[1] for p in b.plan]
            if (min(xs) < self.x0 or max(xs) > self.x0 + self.L
                    or min(ys) < self.y0 or max(ys) > self.y0 + self.W):
                continue
            # the slab the whole plan lies in (H varies across y)
            zlo = max(self.slab(y)[0] for y in ys)
            zhi = min(self.slab(y)[1] for y in ys)
            t = sh["t"]
            if zhi - zlo < t * (1 - 1e-12):
                continue
            i0, j0 = int(math.floor(cx / cell)), int(math.floor(cy / cell))
            near = [o for i in (i0 - 1, i0, i0 + 1) for j in (j0 - 1, j0, j0 + 1)
                    for o in grid.get((i, j), ()) if b.plan_overlaps(o, self.gap)]
            # lowest bottom in [zlo, zhi - t] clear of the plan-overlapping blocks;
            # stacked blocks touch face to face (zero overlap volume: no force),
            # so that H = n t holds n layers exactly
            z = zlo
            for o in sorted(near, key=lambda o: o.z0):
                if o.z0 >= z + t:
                    break
                z = max(z, o.z1)
            if z > zhi - t + 1e-12 * t:
                continue
            if self.H.min() == self.H.max() and abs(self.H.max() - t) < 1e-12 * t:
                z = zlo  # one layer: exactly at the block's own draft
            b.z0, b.z1 = z, z + t
            grid.setdefault((i0, j0), []).append(b)
            return b
        return None

    def _lattice(self, rng, drawn):
        """Rows of blocks (next-fit decreasing height on each block's bounding
        box at its heading, heading uniform in +-yawSpread, shape at random),
        rows spread evenly over the width and blocks evenly along each row,
        each jittered at random inside its own slot: slots are disjoint, so
        no two blocks can meet.  Size-sorted blocks are dealt to the layers in
        turn; layers are stacked face to face from the slab's bottom."""
        placed, failed = [], []
        t = self.t_block
        zlo = self.slab(self.yc)[0]
        for layer in range(self.n_layers):
            items = []
            for k in drawn[layer::self.n_layers]:
                s = rng.randrange(len(self.shapes[k]))
                yaw = rng.uniform(-self.yaw_spread, self.yaw_spread)
                b = convex.Block(self.shapes[k][s]["plan"], 0.0, 0.0, yaw, 0.0, t, k, s)
                xs = [p[0] for p in b.plan]
                ys = [p[1] for p in b.plan]
                items.append((max(ys) - min(ys), max(xs) - min(xs), k, s, yaw,
                              -min(xs), -min(ys)))
            items.sort(key=lambda it: -it[0])
            rows, row, used = [], [], 0.0
            for it in items:
                if row and used + it[1] + self.gap > self.L:
                    rows.append(row)
                    row, used = [], 0.0
                row.append(it)
                used += it[1] + self.gap
            if row:
                rows.append(row)
            heights = [r[0][0] + self.gap for r in rows]
            while rows and sum(heights) > self.W:  # the shortest rows do not fit
                failed.extend(it[2] for it in rows.pop())
                heights.pop()
            # rows (similar sizes) at random places across the channel, blocks
            # in random order along their row: no size gradient across or along
            order = list(range(len(rows)))
            rng.shuffle(order)
            rows = [rows[i] for i in order]
            heights = [heights[i] for i in order]
            for r in rows:
                rng.shuffle(r)
            gy = (self.W - sum(heights)) / max(len(rows), 1)
            y = self.y0
            for r, h in zip(rows, heights):
                slot_h = h + gy
                wsum = sum(it[1] + self.gap for it in r)
                gx = (self.L - wsum) / len(r)
                x = self.x0
                for hb, wb, k, s, yaw, ox, oy in r:
                    slot_w = wb + self.gap + gx
                    slot_h = h + gy
                    # lower-left of the bounding box, inside the slot less gap/2
                    bx = x + self.gap / 2 + rng.uniform(0, slot_w - wb - self.gap)
                    by = y + self.gap / 2 + rng.uniform(0, slot_h - hb - self.gap)
                    b = convex.Block(self.shapes[k][s]["plan"], bx + ox, by + oy, yaw,
                                     zlo + layer * t, t, k, s)
                    placed.append(b)
                    x += slot_w
                y += slot_h
        return placed, failed

    def submerged(self, dz):
        return sum(self._submerged(b, dz) for b in self.blocks)

    def _submerged(self, b, dz):
        d = self.shapes[b.cls][b.shape]["sphere"]
        h = min(b.z1 - b.z0, max(0.0, self.zw - (b.z0 + dz)))  # depth of the bottom
        if d is None:
            return self.area(b) * h
        return math.pi * h * h * (1.5 * d - h) / 3       # spherical cap, radius d/2

    def area(self, b):
        return self.shapes[b.cls][b.shape]["D"] ** 2

    def volume(self, b):
        """The block's ice volume, D^2 t (a sphere has its block's volume)."""
        sh = self.shapes[b.cls][b.shape]
        return sh["D"] ** 2 * sh["t"]

    def _float_spheres(self):
        """Each sphere at its own draft: the cap below z_w holds r of its
        volume (bisection on the depth h of its bottom, pi h^2 (3R - h)/3)."""
        self.V_ice = sum(self.volume(b) for b in self.blocks)
        self.dz = 0.0
        for b in self.blocks:
            d = self.shapes[b.cls][b.shape]["sphere"]
            target = self.r * math.pi * d ** 3 / 6
            lo, hi = 0.0, d
            for _ in range(200):
                h = 0.5 * (lo + hi)
                if math.pi * h * h * (1.5 * d - h) / 3 < target:
                    lo = h
                else:
                    hi = h
            b.z0 = self.zw - 0.5 * (lo + hi)
            b.z1 = b.z0 + d

    def _float_layer(self):
        """Shift all blocks by one dz so that submerged ice = r x ice volume."""
        Vi = sum(self.volume(b) for b in self.blocks)
        self.V_ice = Vi
        if not self.blocks:
            self.dz = 0.0
            return
        f = lambda dz: self.submerged(dz) - self.r * Vi
        if abs(f(0.0)) <= 1e-12 * Vi:
            self.dz = 0.0
            return
        zmin = min(b.z0 for b in self.blocks)
        zmax = max(b.z1 for b in self.blocks)
        lo, hi = self.zw - zmax, self.zw - zmin  # all under / all above water
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if f(mid) > 0:
                lo = mid
            else:
                hi = mid
        self.dz = 0.5 * (lo + hi)
        for b in self.blocks:
            b.z0 += self.dz
            b.z1 += self.dz

    # -- output --------------------------------------------------------------
    def write(self, case):
        inc = os.path.join(case, self.out_include)
        post = os.path.join(case, self.out_post)
        tri = os.path.join(case, "constant", "triSurface")
        os.makedirs(inc, exist_ok=True)
        os.makedirs(post, exist_ok=True)
        used = sorted({(b.cls, b.shape) for b in self.blocks})
        # particleTypes
        lines = [header("dictionary", "particleTypes", self.out_include),
                 f"// brashIceChannel ({self.dict_file}): {len(used)} particle types\n"
                 "// include inside particleTypes { #include \"brashIce/particleTypes\" }\n"]
        for k, s in used:
            sh = self.shapes[k][s]
            if sh["sphere"] is not None:
                lines.append(f"{sh['name']}\n{{\n    shape       sphere;\n"
                             f"    material    {self.material};\n"
                             f"    diameter    {sh['sphere']:.17g};   // the volume of a "
                             f"{sh['D']:.6g} m x {sh['D']:.6g} m x {sh['t']:.6g} m block\n}}\n")
                continue
            if sh["size"] is not None:
                a, b, t = sh["size"]
                geo = f"type box; size ({a:.17g} {b:.17g} {t:.17g});"
            else:
                os.makedirs(tri, exist_ok=True)
                fn = f"{sh['name']}.stl"
                self.write_stl(os.path.join(tri, fn), sh)
                geo = f'type stl; file "{fn}";'
            lines.append(f"{sh['name']}\n{{\n    shape       polyhedron;\n"
                         f"    material    {self.material};\n"
                         f"    geometry    {{ {geo} }}\n}}\n")
        with open(os.path.join(inc, "particleTypes"), "w") as f:
            f.write("".join(lines))
        # insertion: one list per type (a list insertion has one particleType)
        lines = [header("dictionary", "insertion", self.out_include),
                 "// include inside insertion { #include \"brashIce/insertion\" }\n"]
        for k, s in used:
            sh = self.shapes[k][s]
            vel = "" if self.velocity is None else \
                "    velocity        ({:.17g} {:.17g} {:.17g});\n".format(*self.velocity)
            lines.append(f"{sh['name']}\n{{\n    type            list;\n"
                         f"    particleType    {sh['name']};\n{vel}    particles\n    (\n")
            for b in self.blocks:
                if (b.cls, b.shape) != (k, s):
                    continue
                zc = 0.5 * (b.z0 + b.z1)
                if sh["sphere"] is not None:
                    lines.append(f"        {{ position ({b.cx:.17g} {b.cy:.17g} {zc:.17g}); }}\n")
                    continue
                R = convex.matmul(convex.rot_z(b.yaw), sh["P"])
                e = convex.euler_xyz_deg(R)
                lines.append(f"        {{ position ({b.cx:.17g} {b.cy:.17g} {zc:.17g}); "
                             f"orientation ({e[0]:.17g} {e[1]:.17g} {e[2]:.17g}); }}\n")
            lines.append("    );\n}\n")
        with open(os.path.join(inc, "insertion"), "w") as f:
            f.write("".join(lines))
        if self.ice_material is not None:
            E, nu = self.ice_material
            with open(os.path.join(inc, "materials"), "w") as f:
                f.write(header("dictionary", "materials", self.out_include)
                        + f"{self.material} {{ youngsModulus {E:.17g}; poissonsRatio "
                        f"{nu:.17g}; density {self.rho_i:.17g}; }}\n")
        return self.report(post)

    def write_stl(self, path, sh):
        """The prism in the engine's body frame (centroid origin, sorted axes)."""
        t = sh["t"]
        P = sh["P"]
        plan = sh["plan"]
        n = len(plan)

        def body(x, y, z):  # natural -> body: P^T v
            return tuple(P[0][j] * x + P[1][j] * y + P[2][j] * z for j in range(3))
        bot = [body(x, y, -t / 2) for x, y in plan]
        top = [body(x, y, t / 2) for x, y in plan]
        tris = []
        for i in range(1, n - 1):
            tris.append((top[0], top[i], top[i + 1]))
            tris.append((bot[0], bot[i + 1], bot[i]))
        for i in range(n):
            j = (i + 1) % n
            tris.append((bot[i], bot[j], top[j]))
            tris.append((bot[i], top[j], top[i]))
        with open(path, "w") as f:
            f.write(f"solid {sh['name']}\n")
            for a, b, c in tris:
                f.write("  facet normal 0 0 0\n    outer loop\n")
                for p in (a, b, c):
                    f.write(f"      vertex {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
                f.write("    endloop\n  endfacet\n")
            f.write(f"endsolid {sh['name']}\n")

    def report(self, post):
        n = len(self.blocks)
        por = 1 - self.V_ice / self.V_layer
        # thickness and porosity across the channel, 10 bins in y
        nb = 10
        rows = []
        for i in range(nb):
            ya, yb = self.y0 + i * self.W / nb, self.y0 + (i + 1) * self.W / nb
            bs = [b for b in self.blocks if ya <= b.cy < yb]
            Hin = sum(self.H(y - self.yc) for y in
                      [ya + (j + 0.5) * (yb - ya) / 20 for j in range(20)]) / 20
            Hach = max(b.z1 for b in bs) - min(b.z0 for b in bs) if bs else 0.0
            # ice volume in the strip: each plan clipped to ya <= y <= yb
            Vb = sum(_strip_area(b.plan, ya, yb) / convex.polygon_area_centroid(b.plan)[0]
                     * self.volume(b) for b in self.blocks)
            rows.append((0.5 * (ya + yb) - self.yc, Hin, Hach,
                         1 - Vb / (self.L * (yb - ya) * Hin)))
        with open(os.path.join(post, "thickness.dat"), "w") as f:
            f.write("# y_from_centreline[m] H_input[m] H_achieved[m] porosity\n"
                    "# (10 strips across the width; H_achieved: top - bottom of the blocks\n"
                    "#  centred in the strip; porosity: the ice plan clipped to the strip)\n")
            for r in rows:
                f.write(" ".join(f"{v:.6g}" for v in r) + "\n")
        hist = [0] * len(self.classes)
        for b in self.blocks:
            hist[b.cls] += 1
        with open(os.path.join(post, "histogram.dat"), "w") as f:
            f.write("# class size[m] probability_input count fraction_placed\n")
            for k, (D, p) in enumerate(self.classes):
                f.write(f"{k} {D:.6g} {p:.6g} {hist[k]} {hist[k] / max(n, 1):.6g}\n")
        with open(os.path.join(post, "blocks.dat"), "w") as f:
            f.write("# id class shape x y zBottom zTop yaw[rad] size[m] thickness[m]\n")
            for i, b in enumerate(self.blocks):
                sh = self.shapes[b.cls][b.shape]
                f.write(f"{i} {b.cls} {b.shape} {b.cx:.10g} {b.cy:.10g} {b.z0:.10g} "
                        f"{b.z1:.10g} {b.yaw:.10g} {sh['D']:.10g} {sh['t']:.10g}\n")
        summ = {
            "blocks": n, "notPlaced": len(self.failed),
            "particleTypes": len({(b.cls, b.shape) for b in self.blocks}),
            "porosityTarget": self.porosity, "porosity": por,
            "layerVolume": self.V_layer, "iceVolume": self.V_ice,
            "iceVolumeTarget": self.V_target,
            "thicknessMean": sum(r[2] for r in rows) / nb,
            "thicknessInputMean": self.H.integral() / self.W,
            "layerShift": self.dz,
            "submergedFraction": self.submerged(0.0) / self.V_ice if self.V_ice else 0,
            "densityRatio": self.r,
        }
        with open(os.path.join(post, "summary.dat"), "w") as f:
            for k, v in summ.items():
                f.write(f"{k} {v:.10g}\n" if isinstance(v, float) else f"{k} {v}\n")
        self.plot(post, hist, rows)
        return summ

    def plot(self, post, hist, rows):
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("matplotlib not found (python3-matplotlib): no PNG")
            return
        n = max(len(self.blocks), 1)
        fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
        D = [c[0] for c in self.classes]
        w = 0.8 * (min(D[i + 1] - D[i] for i in range(len(D) - 1)) if len(D) > 1 else D[0])
        ax[0].bar(D, [h / n for h in hist], width=w, alpha=0.6, label="placed (fraction)")
        ax[0].plot(D, [p for _, p in self.classes], "ko", label="input class probability")
        ax[0].set_xlabel("block plan size D [m] (D² = plan area)")
        ax[0].set_ylabel("number fraction")
        ax[0].set_title(f"{len(self.blocks)} blocks, {len(self.failed)} not placed")
        ax[0].legend()
        y = [r[0] for r in rows]
        ax[1].plot(y, [r[1] for r in rows], "k-", label="input H(y)")
        ax[1].plot(y, [r[2] for r in rows], "bo", label="achieved (top - bottom)")
        ax2 = ax[1].twinx()
        ax2.plot(y, [r[3] for r in rows], "r^", label="porosity")
        ax2.axhline(self.porosity, color="r", ls=":", label="target porosity")
        ax2.set_ylim(0, 1)
        ax2.set_ylabel("porosity", color="r")
        ax[1].set_xlabel("y from centreline [m]")
        ax[1].set_ylabel("thickness [m]")
        ax[1].set_ylim(0, 1.3 * self.H.max())
        ax[1].legend(loc="lower left")
        ax2.legend(loc="lower right")
        from matplotlib.patches import Polygon
        for b in self.blocks:
            ax[2].add_patch(Polygon(b.plan, closed=True, fc="lightblue", ec="k", lw=0.3))
        ax[2].set_xlim(self.x0, self.x0 + min(self.L, 3 * self.W))
        ax[2].set_ylim(self.y0, self.y0 + self.W)
        ax[2].set_aspect("equal")
        ax[2].set_title("plan view (first 3 widths)")
        fig.tight_layout()
        fig.savefig(os.path.join(post, "brashIceChannel.png"), dpi=110)
        plt.close(fig)


def main(argv=None):
    import argparse
    p = argparse.ArgumentParser(description="Build a floating brash-ice channel as a "
                                "DEM list insertion (see docs/brashIce.md)")
    p.add_argument("-case", default=".", help="case folder (default .)")
    p.add_argument("-dict", default="system/brashIceChannelDict")
    a = p.parse_args(argv)
    dfile = a.dict if os.path.isabs(a.dict) else os.path.join(a.case, a.dict)
    ch = Channel(dfile)
    ch.build()
    s = ch.write(a.case)
    print(f"brashIceChannel: {s['blocks']} blocks ({s['notPlaced']} not placed), "
          f"{s['particleTypes']} particle types")
    print(f"  porosity {s['porosity']:.4f} (target {s['porosityTarget']:.4f})"
          + ("" if s["notPlaced"] == 0 else
             f"  -- not met: random addition jammed, {s['notPlaced']} blocks found no place"))
    print(f"  mean thickness {s['thicknessMean']:.4g} m (input {s['thicknessInputMean']:.4g} m)")
    print(f"  submerged ice fraction {s['submergedFraction']:.6f} "
          f"(rho_ice/rho_water {s['densityRatio']:.6f})")
    print(f"  wrote {ch.out_include}/{{particleTypes,insertion}}, {ch.out_post}/"
          "{summary,histogram,thickness,blocks}.dat, brashIceChannel.png")
    return 0
