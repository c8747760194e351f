#!/usr/bin/env python3
"""Writes the brashIceChannel case (demInterFoam + polyDEM, unresolved mode):
the seed report's dummy hull held fixed in a brash-ice channel, water and
ice flowing past it at the towing speed (hull-fixed frame).

Usage: makeCase.py [-test | -full] [-openWater] [-speed U] [-stiffness K]
                   [-demStep DT] [-endTime T] [-hullDraft T] [-porosity P]
                   [-shape cuboid|sphere] [-rollingFriction MU] [-oneWay]
                   [-seed N] [-noOpenWaterFile] [-dir DIR]

  (default)   4 m x 1 m channel, 0.6 m water + 0.4 m air, 0.05 m cells
              (0.025 m at the free surface and the hull), ~120 blocks, 3 s
  -test       2.4 m x 0.6 m, 0.4 m water + 0.4 m air, 0.05 m cells, ~25
              blocks, 0.4 s
              (CTest smoke run)
  -full       the report's 10 m x 2 m, 2.5 m water + 2.5 m air, 0.02 m
              cells, CFD step 1e-3 s, ~350 blocks, 6 s (a GPU and many
              cores: not run here)
  -openWater  the same case without ice (the open-water resistance)
  -speed U    towing speed [m/s] (default 0.74, the report's)
  -stiffness K  volumetric contact stiffness [N/m3]: -full 2e10 = E/t (E
              2e9 Pa over the 0.1 m block thickness), the reduced sizes 2e9
  -demStep DT DEM step [s]: -full 1e-5 (the report's), reduced 4e-5
  -endTime T  run length [s] (default: 3 s, -test 0.4 s, -full 6 s); the
              inflow keeps the channel fed however long
  -hullDraft T  the dummy hull's draft [m] (waterline above the keel;
              default 0.25, half its 0.5 m depth: the report gives none).
              The keel is at z_w - T, so the water under the hull is
              z_w - T - z_min deep (default 0.35 m; -test 0.15 m); it must
              be at least one base cell, and 0 < T <= 0.5 m
  -porosity P the ice layer's porosity in plan, 1 - the ice concentration
              (default 0.35): the built channel's, and the inflow's
              solidFraction is 1 - P. The inflow's random placement jams
              near 0.5 coverage, so P < 0.5 makes it deliver less than the
              channel built at t = 0 (README, "Steady state"); 0 < P < 1
  -shape S    the ice blocks: cuboid (default; 0.08-0.12 m in plan, 0.1 m
              thick) or sphere (each block's volume as a sphere, d 0.10-
              0.14 m: the spherical floes of the open codes, for the
              polyhedra-against-spheres comparison; same ice volume and
              porosity)
  -rollingFriction MU  rolling resistance (demProperties rolling
              elasticPlastic, Ai et al.) with coefficient MU for ice on ice
              and ice on the hull, 0 on the frictionless tank walls
              (default: none). For spheres standing in for blocks: the
              blocks' tipping arm t/2 over the sphere's radius is 0.7-0.8
  -oneWay     couplingDirection oneWay: drag and buoyancy act on the ice,
              the water does not see the ice (its flow is the open-water
              run's); default two-way
  -seed N     the ice field's random seed (a whole number >= 1, default
              1): the channel builder's (block sizes, places, headings) is
              N, the inflow's N + 6. Runs that differ only in N are
              repeats of one set-up (Allrun -seed; README, "How much one
              run says")
  -noOpenWaterFile  the ice run's iceResistance does not read the
              open-water run's mean (../openWater/...resistanceMean.dat,
              which must exist when the ice run starts); its RiceNet is
              then Rtotal. study.py uses it: it subtracts the open water
              over the ice run's own window, and the two runs can go at
              the same time

What the hull-fixed frame means for the boundaries:
  inlet (x min)   water in at U below the level, air above (alpha from
                  setFields on the patch faces);
  outlet (x max)  outletPhaseMeanVelocity (the water leaves at mean speed U)
                  and variableHeightFlowRate for alpha, as OpenFOAM's DTCHull
                  towing-tank tutorial;
  sides, bottom   slip: the tank's walls move with the water in this frame,
                  so they carry no boundary layer; in the DEM they are
                  frictionless planes for the same reason;
  atmosphere      totalPressure 0;
  hull            no-slip wall; in the DEM the same STL, steel, ice-hull
                  friction 0.1.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get("HEDRA_DIR", os.path.normpath(os.path.join(HERE, "..", "..", "..")))
sys.path.insert(0, os.path.join(ROOT, "applications", "utilities", "brashIceChannel"))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import foamFile  # noqa: E402
from hedraIce.case import makeBrashIceCase  # noqa: E402
from twoPhaseDictionaries import FV_SCHEMES, write_laminar_gravity  # noqa: E402

BANNER = "Hedra tutorial: brashIceChannel (demInterFoam), written by makeCase.py"

RHO_W, NU_W = 1010.0, 1.0e-6       # the report's water
RHO_A, NU_A = 1.2, 1.48e-5          # and air
ICE_THICKNESS = 0.1                 # [m], blocks 0.1 m thick, plan 0.08-0.12 m
RHO_ICE = 920.0                     # the report's ice (the builder's iceDensity, hedraIce.case)

SIZES = {
    # domain min, max, water level, stem x, cell, CFD step, DEM step, contact
    # stiffness, end, write. The report's ice (E 2e9 Pa) is k_v = E / t = 2e10
    # N/m3 with its DEM step 1e-5 s (-full); the reduced sizes take a tenth
    # of it and a 4x larger step (README, "Contact stiffness")
    "test": dict(domain=((0.0, -0.3, 0.0), (2.4, 0.3, 0.8), 0.4), stemX=0.8,
                 cell=0.05, dt=4e-3, dtDem=4e-5, kv=2e9, end=0.4, write=0.1),
    "default": dict(domain=((0.0, -0.5, 0.0), (4.0, 0.5, 1.0), 0.6), stemX=2.2,
                    cell=0.05, dt=4e-3, dtDem=4e-5, kv=2e9, end=3.0, write=0.25),
    "full": dict(domain=((0.0, -1.0, 0.0), (10.0, 1.0, 5.0), 2.5), stemX=3.0,
                 cell=0.02, dt=1e-3, dtDem=1e-5, kv=2e10, end=6.0, write=0.5),
}


def write(path, obj, body, cls="dictionary"):
    foamFile.write(path, obj, body, BANNER, cls)


def number(option, args, expected):
    """The number after option (taken from args), or exit naming what was
    expected"""
    v = args.pop(0) if args else ""
    try:
        return float(v)
    except ValueError:
        sys.exit(f"makeCase.py: {option} '{v}': expected {expected}")


def main():
    size, d, openWater, U, kv, dtDem, end = "default", "case", False, 0.74, None, None, None
    draft = 0.25                 # the dummy hull's default draft (hull.py)
    porosity = 0.35              # the ice layer's plan porosity (the builder's default)
    shape = "cuboid"
    direction = "twoWay"         # couplingDirection: the fluid sees the ice
    rollingMu = None             # rolling resistance (elasticPlastic), none by default
    owFile = True                # the ice run reads the open-water run's mean
    HULL_DEPTH = 0.5             # the dummy hull's depth, keel to deck (the report's)
    seed = 1                     # the ice field's seed: the builder's; the inflow's is seed + 6
    args = sys.argv[1:]
    while args:
        a = args.pop(0)
        if a in ("-test", "-full"):
            size = a[1:]
        elif a == "-openWater":
            openWater = True
        elif a == "-speed":
            U = float(args.pop(0))
        elif a == "-stiffness":
            kv = float(args.pop(0))
        elif a == "-demStep":
            dtDem = float(args.pop(0))
        elif a == "-dir":
            d = args.pop(0)
        elif a == "-endTime":
            end = float(args.pop(0))
        elif a == "-porosity":
            porosity = number(a, args, "a porosity in (0, 1)")
            if not (0 < porosity < 1):
                sys.exit(f"makeCase.py: -porosity {porosity:g}: expected 0 < P < 1")
        elif a == "-shape":
            shape = args.pop(0) if args else ""
            if shape not in ("cuboid", "sphere"):
                sys.exit(f"makeCase.py: -shape '{shape}': expected cuboid or sphere")
        elif a == "-rollingFriction":
            rollingMu = number(a, args, "a rolling friction coefficient >= 0")
            if not (rollingMu >= 0):
                sys.exit(f"makeCase.py: -rollingFriction {rollingMu:g}: expected a coefficient >= 0")
        elif a == "-oneWay":
            direction = "oneWay"
        elif a == "-noOpenWaterFile":
            owFile = False
        elif a == "-hullDraft":
            draft = number(a, args, "a draft in m")
        elif a == "-seed":
            v = args.pop(0) if args else ""
            if not (v.isdigit() and int(v) >= 1):
                sys.exit(f"makeCase.py: -seed '{v}': expected a whole number >= 1")
            seed = int(v)
        else:
            sys.exit(f"makeCase.py: unknown option {a} "
                     "(-test | -full, -openWater, -speed U, -stiffness K, -demStep DT, -endTime T, "
                     "-hullDraft T, -porosity P, -shape cuboid|sphere, -rollingFriction MU, -oneWay, -seed N, "
                     "-noOpenWaterFile, -dir DIR)")
    if not (0 < U < 5):
        sys.exit(f"makeCase.py: -speed {U}: expected a towing speed in (0, 5) m/s")
    P = dict(SIZES[size])
    if end is not None:
        if not (end > 0):
            sys.exit(f"makeCase.py: -endTime {end}: expected a run length > 0 s")
        P["end"] = end
    (dmin, dmax, zw) = P["domain"]
    if not (0 < draft <= HULL_DEPTH):
        sys.exit(f"makeCase.py: -hullDraft {draft:g}: expected 0 < T <= {HULL_DEPTH:g} m "
                 "(the dummy hull's depth)")
    keelClearance = zw - draft - dmin[2]
    if keelClearance < P["cell"] - 1e-12:
        sys.exit(f"makeCase.py: -hullDraft {draft:g}: the keel (z = {zw - draft:g} m) is less than "
                 f"a base cell ({P['cell']:g} m) above the floor (z = {dmin[2]:g} m, water "
                 f"{zw - dmin[2]:g} m deep); expected T <= {zw - dmin[2] - P['cell']:g} m")
    info = makeBrashIceCase(d, full=False, domain=P["domain"], stemX=P["stemX"],
                            cellSize=P["cell"], iceThickness=ICE_THICKNESS,
                            velocity=(U, 0.0, 0.0), snap=False, porosity=porosity, shape=shape, seed=seed,
                            bowPoints=32, hullLevels=2,
                            hullDict=f"type dummy; depth {HULL_DEPTH:g}; draft {draft:g};")
    ice = info["ice"]
    # The stem is at the waterline at stemX; the hull runs its length aft of it
    hullEnd = P["stemX"] + info["hullLength"]
    kv = P["kv"] if kv is None else kv
    dt, dtDem = P["dt"], (P["dtDem"] if dtDem is None else dtDem)
    nDem = round(dt / dtDem)
    if abs(nDem * dtDem - dt) > 1e-9 * dt:
        sys.exit(f"makeCase.py: -demStep {dtDem:g}: the CFD step {dt:g} s must be a whole "
                 "number of DEM steps")

    flux_fos = "".join(f"""    water_{patch}
    {{
        type            surfaceFieldValue;
        libs            (fieldFunctionObjects);
        writeControl    timeStep;
        writeInterval   1;
        log             false;
        writeFields     false;
        regionType      patch;
        name            {patch};
        operation       sum;
        fields          (alphaPhi0.water);
    }}
