#!/usr/bin/env python3
"""Dam break on a collapsed rock pile: writes the two cases of Allrun.

    python3 makeCase.py default|full|test [resolved]

  dem/      demFoam: rocks poured into a column held by two gates (planes
            removed at tRelease), the column collapses into a pile, which
            settles until tCouple.
  coupled/  demInterFoam: the same demProperties (the same walls, the
            gates already removed), started at tCouple from the DEM state
            of dem/ (Allrun copies dem/<tCouple>/polyDEM), with the water
            column released at tCouple.

Sizes (README.md, "What is reduced"):
  default   2D-ish slab 0.1 m thick (1 cell), 50 rocks d_eq = 0.06 m,
            soft contacts (volumetricStiffness 2e9 N/m3, DEM step 1e-4 s)
  full      3D flume 0.2 m wide (10 cells), 330 rocks d_eq = 0.04 m,
            volumetricStiffness from the rocks' E (5.5e10 N/m3), step 2e-5 s
  test      the default slab, 24 rocks, 1 s of flow on a coarser mesh
  resolved  the coupled case in demInterFoam's resolved mode (immersed
            boundary on the rocks' true shapes): the slab meshed across
            (cells of dx in y too, side walls slip), one level of
            refinement around the rocks (dx/2: d_eq/dx 5.6 at the default
            size), the time step from the Courant number
"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import foamFile  # noqa: E402
from twoPhaseDictionaries import write_two_phase_dictionaries  # noqa: E402

mode = sys.argv[1] if len(sys.argv) > 1 else "default"
resolved = sys.argv[2:] == ["resolved"]
if mode not in ("default", "full", "test") or (len(sys.argv) > 2 and not resolved):
    sys.exit("usage: makeCase.py default|full|test [resolved]")

# ---- Geometry (damBreakRockPile.md; README: how the figure was read) ------
L, H = 2.2, 1.0                 # flume length, height of the domain [m]
waterW, waterH = 0.25, 0.8      # water column at x = 0 .. 0.25 m
colX0 = 1.30                    # rock column between the gates x = 1.30 ..
colH = 0.7                      # target height of the rock column [m]

P = {
    # W: flume width; dx: cell size; ny: cells across; n: rocks; d: d_eq;
    # ibLevels: refinement levels around the rocks in the resolved mode
    # (12.5 mm at default and test, d_eq/dx 5.6; 5 mm at full, 8)
    "default": dict(W=0.15, dx=0.025, ny=1, n=50, d=0.07, colW=0.18, Kv=5e8,
                    dtDem=1e-4, tRelease=2.6, tCouple=3.8, flow=1.5, dtCfd=2e-3,
                    pours=4, ibLevels=1),
    "test":    dict(W=0.15, dx=0.05, ny=1, n=24, d=0.07, colW=0.18, Kv=5e8,
                    dtDem=1e-4, tRelease=1.4, tCouple=2.4, flow=1.0, dtCfd=2e-3,
                    pours=2, ibLevels=2),
    "full":    dict(W=0.20, dx=0.02, ny=10, n=330, d=0.04, colW=0.15, Kv=5e9,
                    dtDem=2e-5, tRelease=3.8, tCouple=5.2, flow=3.0, dtCfd=1e-3,
                    pours=5, ibLevels=2),
}[mode]
W, dx, d = P["W"], P["dx"], P["d"]
colX1 = colX0 + P["colW"]
nx, nz = int(round(L/dx)), int(round(H/dx))
tRelease, tCouple = P["tRelease"], P["tCouple"]
tEnd = tCouple + P["flow"]
if resolved:
    # The immersed boundary needs the rocks' shape across the slab too
    P["ny"] = int(round(W/dx))
slab = P["ny"] == 1

BANNER = f"Hedra tutorial demInterFoam/damBreakRockPile ({mode}), written by makeCase.py"


def write(path, obj, body, cls="dictionary"):
    foamFile.write(path, obj, body, BANNER, cls)


# ---- DEM: shared by both cases --------------------------------------------
# Rock pours: the column is filled in batches (random sequential addition
# jams near a solid fraction of 0.3, so each batch is placed in a tall box
# above the column and falls in before the next one)
per = [P["n"]//P["pours"] + (1 if k < P["n"] % P["pours"] else 0) for k in range(P["pours"])]
pours = ""
for k, num in enumerate(per):
    pours += f"""    pour{k}
    {{
        type            randomFill;
        particleType    rocks;
        number          {num};
        seed            {k + 1};
        time            {0.6*k:g};
        region
        {{
            type    box;    // holds the whole bounding sphere of each rock
            min     ({colX0 + 1e-3:g} 1e-3 {0.05 + 0.15*k:g});
            max     ({colX1 - 1e-3:g} {W - 1e-3:g} {2.7 + 0.05*k:g});
        }}
        velocity        (0 0 -0.5);
    }}
