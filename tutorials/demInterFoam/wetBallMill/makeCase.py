#!/usr/bin/env python3
"""Wet ball mill (demInterFoam): writes the fluid side of one mill case into
the current folder (Allrun runs it in noLifters/ and lifters8/, after copying
the dry tutorial's constant/demProperties there).

    python3 makeCase.py [--D 3] [--L 0.2] [--endTime 16] [--steadyStart 6]
                        [--dt 2e-3] [--cells 0.1] [--fill 0.1188]
                        [--mesh snappy|ogrid] [--meshMotion rotating|static]

Writes
  system/blockMeshDict      (--mesh snappy, the default) a Cartesian
                            background of --cells m cells and the smooth
                            shell's STL for snappyHexMesh, or (--mesh ogrid)
                            an O-grid of the shell's inside (../common/
                            rotatingDrum.py); one cell thick (the slice;
                            front and back 'empty') or, for L > 2 cells,
                            L/cells cells along the axis with slip end walls
  constant/dynamicMeshDict  (--meshMotion rotating, the default) the whole
                            mesh turns with the shell as a solid body from
                            tCouple, 15 rpm counter-clockwise seen from +z
                            (omega along +z, as the DEM shell's rotation);
                            --meshMotion static: the mesh stands and the
                            shell patch is a rotatingWallVelocity
  system/setAlphaFieldDict  the slurry: a pool at the bottom holding --fill
                            of the shell's inside volume pi D^2/4 L (the
                            seed's 4 200 L in the 3 m x 5 m mill: 11.88 %),
                            level from the mesh's own cross-section
  system/controlDict, fvSchemes, fvSolution, constant/g,
  transportProperties (slurry: rho 1800, mu 0.3 Pa s; air),
  turbulenceProperties, couplingProperties, 0/U, 0/p_rgh, 0/alpha.water,
  case.info (mesh and slurry numbers).
Function objects: chargeShape 'charge' (the dry tutorial's: shoulder, toe,
the balls' torque on the shell) and forces 'fluidForces' (the fluid's force
and moment on the shell patch about the axis).
"""
import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import foamFile  # noqa: E402
from rotatingDrum import PIMPLE_O_GRID, o_grid_block_mesh, dynamic_mesh_dict  # noqa: E402
from twoPhaseDictionaries import FV_SCHEMES  # noqa: E402

p = argparse.ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("--D", type=float, default=3.0)
p.add_argument("--L", type=float, default=0.2)
p.add_argument("--rpm", type=float, default=15.0)
p.add_argument("--endTime", type=float, default=16.0)
p.add_argument("--steadyStart", type=float, default=6.0)
p.add_argument("--dt", type=float, default=2e-3, help="CFD time step [s]")
p.add_argument("--cells", type=float, default=0.1, help="fluid cell size [m]")
p.add_argument("--fill", type=float, default=4.2 / (math.pi * 1.5 ** 2 * 5.0),
               help="slurry volume / shell inside volume")
p.add_argument("--writeInterval", type=float, default=1.0)
p.add_argument("--mesh", choices=("snappy", "ogrid"), default="snappy",
               help="the fluid mesh: Cartesian cut by snappyHexMesh, or the O-grid")
p.add_argument("--meshMotion", choices=("rotating", "static"), default="rotating",
               help="the fluid mesh turns with the shell as a solid body (default), or "
                    "stands with its shell wall turning (README, 'Mesh motion')")
p.add_argument("--smoothing", type=float, default=0.1,
               help="implicitDiffusion length of the particle fields [m] (0: none)")
p.add_argument("--airNu", type=float, default=1.48e-5,
               help="kinematic viscosity of the air [m2/s] (1e-2: README, 'The air')")
p.add_argument("--tCouple", type=float, default=2.5,
               help="start of the wet run (the dry filling before it, demFoam)")
args = p.parse_args()

R = 0.5 * args.D
L = args.L
OMEGA = args.rpm * 2 * math.pi / 60
# O-grid (--mesh ogrid): inner square of half side 0.4 R with N x N cells,
# M cells from it to the shell
C = 0.4 * R
N = max(4, int(round(2 * C / args.cells)))
M = max(2, int(round((R - C) / args.cells)))
# Cartesian background (--mesh snappy): NB x NB cells over 2 (R + margin)
NB = int(math.ceil(2 * R / args.cells)) + 2
B = 0.5 * NB * args.cells
NZ = max(1, int(round(L / args.cells))) if L > 2 * args.cells else 1
SIDE = "empty" if NZ == 1 else "wall"
ENDS = "ends" if args.mesh == "ogrid" else "(front|back)"

