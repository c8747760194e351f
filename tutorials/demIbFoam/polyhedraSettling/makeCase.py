#!/usr/bin/env python3
"""Make one case of the polyhedral settling study from template/.

Usage: makeCase.py NAME [-n N] [-refine L] [-band B] [-full] [-endTime T] [-height H]
                   [-tilt DEG] [-dir D]
  NAME       A<AR>C<C><H|V>  e.g. A1.25C20H (aspect ratio 1.25, 20 facets,
             horizontal release), A2.0C50V (vertical release),
             ellipsoid (the verification particle, see README.md), or
             cube (the convergence case: a cube, d_eq 10 mm, rho_p 1500, in
             a fluid of rho 1000, mu 0.015 Pa s, face-on; terminal Re ~170)
  -n N       cells per equivalent diameter near the body (default 5;
             ellipsoid 5; cube 8)
  -refine L  refinement levels around the body (default 1, cube 2; 0: uniform mesh
             of cells d/N everywhere): the base mesh has cells 2^L d/N and
             dynamicRefineFvMesh refines it L times on the field ibRefinement
             (cells within B of the bounding sphere), following the body
  -band B    width of the refined band beyond the bounding sphere, in
             equivalent diameters (default 1)
  -interval K  refine (and unrefine) every K time steps (default 4); the
             body moves 0.3 K near-body cells meanwhile, well inside the band
  -full      the published set-up: polyhedra d/dx = 12.5 (dx = 0.8 mm) in a
             0.1 x 0.1 x 0.32 m box released at z = 0.28 m; ellipsoid
             dx = 0.6 mm in the 0.07 x 0.07 x 0.3 m box
  -endTime T [s] (default: reduced 0.45 s polyhedra, 2 s ellipsoid;
             full 0.6 s polyhedra, 5 s ellipsoid)
  -height H  domain height [m] (release 0.02 m below the top; default
             reduced 0.22 m polyhedra, 0.12 m ellipsoid)
  -dir D     case folder (default cases/NAME)
  -tilt DEG  vertical release: initial angle of the long axis from the
             vertical (default 2; 0 = exactly vertical); horizontal: from
             the horizontal (default 0)

Writes the case folder (cases/NAME/): 0.orig, constant (ibProperties from template/,
transportProperties, demProperties, triSurface/shape.stl from polyhedronGen),
system (fvSchemes, fvSolution from template/, blockMeshDict, controlDict).
The particle is released at rest by a `type list` insertion in
constant/demProperties with its position and orientation (long axis = body
x, the axis of least moment: along world x for H, along world z, tilted by
-tilt about y, for V; `orientation (0 b 0)`, a rotation by b degrees about
world y), inserted by demIbFoam (demBackend polyDEM) at the start.
"""
import math
import os
import re
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
rhoF, muF = 1000.0, 1e-3           # water

args = sys.argv[1:]
if not args or args[0].startswith("-"):
    sys.exit(__doc__)
name = args[0]


def option(flag, default, conv=float):
    if flag in args:
        i = args.index(flag) + 1
        try:
            return conv(args[i])
        except (IndexError, ValueError):
            sys.exit("makeCase.py: %s needs a%s value, got '%s'"
                     % (flag, "n integer" if conv is int else conv is float and " number" or "",
                        args[i] if i < len(args) else ""))
    return default


full = "-full" in args
ellipsoid = name == "ellipsoid"
cube = name == "cube"
levels = option("-refine", 2 if cube else 1, int)
if levels < 0 or levels > 4:
    sys.exit("makeCase.py: -refine must be 0 ... 4, got %d" % levels)
band = option("-band", 1.0)
interval = option("-interval", 4, int)
if interval < 1:
    sys.exit("makeCase.py: -interval must be >= 1, got %d" % interval)
if band < 0:
    sys.exit("makeCase.py: -band must be >= 0, got %g" % band)
if ellipsoid:
    R, AR, rhoP = 3.5e-3, 1.30, 1031.0
    # three overlapping spheres of radius R on the x axis: their convex hull
    # is a capsule (cylinder of length 2s between hemispheres),
    # L / W = (2R + 2s) / 2R = AR
    s = (AR - 1.0) * R
    d = 2 * (3.0 / (4 * math.pi) * (4.0 / 3 * math.pi * R**3 + math.pi * R**2 * 2 * s)) ** (1 / 3.0)
    horizontal = True
    if full:
        L, H, z0, dx, tEnd, uRef = 0.07, 0.30, 0.27, 0.6e-3, 5.0, 0.06
    else:
        N = option("-n", 5.0)
        L, H, z0, dx, tEnd, uRef = 0.05, 0.12, 0.10, d / N, 2.0, 0.06
    writeEvery = 0.02
    tilt = 0.0
