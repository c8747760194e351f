#!/usr/bin/env python3
"""Writes the floatingBlocks case (demInterFoam + polyDEM) into a folder.

Usage: makeCase.py [-test | -full] -dir DIR

A tank of water open to the atmosphere at the top (box mesh of cubic cells
dx, the water level on a cell face), cuboid ice-like blocks (polyDEM
polyhedra, geometry box) released 5 mm above the surface with a small tilt
and a yaw; each block's size, density and pose are written to DIR/blocks.dat
(what draft.py needs besides the DEM states).

Sizes (Allrun's options):
  (default) tank 0.36 x 0.24 x 0.12 m, dx 10 mm (36 x 24 x 12 cells), water
            0.07 m deep, 6 blocks (500, 700, 920 kg/m3 slabs 60 x 50 x 30 mm;
            900, 917, 920 kg/m3 blocks 45 x 40 x 35 mm), 4 s
  -test     tank 0.24 x 0.12 x 0.12 m, dx 10 mm, water 0.07 m, 2 blocks
            (920 kg/m3 slab, 900 kg/m3 block), 3 s
  -full     the default tank and blocks at dx 5 mm (72 x 48 x 24 cells), 6 s
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import foamFile  # noqa: E402

BANNER = "Hedra tutorial: floatingBlocks (demInterFoam), written by makeCase.py"

# Blocks: (name, size a b c [m] with a >= b >= c, density [kg/m3], centre x y
# [m] as a fraction of the tank, yaw [deg], tilt about world x [deg])
SLAB = (0.06, 0.05, 0.03)
BLOCK = (0.045, 0.04, 0.035)
DEFAULT_BLOCKS = [
    ("slab500", SLAB, 500.0, (1 / 6, 1 / 4), 10.0, 3.0),
    ("slab700", SLAB, 700.0, (3 / 6, 1 / 4), -20.0, -3.0),
    ("slab920", SLAB, 920.0, (5 / 6, 1 / 4), 35.0, 3.0),
    ("ice900", BLOCK, 900.0, (1 / 6, 3 / 4), -5.0, -3.0),
    ("ice917", BLOCK, 917.0, (3 / 6, 3 / 4), 25.0, 3.0),
    ("ice920", BLOCK, 920.0, (5 / 6, 3 / 4), -40.0, -3.0),
]
# -test (CTest): the two sea-ice densities
TEST_BLOCKS = [
    ("slab920", SLAB, 920.0, (1 / 4, 1 / 2), 10.0, 3.0),
    ("ice900", BLOCK, 900.0, (3 / 4, 1 / 2), -20.0, -3.0),
]
LEVEL = 0.07       # water depth [m], on a cell face at every size
DROP = 0.005       # lowest vertex this far above the surface [m]
RHO_W, RHO_A = 1000.0, 1.0


def write(path, obj, body, cls="dictionary"):
    foamFile.write(path, obj, body, BANNER, cls)


def rot(yaw, tilt):
    """R = Rz(yaw) Rx(tilt): demProperties' orientation (tilt 0 yaw)."""
    a, c = math.radians(tilt), math.radians(yaw)
    Rx = [[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]]
    Rz = [[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]]
    return [[sum(Rz[i][k] * Rx[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def main():
    size, d = "default", None
    args = sys.argv[1:]
    while args:
        a = args.pop(0)
        if a in ("-test", "-full"):
            size = a[1:]
        elif a == "-dir":
            d = args.pop(0)
        else:
            sys.exit(f"makeCase.py: unknown option {a} (-test | -full, -dir DIR)")
    if d is None:
        sys.exit("makeCase.py: -dir DIR missing")
    if size == "test":
        L, dx, end, blocks = (0.24, 0.12, 0.12), 0.01, 3.0, TEST_BLOCKS
    elif size == "full":
        L, dx, end, blocks = (0.36, 0.24, 0.12), 0.005, 6.0, DEFAULT_BLOCKS
    else:
        L, dx, end, blocks = (0.36, 0.24, 0.12), 0.01, 4.0, DEFAULT_BLOCKS
    n = [round(l / dx) for l in L]
    dt = 2e-3 if dx >= 0.01 else 1e-3    # fluid step; Courant ~0.1 at impact
    here = os.path.dirname(os.path.abspath(__file__))
    os.makedirs(d, exist_ok=True)
    # Static files from template/
    for root, _, files in os.walk(os.path.join(here, "template")):
        for f in files:
            src = os.path.join(root, f)
            dst = os.path.join(d, os.path.relpath(src, os.path.join(here, "template")))
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            with open(src) as fi, open(dst, "w") as fo:
                fo.write(fi.read())

    write(os.path.join(d, "system/blockMeshDict"), "blockMeshDict", f"""convertToMeters 1;

vertices
(
    (0 0 0) ({L[0]} 0 0) ({L[0]} {L[1]} 0) (0 {L[1]} 0)
    (0 0 {L[2]}) ({L[0]} 0 {L[2]}) ({L[0]} {L[1]} {L[2]}) (0 {L[1]} {L[2]})
);

blocks ( hex (0 1 2 3 4 5 6 7) ({n[0]} {n[1]} {n[2]}) simpleGrading (1 1 1) );

edges ();

boundary
(
    walls
    {{
        type wall;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1));
    }}
    atmosphere
    {{
        type patch;
        faces ((4 5 6 7));
    }}
);
""")
    write(os.path.join(d, "system/setFieldsDict"), "setFieldsDict", f"""defaultFieldValues ( volScalarFieldValue alpha.water 0 );

// The level is on a cell face: the cells below are full, those above empty
regions
(
    boxToCell
    {{
        box (-1 -1 -1) (1 1 {LEVEL});
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
);
""")
    with open(os.path.join(d, "system/controlDict")) as f:
        txt = f.read()
    txt = txt.replace("@END@", f"{end:g}").replace("@DT@", f"{dt:g}")
    with open(os.path.join(d, "system/controlDict"), "w") as f:
        f.write(txt)

    # demProperties: one material and one particle type per block (own
    # density and size)
    mats = "\n".join(f"    {b[0]} {{ youngsModulus 1e8; poissonsRatio 0.3; density {b[2]:g}; }}"
                     for b in blocks)
    types = "\n".join(
        f"    {b[0]}\n    {{\n        shape       polyhedron;\n        material    {b[0]};\n"
        f"        geometry    {{ type box; size ({b[1][0]:g} {b[1][1]:g} {b[1][2]:g}); }}\n    }}"
        for b in blocks)
    ins = ""
    table = []
    for i, (name, s, rho, (fx, fy), yaw, tilt) in enumerate(blocks):
        R = rot(yaw, tilt)
        # lowest vertex of the tilted box DROP above the surface
        low = min(sum(R[2][k] * sg[k] * s[k] / 2 for k in range(3))
                  for sg in [(i1, i2, i3) for i1 in (-1, 1) for i2 in (-1, 1) for i3 in (-1, 1)])
        c = (fx * L[0], fy * L[1], LEVEL + DROP - low)
        ins += (f"    {name}\n    {{\n        type            list;\n        particleType    {name};\n"
                f"        particles ( {{ position ({c[0]:.6g} {c[1]:.6g} {c[2]:.6g});"
                f" orientation ({tilt:g} 0 {yaw:g}); }} );\n    }}\n")
        table.append(f"{i} {name} {s[0]:g} {s[1]:g} {s[2]:g} {rho:g} {c[0]:.6g} {c[1]:.6g} {c[2]:.6g}")
    walls = ""
    for name, pt, nv in (("floor", (0, 0, 0), (0, 0, 1)), ("xmin", (0, 0, 0), (1, 0, 0)),
                         ("xmax", L, (-1, 0, 0)), ("ymin", (0, 0, 0), (0, 1, 0)),
                         ("ymax", L, (0, -1, 0))):
        walls += (f"    {name} {{ type plane; point ({pt[0]:g} {pt[1]:g} {pt[2]:g});"
                  f" normal ({nv[0]} {nv[1]} {nv[2]}); material {blocks[0][0]}; }}\n")
    write(os.path.join(d, "constant/demProperties"), "demProperties", f"""device          cpu;            // cpu | cuda

timeStep        1e-4;           // [s]; demStepsPerFluidStep from deltaT

gravity         (0 0 -9.81);

// Blocks that touch (each other, the walls) push apart with the overlap
// volume; they float, so contacts are rare and short
contactModel
{{
    law                         overlapVolume;
    volumetricStiffness         1e6;    // [N/m3]
    tangentialStiffnessRatio    0.2857;
}}

// One material per block: its density (youngsModulus is not used by the
// overlapVolume law)
materials
{{
{mats}
}}

interactions
{{
    default {{ restitution 0.3; friction 0.3; }}
}}

// Cuboids: body x, y, z along the edges a >= b >= c (docs/demProperties.md)
particleTypes
{{
{types}
}}

walls
{{
{walls}}}

// Each block released with its lowest vertex {DROP} m above the surface,
// orientation (tilt 0 yaw): tilted about the world x axis, then turned
// about the vertical
insertion
{{
{ins}}}

output
{{
    format      ascii;
    vtk         true;
}}
""")
    with open(os.path.join(d, "blocks.dat"), "w") as f:
        f.write(f"# floatingBlocks ({size}): tank {L[0]:g} {L[1]:g} {L[2]:g} m, dx {dx:g} m,"
                f" level {LEVEL:g} m, rho_w {RHO_W:g}, rho_a {RHO_A:g}\n")
        f.write(f"tank {L[0]:g} {L[1]:g} {L[2]:g}\nlevel {LEVEL:g}\ndx {dx:g}\n"
                f"rho {RHO_W:g} {RHO_A:g}\n")
        f.write("# block name a b c [m] density [kg/m3] released at x y z [m]\n")
        f.write("\n".join(table) + "\n")


main()