"""


def plane(name, pt, nv, mat, extra=""):
    return (f"    {name}\n    {{\n        type plane; point ({pt[0]:g} {pt[1]:g} {pt[2]:g});"
            f" normal ({nv[0]:g} {nv[1]:g} {nv[2]:g}); material {mat};{extra}\n    }}\n")


walls = (plane("floor", (0, 0, 0), (0, 0, 1), "steel")
         + plane("inlet", (0, 0, 0), (1, 0, 0), "steel")
         + plane("outlet", (L, 0, 0), (-1, 0, 0), "steel")
         + plane("front", (0, 0, 0), (0, 1, 0), "steel")
         + plane("back", (0, W, 0), (0, -1, 0), "steel")
         # The gates that hold the column; removed at tRelease (also in the
         # coupled case, where they are gone already: the wall list, and so
         # the wall indices of the contact springs in the state, stays the same)
         + plane("gateUpstream", (colX0, 0, 0), (1, 0, 0), "steel",
                 f" activeUntil {tRelease:g}; displaySize 0.3;")
         + plane("gateDownstream", (colX1, 0, 0), (-1, 0, 0), "steel",
                 f" activeUntil {tRelease:g}; displaySize 0.3;"))

demProperties = f"""// {P['n']} rocks poured between two gates into a column ~{colH} m high; the
// gates are removed at t = {tRelease:g} s and the column collapses into a pile.
device          cpu;
timeStep        {P['dtDem']:g};
gravity         (0 0 -9.81);

// Rocks leaving this box are removed (none should)
domain {{ min (-0.1 -0.1 -0.1); max ({L + 0.1:g} {W + 0.1:g} 3.5); }}

contactModel
{{
    law                         overlapVolume;  // Fn = Kv x overlap volume (the talk's law)
    volumetricStiffness         {P['Kv']:g};    // [N/m3]; README "Contact stiffness"
    tangentialStiffnessRatio    0.5;            // K_T = K_n/2 (the talk: K_T >= K_n/2)
}}

materials
{{
    // E and nu are read but not used by the overlapVolume law (README)
    rock  {{ youngsModulus 3e9;    poissonsRatio 0.3;  density 2700; }}
    steel {{ youngsModulus 2.1e11; poissonsRatio 0.33; density 7850; }}
}}

interactions
{{
    default     {{ restitution 0.6; friction 0.3; }}                   // rock on rock
    rockOnFlume {{ materials (rock steel); restitution 0.8; friction 0.35; }} // the flume's values
}}

particleTypes
{{
    rocks
    {{
        shape       polyhedron;
        material    rock;
        geometry
        {{
            type                rock;
            equivalentDiameter  {d:g};
            elongation          0.8;
            flatness            0.8;
            points              12;     // 12 vertices, 20 faces
            seed                3;
            shapes              10;
        }}
    }}
}}

walls
{{
{walls}}}

insertion
{{
{pours}}}