""" for patch in ("inlet", "outlet", "atmosphere"))
    write(f"{d}/system/controlDict", "controlDict", f"""application     demInterFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {P['end']:g};
deltaT          {dt:g};
writeControl    adjustableRunTime;
writeInterval   {P['write']:g};
purgeWrite      0;
writeFormat     ascii;          // postProcess.py reads alpha.water, C and V
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
adjustTimeStep  no;             // a whole number of DEM steps per fluid step
maxCo           0.5;
maxAlphaCo      0.5;
maxDeltaT       {dt:g};

functions
{{
    // The resistance of the hull: the ice load on the DEM wall 'hull' (the
    // same STL as the fluid patch) plus the fluid force on the patch 'hull',
    // along the flow (+x: the water and the ice push the hull downstream)
    resistance
    {{
        type            iceResistance;
        libs            (demFunctionObjects);
        wall            hull;
        patches         (hull);
        direction       (1 0 0);
        CofR            ({P['stemX']:g} 0 {zw:g});
        nBatches        10;
        {'' if (openWater or not owFile) else 'openWaterFile   "../openWater/postProcessing/resistance/0/resistanceMean.dat";'}
    }}
    // The water through each open boundary (with the solver's own
    // postProcessing/demInterFoam/<t0>/waterVolume.dat: the water balance)
{flux_fos}}}
""")
    write(f"{d}/system/decomposeParDict", "decomposeParDict",
          "// Allrun -np N sets numberOfSubdomains and n (N 1 1): slices along the\n"
          "// flow (scotch and metis are stubs in Debian's OpenFOAM, docs/install.md)\n"
          "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n")
    write(f"{d}/system/fvSchemes", "fvSchemes", FV_SCHEMES + "wallDist { method meshWave; }\n")
    write(f"{d}/system/fvSolution", "fvSolution", """solvers
{
    "alpha.water.*"
    {
        nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1;
        // MULES' limiter is bounded only once its iterations converge;
        // blocks coming in through the inlet (fluid fraction 0.1-0.4 in
        // its first cells) need 50 for alpha within 1e-6 of [0, 1]
        // (docs/models.md, "MULES with particles")
        MULESCorr yes; nLimiterIter 50;
        solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0;
    }
    "pcorr.*" { solver GAMG; smoother DIC; tolerance 1e-8; relTol 0; }
    p_rgh { solver GAMG; smoother DIC; tolerance 1e-7; relTol 0.01; }
    p_rghFinal { $p_rgh; relTol 0; }
    "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0; }
}
PIMPLE
{
    momentumPredictor no;
    nOuterCorrectors 1;
    nCorrectors 2;
    nNonOrthogonalCorrectors 1;     // snappyHexMesh cells at the hull
}
relaxationFactors { equations { ".*" 1; } }
""")
    write(f"{d}/system/setFieldsDict", "setFieldsDict", f"""defaultFieldValues ( volScalarFieldValue alpha.water 0 );