elif cube:
    if full:
        sys.exit("makeCase.py: -full is for the published cases, not the cube")
    # Terminal Re ~170 on d_eq (Holzer-Sommerfeld: 0.25 m/s face-on): the
    # regime of the fixed cube (tests/validation/ib/fixedCube, Re_a 100-200)
    AR, C, horizontal, d, rhoP = 1.0, "-", True, 0.010, 1500.0
    muF = 0.015
    N = option("-n", 8.0)
    L, H, z0, dx, tEnd, uRef = 0.08, 0.26, 0.24, d / N, 0.8, 0.3
    writeEvery = 0.01
    tilt = 0.0
else:
    m = re.fullmatch(r"A([0-9.]+)C([0-9]+)([HV])", name)
    if not m:
        sys.exit("makeCase.py: NAME must be A<AR>C<C><H|V> or ellipsoid, got '%s'" % name)
    AR, C, horizontal = float(m.group(1)), int(m.group(2)), m.group(3) == "H"
    d, rhoP = 0.010, 2650.0
    if full:
        L, H, z0, dx, tEnd, uRef = 0.10, 0.32, 0.28, 0.8e-3, 0.6, 0.8
    else:
        N = option("-n", 5.0)
        L, H, z0, dx, tEnd, uRef = 0.04, 0.22, 0.20, d / N, 0.45, 0.5
    writeEvery = 0.004
    tilt = 0.0 if horizontal else 2.0
tEnd = option("-endTime", tEnd)
if "-height" in args:
    H = option("-height", H)
    z0 = H - 0.02
tilt = option("-tilt", tilt)

# base mesh of cells 2^levels dx, refined levels times around the body
dxBase = dx * 2**levels
nxy, nz = int(round(L / dxBase)), int(round(H / dxBase))
if nxy < 2 or nz < 2:
    sys.exit("makeCase.py: base mesh %d x %d x %d: too coarse, lower -refine" % (nxy, nxy, nz))
dxBase = L / nxy
dx = dxBase / 2**levels
H = nz * dxBase
# deltaT: Courant number 0.3 at uRef (about the largest settling velocity),
# rounded down to a whole number of 1e-4 s (and of DEM steps)
dtDEM = 1e-5
dt = max(1e-4, math.floor(0.3 * dx / uRef / 1e-4 + 1e-9) * 1e-4)
if dt > 2e-3:
    dt = math.floor(0.3 * dx / uRef / 1e-3 + 1e-9) * 1e-3
nWrite = max(1, int(round(writeEvery / dt)))

case = os.path.abspath(option("-dir", os.path.join(here, "cases", name), str))
if os.path.exists(case):
    shutil.rmtree(case)
shutil.copytree(os.path.join(here, "template"), case)
os.makedirs(os.path.join(case, "constant", "triSurface"))
stl = os.path.join(case, "constant", "triSurface", "shape.stl")

# ---- shape ---------------------------------------------------------------
if ellipsoid:
    # 34 points on a capsule (Fibonacci spiral in its arc length from tip
    # to tip): every one a hull vertex, 2 x 34 - 4 = 64 triangular facets,
    # the engine's limit. With 34 points the hull is narrower than the
    # capsule, so the capsule's half-length s2 is chosen (bisection) so that
    # the hull's L / mean(W1, W2) along its principal axes (the measure of
    # polyhedronGen -AR) is AR; the hull is scaled to the volume of the
    # three spheres' hull.
    n = 34
    golden = math.pi * (3 - math.sqrt(5))

    def capsule(s2):
        arc = 2 * s2 + math.pi * R
        pts = []
        for i in range(n):
            a = (i + 0.5) / n * arc
            if a < math.pi * R / 2:                  # first cap
                th = a / R
                x, r = -s2 - R * math.cos(th), R * math.sin(th)
            elif a > 2 * s2 + math.pi * R / 2:       # second cap
                th = (arc - a) / R
                x, r = s2 + R * math.cos(th), R * math.sin(th)
            else:                                    # cylinder
                x, r = -s2 + (a - math.pi * R / 2), R
            phi = i * golden
            pts.append((x, r * math.cos(phi), r * math.sin(phi)))
        return pts

    def stlRatio(path):
        # L / mean(W1, W2) along the body (principal) axes of the STL
        v = set()
        for line in open(path):
            if line.strip().startswith("vertex"):
                v.add(tuple(float(x) for x in line.split()[1:4]))
        e = [max(p[k] for p in v) - min(p[k] for p in v) for k in range(3)]
        return e[0] / (0.5 * (e[1] + e[2]))

    obj = os.path.join(case, "constant", "triSurface", "points.obj")
    # rescaled to the volume of the three spheres' hull (the capsule)
    gen = ["polyhedronGen", "-shape", "hull", "-input", obj, "-d", repr(d), "-o", stl,
           "-properties"]

    def hull(s2):
        with open(obj, "w") as f:
            f.write("# convex hull of three spheres R = %g m, AR %g (see makeCase.py)\n"
                    % (R, AR))
            for p in capsule(s2):
                f.write("v %.9e %.9e %.9e\n" % p)
        if subprocess.run(gen, capture_output=True).returncode:
            sys.exit("polyhedronGen failed: " + " ".join(gen))
        return stlRatio(stl)

    lo, hi = 0.0, 2 * s
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if hull(mid) < AR else (lo, mid)
    hull(0.5 * (lo + hi))
    shapeNote = "ellipsoid-like: convex hull of three spheres R = %g mm, AR %g" % (1e3 * R, AR)
