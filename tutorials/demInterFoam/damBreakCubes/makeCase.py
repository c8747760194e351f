#!/usr/bin/env python3
"""Dam break hitting a stack of cubes (generic configuration, README.md):
writes the demInterFoam case case/.

    python3 makeCase.py default|full|test

A slab (2D-ish: one cell across, slip side walls) of a flume L x W x H; a
water column x0 wide and h0 high at the upstream end, released at t = 0; a
pyramid of cubes (3-2-1, edge a) standing on the floor at xStack.
  default   cells of 12.5 mm (cube 4 cells), 0.8 s
  full      cells of 5 mm (cube 10 cells), 1.5 s
  test      cells of 20 mm (cube 2.5 cells), 0.6 s (CTest)
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import foamFile  # noqa: E402
from twoPhaseDictionaries import write_two_phase_dictionaries  # noqa: E402

mode = sys.argv[1] if len(sys.argv) > 1 else "default"
if mode not in ("default", "full", "test"):
    sys.exit("usage: makeCase.py default|full|test")

# ---- Generic configuration (not a published experiment: README) -----------
L, W, H = 1.6, 0.10, 0.6        # flume length, slab width, domain height [m]
x0, h0 = 0.4, 0.3               # water column: 0 .. x0 long, h0 high [m]
a = 0.05                        # cube edge [m]
rhoCube = 800.0                 # [kg/m3] (lighter than water: the cubes float off)
xStack = 1.0                    # upstream face of the stack's bottom row [m]
gap = 1e-4                      # between neighbouring cubes and above the floor [m]

P = {"default": dict(dx=0.0125, end=0.8, dtCfd=1e-3),
     "full":    dict(dx=0.005, end=1.5, dtCfd=5e-4),
     "test":    dict(dx=0.02, end=0.6, dtCfd=2e-3)}[mode]
dx = P["dx"]
nx, nz = int(round(L/dx)), int(round(H/dx))
dtDem = 1e-4

# Pyramid 3-2-1: row r holds 3 - r cubes, each over the gap of the two below
cubes = []
for r in range(3):
    for k in range(3 - r):
        cubes.append((xStack + a/2 + (k + 0.5*r)*(a + gap), W/2, a/2 + gap + r*(a + gap)))

BANNER = f"Hedra tutorial demInterFoam/damBreakCubes ({mode}), written by makeCase.py"


def write(path, obj, body, cls="dictionary"):
    foamFile.write(path, obj, body, BANNER, cls)


def plane(name, pt, nv):
    return (f"    {name} {{ type plane; point ({pt[0]:g} {pt[1]:g} {pt[2]:g});"
            f" normal ({nv[0]:g} {nv[1]:g} {nv[2]:g}); material flume; }}\n")


c = "case"
plist = "\n".join(f"            {{ position ({p[0]:.6g} {p[1]:.6g} {p[2]:.6g}); }}" for p in cubes)
write(f"{c}/constant/demProperties", "demProperties", f"""// {len(cubes)} cubes of edge {a} m ({rhoCube:g} kg/m3) stacked 3-2-1 on the floor
device          cpu;
timeStep        {dtDem:g};
gravity         (0 0 -9.81);
domain {{ min (-0.1 -0.1 -0.1); max ({L + 0.1:g} {W + 0.1:g} {H + 0.5:g}); }}

contactModel
{{
    law                         overlapVolume;
    // A cube under two others (2 N) overlaps its support by 2e-8 m3, i.e.
    // 8 micrometres over a face: rigid for the flow; contact time ~2 ms = 20 steps
    volumetricStiffness         1e8;
    tangentialStiffnessRatio    0.5;
}}

materials
{{
    // E, nu: read, not used by the overlapVolume law
    cube  {{ youngsModulus 3e9;    poissonsRatio 0.35; density {rhoCube:g}; }}
    flume {{ youngsModulus 2.1e11; poissonsRatio 0.3;  density 7850; }}
}}

interactions
{{
    default {{ restitution 0.5; friction 0.4; }}  // generic values (README)
}}

particleTypes
{{
    cube {{ shape polyhedron; material cube; geometry {{ type cube; edge {a:g}; }} }}
}}