output
{{
    format      ascii;
    vtk         true;
}}
"""

# ---- dem/: demFoam --------------------------------------------------------
write("dem/constant/demProperties", "demProperties", demProperties)
write("dem/system/controlDict", "controlDict", f"""application     demFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {tCouple:g};
deltaT          0.01;
writeControl    runTime;
writeInterval   0.1;
purgeWrite      0;
writeFormat     ascii;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
functions
{{
    pile {{ type boundingBox; libs (demFunctionObjects); interval 0.02; }}
}}
""")

# ---- coupled/: demInterFoam -----------------------------------------------
c = "coupled"
write(f"{c}/constant/demProperties", "demProperties", demProperties)
# Slip side walls on the slab (and in the resolved slab: its 6 cells across
# do not resolve the side walls' boundary layers either)
sideType = "slip" if slab or resolved else "noSlip"
write(f"{c}/system/blockMeshDict", "blockMeshDict", f"""convertToMeters 1;
vertices
(
    (0 0 0) ({L} 0 0) ({L} {W} 0) (0 {W} 0)
    (0 0 {H}) ({L} 0 {H}) ({L} {W} {H}) (0 {W} {H})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {P['ny']} {nz}) simpleGrading (1 1 1) );
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
        box (-1 -1 -1) ({waterW} {W + 1} {waterH});
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
);
""")
timeStepNote = ("the first step; then from maxCo on the refined cells, a whole multiple "
                "of the DEM step" if resolved else "fixed: a whole multiple of the DEM step")
write(f"{c}/system/controlDict", "controlDict", f"""application     demInterFoam;
startFrom       startTime;
startTime       {tCouple:g};
stopAt          endTime;
endTime         {tEnd:g};
deltaT          {P['dtCfd']:g};     // {timeStepNote}
writeControl    {"adjustableRunTime" if resolved else "runTime"};
writeInterval   0.05;
purgeWrite      0;
writeFormat     ascii;
writePrecision  10;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
adjustTimeStep  {"yes" if resolved else "no"};
maxCo           {0.5 if resolved else 1};
maxAlphaCo      {0.5 if resolved else 1};
maxDeltaT       {P['dtCfd'] if resolved else 1:g};
functions
{{
    // The pile's extent
    pile {{ type boundingBox; libs (demFunctionObjects); interval 0.01; }}
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
# The resolved run takes ~2500 variable steps: the alpha predictor to 1e-11
# (at 1e-8 the water balance drifted by 1.1e-5 of the water, at 1e-11 by 8.5e-9
# in the -test run), and 200 limiter iterations: MULES' limiter is bounded only
# once converged, and it converges slowly in the cells between rocks in
# contact (with 20 alpha.water reached -3.8e-6 and -5.9e-6, README; with 60,
# after a round-off change of the DEM on 2026-12-07, -4.5e-6 at 3.013 s of
# the -test run, where 120 gave -1.4e-6 and 200 -2.3e-7 at 34 % more CPU
# over those steps)
if resolved:
    write_two_phase_dictionaries(c, write, alpha_tolerance="1e-11", limiter_iter=200)
else:
    write_two_phase_dictionaries(c, write)
if resolved:
    # Band of refined cells around each rock: half a rock, so that the
    # refined region covers the rock's next cells while it moves between
    # two refinements (every step)
    write(f"{c}/constant/couplingProperties", "couplingProperties", f"""couplingMode        resolved;
demBackend          polyDEM;        // reads constant/demProperties
// The rock's inside moves with it; the water is carried by the fluid
// outside the rocks only (docs/models.md, resolved mode)
internalFluid       integrated;
directForcing
{{
    interface       penalised;      // the no-slip point on the true surface
    nSubSamples     8;              // 8^3 samples per cut cell
}}
refinement
{{
    band            {d/2:g};
}}
""")
    write(f"{c}/constant/dynamicMeshDict", "dynamicMeshDict", f"""dynamicFvMesh dynamicRefineFvMesh;
// {P["ibLevels"]} level(s) around the rocks (field ibRefinement of the immersed
// boundary): cells of {dx/2**P["ibLevels"]:g} m there; the cells they leave are merged again
dynamicRefineFvMeshCoeffs
{{
    refineInterval 1; field ibRefinement;
    lowerRefineLevel 0.5; upperRefineLevel 1.5; unrefineLevel 0.5;
    nBufferLayers 1; maxRefinement {P["ibLevels"]}; maxCells 2000000;
    // demInterFoam's fluxes are rebuilt after a mesh change, not mapped
    correctFluxes
    (
        (phi none) (nHatf none) (rhoPhi none) (alphaPhi0.water none) (ghf none)
        (alphaPhiUn none) (epsf none) (phiWater none)
        (phiInterstitial none) (phiInterstitial_0 none)
    );
    dumpLevel false;
}}
""")
else:
    write(f"{c}/constant/couplingProperties", "couplingProperties", """couplingMode        unresolved;     // -resolved: README
formulation         setI;
momentumCoupling    implicit;
locateModel         hinted;
// Rocks of 1.2-2.4 cells: the exact cell-rock overlap volumes
voidFractionModel   exactOverlap;
smoothingModel      none;
// Drag of the mixture around the rock (Ergun/Wen-Yu) and the pressure force
// with the buoyancy of each rock's own submerged volume
forceModels         (Gidaspow freeSurfacePressure);
""")
t0 = f"{c}/{tCouple:g}"
bc = f"    walls {{ type noSlip; }}\n    sides {{ type {sideType}; }}\n"
write(f"{t0}/U", "U", "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
      "boundaryField\n{\n" + bc +
      "    atmosphere { type pressureInletOutletVelocity; value uniform (0 0 0); }\n}\n",
      cls="volVectorField")
write(f"{t0}/p_rgh", "p_rgh", "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
      "boundaryField\n{\n    walls { type fixedFluxPressure; value uniform 0; }\n"
      "    sides { type fixedFluxPressure; value uniform 0; }\n"
      "    atmosphere { type totalPressure; p0 uniform 0; value uniform 0; }\n}\n",
      cls="volScalarField")
write(f"{t0}/alpha.water", "alpha.water", "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0;\n"
      "boundaryField\n{\n    walls { type zeroGradient; }\n    sides { type zeroGradient; }\n"
      "    atmosphere { type inletOutlet; inletValue uniform 0; value uniform 0; }\n}\n",
      cls="volScalarField")

with open("case.info", "w") as f:
    for k, v in dict(mode=mode, coupling="resolved" if resolved else "unresolved", L=L, H=H, W=W, dx=dx, nx=nx, ny=P["ny"], nz=nz, n=P["n"], d=d,
                     colX0=colX0, colX1=colX1, waterW=waterW, waterH=waterH,
                     tRelease=tRelease, tCouple=tCouple, tEnd=tEnd, Kv=P["Kv"],
                     dtDem=P["dtDem"], dtCfd=P["dtCfd"]).items():
        f.write(f"{k} {v}\n")
print(f"makeCase.py {mode}: {P['n']} rocks d_eq {d} m in a column {colX0}..{colX1} m, "
      f"mesh {nx} x {P['ny']} x {nz}, DEM to {tCouple} s (gates off at {tRelease} s), "
      f"coupled {tCouple} .. {tEnd} s")
