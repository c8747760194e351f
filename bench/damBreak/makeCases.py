#!/usr/bin/env python3
"""Cases for bench/damBreak/run.

    makeCases.py WORK N END

WORK/interFoam      OpenFOAM v1912's laminar damBreak tutorial
                    (tutorials/multiphase/interFoam/laminar/damBreak/damBreak,
                    2D, 2268 cells, adjustable time step maxCo 1), as
                    tests/validation/vofDamBreakInterFoam.py builds it, to
                    its endTime 1 s, written only at the end;
WORK/demInterFoam   the same case for demInterFoam: couplingProperties and a
                    demProperties with no particles added (eps = 1);
WORK/rocks          a 3D dam break onto a pile of N polyhedral rocks
                    (unresolved mode): tank 0.4 x 0.08 x 0.24 m open at the
                    top, cells of 10 mm (40 x 8 x 24 = 7680), water column
                    0.1 m wide, 0.15 m high at x = 0; rocks (rockPile's
                    random convex shapes: 12 vertices, 20 faces, d_eq 6 mm,
                    2700 kg/m3, 10 shapes) filled at random into
                    0.2 < x < 0.3, z < 0.12 m (400 rocks; higher for more)
                    at t = 0, they fall onto the
                    floor and the water reaches them at ~0.15 s; fixed
                    deltaT 1e-3 s, 10 DEM steps of 1e-4 s per fluid step,
                    to END s;
WORK/noRocks        the same case with no particles (insertion empty).
"""
import os
import re
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tests", "validation"))
import hedracase as hc      # noqa: E402
import vofcase as vc        # noqa: E402

work, N, END = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
foam = os.environ.get("FOAM_TUTORIALS") or os.path.join(
    os.environ.get("HEDRA_CACHE", os.path.expanduser("~/.cache/hedra")), "openfoam-v1912-src/tutorials")
SRC = os.path.join(foam, "multiphase/interFoam/laminar/damBreak/damBreak")
if not os.path.isdir(SRC):
    sys.exit(f"makeCases.py: OpenFOAM's damBreak tutorial not found at {SRC}"
             " (source etc/bashrc; etc/install-dependencies fetches the OpenFOAM sources)")


def damBreak(case, app):
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(SRC, case)
    cd = os.path.join(case, "system/controlDict")
    txt = open(cd).read()
    txt = re.sub(r"application\s+\w+;", f"application {app};", txt)
    txt = re.sub(r"writeInterval\s+[\d.]+;", "writeInterval 1;", txt)
    txt = re.sub(r"runTimeModifiable\s+\w+;", "runTimeModifiable false;", txt)
    txt = txt.replace('#sinclude   "sampling"', "")
    open(cd, "w").write(txt)
    shutil.copy(os.path.join(case, "0/alpha.water.orig"), os.path.join(case, "0/alpha.water"))
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("setFields", case, "log.setFields")


COUPLING = """couplingMode unresolved;
demBackend polyDEM;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel divided;
dividedCoeffs { nShells 2; alphaMin 0.1; }
smoothingModel none;
submergedVolume interfacePlane;
forceModels (Gidaspow freeSurfacePressure);
"""

# (a) the 2D tutorial, both solvers
damBreak(os.path.join(work, "interFoam"), "interFoam")
new = os.path.join(work, "demInterFoam")
damBreak(new, "demInterFoam")
hc.coupling(new, COUPLING)
hc.foamfile(os.path.join(new, "constant/demProperties"), "demProperties", """device cpu;
timeStep 1e-5;
gravity (0 -9.81 0);
contactModel { law hertzMindlin; rolling none; }
materials { mat { youngsModulus 1e7; poissonsRatio 0.3; density 2500; } }
interactions { default { restitution 0.5; friction 0.5; } }
particleTypes { grain { shape sphere; material mat; diameter 0.005; } }
walls { floor { type plane; point (0 0 0); normal (0 1 0); material mat; } }
insertion { }
output { format ascii; vtk false; }
""")