walls
{{
{plane("floor", (0, 0, 0), (0, 0, 1))}{plane("upstream", (0, 0, 0), (1, 0, 0))}{plane("downstream", (L, 0, 0), (-1, 0, 0))}{plane("front", (0, 0, 0), (0, 1, 0))}{plane("back", (0, W, 0), (0, -1, 0))}}}

insertion
{{
    stack
    {{
        type            list;
        particleType    cube;
        particles
        (
{plist}
        );
    }}
}}

output {{ format ascii; vtk true; }}
""")
write(f"{c}/system/blockMeshDict", "blockMeshDict", f"""convertToMeters 1;
vertices
(
    (0 0 0) ({L} 0 0) ({L} {W} 0) (0 {W} 0)
    (0 0 {H}) ({L} 0 {H}) ({L} {W} {H}) (0 {W} {H})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} 1 {nz}) simpleGrading (1 1 1) );
edges ();
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 3 2 1)); }}
    sides {{ type wall; faces ((0 1 5 4) (3 7 6 2)); }}
    atmosphere {{ type patch; faces ((4 5 6 7)); }}
);
""")
write(f"{c}/system/setFieldsDict", "setFieldsDict", f"""defaultFieldValues ( volScalarFieldValue alpha.water 0 );
regions
(
    boxToCell
    {{
        box (-1 -1 -1) ({x0} {W + 1} {h0});
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
);
""")
write(f"{c}/system/controlDict", "controlDict", f"""application     demInterFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {P['end']:g};
deltaT          {P['dtCfd']:g};     // fixed: a whole multiple of the DEM step
writeControl    runTime;
writeInterval   0.02;
purgeWrite      0;
writeFormat     ascii;
writePrecision  10;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
adjustTimeStep  no;
maxCo           1;
maxAlphaCo      1;
maxDeltaT       1;
functions
{{
    // Water leaving through the open top (splash): sum over the patch of the
    // MULES water flux, every step, for the water balance of postProcess.py
    waterOut
    {{
        type            surfaceFieldValue;
        libs            (fieldFunctionObjects);
        writeControl    timeStep;
        writeInterval   1;
        log             false;
        writeFields     false;
        regionType      patch;
        name            atmosphere;
        operation       sum;
        fields          (alphaPhi0.water);
    }}
}}
""")
write_two_phase_dictionaries(c, write)
write(f"{c}/constant/couplingProperties", "couplingProperties", """couplingMode        unresolved;     // resolved: to come (README)
formulation         setI;
momentumCoupling    implicit;
locateModel         hinted;
voidFractionModel   exactOverlap;   // cubes of 2.5-10 cells: exact overlap volumes
smoothingModel      none;
forceModels         (Gidaspow freeSurfacePressure);
""")
bc = "    walls { type noSlip; }\n    sides { type slip; }\n"
write(f"{c}/0/U", "U", "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
      "boundaryField\n{\n" + bc +
      "    atmosphere { type pressureInletOutletVelocity; value uniform (0 0 0); }\n}\n",
      cls="volVectorField")
write(f"{c}/0/p_rgh", "p_rgh", "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
      "boundaryField\n{\n    walls { type fixedFluxPressure; value uniform 0; }\n"
      "    sides { type fixedFluxPressure; value uniform 0; }\n"
      "    atmosphere { type totalPressure; p0 uniform 0; value uniform 0; }\n}\n",
      cls="volScalarField")
write(f"{c}/0/alpha.water.orig", "alpha.water", "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0;\n"
      "boundaryField\n{\n    walls { type zeroGradient; }\n    sides { type zeroGradient; }\n"
      "    atmosphere { type inletOutlet; inletValue uniform 0; value uniform 0; }\n}\n",
      cls="volScalarField")

with open("case.info", "w") as f:
    for k, v in dict(mode=mode, L=L, W=W, H=H, dx=dx, nx=nx, nz=nz, x0=x0, h0=h0, a=a,
                     rhoCube=rhoCube, xStack=xStack, n=len(cubes), end=P["end"],
                     dtCfd=P["dtCfd"], dtDem=dtDem).items():
        f.write(f"{k} {v}\n")
print(f"makeCase.py {mode}: {len(cubes)} cubes a = {a} m at x = {xStack} m, water {x0} x {h0} m,"
      f" mesh {nx} x 1 x {nz}, to {P['end']} s")