elif cube:
    gen = ["polyhedronGen", "-shape", "cube", "-d", repr(d), "-o", stl, "-properties"]
    shapeNote = "cube, d_eq %g mm (edge %.4g mm)" % (1e3 * d, 1e3 * d * (math.pi / 6) ** (1 / 3.0))
else:
    gen = ["polyhedronGen", "-shape", "settling", "-d", repr(d), "-AR", repr(AR),
           "-C", str(C), "-o", stl, "-properties"]
    shapeNote = "settling particle AR %g, C %d facets, d_eq %g mm" % (AR, C, 1e3 * d)
out = subprocess.run(gen, capture_output=True, text=True)
if out.returncode:
    sys.exit("polyhedronGen failed:\n" + out.stdout + out.stderr)
with open(os.path.join(case, "shape.log"), "w") as f:
    f.write(" ".join(gen) + "\n" + out.stdout)
props = dict(re.findall(r"^(\w+)\s+(\S+)", out.stdout, re.M))
dEq = float(props["equivalentDiameter"])
vol = float(props["volume"])

# ---- dictionaries --------------------------------------------------------
with open(os.path.join(case, "constant", "transportProperties"), "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
// %s: rho_f = %g kg/m3, mu_f = %g Pa s
nu  %.6e;
rho %g;
""" % ("viscous liquid" if cube else "water", rhoF, muF, muF / rhoF, rhoF))

with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
// generated by makeCase.py: base mesh d/dx = %.3g (dx = %.4g mm); %d refinement
// levels around the body: d/dx = %.3g there (constant/dynamicMeshDict)
vertices ((0 0 0) (%g 0 0) (%g %g 0) (0 %g 0) (0 0 %g) (%g 0 %g) (%g %g %g) (0 %g %g));
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
boundary ( walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); } );
""" % (dEq / dxBase, 1e3 * dxBase, levels, dEq / dx, L, L, L, L, H, L, H, L, L, H, L, H,
       nxy, nxy, nz))

# ---- refinement around the body (dynamicRefineFvMesh on ibRefinement, as
# tests/validation/ibRefinement.py): the cells within `band` of the body's
# bounding sphere are refined `levels` times every step, and those it has
# left are unrefined (unrefineLevel 0.5), so the body stays in cells d/N
with open(os.path.join(case, "constant", "dynamicMeshDict"), "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object dynamicMeshDict; }\n")
    if levels == 0:
        f.write("dynamicFvMesh staticFvMesh;\n")
    else:
        f.write("""// generated by makeCase.py: %d levels, cells d/%.3g within %g d of the
// bounding sphere
dynamicFvMesh dynamicRefineFvMesh;
dynamicRefineFvMeshCoeffs
{
    refineInterval %d; field ibRefinement;
    lowerRefineLevel 0.5; upperRefineLevel 1.5; unrefineLevel 0.5;
    nBufferLayers 1; maxRefinement %d; maxCells 20000000;
    correctFluxes ((phi none)); dumpLevel true;
}
""" % (levels, dEq / dx, band, interval, levels))
if levels > 0:
    ibp = os.path.join(case, "constant", "ibProperties")
    txt = open(ibp).read()
    txt += "// refined band beyond the bounding sphere: %g d (makeCase.py -band)\nrefinement { band %.9g; }\n" % (band, band * dEq)
    with open(ibp, "w") as f:
        f.write(txt)
    fvs = os.path.join(case, "system", "fvSolution")
    txt = open(fvs).read()
    a = "    pFinal { $p; relTol 0.005; }\n"
    assert a in txt, "template/system/fvSolution: no pFinal line to add pcorr after"
    # CorrectPhi after each mesh change (demIbFoam) needs a pcorr solver
    txt = txt.replace(a, a + "    \"pcorr.*\" { $p; tolerance 1e-9; relTol 0; }\n")
    with open(fvs, "w") as f:
        f.write(txt)

