#!/usr/bin/env python3
"""Write the mesh, refinement and physics dictionaries of the fixed-cube case.

Cube of edge a = 1 held at the origin (demBackend fixed, shape box), uniform
inflow U = 1 along x, nu = 1/Re (Re = U a / nu, on the edge length), rho = 1.
Domain x in [-4, 8], y, z in [-5, 5] (blockage a^2/100 = 1 % face-on,
sqrt(2) a^2/100 = 1.4 % edge-on); uniform base mesh of cells 2^L/N, refined
L levels by dynamicRefineFvMesh on the field ibRefinement
(ibRefinementIndicator) within `band` of the cube's bounding sphere, so that
the cube sits in cells a/N and the far field stays coarse. The body does not
move: the mesh is refined in the first L steps and then stays.

Usage: makeCase.py [-n N] [-re Re] [-angle deg] [-offset s] [-levels L]
                   [-band b] [-interface penalised|explicit] [-nsub k]
                   [-endTime T] [-co C] [-closed | -open]
  -n       cells per edge near the cube (default 8)
  -angle   rotation about z (0: face-on, 45: edge-on; default 0)
  -offset  shift of the cube centre in x, y, z in fine cells (default: 0
           for even N, 0.5 for odd N, so that the faces of a face-on cube
           lie on cell faces)
  -levels  refinement levels (default 2 for N >= 8, 1 below; 0: uniform
           mesh of cells a/N everywhere)
  -band    refined band beyond the bounding sphere (default 1.2 a)
  -co      Courant number U dt N / a (default 0.75, as fixedSphere)
"""
import argparse
import math
import os

ap = argparse.ArgumentParser()
ap.add_argument("-n", type=int, default=8)
ap.add_argument("-re", type=float, default=20.0)
ap.add_argument("-angle", type=float, default=0.0)
ap.add_argument("-offset", type=float, default=None)
ap.add_argument("-levels", type=int, default=None)
ap.add_argument("-band", type=float, default=1.2)
ap.add_argument("-interface", default="penalised")
ap.add_argument("-nsub", type=int, default=4)
surface = ap.add_mutually_exclusive_group()
surface.add_argument("-closed", action="store_true",
                     help="directForcing closedSurface true: the rigid-body flux on "
                          "the faces of the forced cells (directForcingIB.H, 8.; "
                          "demIbFoam's default since 2026-12-04, written out)")
surface.add_argument("-open", action="store_true",
                     help="directForcing closedSurface false: the flux through the "
                          "forced cells' faces from the pressure equation (the "
                          "default before 2026-12-04)")
ap.add_argument("-endTime", type=float, default=12.0)
ap.add_argument("-co", type=float, default=0.75)
ap.add_argument("-accel", type=float, default=None,
                help="added-mass check: the cube accelerated from rest at this "
                     "rate along x in still fluid (open ends, p = 0); -re is "
                     "then U_end a/nu with U_end = accel endTime")
ap.add_argument("-dt", type=float, default=None)
ap.add_argument("-unrefine", type=float, default=-1.0,
                help="unrefineLevel of dynamicRefineFvMesh (default -1: never "
                     "unrefine; the body hardly moves, and with 0.5 the cells at "
                     "the band's edge flip between levels every step)")
ap.add_argument("-sphere", action="store_true",
                help="a sphere of diameter 1 instead of the cube (the added-mass "
                     "check's analytic anchor, C_a = 1/2)")
a = ap.parse_args()

os.makedirs("constant", exist_ok=True)
N = a.n
L = a.levels if a.levels is not None else (2 if N >= 8 else 1)
off = a.offset if a.offset is not None else (0.5 if N % 2 else 0.0)
h = 1.0 / N
hb = h * 2**L
x0, x1, y0, y1 = -4.0, 8.0, -5.0, 5.0
nx = int(round((x1 - x0) / hb))
ny = int(round((y1 - y0) / hb))
x1 = x0 + nx * hb          # whole base cells
y0, y1 = -0.5 * ny * hb, 0.5 * ny * hb
pos = off * h


def header(obj):
    return "FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n" % obj


