#!/usr/bin/env python3
"""Body-fitted reference for the fixed cube: the same domain and boundary
conditions as the immersed-boundary case (../makeCase.py), meshed with
blockMesh as 26 blocks around a cube hole (no-slip patches cubeXm, cubeXp:
the faces normal to x, cube: the other four), steady laminar simpleFoam,
C_d from forceCoeffs (A = a^2, U = 1); or potentialFoam for the added mass
(Allrun, face-on only).

Face-on (-angle 0): stream (1 0 0), x in [-4, 8], y, z in [-5, 5]; inlet x-,
outlet x+, slip sides y+-, z+-.
Edge-on (-angle 45): the mesh stays aligned with the cube and the STREAM is
turned by 45 deg about z, U = (cos 45, sin 45, 0): x, y in [-4, 8] (the wake
along (1 1 0) has room), z in [-5, 5]; inlet (fixed U) x- and y-, outlet
(p = 0, inletOutlet U) x+ and y+, slip z+-. forceCoeffs' dragDir is the
stream, liftDir (-sin 45, cos 45, 0); Aref = a^2 for both orientations.
The stream and the force directions go to constant/freestream, included by
0/U and system/controlDict.

Usage: makeCase.py [-n nc] [-re Re] [-g grow] [-edge r] [-angle A] [-far F]
  nc    cells across the cube edge (default 16), graded so that the cells at
        the cube's edges are `edge` (default 3) times smaller than mid-face
  grow  cell-to-cell growth away from the cube (default 1.2)
  A     angle of the stream to x about z in degrees, 0 (face-on, default)
        or 45 (edge-on)
  F     multiplies the far-field distances (default 1; domain check)
"""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("-n", type=int, default=16)
ap.add_argument("-re", type=float, default=20.0)
ap.add_argument("-g", type=float, default=1.2)
ap.add_argument("-edge", type=float, default=3.0)
ap.add_argument("-angle", type=float, default=0.0)
ap.add_argument("-far", type=float, default=1.0)
a = ap.parse_args()
if a.angle not in (0.0, 45.0):
    ap.error("-angle: 0 (face-on) or 45 (edge-on)")
if a.far <= 0:
    ap.error("-far: > 0")
edgeOn = a.angle == 45.0

nc = a.n
half = nc // 2
# first (edge) cell of a half span 0.5 with expansion `edge` over `half` cells
r = a.edge ** (1.0 / max(half - 1, 1))
h0 = 0.5 * (r - 1) / (r**half - 1) if half > 1 else 0.5


def outer(length):
    n = max(1, round(math.log(1 + length * (a.g - 1) / h0) / math.log(a.g)))
    lo, hi = 1.0 + 1e-9, 3.0
    for _ in range(200):
        q = 0.5 * (lo + hi)
        s = h0 * (q**n - 1) / (q - 1)
        lo, hi = (q, hi) if s < length else (lo, q)
    return n, q ** (n - 1)


F = a.far
xs = [-4.0 * F, -0.5, 0.5, 8.0 * F]
ys = list(xs) if edgeOn else [-5.0 * F, -0.5, 0.5, 5.0 * F]
zs = [-5.0 * F, -0.5, 0.5, 5.0 * F]


def spans(c):
    n0, e0 = outer(c[1] - c[0])
    n2, e2 = outer(c[3] - c[2])
    mid = "((0.5 0.5 %.8g) (0.5 0.5 %.8g))" % (a.edge, 1.0 / a.edge)
    return [n0, nc, n2], ["%.8g" % (1.0 / e0), mid, "%.8g" % e2]


nx, gx = spans(xs)
ny, gy = spans(ys)
nz, gz = spans(zs)


def v(i, j, k):
    return i + 4 * j + 16 * k


lines = []
for k in range(4):
    for j in range(4):
        for i in range(4):
            lines.append("    (%g %g %g)" % (xs[i], ys[j], zs[k]))