BANNER = "Hedra tutorial demInterFoam/wetBallMill, written by makeCase.py"


def write(path, obj, body, cls="dictionary"):
    foamFile.write(path, obj, body, BANNER, cls)


# ---- mesh and its motion --------------------------------------------------
if args.mesh == "ogrid":
    blocks = o_grid_block_mesh(R, N, M, C, -0.5 * L, 0.5 * L, sides="ends", sideType=SIDE)
    if NZ > 1:
        blocks = blocks.replace(" 1) simpleGrading", f" {NZ}) simpleGrading")
    write("system/blockMeshDict", "blockMeshDict", blocks)
else:
    # A Cartesian background of cells args.cells, cut to the shell's inside
    # by snappyHexMesh (castellated and snapped to constant/triSurface/
    # fluidShell.stl, the smooth shell); front and back become 'empty'
    # after snapping (Allrun) when the slice is one cell thick
    write("system/blockMeshDict", "blockMeshDict", f"""
convertToMeters 1;
vertices
(
    ({-B:.12g} {-B:.12g} {-0.5 * L:.12g}) ({B:.12g} {-B:.12g} {-0.5 * L:.12g})
    ({B:.12g} {B:.12g} {-0.5 * L:.12g}) ({-B:.12g} {B:.12g} {-0.5 * L:.12g})
    ({-B:.12g} {-B:.12g} {0.5 * L:.12g}) ({B:.12g} {-B:.12g} {0.5 * L:.12g})
    ({B:.12g} {B:.12g} {0.5 * L:.12g}) ({-B:.12g} {B:.12g} {0.5 * L:.12g})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({NB} {NB} {NZ}) simpleGrading (1 1 1) );
edges ();
boundary
(
    box {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }}
    back {{ type patch; faces ((0 3 2 1)); }}
    front {{ type patch; faces ((4 5 6 7)); }}
);
""")
    # the smooth shell, longer than the slice (snappy cuts the background)
    nf = 720
    z0, z1 = -0.5 * L - 0.2, 0.5 * L + 0.2
    pts = [(R * math.cos(2 * math.pi * k / nf), R * math.sin(2 * math.pi * k / nf)) for k in range(nf)]
    os.makedirs("constant/triSurface", exist_ok=True)
    with open("constant/triSurface/fluidShell.stl", "w") as f:
        f.write("solid shell\n")
        for k in range(nf):
            (xa, ya), (xb, yb) = pts[k], pts[(k + 1) % nf]
            for t in (((xa, ya, z0), (xa, ya, z1), (xb, yb, z1)), ((xa, ya, z0), (xb, yb, z1), (xb, yb, z0))):
                f.write("  facet normal 0 0 0\n    outer loop\n" +
                        "".join("      vertex %.12g %.12g %.12g\n" % q for q in t) +
                        "    endloop\n  endfacet\n")
        f.write("endsolid shell\n")
    write("system/snappyHexMeshDict", "snappyHexMeshDict", """
castellatedMesh true;
snap            true;
addLayers       false;
geometry { fluidShell.stl { type triSurfaceMesh; name shell; } }
castellatedMeshControls
{
    maxLocalCells 1000000; maxGlobalCells 2000000; minRefinementCells 0;
    nCellsBetweenLevels 1; maxLoadUnbalance 0.1;
    features ();
    refinementSurfaces { shell { level (0 0); patchInfo { type wall; } } }
    resolveFeatureAngle 30;
    refinementRegions {}
    locationInMesh (0.0123 0.0171 0.0011);
    allowFreeStandingZoneFaces true;
}
snapControls
{
    nSmoothPatch 3; tolerance 2.0; nSolveIter 50; nRelaxIter 5;
    nFeatureSnapIter 0; implicitFeatureSnap false; explicitFeatureSnap false;
}
addLayersControls
{
    relativeSizes true; layers {} expansionRatio 1; finalLayerThickness 0.3;
    minThickness 0.1; nGrow 0; featureAngle 60; nRelaxIter 3;
    nSmoothSurfaceNormals 1; nSmoothNormals 3; nSmoothThickness 10;
    maxFaceThicknessRatio 0.5; maxThicknessToMedialRatio 0.3;
    minMedialAxisAngle 90; nBufferCellsNoExtrude 0; nLayerIter 50;
}
meshQualityControls
{
    maxNonOrtho 65; maxBoundarySkewness 20; maxInternalSkewness 4;
    maxConcave 80; minVol 1e-13; minTetQuality 1e-15; minArea -1;
    minTwist 0.02; minDeterminant 0.001; minFaceWeight 0.05;
    minVolRatio 0.01; minTriangleTwist -1; nSmoothScale 4;
    errorReduction 0.75; relaxed { maxNonOrtho 75; }
}
mergeTolerance 1e-6;
""")