with open("system/blockMeshDict", "w") as f:
    f.write(header("blockMeshDict"))
    f.write("// makeCase.py: N = %d, %d refinement levels, base cell %g\n" % (N, L, hb))
    f.write("scale 1;\nvertices\n(\n")
    for z in (y0, y1):
        f.write("    (%.12g %.12g %.12g) (%.12g %.12g %.12g) (%.12g %.12g %.12g) (%.12g %.12g %.12g)\n"
                % (x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z))
    f.write(""");
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
boundary
(
    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    sides  { type patch; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }
);
""" % (nx, ny, ny))

with open("constant/dynamicMeshDict", "w") as f:
    f.write(header("dynamicMeshDict"))
    if L == 0:
        f.write("dynamicFvMesh staticFvMesh;\n")
    else:
        f.write("""dynamicFvMesh dynamicRefineFvMesh;
dynamicRefineFvMeshCoeffs
{
    refineInterval 1; field ibRefinement;
    lowerRefineLevel 0.5; upperRefineLevel 1.5; unrefineLevel %g;
    nBufferLayers 1; maxRefinement %d; maxCells 5000000;
    correctFluxes ((phi none)); dumpLevel true;
}
""" % (a.unrefine, L))

rot = "" if a.angle == 0 else " rotation { axis (0 0 1); angle %.12g; }" % a.angle
with open("constant/ibProperties", "w") as f:
    f.write(header("ibProperties"))
    f.write("""demBackend fixed;
// Penalised interface (directForcingIB.H); written by makeCase.py
directForcing
{
    nSubSamples        %d;
    pressureCorrection true;
    nCorrections       1;
    interface          %s;
    integralForcing    true;
    integralThreshold  0.5;%s
}
refinement { band %.12g; }
bodies
(
    { %s position (%.12g %.12g %.12g);%s%s }
);
""" % (a.nsub, a.interface,
       "\n    closedSurface      true;" if a.closed else
       "\n    closedSurface      false;" if a.open else "", a.band,
       "shape sphere; radius 0.5;" if a.sphere else "shape box; size (1 1 1);",
       pos, pos, pos, rot,
       "" if a.accel is None else " acceleration (%.12g 0 0);" % a.accel))

if a.accel is not None:
    # Still fluid, both ends open at p = 0 (the far field of an accelerated
    # body is at rest; no net flow through the box)
    for name, cls, dim, body in (
        ("U", "volVectorField", "[0 1 -1 0 0 0 0]",
         "internalField uniform (0 0 0);\nboundaryField\n{\n"
         "    \"(inlet|outlet)\" { type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0); }\n"
         "    sides  { type slip; }\n}\n"),
        ("p", "volScalarField", "[0 2 -2 0 0 0 0]",
         "internalField uniform 0;\nboundaryField\n{\n"
         "    \"(inlet|outlet)\" { type fixedValue; value uniform 0; }\n"
         "    sides  { type zeroGradient; }\n}\n")):
        with open("0/" + name, "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
                    "dimensions %s;\n%s" % (cls, name, dim, body))

with open("constant/transportProperties", "w") as f:
    f.write(header("transportProperties"))
    f.write("// makeCase.py: Re = U a / nu = %g (U = 1, a = 1)\nnu  %.10g;\nrho 1;\n"
            % (a.re, 1.0 / a.re))

dt = a.dt if a.dt is not None else a.co * h
txt = open("system/controlDict").read().splitlines()
out = []
for line in txt:
    w = line.split()
    if w and w[0] == "deltaT":
        line = "deltaT          %.8g;" % dt
    elif w and w[0] == "endTime":
        line = "endTime         %.8g;" % a.endTime
    elif w and w[0] == "writeInterval":
        line = "writeInterval   %.8g;" % a.endTime
    out.append(line)
open("system/controlDict", "w").write("\n".join(out) + "\n")
print("N = %d, Re = %g, angle %g, offset %g cells, %d levels: base %d x %d x %d = %d cells, "
      "dt = %g, %d steps" % (N, a.re, a.angle, off, L, nx, ny, ny, nx * ny * ny, dt,
                             int(round(a.endTime / dt))))
