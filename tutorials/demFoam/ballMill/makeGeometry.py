#!/usr/bin/env python3
"""Ball mill tutorial geometry: writes ASCII STL files into constant/triSurface.

  shell.stl       the mill shell (inside diameter D, length L) along the z
                  axis, centred on the origin, with N lifters running the
                  full length: its lateral surface only, open at the ends
                  (the end walls are planes in demProperties)
  fillRegion.stl  a closed cylinder inside the lifter tips: where the balls
                  are placed (randomFill region: a ball lies wholly
                  inside it, so it spans the full length; margin: its
                  radial gap to the lifter tips)

Lifters: N equally spaced (the first on the +x axis), each of height h
(radial, at its centre line) and width w (at its base), its two faces
inclined by the face angle a to the lifter's centre line (a = 0: a
rectangular lifter, faces parallel to the centre line; a > 0: a trapezoid,
top width w - 2 h tan a). N = 0: a smooth shell.

Usage: makeGeometry.py [--D 3] [--L 0.2] [--lifters 8] [--height 0.05]
                       [--width 0.05] [--faceAngle 0] [--facets 360]
                       [--margin 0.01]
"""
import argparse
import math
import os

p = argparse.ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("--D", type=float, default=3.0, help="shell inside diameter [m]")
p.add_argument("--L", type=float, default=0.2, help="shell length (slice) [m]")
p.add_argument("--lifters", type=int, default=8, help="number of lifters")
p.add_argument("--height", type=float, default=0.05, help="lifter height [m]")
p.add_argument("--width", type=float, default=0.05, help="lifter base width [m]")
p.add_argument("--faceAngle", type=float, default=0.0,
               help="lifter face angle to its centre line [deg]")
p.add_argument("--facets", type=int, default=360,
               help="facets around the smooth part of the shell")
p.add_argument("--margin", type=float, default=0.01,
               help="radial gap between the fill region and the lifter tips [m]")
args = p.parse_args()

R = 0.5 * args.D
L = args.L
N = args.lifters
h, w = args.height, args.width
alpha = math.radians(args.faceAngle)

if not (R > 0 and L > 0):
    raise SystemExit("makeGeometry.py: D and L must be positive")
if N > 0:
    topWidth = w - 2 * h * math.tan(alpha)
    if not (0 < h < R and 0 < w < 2 * R and topWidth > 0 and 0 <= alpha < math.pi / 2):
        raise SystemExit("makeGeometry.py: expected 0 < height < D/2, 0 < width < D, "
                         "0 <= faceAngle < 90 and width - 2 height tan(faceAngle) > 0")
    halfBase = math.asin(0.5 * w / R)     # half the angle a lifter's base spans
    if 2 * halfBase * N >= 2 * math.pi:
        raise SystemExit("makeGeometry.py: the lifters overlap (N width > circumference)")


def profile():
    """The shell's inside cross-section as a closed polygon (counter-clockwise)."""
    pts = []
    centres = [2 * math.pi * k / N for k in range(N)] if N > 0 else []

    def inLifter(theta):
        for c in centres:
            d = (theta - c + math.pi) % (2 * math.pi) - math.pi
            if abs(d) < halfBase + 0.25 * 2 * math.pi / args.facets:
                return True
        return False

    def lifter(c):
        # Corners in the lifter's frame (radial e, tangential t), counter-clockwise
        e = (math.cos(c), math.sin(c))
        t = (-math.sin(c), math.cos(c))
        base = math.sqrt(R * R - 0.25 * w * w)
        top = R - h
        ht = 0.5 * w - h * math.tan(alpha)
        corners = [(base, -0.5 * w), (top, -ht), (top, ht), (base, 0.5 * w)]
        return [(a * e[0] + b * t[0], a * e[1] + b * t[1]) for a, b in corners]

    # Walk around: circle points outside the lifters, each lifter's corners
    # at its centre angle
    events = []
    for k in range(args.facets):
        theta = 2 * math.pi * k / args.facets
        if not inLifter(theta):
            events.append((theta, [(R * math.cos(theta), R * math.sin(theta))]))
    for c in centres:
        events.append((c % (2 * math.pi), lifter(c)))
    # A lifter's corners sort by its centre angle, but its first corner lies
    # before it: order by the angle of each group's first point
    events.sort(key=lambda ev: math.atan2(ev[1][0][1], ev[1][0][0]) % (2 * math.pi))
    for _, group in events:
        pts.extend(group)
    return pts


def signedArea(poly):
    a = 0.0
    for k in range(len(poly)):
        x0, y0 = poly[k]
        x1, y1 = poly[(k + 1) % len(poly)]
        a += x0 * y1 - x1 * y0
    return 0.5 * a


def extrude(poly, z0, z1):
    """The lateral surface; normals point to the axis (into the mill)."""
    tris = []
    n = len(poly)
    for k in range(n):
        (xa, ya), (xb, yb) = poly[k], poly[(k + 1) % n]
        a, b = (xa, ya, z0), (xb, yb, z0)
        c, d = (xb, yb, z1), (xa, ya, z1)
        # counter-clockwise polygon: (b - a) x z points outwards; reverse
        tris.append((a, d, c))
        tris.append((a, c, b))
    return tris


def closedCylinder(r, z0, z1, n):
    ring0 = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), z0)
             for k in range(n)]
    ring1 = [(x, y, z1) for x, y, _ in ring0]
    tris = []
    for k in range(n):
        a, b = ring0[k], ring0[(k + 1) % n]
        c, d = ring1[(k + 1) % n], ring1[k]
        tris.append((a, b, c))
        tris.append((a, c, d))
        tris.append(((0, 0, z1), d, c))
        tris.append(((0, 0, z0), b, a))
    return tris


def normal(t):
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = t
    ux, uy, uz = bx - ax, by - ay, bz - az
    vx, vy, vz = cx - ax, cy - ay, cz - az
    nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    m = math.sqrt(nx * nx + ny * ny + nz * nz) or 1.0
    return nx / m, ny / m, nz / m


def writeStl(path, name, tris):
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for t in tris:
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % normal(t))
            for q in t:
                f.write("      vertex %.12g %.12g %.12g\n" % q)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name)


poly = profile()
assert signedArea(poly) > 0, "profile must be counter-clockwise"
os.makedirs("constant/triSurface", exist_ok=True)
writeStl("constant/triSurface/shell.stl", "shell", extrude(poly, -0.5 * L, 0.5 * L))
rFill = R - (h if N > 0 else 0) - args.margin
writeStl("constant/triSurface/fillRegion.stl", "fillRegion",
         closedCylinder(rFill, -0.5 * L, 0.5 * L, 96))
# The cross-section's open area (inside the lifters): for the filling
area = signedArea(poly)
with open("constant/triSurface/shell.info", "w") as f:
    f.write("D %.9g\nL %.9g\nlifters %d\nheight %.9g\nwidth %.9g\nfaceAngle %.9g\n"
            "area %.9g\nfillRadius %.9g\n" % (args.D, L, N, h, w, args.faceAngle, area, rFill))
print("shell: D = %g m, L = %g m, axis z, %d lifters %g x %g m (face angle %g deg),"
      " cross-section %.6g m2 (%d facets); fill region r = %g m"
      % (args.D, L, N, h, w, args.faceAngle, area, 2 * len(poly), rFill))