if args.meshMotion == "rotating":
    # The mesh is rotationally symmetric (the lifters are in the DEM wall
    # only), so its phase does not matter: it stands still until the wet
    # run starts at tCouple (rotatingMotion turns it by the integral of
    # omega from t = 0; a mesh turned by omega tCouple at the first step
    # would sweep a flux of half a revolution)
    write("constant/dynamicMeshDict", "dynamicMeshDict", dynamic_mesh_dict(OMEGA).replace(
        f"omega   {OMEGA:.12g};",
        f"omega   table ((0 0) ({args.tCouple:.12g} 0) ({args.tCouple + 1e-3:.12g} {OMEGA:.12g})"
        f" (1e6 {OMEGA:.12g}));"))
    SHELL_U = "shell { type movingWallVelocity; value uniform (0 0 0); }"
else:
    # static mesh: the shell's wall moves at omega x r (the same smooth
    # circular wall as the turning mesh's)
    SHELL_U = (f"shell {{ type rotatingWallVelocity; origin (0 0 0); axis (0 0 1);"
               f" omega {OMEGA:.12g}; value uniform (0 0 0); }}")

target = args.fill * math.pi * R * R          # per unit length
# the pool's level over the settled balls: pool.py, at tCouple

# ---- fields ----------------------------------------------------------------
ends = f'    "{ENDS}" {{ type {"empty" if NZ == 1 else "slip"}; }}\n'
endsS = f'    "{ENDS}" {{ type {"empty" if NZ == 1 else "zeroGradient"}; }}\n'
endsP = f'    "{ENDS}" {{ type empty; }}\n' if NZ == 1 else \
    f'    "{ENDS}" {{ type fixedFluxPressure; value uniform 0; }}\n'

T0 = f"{args.tCouple:g}"
write(f"{T0}/U", "U", "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
      "boundaryField\n{\n    " + SHELL_U + "\n"
      + ends + "}\n", cls="volVectorField")
write(f"{T0}/p_rgh", "p_rgh", "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
      "boundaryField\n{\n    shell { type fixedFluxPressure; value uniform 0; }\n"
      + endsP + "}\n", cls="volScalarField")
write(f"{T0}/alpha.water", "alpha.water", "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0;\n"
      "boundaryField\n{\n    shell { type zeroGradient; }\n" + endsS + "}\n",
      cls="volScalarField")

# ---- physical properties ---------------------------------------------------
write("constant/transportProperties", "transportProperties", f"""
// The seed's slurry as a Newtonian liquid: specific gravity 1.8, 300 cP
phases (water air);
water {{ transportModel Newtonian; nu 1.666666666667e-04; rho 1800; }}
// air (--airNu: a larger viscosity damps the light phase's parasitic
// currents; README, "Numerics", "The air")
air {{ transportModel Newtonian; nu {args.airNu:.6g}; rho 1; }}
sigma 0.07;
""")
write("constant/turbulenceProperties", "turbulenceProperties", "simulationType laminar;\n")
write("constant/g", "g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n",
      cls="uniformDimensionedVectorField")
smoothing = ("smoothingModel      none;" if args.smoothing <= 0 else
             "// the particle fields (void fraction, exchange) smoothed over about a\n"
             "// cell: a 52-80 mm ball's sample points crossing a cell face change\n"
             "// the void fraction of a 0.1 m cell (and more of a small cut cell at\n"
             "// the shell) by steps that drive the fluid through the bed\n"
             f"smoothingModel      implicitDiffusion;\nimplicitDiffusionCoeffs {{ lengthScale {args.smoothing:g}; }}")
