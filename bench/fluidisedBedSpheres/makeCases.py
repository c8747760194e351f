#!/usr/bin/env python3
"""Cases for bench/fluidisedBedSpheres/run: one fluidised bed of spheres,
coupled in demPimpleFoam, with two DEMs.

    makeCases.py WORK N W TPOUR TFLOW U

WORK/pour      demFoam pours N spheres (d = 1 mm, rho_p 2000) into a
               W x W box on a floor 4 mm above the inlet (polyDEM, TPOUR s);
               run here (the bench does not time it);
WORK/polyDEM   demPimpleFoam, demBackend polyDEM, from the poured state;
WORK/liggghts  the same with demBackend liggghts: the poured positions given
               to LIGGGHTS (create_atoms single) with the same Hertz-Mindlin
               spheres, walls, gravity and time step;
WORK/liggghts-np2   a copy of WORK/liggghts with system/decomposeParDict
               (simple 1 1 2: the fluid split at mid-height); the bench
               decomposes and runs it on 2 ranks.
Fluid: the liggghtsErgunBed.py / ergunBed.py column (gas rho 10, nu 1.5e-4;
Gidaspow + pressureGradient, setI, divided void fraction, implicit; 1D
column of 2 mm cells, H = 40 mm), gas at U m/s from the start for TFLOW s,
deltaT 1e-4 s, 10 DEM steps of 1e-5 s per fluid step.
"""
import os
import shutil
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tests", "validation"))
import hedracase as hc      # noqa: E402
import liggghtscase as lc   # noqa: E402

work, N, W, tPour, tFlow, U = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), \
    float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])
d, rhoP, rho, nu = 1e-3, 2000.0, 10.0, 1.5e-4
H, zFloor, dtDem, dtF = 0.04, 0.004, 1e-5, 1e-4
tstr = f"{tPour:g}"

pour = os.path.join(work, "pour")
shutil.rmtree(pour, ignore_errors=True)
os.makedirs(pour)
hc.block_mesh(pour, (0, 0, 0), (W, W, H), (1, 1, 20),
              {"inlet": ("patch", ["zmin"]), "outlet": ("patch", ["zmax"]),
               "sides": ("empty", ["xmin", "xmax", "ymin", "ymax"])})
walls = {"floor": ((0, 0, zFloor), (0, 0, 1)),
         "x0": ((0, 0, 0), (1, 0, 0)), "x1": ((W, 0, 0), (-1, 0, 0)),
         "y0": ((0, 0, 0), (0, 1, 0)), "y1": ((0, W, 0), (0, -1, 0))}
hc.dem_properties(pour, dtDem, rhoP, d, walls,
                  hc.random_fill("bed", N, (0, 0, zFloor + 1e-4), (W, W, H)),
                  E=5e6, restitution=0.3, friction=0.5)
hc.transport(pour, nu, rho)
hc.schemes_solution(pour, nCorr=2, nOuter=1)
hc.control_dict(pour, tPour, 1e-3, tPour)
cd = os.path.join(pour, "system/controlDict")
txt = open(cd).read().replace("demPimpleFoam", "demFoam")
open(cd, "w").write(txt)
hc.run("blockMesh", pour, "log.blockMesh")
hc.run("demFoam", pour, "log.demFoam", timeout=3600)

hc.fields(pour,
          {"inlet": f"type fixedValue; value uniform (0 0 {U});",
           "outlet": "type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0);",
           "sides": "type empty;"},
          {"inlet": "type fixedFluxPressure;", "outlet": "type fixedValue; value uniform 0;",
           "sides": "type empty;"}, time=tstr)
fo = """functions
{
    inletP
    {
        type surfaceFieldValue; libs ("libfieldFunctionObjects.so");
        writeControl timeStep; writeInterval 1; log false;
        writeFields false; regionType patch; name inlet;
        operation areaAverage; fields (p);
    }
}
"""
# One write at the end only: the bench times the stepping, not the output
hc.control_dict(pour, tPour + tFlow, dtF, tFlow, extra=fo)
COUPLING = """formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel divided;
smoothingModel none;
forceModels (Gidaspow pressureGradient);
demStepsPerFluidStep 10;
"""


def poured(path):
    lines = open(path).read().split("\n")
    i = lines.index("data")
    n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
    rows = [l.split() for l in lines[i + 1:i + 1 + n]]
    return [tuple(float(x) for x in v[7:10]) for v in sorted(rows, key=lambda v: int(v[0]))]


positions = poured(os.path.join(pour, tstr, "polyDEM/state"))
ign = shutil.ignore_patterns("postProcessing", "log.*")
poly = os.path.join(work, "polyDEM")
lig = os.path.join(work, "liggghts")
for c in (poly, lig, lig + "-np2"):
    shutil.rmtree(c, ignore_errors=True)
shutil.copytree(pour, poly, ignore=ign)
shutil.copytree(pour, lig, ignore=shutil.ignore_patterns("polyDEM", "postProcessing", "log.*"))
hc.coupling(poly, COUPLING)
extra = "".join(
    f"fix {n} all wall/gran model hertz tangential history primitive type 1 {p} {v}\n"
    for n, p, v in (("x0", "xplane", 0.0), ("x1", "xplane", W), ("y0", "yplane", 0.0),
                    ("y1", "yplane", W)))
lc.script(lig, ((0, 0, 0), (W, W, H)), dtDem, rhoP, d, positions, floor_z=zFloor,
          restitution=0.3, couple_every=10, extra=extra)
hc.coupling(lig, COUPLING + lc.coupling_lines())
shutil.copytree(lig, lig + "-np2")
print(f"cases: {len(positions)} spheres poured in {W * 1e3:g} x {W * 1e3:g} mm, "
      f"flow {tstr} -> {tPour + tFlow:g} s at U = {U} m/s")
