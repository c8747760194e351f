#!/usr/bin/env python3
"""Hopper tutorial geometry: writes ASCII STL files into constant/triSurface.

  hopper.stl      the wall: a vertical cylinder (radius R, open top) on a
                  conical bottom (half-angle from the vertical coneHalfAngle)
                  ending in a circular orifice of diameter D at z = 0
  fillRegion.stl  a closed cylinder inside the hopper where the spheres are
                  placed at the start (randomFill region)

Usage: makeGeometry.py [R H D coneHalfAngleDeg]  (metres, degrees)
"""
import math
import os
import sys

R = 0.05              # hopper radius [m]
H = 0.20              # height of the top rim above the orifice [m]
D = 0.035             # orifice diameter [m]
coneHalfAngle = 60.0  # cone half-angle from the vertical [deg]
nTheta = 72           # facets around

if len(sys.argv) == 5:
    R, H, D, coneHalfAngle = map(float, sys.argv[1:])

r0 = 0.5 * D
hCone = (R - r0) / math.tan(math.radians(coneHalfAngle))


def ring(r, z):
    return [(r * math.cos(2 * math.pi * k / nTheta),
             r * math.sin(2 * math.pi * k / nTheta), z) for k in range(nTheta)]


def band(lower, upper, tris):
    """Quads between two rings, as triangles (normals point inwards)."""
    n = len(lower)
    for k in range(n):
        a, b = lower[k], lower[(k + 1) % n]
        c, d = upper[(k + 1) % n], upper[k]
        tris.append((a, d, c))
        tris.append((a, c, b))


def disc(centre, rim, tris, up):
    n = len(rim)
    for k in range(n):
        a, b = rim[k], rim[(k + 1) % n]
        tris.append((centre, a, b) if up else (centre, b, a))


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

# Hopper wall: cone then cylinder
hopper = []
band(ring(r0, 0.0), ring(R, hCone), hopper)
band(ring(R, hCone), ring(R, H), hopper)
writeStl("constant/triSurface/hopper.stl", "hopper", hopper)

# Fill region: closed cylinder, clear of the wall and above the cone
rFill, z0, z1 = R - 0.005, hCone + 0.01, H
region = []
band(ring(rFill, z0), ring(rFill, z1), region)
# outward normals for a closed region: flip the band, caps facing out
region = [(a, c, b) for (a, b, c) in region]
disc((0, 0, z1), ring(rFill, z1), region, up=True)
disc((0, 0, z0), ring(rFill, z0), region, up=False)
writeStl("constant/triSurface/fillRegion.stl", "fillRegion", region)

print("hopper: R = %g m, H = %g m, orifice D = %g m, cone half-angle %g deg "
      "(cone height %.4g m); fill region z in [%.4g, %.4g] m"
      % (R, H, D, coneHalfAngle, hCone, z0, z1))