write("constant/couplingProperties", "couplingProperties", f"""
couplingMode        unresolved;     // balls 52-80 mm, fluid cells ~0.1 m
// the fluid velocity at the particles from the cell values: the default
// (flux: the reconstructed flux) is the reconstruction that is unstable on
// curved meshes (docs/models.md, "Velocity correction")
fluidVelocity       cell;
formulation         setI;
momentumCoupling    implicit;
locateModel         hinted;
// The ball's volume by sample points (nShells 2: 29 points); a ball is
// 4-13 % of a 0.1 m cell's volume (more in the cut cells at the shell)
voidFractionModel   divided;
{smoothing}
// Gidaspow: Ergun in the dense charge (void fraction 0.4), Wen-Yu where it
// is dilute (SchillerNaumann has no void-fraction correction: it would
// leave out most of the drag of the slurry flowing through the bed);
// freeSurfacePressure: the non-hydrostatic pressure gradient and the
// buoyancy of each ball's submerged volume
forceModels         (Gidaspow freeSurfacePressure);
""")

# ---- numerics --------------------------------------------------------------
write("system/fvSchemes", "fvSchemes", FV_SCHEMES)
write("system/fvSolution", "fvSolution", """
solvers
{
    "alpha.water.*"
    {
        nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1;
        // 20 limiter iterations (the dam-break tutorials: alpha stays in
        // [0, 1] to 4e-8 where the surface runs through particles)
        MULESCorr yes; nLimiterIter 20;
        solver smoothSolver; smoother symGaussSeidel; tolerance 1e-10; relTol 0;
    }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-10; relTol 0; }
    p_rgh { solver PCG; preconditioner DIC; tolerance 1e-9; relTol 0.01; }
    p_rghFinal { $p_rgh; relTol 0; }
    "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-9; relTol 0; }
}
PIMPLE
{
    // correctPhi after the mesh motion, the motion once per step, and the
    // velocity correction gaussBalance (../common/rotatingDrum.py):
    // interFoam's reconstruction of the pressure flux grows from round-off
    // on curved meshes (the O-grid, a polar mesh, the cut cells of this
    // one) with the slurry at rest, gradient breaks the balance of pressure
    // and gravity at the free surface (README, "Numerics")
""" + PIMPLE_O_GRID + """    momentumPredictor no;
    nOuterCorrectors 1;
    nCorrectors 3;
    nNonOrthogonalCorrectors 0;
    pRefCell 0;
    pRefValue 0;
}
""")

write("system/controlDict", "controlDict", f"""
application     demInterFoam;
startFrom       latestTime;
startTime       {args.tCouple:g};
stopAt          endTime;
endTime         {args.endTime:g};
// fixed CFD step, a whole number of DEM steps; the balls' forces from the
// fluid are held over the DEM steps of one CFD step
deltaT          {args.dt:g};
writeControl    runTime;
writeInterval   {args.writeInterval:g};
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
    // The dry tutorial's monitor (tutorials/demFoam/ballMill): shoulder,
    // toe, centre of mass, the balls' torque on the shell (every DEM step)
    charge
    {{
        type            chargeShape;
        libs            (demFunctionObjects);
        walls           (shell front back);
        origin          (0 0 0);
        axis            (0 0 1);
        shellRadius     {R:g};
        nBins           72;
        coverFraction   0.5;
        steadyStart     {args.steadyStart:g};
        nBatches        8;
        interval        0.05;
    }}
    // The fluid's force and moment on the shell about the axis (pressure
    // and viscous; the mixture density rho = alpha rho1 + (1 - alpha) rho2
    // and the full pressure p), every CFD step
    fluidForces
    {{
        type            forces;
        libs            (forces);
        writeControl    timeStep;
        writeInterval   1;
        log             false;
        patches         (shell);
        rho             rho;
        p               p;
        U               U;
        CofR            (0 0 0);
    }}
}}
""")

cells = (N * N + 4 * N * M) * NZ if args.mesh == "ogrid" else "snappy"
with open("case.info", "w") as f:
    f.write(f"tCouple {args.tCouple:g}\nsteadyStart {args.steadyStart:g}\nendTime {args.endTime:g}\nR {R:g}\nL {L:g}\nomega {OMEGA:.12g}\nmesh {args.mesh}\n"
            f"meshMotion {args.meshMotion}\ncellsAxial {NZ}\nsides {SIDE}\n"
            f"shellVolume {math.pi * R * R * L:.9g}\nslurryFraction {args.fill:.9g}\n"
            f"slurryVolume {target * L:.9g}\n")
print(f"fluid mesh: {args.mesh} ({cells} cells), {args.meshMotion}; slurry {target * L:.6f} m3"
      f" ({args.fill:.4f} of the shell)")