# (b) 3D dam break onto a rock pile, and the same without rocks
LO, HI, NC = (0.0, 0.0, 0.0), (0.4, 0.08, 0.24), (40, 8, 24)
DT = 1e-3


def rocks_case(case, n):
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    vc.closed_tank(case, LO, HI, NC, open_top=True)
    # water column x < 0.1 m, z < 0.15 m: whole cells (cell size 10 mm)
    vals = []
    for k in range(NC[2]):
        for j in range(NC[1]):
            for i in range(NC[0]):
                vals.append("1" if (i + 0.5) * 0.01 < 0.1 and (k + 0.5) * 0.01 < 0.15 else "0")
    hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water",
                "dimensions [0 0 0 0 0 0 0];\ninternalField nonuniform List<scalar>\n"
                f"{len(vals)}\n(\n" + "\n".join(vals) + "\n);\n"
                "boundaryField\n{\n    walls { type zeroGradient; }\n"
                "    atmosphere { type inletOutlet; inletValue uniform 0; value uniform 0; }\n}\n",
                cls="volScalarField")
    vc.vof_dicts(case, END, DT, END)
    # damBreak's solver settings (vof_dicts' are a test's, to round-off)
    hc.foamfile(os.path.join(case, "system/fvSolution"), "fvSolution", """
solvers
{
    "alpha.water.*"
    {
        nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1;
        MULESCorr yes; nLimiterIter 3;
        solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0;
    }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 0; }
    p_rgh { solver PCG; preconditioner DIC; tolerance 1e-7; relTol 0.05; }
    p_rghFinal { $p_rgh; relTol 0; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-6; relTol 0; }
}
PIMPLE
{
    momentumPredictor no;
    nOuterCorrectors 1;
    nCorrectors 3;
    nNonOrthogonalCorrectors 0;
}
""")
    hc.coupling(case, COUPLING)
    # fill region: 0.116 m high per 400 rocks (a random fill of their
    # bounding spheres to ~25 %), at most to 4 mm under the top
    ztop = min(0.236, 0.004 + 0.116 * n / 400)
    insertion = "" if n == 0 else f"""    pile
    {{
        type randomFill; particleType rocks; number {n}; seed 1;
        region {{ type box; min (0.2 0.004 0.004); max (0.3 0.076 {ztop:.4g}); }}
    }}
"""
    walls = ""
    for name, (pt, nv) in {
        "floor": (LO, (0, 0, 1)), "xmin": (LO, (1, 0, 0)), "xmax": (HI, (-1, 0, 0)),
        "ymin": (LO, (0, 1, 0)), "ymax": (HI, (0, -1, 0)), "top": (HI, (0, 0, -1)),
    }.items():
        walls += (f"    {name} {{ type plane; point ({pt[0]} {pt[1]} {pt[2]});"
                  f" normal ({nv[0]} {nv[1]} {nv[2]}); material granite; }}\n")
    hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", f"""device cpu;
timeStep 1e-4;
gravity (0 0 -9.81);
contactModel {{ law overlapVolume; volumetricStiffness 4e7; tangentialStiffnessRatio 0.2857; }}
materials {{ granite {{ youngsModulus 5e9; poissonsRatio 0.25; density 2700; }} }}
interactions {{ default {{ restitution 0.3; friction 0.5; }} }}
particleTypes
{{
    rocks
    {{
        shape polyhedron; material granite;
        geometry {{ type rock; equivalentDiameter 6e-3; elongation 0.8; flatness 0.8;
                   points 12; seed 3; shapes 10; }}
    }}
}}
walls
{{
{walls}}}
insertion
{{
{insertion}}}
output {{ format ascii; vtk false; }}
""")
    hc.run("blockMesh", case, "log.blockMesh")


rocks_case(os.path.join(work, "rocks"), N)
rocks_case(os.path.join(work, "noRocks"), 0)