// Water below the level, in the cells and on the inlet's faces (the inlet's
// fixedValue alpha); cells that ice fills keep the level's water fraction
// (docs/models.md)
regions
(
    boxToCell
    {{
        box (-1e3 -1e3 -1e3) (1e3 1e3 {zw:g});
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
    boxToFace
    {{
        box (-1e3 -1e3 -1e3) (1e3 1e3 {zw:g});
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
);
""")
    write(f"{d}/constant/transportProperties", "transportProperties", f"""phases (water air);
water {{ transportModel Newtonian; nu {NU_W:g}; rho {RHO_W:g}; }}
air {{ transportModel Newtonian; nu {NU_A:g}; rho {RHO_A:g}; }}
sigma 0.07;
""")
    write_laminar_gravity(d, write)
    write(f"{d}/constant/couplingProperties", "couplingProperties", f"""couplingMode        unresolved;     // blocks of 2-4 cells: semi-resolved with exactOverlap
formulation         setI;
momentumCoupling    implicit;
// twoWay: the water sees the ice (volume and momentum); oneWay (-oneWay):
// drag and buoyancy on the ice only, the water that of the open-water run
couplingDirection   {direction};
demStepsPerFluidStep {nDem};
locateModel         hinted;
voidFractionModel   exactOverlap;   // the exact overlap of each block with each cell
// Semi-resolved: the blocks' solid fraction (and exchange fields) spread
// over about a quarter of a block. Unsmoothed, cells inside a block sit at
// alphaMin 0.1, where the Gidaspow drag is ~1e3 times that of the open
// layer and the air a block displaces as it heaves leaves at ~10 v_block:
// the default size blew up at 0.75 s (README, "Coupling")
smoothingModel      implicitDiffusion;
implicitDiffusionCoeffs {{ lengthScale {0.5 * P['cell']:g}; }}
// Drag of a dense layer (Ergun / Wen-Yu) and the buoyancy of each block's
// own submerged volume (freeSurfacePressure, exact for a flat surface at any
// block/cell size ratio)
forceModels         (Gidaspow freeSurfacePressure);
""")

    # Fields. U: the towing speed everywhere at the start (water and air
    # move past the hull), as OpenFOAM's DTCHull
    Uv = f"({U:g} 0 0)"
    write(f"{d}/0.orig/U", "U", f"""dimensions [0 1 -1 0 0 0 0];
internalField uniform {Uv};
boundaryField
{{
    inlet       {{ type fixedValue; value uniform {Uv}; }}
    outlet      {{ type outletPhaseMeanVelocity; alpha alpha.water; Umean {U:g}; value uniform {Uv}; }}
    atmosphere  {{ type pressureInletOutletVelocity; tangentialVelocity uniform {Uv}; value uniform {Uv}; }}
    sides       {{ type slip; }}
    bottom      {{ type slip; }}
    hull        {{ type noSlip; }}
}}
""", cls="volVectorField")
    write(f"{d}/0.orig/p_rgh", "p_rgh", """dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet       { type fixedFluxPressure; value uniform 0; }
    outlet      { type zeroGradient; }
    atmosphere  { type totalPressure; p0 uniform 0; value uniform 0; }
    sides       { type fixedFluxPressure; value uniform 0; }
    bottom      { type fixedFluxPressure; value uniform 0; }
    hull        { type fixedFluxPressure; value uniform 0; }
}
""", cls="volScalarField")
    write(f"{d}/0.orig/alpha.water", "alpha.water", """dimensions [0 0 0 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet       { type fixedValue; value uniform 0; }
    outlet      { type variableHeightFlowRate; lowerBound 0; upperBound 1; value uniform 0; }
    atmosphere  { type inletOutlet; inletValue uniform 0; value uniform 0; }
    sides       { type zeroGradient; }
    bottom      { type zeroGradient; }
    hull        { type zeroGradient; }
}
""", cls="volScalarField")

    # DEM. Side walls and floor: frictionless (they move with the water in
    # this frame); the hull: the fluid's STL. Ice leaves through the outlet
    # box and enters through the inflow region at the inlet. The outlet box
    # lies beyond the fluid mesh (from a block's bounding radius past the
    # outlet patch): a block is removed only once no part of it is in a
    # cell. Removed inside the mesh, its volume turned to fluid in one step,
    # and that d(eps)/dt kicked every block (total vertical fluid force on
    # the 120 blocks of the default size swinging from -420 to 2300 N,
    # weight 1080 N, at each removal; README, "Ice inflow and outflow").
    t = ICE_THICKNESS
    r = RHO_ICE / RHO_W
    zlo, zhi = zw - r * t, zw + (1 - r) * t
    y0, y1 = dmin[1], dmax[1]
    outletX = dmax[0] + 0.1      # > the largest bounding radius, 0.099 m (0.12 x 0.12 x 0.1)
    # The inflow mirrors the outlet: blocks are placed upstream of the inlet
    # patch, outside the fluid mesh (their centres at least a bounding
    # radius before it), as a floating layer at the builder's draft (centre
    # z_w - r t + t/2), and moved kinematically at U through the approach
    # box, which ends a bounding radius past the inlet: a block is released
    # to coupled dynamics once it is wholly inside the mesh, where it gets
    # its whole buoyancy. It enters the fluid through the inlet patch as
    # smoothly as it leaves through the outlet (README, "Ice inflow").
    # Sizes: the builder's classes (equal probability), each class with the
    # builder's flat orientation, a random heading about z. Spheres: the
    # region is the same slab (the same ice volume per area at the same
    # solid fraction); they are placed at the mean of the classes' floating
    # centres (within 5 mm of each class's: they settle to it in the approach)
    R = 0.1                      # >= the largest bounding radius
    xin = dmin[0]
    Lr = 0.3                     # region length along the flow
    classes, orient, centre = [], {}, {}
    if not openWater:
        import re
        src = open(f"{d}/constant/brashIce/insertion").read()
        for m in re.finditer(r"particleType\s+(\w+);.*?position\s*\(([^)]*)\);"
                             r"(?:\s*orientation\s*\(([^)]*)\))?", src, re.S):
            if m.group(1) not in centre:
                classes.append(m.group(1))
                centre[m.group(1)] = float(m.group(2).split()[2])
                if m.group(3) is not None:
                    orient[m.group(1)] = m.group(3).split()
    orientations = " ".join(f"({' '.join(f'{float(a):.6g}' for a in orient[c])})"
                            for c in classes if c in orient)
    height = sum(centre.values()) / len(centre) if centre else zlo + 0.5 * t
    flat = "" if shape == "sphere" else f"""
        orientations    ({orientations});   // flat, per class
        randomYaw       true;"""
    insertion = "" if openWater else f"""    #include "brashIce/insertion"
    // The channel ahead of the hull is built by brashIceChannel; the inflow
    // keeps feeding it from upstream of the inlet (docs/demProperties.md,
    // "Inflow and outflow")
    inlet
    {{
        type            inflow;
        particleTypes   ({' '.join(classes)});     // the builder's classes, equally likely{flat}
        region          {{ type box; min ({xin - R - Lr:g} {y0:g} {zlo:.6g}); max ({xin - R:g} {y1:g} {zhi:.6g}); }}
        solidFraction   {1 - ice['porosity']:.4g};   // the built channel's
        velocity        {Uv};
        interval        {max(4 * dt, round(Lr / U / 8 / dt) * dt):g};   // region length / U / 8
        attempts        300;
        seed            {seed + 6};   // the builder's + 6
        approach        // kinematic at U: from upstream of the region to a radius past the inlet
        {{
            min     ({xin - R - Lr - 0.05:g} {y0 - 0.05:g} {zlo - 0.1:.6g});
            max     ({xin + R:g} {y1 + 0.05:g} {zhi + 0.1:.6g});
            height  {height:.6g};     // centre of a block floating at its draft
        }}
    }}
"""
    # Rolling resistance (-rollingFriction): Ai et al.'s elastic-plastic
    # spring-dashpot (docs/dem.md), none on the frictionless tank walls
    rollingLaw = rolling = rolling0 = ""
    if rollingMu is not None:
        rollingLaw = "\n    rolling                     elasticPlastic;"
        rolling = f" rollingFriction {rollingMu:g};"
        rolling0 = " rollingFriction 0;"
    write(f"{d}/constant/demProperties", "demProperties", f"""device          cpu;            // cpu | cuda

timeStep        {dtDem:g};      // [s]; {nDem} DEM steps per fluid step

gravity         (0 0 -9.81);

domain                          // blocks that stray are removed
{{
    min         ({dmin[0] - 0.5:g} {dmin[1] - 0.05:g} {dmin[2] - 0.5:g});
    max         ({dmax[0] + 0.5:g} {dmax[1] + 0.05:g} {dmax[2] + 0.5:g});
}}

outlets
{{
    downstream  {{ min ({outletX:g} {y0 - 0.05:g} {dmin[2] - 0.5:g}); max ({dmax[0] + 0.5:g} {y1 + 0.05:g} {dmax[2] + 0.5:g}); }}
}}

// Face-to-face contact of two 0.1 m blocks: F = k_v A delta, i.e. a spring
// k_v A; k_v = E / t = 2e9 Pa / 0.1 m = 2e10 N/m3 gives the axial stiffness
// E A / t of the report's ice (README, "Contact stiffness")
contactModel
{{
    law                         overlapVolume;
    volumetricStiffness         {kv:g};     // [N/m3]
    tangentialStiffnessRatio    0.2857;{rollingLaw}
}}

materials
{{
    #include "brashIce/materials"
    steel {{ youngsModulus 2.1e11; poissonsRatio 0.3; density 7800; }}
    tank  {{ youngsModulus 2.1e11; poissonsRatio 0.3; density 7800; }}
}}

// The report: ice-ice 0.3, ice-structure 0.1; the tank walls move with the
// water in the hull-fixed frame: no friction there
interactions
{{
    default     {{ restitution 0.3; friction 0.3;{rolling} }}
    iceOnHull   {{ materials (ice steel); restitution 0.3; friction 0.1;{rolling} }}
    iceOnTank   {{ materials (ice tank); restitution 0.3; friction 0;{rolling0} }}
}}

particleTypes
{{
    #include "brashIce/particleTypes"
}}

walls
{{
    hull    {{ type mesh; file "hull.stl"; material steel; }}
    floor   {{ type plane; point (0 0 {dmin[2]:g}); normal (0 0 1); material tank; }}
    right   {{ type plane; point (0 {y0:g} 0); normal (0 1 0); material tank; }}
    left    {{ type plane; point (0 {y1:g} 0); normal (0 -1 0); material tank; }}
}}

insertion
{{
{insertion}}}

output
{{
    format      ascii;
    vtk         true;
}}
""")
    with open(f"{d}/case.info", "w") as f:
        for k, v in dict(size=size, openWater=int(openWater), speed=U, stiffness=kv,
                         xmin=dmin[0], xmax=dmax[0], ymin=dmin[1], ymax=dmax[1],
                         zmin=dmin[2], zmax=dmax[2], waterLevel=zw, stemX=P["stemX"],
                         hullEnd=hullEnd, hullBeam=info["hullBeam"], hullDraft=draft, keelClearance=round(keelClearance, 9),
                         cell=P["cell"], dt=dt, dtDem=dtDem, end=P["end"],
                         blocks=ice["blocks"], porosity=ice["porosity"], shape=shape,
                         couplingDirection=direction,
                         rollingFriction=0 if rollingMu is None else rollingMu, seed=seed,
                         iceThickness=ICE_THICKNESS, rhoWater=RHO_W, rhoIce=RHO_ICE,
                         fsicrModel=info["fsicr"]["Rmodel"]).items():
            f.write(f"{k} {v}\n")
    print(f"makeCase.py {size}{' openWater' if openWater else ''}: U {U:g} m/s, "
          f"{0 if openWater else ice['blocks']} blocks (porosity {ice['porosity']:.3f}), "
          f"cells {P['cell']:g} m, to {P['end']:g} s, dt {dt:g} / {dtDem:g} s, "
          f"hull draft {draft:g} m ({round(keelClearance, 9):g} m of water under the keel), "
          f"inflow solid fraction {1 - ice['porosity']:.4g}, {shape}s"
          + (f", rolling friction {rollingMu:g}" if rollingMu is not None else "")
          + (", one-way coupling" if direction == "oneWay" else "")
          + (f", seed {seed}" if seed != 1 else ""))


main()
