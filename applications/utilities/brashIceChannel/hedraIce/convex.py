"""Flat convex ice blocks: right prisms with a convex plan polygon.

A block lies flat (its plan horizontal, random heading), so two blocks
intersect exactly when their height intervals overlap and their plan polygons
intersect: the separating-axis theorem on the two polygons' edge normals is an
exact test for convex polygons (Gottschalk et al. 1996; Ericson, "Real-Time
Collision Detection", 2005, sec. 5.2.1).  `gap` asks for that much clearance.

The body frame is the engine's (src/polyDEM/shapes/MassProperties.cpp,
principalAxes): origin at the centroid, axes the principal axes sorted by
increasing moment (body x = least moment = the long axis), right-handed.
`engine_frame` reproduces that sort so the orientation written for a `list`
insertion puts the block exactly where it is placed here.
"""
import math


def polygon_area_centroid(pts):
    a = cx = cy = 0.0
    n = len(pts)
    for i in range(n):
        x0, y0 = pts[i]
        x1, y1 = pts[(i + 1) % n]
        c = x0 * y1 - x1 * y0
        a += c
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    a *= 0.5
    return a, cx / (6 * a), cy / (6 * a)


def polygon_second_moments(pts):
    """(Sxx, Syy, Sxy) = integrals of x^2, y^2, xy over a CCW polygon."""
    sxx = syy = sxy = 0.0
    n = len(pts)
    for i in range(n):
        x0, y0 = pts[i]
        x1, y1 = pts[(i + 1) % n]
        c = x0 * y1 - x1 * y0
        sxx += c * (x0 * x0 + x0 * x1 + x1 * x1)
        syy += c * (y0 * y0 + y0 * y1 + y1 * y1)
        sxy += c * (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0)
    return sxx / 12, syy / 12, sxy / 24


def principal_plan(pts):
    """Translate to the centroid and turn to the principal axes of the plan,
    x along the larger spread (so x is the axis of least moment of the prism)."""
    a, cx, cy = polygon_area_centroid(pts)
    p = [(x - cx, y - cy) for x, y in pts]
    sxx, syy, sxy = polygon_second_moments(p)
    th = 0.5 * math.atan2(2 * sxy, sxx - syy)  # direction of largest spread
    c, s = math.cos(th), math.sin(th)
    q = [(c * x + s * y, -s * x + c * y) for x, y in p]
    return q


def prism_moments(plan, t):
    """Principal moments per unit density of a prism (plan in principal axes)."""
    a, _, _ = polygon_area_centroid(plan)
    sxx, syy, _ = polygon_second_moments(plan)
    szz = a * t ** 3 / 12.0  # integral of z^2 over the prism
    ixx = syy * t + szz
    iyy = sxx * t + szz
    izz = (sxx + syy) * t
    return [ixx, iyy, izz]


def engine_frame(moments):
    """Columns of P: the body axes (engine order) in the natural frame."""
    order = [0, 1, 2]
    # std::stable_sort with comp(i, j) = m_i < m_j (1 - 1e-12)
    for k in range(1, 3):  # insertion sort is stable
        j = k
        while j > 0 and moments[order[j]] < moments[order[j - 1]] * (1 - 1e-12):
            order[j - 1], order[j] = order[j], order[j - 1]
            j -= 1
    P = [[1.0 if r == order[j] else 0.0 for j in range(3)] for r in range(3)]
    det = (P[0][0] * (P[1][1] * P[2][2] - P[1][2] * P[2][1])
           - P[0][1] * (P[1][0] * P[2][2] - P[1][2] * P[2][0])
           + P[0][2] * (P[1][0] * P[2][1] - P[1][1] * P[2][0]))
    if det < 0:
        for r in range(3):
            P[r][2] = -P[r][2]
    return P


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


def euler_xyz_deg(R):
    """(a b c) with R = Rz(c) Ry(b) Rx(a): docs/demProperties.md, orientation."""
    sb = -R[2][0]
    sb = max(-1.0, min(1.0, sb))
    b = math.asin(sb)
    if abs(math.cos(b)) > 1e-9:
        a = math.atan2(R[2][1], R[2][2])
        c = math.atan2(R[1][0], R[0][0])
    else:  # gimbal lock: put all of the turn about z
        a = 0.0
        c = math.atan2(-R[0][1], R[1][1])
    return [math.degrees(a), math.degrees(b), math.degrees(c)]


def rot_from_euler_deg(e):
    a, b, c = (math.radians(x) for x in e)
    Rx = [[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]]
    Ry = [[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]]
    return matmul(rot_z(c), matmul(Ry, Rx))


class Block:
    """A placed block: plan polygon (world, CCW), bottom and top heights."""
    __slots__ = ("plan", "z0", "z1", "cls", "shape", "yaw", "cx", "cy", "r",
                 "axes", "proj")

    def __init__(self, local_plan, cx, cy, yaw, z0, t, cls, shape):
        c, s = math.cos(yaw), math.sin(yaw)
        self.plan = [(cx + c * x - s * y, cy + s * x + c * y) for x, y in local_plan]
        self.cx, self.cy, self.yaw = cx, cy, yaw
        self.z0, self.z1 = z0, z0 + t
        self.cls, self.shape = cls, shape
        self.r = max(math.hypot(x, y) for x, y in local_plan)
        n = len(self.plan)
        self.axes = []
        for i in range(n):
            x0, y0 = self.plan[i]
            x1, y1 = self.plan[(i + 1) % n]
            ex, ey = x1 - x0, y1 - y0
            L = math.hypot(ex, ey)
            self.axes.append((ey / L, -ex / L))  # outward normal (CCW)
        self.proj = [self._project(ax) for ax in self.axes]

    def _project(self, ax):
        lo = hi = self.plan[0][0] * ax[0] + self.plan[0][1] * ax[1]
        for x, y in self.plan[1:]:
            d = x * ax[0] + y * ax[1]
            lo = min(lo, d)
            hi = max(hi, d)
        return lo, hi

    def plan_overlaps(self, other, gap=0.0):
        """True unless an edge normal of either polygon separates them by >= gap."""
        if math.hypot(self.cx - other.cx, self.cy - other.cy) >= self.r + other.r + gap:
            return False
        for A, B in ((self, other), (other, self)):
            for ax, (lo, hi) in zip(A.axes, A.proj):
                blo, bhi = B._project(ax)
                if blo >= hi + gap or bhi <= lo - gap:
                    return False
        return True

    def overlaps(self, other, gap=0.0):
        if other.z0 >= self.z1 + gap or self.z0 >= other.z1 + gap:
            return False
        return self.plan_overlaps(other, gap)
