#!/usr/bin/env python3
"""Rotating drum tutorial geometry: writes ASCII STL files into
constant/triSurface.

  drum.stl        closed cylinder (radius R, length L) along the y axis,
                  centred on the origin: the drum shell and its end caps
  fillRegion.stl  a slightly smaller closed cylinder: where the spheres are
                  placed at the start (randomFill region)

Usage: makeGeometry.py [R L]  (metres)
"""
import math
import os
import sys

R = 0.05      # drum radius [m]
L = 0.04      # drum length [m]
nTheta = 96   # facets around

if len(sys.argv) == 3:
    R, L = map(float, sys.argv[1:])


def ring(r, y):
    return [(r * math.cos(2 * math.pi * k / nTheta), y,
             r * math.sin(2 * math.pi * k / nTheta)) for k in range(nTheta)]


def signedVolume(tris):
    v = 0.0
    for a, b, c in tris:
        v += (a[0] * (b[1] * c[2] - b[2] * c[1])
              - a[1] * (b[0] * c[2] - b[2] * c[0])
              + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    return v


def closedCylinder(r, length):
    """Triangles of a closed cylinder, outward normals."""
    y0, y1 = -0.5 * length, 0.5 * length
    a, b = ring(r, y0), ring(r, y1)
    tris = []
    n = len(a)
    for k in range(n):
        p, q = a[k], a[(k + 1) % n]
        s, t = b[(k + 1) % n], b[k]
        tris.append((p, t, s))
        tris.append((p, s, q))
    for k in range(n):
        tris.append(((0, y1, 0), b[(k + 1) % n], b[k]))
        tris.append(((0, y0, 0), a[k], a[(k + 1) % n]))
    if signedVolume(tris) < 0:
        tris = [(a, c, b) for (a, b, c) in tris]
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
            for p in t:
                f.write("      vertex %.9g %.9g %.9g\n" % p)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name)


os.makedirs("constant/triSurface", exist_ok=True)
drum = closedCylinder(R, L)
region = closedCylinder(R - 0.003, L - 0.006)
assert signedVolume(drum) > 0 and signedVolume(region) > 0
writeStl("constant/triSurface/drum.stl", "drum", drum)
writeStl("constant/triSurface/fillRegion.stl", "fillRegion", region)
print("drum: R = %g m, L = %g m, axis y; fill region R = %g m, L = %g m"
      % (R, L, R - 0.003, L - 0.006))