# Release orientation: rotation by releaseAngle about world y, which turns
# body x (the long axis) to (cos a, 0, -sin a)
if horizontal:
    releaseAngle = tilt               # long axis along world x
else:
    releaseAngle = 90.0 - tilt        # long axis tilt degrees from world z
pos = (L / 2, L / 2, z0)

demProps = """FoamFile { version 2.0; format ascii; class dictionary; object demProperties; }
// %s, rho_p = %g kg/m3.
// Released at rest at the given position and orientation (rotation about
// world y; body x, the long axis, along world x for H, near world z for V).
// Contact only at the bottom (not studied): soft, so that the DEM step is
// 1e-5 s (the published E = 0.1 GPa needs 1e-7 s); friction 0.2 and
// restitution 0.3 as published.
device          cpu;
timeStep        %g;
gravity         (0 0 -9.81);
contactModel    { law overlapVolume; volumetricStiffness 3e8; tangentialStiffnessRatio 0.2857; }
materials       { solid { youngsModulus 5e6; poissonsRatio 0.3; density %g; } }
interactions    { default { restitution 0.3; friction 0.2; } }
particleTypes   { particle { shape polyhedron; material solid; geometry { type stl; file "shape.stl"; } } }
walls
{
    bottom { type plane; point (0 0 0); normal (0 0 1); material solid; }
}
insertion
{
    release
    {
        type list; particleType particle;
        particles ( { position (%.17g %.17g %.17g); orientation (0 %.17g 0); } );
    }
}
output { format ascii; vtk true; }
""" % ((shapeNote, rhoP, dtDEM, rhoP) + pos + (releaseAngle,))
with open(os.path.join(case, "constant", "demProperties"), "w") as f:
    f.write(demProps)


def controlDict(endTime, app):
    with open(os.path.join(case, "system", "controlDict"), "w") as f:
        f.write("""FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
// generated by makeCase.py %s
application %s;
startFrom startTime; startTime 0; stopAt endTime; endTime %g;
deltaT %g;
// frequent writes: the DEM state (angular velocity, orientation) is written
// with the fields; Allrun deletes the fields after the post-processing
writeControl timeStep; writeInterval %d;
writeFormat binary; writePrecision 12; timeFormat general; timePrecision 6;
runTimeModifiable false;
""" % (" ".join(sys.argv[1:]), app, endTime, dt, nWrite))


controlDict(tEnd, "demIbFoam")
mP = rhoP * vol
with open(os.path.join(case, "caseInfo"), "w") as f:
    f.write("name %s\nAR %g\nfacets %s\nrelease %s\ntilt %g\nrhoP %g\nrhoF %g\nmuF %g\n"
            "dEq %.9g\nvolume %.9g\nmass %.9g\nnetWeight %.9g\nL %g\nH %g\nz0 %g\n"
            "dx %.9g\ndOverDx %.4g\ncells %d\ndeltaT %g\nendTime %g\nfull %d\n"
            "refine %d\nband %g\ninterval %d\ndxBase %.9g\n"
            % (name, AR, "-" if ellipsoid else C, "H" if horizontal else "V", tilt,
               rhoP, rhoF, muF, dEq, vol, mP, (rhoP - rhoF) * vol * 9.81, L, H, z0,
               dx, dEq / dx, nxy * nxy * nz, dt, tEnd, full, levels, band, interval, dxBase))
meshNote = ("uniform mesh" if levels == 0 else
            "%d refinement levels within %g d of the bounding sphere, every %d steps"
            % (levels, band, interval))
print("%s: %s; base mesh %d x %d x %d = %d cells (d/dx %.3g), %s: d/dx %.3g (dx %.3g mm)"
      " near the body; deltaT %g (Co 0.3 at %g m/s), endTime %g, release at z = %g m %s"
      " (tilt %g deg)"
      % (name, shapeNote, nxy, nxy, nz, nxy * nxy * nz, dEq / dxBase, meshNote,
         dEq / dx, 1e3 * dx, dt, uRef, tEnd, z0, "horizontal" if horizontal else "vertical",
         tilt))