blocks = []
for k in range(3):
    for j in range(3):
        for i in range(3):
            if (i, j, k) == (1, 1, 1):
                continue
            blocks.append("    hex (%d %d %d %d %d %d %d %d) (%d %d %d) simpleGrading (%s %s %s)" % (
                v(i, j, k), v(i + 1, j, k), v(i + 1, j + 1, k), v(i, j + 1, k),
                v(i, j, k + 1), v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1),
                nx[i], ny[j], nz[k], gx[i], gy[j], gz[k]))


def quad(axis, level, p, q):
    # face normal to `axis` at vertex index `level`, cell (p, q) of the other two
    if axis == 0:
        return "(%d %d %d %d)" % (v(level, p, q), v(level, p + 1, q), v(level, p + 1, q + 1), v(level, p, q + 1))
    if axis == 1:
        return "(%d %d %d %d)" % (v(p, level, q), v(p + 1, level, q), v(p + 1, level, q + 1), v(p, level, q + 1))
    return "(%d %d %d %d)" % (v(p, q, level), v(p + 1, q, level), v(p + 1, q + 1, level), v(p, q + 1, level))


# face-on: inlet x-, outlet x+; edge-on (stream along (1 1 0)): inlet x- and
# y-, outlet x+ and y+; the rest slip
inAxes = (0, 1) if edgeOn else (0,)
inlet = [quad(ax, 0, p, q) for ax in inAxes for p in range(3) for q in range(3)]
outlet = [quad(ax, 3, p, q) for ax in inAxes for p in range(3) for q in range(3)]
sides = [quad(ax, lv, p, q) for ax in (0, 1, 2) if ax not in inAxes
         for lv in (0, 3) for p in range(3) for q in range(3)]
cube = [quad(ax, lv, 1, 1) for ax in (0, 1, 2) for lv in (1, 2)]
# the two faces normal to the flow apart (the added mass from the potential
# on them, Allrun potential)
cubeXm, cubeXp = [cube[0]], [cube[1]]
cube = cube[2:]
with open("system/blockMeshDict", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }\n")
    f.write("// bodyFitted/makeCase.py -n %d: edge cell %.4g, growth %g%s\nscale 1;\n" % (
        nc, h0, a.g, "".join((", angle %g" % a.angle if edgeOn else "", ", far %g" % F if F != 1 else ""))))
    f.write("vertices\n(\n%s\n);\nblocks\n(\n%s\n);\n" % ("\n".join(lines), "\n".join(blocks)))
    f.write("boundary\n(\n")
    for name, typ, fs in (("inlet", "patch", inlet), ("outlet", "patch", outlet),
                          ("sides", "patch", sides), ("cube", "wall", cube),
                          ("cubeXm", "wall", cubeXm), ("cubeXp", "wall", cubeXp)):
        f.write("    %s { type %s; faces (%s); }\n" % (name, typ, " ".join(fs)))
    f.write(");\n")
with open("constant/transportProperties", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }\n")
    f.write("transportModel Newtonian;\nnu %.10g;\n" % (1.0 / a.re))
# stream, drag and lift directions (0/U, system/controlDict include this)
c, sn = math.cos(math.radians(a.angle)), math.sin(math.radians(a.angle))
vec = lambda x, y: "(%.10g %.10g 0)" % (x, y)
with open("constant/freestream", "w") as f:
    f.write("// bodyFitted/makeCase.py: stream at %g deg to x about z\n" % a.angle)
    f.write("Uinf    %s;\ndragDir %s;\nliftDir %s;\n" % (vec(c, sn), vec(c, sn), vec(-sn + 0.0, c)))
n = sum(nx) * sum(ny) * sum(nz) - nc**3
print("nc = %d (edge cell %.4g), growth %g: %d cells, Re = %g%s%s" % (
    nc, h0, a.g, n, a.re, ", edge-on (stream at 45 deg)" if edgeOn else "",
    ", far-field x %g" % F if F != 1 else ""))
