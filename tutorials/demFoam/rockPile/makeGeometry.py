#!/usr/bin/env python3
"""Rock pile tutorial geometry: a circular plate of radius R at z = 0
(normal +z), written to constant/triSurface/plate.stl.

The disc is triangulated ring by ring with triangles about h = R/nRings
across, larger than the particles, so that a particle touches one to three
triangles (a fan from the centre would put dozens of thin triangles under
the particle at the centre, each a wall contact).

    python3 makeGeometry.py [R] [nRings]
"""
import math
import os
import sys

R = float(sys.argv[1]) if len(sys.argv) > 1 else 0.03
nRings = int(sys.argv[2]) if len(sys.argv) > 2 else 4

rings = [[(0.0, 0.0)]]
for i in range(1, nRings + 1):
    r = R*i/nRings
    n = 6*i
    rings.append([(r*math.cos(2*math.pi*k/n), r*math.sin(2*math.pi*k/n)) for k in range(n)])

tris = []
for i in range(nRings):
    inner, outer = rings[i], rings[i + 1]
    ni, no = len(inner), len(outer)
    # Walk both rings by angle, always advancing the one that lags
    a = b = 0
    while a < ni or b < no:
        ta = (a + 0.5)/ni if ni > 1 else 2.0
        tb = (b + 0.5)/no
        if ni == 1 and a == 0 and b >= no:
            break
        if b < no and (a >= ni or tb <= ta):
            tris.append((inner[a % ni], outer[b % no], outer[(b + 1) % no]))
            b += 1
        else:
            tris.append((inner[a % ni], outer[b % no], inner[(a + 1) % ni]))
            a += 1

os.makedirs("constant/triSurface", exist_ok=True)
with open("constant/triSurface/plate.stl", "w") as f:
    f.write("solid plate\n")
    for t in tris:
        # counter-clockwise seen from above: normal +z
        (x0, y0), (x1, y1), (x2, y2) = t
        if (x1 - x0)*(y2 - y0) - (y1 - y0)*(x2 - x0) < 0:
            t = (t[0], t[2], t[1])
        f.write("  facet normal 0 0 1\n    outer loop\n")
        for x, y in t:
            f.write("      vertex %.9g %.9g 0\n" % (x, y))
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid plate\n")
area = sum(0.5*abs((t[1][0] - t[0][0])*(t[2][1] - t[0][1]) - (t[1][1] - t[0][1])*(t[2][0] - t[0][0])) for t in tris)
print("plate.stl: radius %g m, %d triangles, area %.6g m2 (disc %.6g)"
      % (R, len(tris), area, math.pi*R*R))
