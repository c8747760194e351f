"""Helpers for the demInterFoam validation cases (two-phase, water/air):
uniform box meshes, an initial water field that accounts for axis-aligned
blocks, the VOF dictionaries, the water-volume log. Uses hedracase."""
import math
import os
import re
import sys

import hedracase as hc

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "../../tutorials/demInterFoam/common"))
import rotatingDrum  # noqa: E402

RHO_W, RHO_A = 1000.0, 1.0
NU_W, NU_A = 1e-6, 1.48e-5


def overlap1(a0, a1, b0, b1):
    return max(0.0, min(a1, b1) - max(a0, b0))


def water_field(case, lo, hi, n, level, boxes=()):
    """alpha.water with the free surface at z = level and the blocks of
    'boxes' ((lo, hi) axis-aligned) excluded from the fluid: alpha is the
    water part of the fluid in each cell, so the water volume is exactly
    that of the flat surface minus the blocks' submerged volume."""
    dx = [(hi[k] - lo[k]) / n[k] for k in range(3)]
    vals = []
    for k in range(n[2]):
        z0 = lo[2] + k * dx[2]
        z1 = z0 + dx[2]
        for j in range(n[1]):
            y0 = lo[1] + j * dx[1]
            y1 = y0 + dx[1]
            for i in range(n[0]):
                x0 = lo[0] + i * dx[0]
                x1 = x0 + dx[0]
                V = dx[0] * dx[1] * dx[2]
                below = dx[0] * dx[1] * overlap1(z0, z1, z0 - 1, level)
                solid = solidBelow = 0.0
                for bl, bh in boxes:
                    a = overlap1(x0, x1, bl[0], bh[0]) * overlap1(y0, y1, bl[1], bh[1])
                    solid += a * overlap1(z0, z1, bl[2], bh[2])
                    solidBelow += a * overlap1(z0, z1, bl[2], min(bh[2], level))
                fluid = V - solid
                w = below - solidBelow
                # A cell a block fills holds no fluid, but the solver keeps
                # eps = alphaMin of fictitious fluid there: it gets the water
                # fraction of the undisturbed level (below/V), so that rho
                # stays layered; alpha 0 there would be a bubble in the
                # water, pushed up by buoyancy (gh grad rho has no balancing
                # p_rgh) and pushing the block with it
                vals.append(min(max(w / fluid, 0.0), 1.0) if fluid > 1e-14 * V else below / V)
    body = ("dimensions [0 0 0 0 0 0 0];\ninternalField nonuniform List<scalar>\n"
            f"{len(vals)}\n(\n" + "\n".join(f"{v:.17g}" for v in vals) + "\n);\n"
            "boundaryField\n{\n    walls { type zeroGradient; }\n"
            "    atmosphere { type inletOutlet; inletValue uniform 0; value uniform 0; }\n}\n")
    hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water", body,
                cls="volScalarField")


def closed_tank(case, lo, hi, n, open_top=False):
    """Box tank of walls; open_top: the top is an atmosphere (total
    pressure 0, air in and out), so the fluid volume in the tank may change
    (a block that fills cells, where eps is clipped at alphaMin, changes the
    solid volume the mesh holds as it moves)."""
    sides = ["xmin", "xmax", "ymin", "ymax", "zmin"] + ([] if open_top else ["zmax"])
    patches = {"walls": ("wall", sides)}
    top = ""
    if open_top:
        patches["atmosphere"] = ("patch", ["zmax"])
    hc.block_mesh(case, lo, hi, n, patches)
    Utop = "    atmosphere { type pressureInletOutletVelocity; value uniform (0 0 0); }\n" if open_top else ""
    ptop = "    atmosphere { type totalPressure; p0 uniform 0; value uniform 0; }\n" if open_top else ""
    hc.foamfile(os.path.join(case, "0/U"), "U",
                "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
                "boundaryField\n{\n    walls { type noSlip; }\n" + Utop + "}\n", cls="volVectorField")
    hc.foamfile(os.path.join(case, "0/p_rgh"), "p_rgh",
                "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
                "boundaryField\n{\n    walls { type fixedFluxPressure; value uniform 0; }\n" + ptop + "}\n",
                cls="volScalarField")


def vof_dicts(case, end, dt, write, maxCo=0.5, adjust=False, pTol=1e-12, limiterIter=5):
    body = f"""application demInterFoam;
startFrom latestTime;
startTime 0;
stopAt endTime;
endTime {end};
deltaT {dt};
writeControl {"adjustableRunTime" if adjust else "runTime"};
writeInterval {write};
purgeWrite 0;
writeFormat ascii;
writePrecision 14;
writeCompression off;
timeFormat general;
timePrecision 8;
runTimeModifiable false;
adjustTimeStep {"yes" if adjust else "no"};
maxCo {maxCo};
maxAlphaCo {maxCo};
maxDeltaT 1;
"""
    hc.foamfile(os.path.join(case, "system/controlDict"), "controlDict", body)
    hc.foamfile(os.path.join(case, "system/fvSchemes"), "fvSchemes", """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U)  Gauss linearUpwind grad(U);
    div(phi,alpha)  Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
    hc.foamfile(os.path.join(case, "system/fvSolution"), "fvSolution", f"""
solvers
{{
    "alpha.water.*"
    {{
        nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1;
        MULESCorr yes; nLimiterIter {limiterIter};
        solver smoothSolver; smoother symGaussSeidel; tolerance 1e-12; relTol 0;
    }}
    "pcorr.*" {{ solver PCG; preconditioner DIC; tolerance {pTol}; relTol 0; }}
    p_rgh {{ solver PCG; preconditioner DIC; tolerance {pTol}; relTol 0; }}
    p_rghFinal {{ $p_rgh; relTol 0; }}
    "U.*" {{ solver smoothSolver; smoother symGaussSeidel; tolerance 1e-12; relTol 0; }}
}}
PIMPLE
{{
    momentumPredictor no;
    nOuterCorrectors 1;
    nCorrectors 3;
    nNonOrthogonalCorrectors 0;
    pRefCell 0;
    pRefValue 0;
}}
""")
    hc.foamfile(os.path.join(case, "constant/transportProperties"), "transportProperties", f"""
phases (water air);
water {{ transportModel Newtonian; nu {NU_W}; rho {RHO_W}; }}
air {{ transportModel Newtonian; nu {NU_A}; rho {RHO_A}; }}
sigma 0.07;
""")
    hc.foamfile(os.path.join(case, "constant/turbulenceProperties"),
                "turbulenceProperties", "simulationType laminar;\n")
    hc.foamfile(os.path.join(case, "constant/g"), "g",
                "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n",
                cls="uniformDimensionedVectorField")


def read_water(case):
    """Rows of postProcessing/demInterFoam/<t0>/waterVolume.dat:
    t, water volume, min alpha, max alpha, solid volume, nParticles."""
    base = os.path.join(case, "postProcessing/demInterFoam")
    rows = []
    for t in sorted(os.listdir(base), key=float):
        with open(os.path.join(base, t, "waterVolume.dat")) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                rows.append([float(x) for x in line.split()])
    return rows


def dem_blocks(case, dt, density, blocks, size, tank, extra_types="", E=None,
               orientations=None):
    """demProperties for boxes of the given size (x y z) placed by 'blocks'
    (list of centre positions), in a tank of planes tank = (lo, hi);
    orientations: None (axis-aligned) or each block's list-insertion
    orientation (rx ry rz) [deg]."""
    lo, hi = tank
    orient = [""] * len(blocks) if orientations is None else [
        f" orientation ({o[0]} {o[1]} {o[2]});" for o in orientations]
    plist = "\n".join(f"            {{ position ({p[0]} {p[1]} {p[2]});{o} }}"
                      for p, o in zip(blocks, orient))
    walls = ""
    for name, (pt, nv) in {
        "floor": (lo, (0, 0, 1)), "xmin": (lo, (1, 0, 0)), "xmax": (hi, (-1, 0, 0)),
        "ymin": (lo, (0, 1, 0)), "ymax": (hi, (0, -1, 0)), "top": (hi, (0, 0, -1)),
    }.items():
        walls += (f"    {name} {{ type plane; point ({pt[0]} {pt[1]} {pt[2]});"
                  f" normal ({nv[0]} {nv[1]} {nv[2]}); material mat; }}\n")
    body = f"""device cpu;
timeStep {dt};
gravity (0 0 -9.81);
contactModel {{ law overlapVolume; volumetricStiffness 1e6; tangentialStiffnessRatio 0.2857; }}
materials {{ mat {{ youngsModulus 1e8; poissonsRatio 0.3; density {density}; }} }}
interactions {{ default {{ restitution 0.3; friction 0.3; }} }}
particleTypes {{ block {{ shape polyhedron; material mat;
    geometry {{ type box; size ({size[0]} {size[1]} {size[2]}); }} }} }}
walls
{{
{walls}}}
insertion
{{
    blocks
    {{
        type list;
        particleType block;
        particles
        (
{plist}
        );
    }}
}}
output {{ format ascii; vtk false; }}
"""
    hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", body)


def box_walls(lo, hi):
    """The six plane DEM walls of a closed box tank (hc.dem_properties format)."""
    return {"floor": (lo, (0, 0, 1)), "xmin": (lo, (1, 0, 0)), "xmax": (hi, (-1, 0, 0)),
            "ymin": (lo, (0, 1, 0)), "ymax": (hi, (0, -1, 0)), "top": (hi, (0, 0, -1))}


def floating_block_coupling(case, method="interfacePlane", solid="centre"):
    """couplingProperties of an unresolved floating block (vofFloatingBlocks,
    vofRightingMoment): exactOverlap void fraction, Gidaspow drag and
    freeSurfacePressure with the given submergedVolume method; solid: the
    solidVelocity (centre | rigidBody)."""
    hc.coupling(case, f"""couplingMode unresolved;
solidVelocity {solid};
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
submergedVolume {method};
forceModels (Gidaspow freeSurfacePressure);
""")


# Unresolved spheres falling into water (vofWaterVolume, vofAdjustTimeStep)
SPHERES_COUPLING = """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel divided;
smoothingModel none;
forceModels (SchillerNaumann freeSurfacePressure);
"""


def coupling_without_particles(case, up, floor=True):
    """couplingProperties and demProperties of an unresolved demInterFoam
    run with the coupling switched on and no particle in it (the solver the
    particle cases use, on a flow without them); up: the unit vector
    against gravity, e.g. (0, 0, 1); floor: a plane wall through the origin
    normal to it (none for a domain around the origin, a drum)."""
    hc.coupling(case, """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
forceModels (SchillerNaumann freeSurfacePressure);
""")
    g = " ".join(f"{-9.81 * u:g}" if u else "0" for u in up)
    n = " ".join(f"{u:g}" for u in up)
    wall = f"floor {{ type plane; point (0 0 0); normal ({n}); material mat; }} " if floor else ""
    hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", f"""device cpu;
timeStep 1e-5;
gravity ({g});
contactModel {{ law hertzMindlin; rolling none; }}
materials {{ mat {{ youngsModulus 1e7; poissonsRatio 0.3; density 2500; }} }}
interactions {{ default {{ restitution 0.5; friction 0.5; }} }}
particleTypes {{ grain {{ shape sphere; material mat; diameter 0.005; }} }}
walls {{ {wall}}}
insertion {{ }}
output {{ format ascii; vtk false; }}
""")


def _rotation(q):
    """Rotation matrix of the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def submerged_box_volume(centre, q, size, level):
    """The submerged volume of _submerged_box (below)."""
    return _submerged_box(centre, q, size, level)[0]


def submerged_box_centroid(centre, q, size, level):
    """Centroid of the part of the box below z = level (None if none is)."""
    return _submerged_box(centre, q, size, level)[1]


def _submerged_box(centre, q, size, level):
    """Exact volume of the box of edges 'size' (body frame), centred at
    'centre' and turned by the quaternion q (w, x, y, z), below the plane
    z = level: each face polygon clipped to z <= level (Sutherland-Hodgman),
    the cut closed by the polygon of the plane inside the box, volume by the
    divergence theorem (sum of the faces' signed cone volumes about the
    centre), with its centroid (the cones' tetrahedra: each at its
    centroid, the mean of its four corners)."""
    R = _rotation(q)
    h = [0.5 * a for a in size]

    def point(s):
        return [centre[i] + sum(R[i][j] * s[j] * h[j] for j in range(3)) for i in range(3)]

    faces = []
    for ax in range(3):
        for sgn in (-1, 1):
            u, v = [a for a in range(3) if a != ax]
            corners = []
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                s = [0, 0, 0]
                s[ax], s[u], s[v] = sgn, a, b
                corners.append(point(s))
            faces.append(corners)
    clipped, cut = [], []
    for poly in faces:
        out = []
        for k in range(len(poly)):
            a, b = poly[k], poly[(k + 1) % len(poly)]
            ina, inb = a[2] <= level, b[2] <= level
            if ina:
                out.append(a)
            if ina != inb:
                t = (level - a[2]) / (b[2] - a[2])
                x = [a[i] + t * (b[i] - a[i]) for i in range(3)]
                out.append(x)
                cut.append(x)
        if len(out) >= 3:
            clipped.append(out)
    vol = 0.0
    mom = [0.0, 0.0, 0.0]

    def cone(poly):
        # volume of the cone from the centre over the (convex) polygon, and
        # its first moment about the centre; both signed by the polygon's
        # turning, the same for all of its fan's tetrahedra
        c = centre
        v, m = 0.0, [0.0, 0.0, 0.0]
        for k in range(1, len(poly) - 1):
            a, b, d = poly[0], poly[k], poly[k + 1]
            a = [a[i] - c[i] for i in range(3)]
            b = [b[i] - c[i] for i in range(3)]
            d = [d[i] - c[i] for i in range(3)]
            t = (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
                 + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6.0
            v += t
            for i in range(3):
                m[i] += t * (a[i] + b[i] + d[i]) / 4.0
        return v, m

    def add(poly, sign):
        # sign: +1 for a cone counted positive, -1 negative (abs of the
        # polygon's own turning taken first)
        nonlocal vol
        v, m = cone(poly)
        f = sign * (1 if v >= 0 else -1)
        vol += f * v
        for i in range(3):
            mom[i] += f * m[i]

    # the box's faces face away from its centre: their cones count positive;
    # the cap faces up, towards the centre when the centre is above it
    for poly in clipped:
        add(poly, 1)
    if len(cut) >= 3:
        mx = sum(p[0] for p in cut) / len(cut)
        my = sum(p[1] for p in cut) / len(cut)
        cut.sort(key=lambda p: math.atan2(p[1] - my, p[0] - mx))
        # the cap faces up (the submerged part lies below it)
        add(cut, 1 if level >= centre[2] else -1)
    if vol <= 0.0:
        return 0.0, None
    return vol, [centre[i] + mom[i] / vol for i in range(3)]



def submerged_from_water(centre, q, size, water, area):
    """Level and submerged volume of a box floating in a tank of horizontal
    area 'area' holding the water volume 'water' outside it (flat
    surface): water = level area - V_sub(level), solved by bisection."""
    lo, hi = centre[2] - 2 * max(size), centre[2] + 2 * max(size)
    lo = min(lo, water / area - max(size) ** 3 / area)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if mid * area - submerged_box_volume(centre, q, size, mid) < water:
            lo = mid
        else:
            hi = mid
    level = 0.5 * (lo + hi)
    return level, submerged_box_volume(centre, q, size, level)


def refine_at_surface(case):
    """constant/dynamicMeshDict: dynamicRefineFvMesh refining one level at
    the free surface (alpha.water between 0.001 and 0.999, one buffer
    layer), unrefining elsewhere; demInterFoam's fluxes listed without
    correction (the solver rebuilds them: docs/models.md, refining meshes)."""
    hc.foamfile(os.path.join(case, "constant/dynamicMeshDict"), "dynamicMeshDict", """
dynamicFvMesh dynamicRefineFvMesh;
dynamicRefineFvMeshCoeffs
{
    refineInterval 1; field alpha.water;
    lowerRefineLevel 0.001; upperRefineLevel 0.999; unrefineLevel 10;
    nBufferLayers 1; maxRefinement 1; maxCells 2000000;
    correctFluxes
    (
        (phi none) (nHatf none) (rhoPhi none) (alphaPhi0.water none) (ghf none)
        (alphaPhiUn none) (epsf none) (phiInterstitial none) (phiInterstitial_0 none)
    );
    dumpLevel false;
}
""")


RESOLVED_CUBE_COUPLING = """couplingMode resolved;
demBackend polyDEM;
internalFluid integrated;
directForcing
{
    interface penalised;
    nSubSamples 8;
}
"""


def refine_around_bodies(case, max_level=1, free_surface=False):
    """constant/dynamicMeshDict for demInterFoam's resolved mode:
    dynamicRefineFvMesh on the field ibRefinement (ibRefinementIndicator:
    the cells near the bodies, and with free_surface the interface cells),
    max_level levels, unrefining where the bodies have left."""
    hc.foamfile(os.path.join(case, "constant/dynamicMeshDict"), "dynamicMeshDict", f"""
dynamicFvMesh dynamicRefineFvMesh;
dynamicRefineFvMeshCoeffs
{{
    refineInterval 1; field ibRefinement;
    lowerRefineLevel 0.5; upperRefineLevel 1.5; unrefineLevel 0.5;
    nBufferLayers 1; maxRefinement {max_level}; maxCells 2000000;
    correctFluxes
    (
        (phi none) (nHatf none) (rhoPhi none) (alphaPhi0.water none) (ghf none)
        (alphaPhiUn none) (epsf none) (phiWater none)
        (phiInterstitial none) (phiInterstitial_0 none)
    );
    dumpLevel false;
}}
""")


def resolved_cube(name, rho_b, xy, zb0, H, lo, hi, n, level, end, dt, write,
                  open_top=True, limiter_iter=20, refinement=None, ranks=1,
                  closed_surface=False):
    """A cube of edge H (density rho_b, bottom at zb0, centre xy) in a tank
    of water to 'level', demInterFoam couplingMode resolved; refinement:
    None (the uniform mesh n) or the couplingProperties refinement entries
    (e.g. "band 5e-3;"), with refine_around_bodies' dynamicMeshDict;
    closed_surface: directForcing { closedSurface true; }. Runs
    blockMesh and demInterFoam (ranks > 1: split in x by decomposePar, run
    with mpirun); returns the case folder."""
    case = hc.workdir(name)
    closed_tank(case, lo, hi, n, open_top=open_top)
    # Water outside the cube exactly (water_field); the cells the cube
    # fills are set from the level by the solver (fillSolidCells)
    box = ((xy[0] - H / 2, xy[1] - H / 2, zb0), (xy[0] + H / 2, xy[1] + H / 2, zb0 + H))
    water_field(case, lo, hi, n, level, [box])
    vof_dicts(case, end, dt, write, limiterIter=limiter_iter)
    dem_blocks(case, 1e-4, rho_b, [(xy[0], xy[1], zb0 + H / 2)], (H, H, H), (lo, hi))
    coupling = RESOLVED_CUBE_COUPLING
    if closed_surface:
        coupling = coupling.replace("interface penalised;",
                                    "interface penalised;\n    closedSurface true;")
    if refinement is not None:
        refine_around_bodies(case)
        coupling += "refinement\n{\n    " + refinement + "\n}\n"
    hc.coupling(case, coupling)
    hc.run("blockMesh", case, "log.blockMesh")
    if ranks > 1:
        hc.foamfile(os.path.join(case, "system/decomposeParDict"), "decomposeParDict", f"""
numberOfSubdomains {ranks};
method simple;
simpleCoeffs {{ n ({ranks} 1 1); delta 0.001; }}
""")
        hc.run("decomposePar", case, "log.decomposePar")
        hc.run(f"mpirun -np {ranks} demInterFoam -parallel", case, "log.demInterFoam", timeout=1800)
    else:
        hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)
    return case


def late_mean(values, fraction=0.3):
    """Mean of the last 'fraction' of a time series (a settled state)."""
    late = values[int((1 - fraction) * len(values)):]
    return sum(late) / max(len(late), 1)


def read_ib_forces(case):
    """(t, z, Uz, centre, quaternion (w x y z)) per step of
    postProcessing/ibForces/<t0>/forces.dat"""
    base = os.path.join(case, "postProcessing/ibForces")
    rows = []
    for t in sorted(os.listdir(base), key=float):
        for line in open(os.path.join(base, t, "forces.dat")):
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            rows.append((v[0], v[4], v[7], tuple(v[2:5]), tuple(v[20:24])))
    return rows


def drum_mesh(case, R, N, M, C, DZ):
    """blockMeshDict of a 2D drum of radius R about the z axis: an O-grid
    of five blocks (an inner square of half side C, N x N cells, and four
    arcs M cells deep), one cell DZ thick; patches shell (wall) and
    frontAndBack (empty). The wet mill tutorial's recipe
    (tutorials/demInterFoam/common/rotatingDrum.py)."""
    hc.foamfile(os.path.join(case, "system/blockMeshDict"), "blockMeshDict",
                rotatingDrum.o_grid_block_mesh(R, N, M, C, 0.0, DZ))


def rotating_mesh(case, omega):
    """dynamicMeshDict turning the whole mesh as a solid body about the z
    axis at omega rad/s (omega None: a static mesh)."""
    if omega is None:
        body = "dynamicFvMesh   staticFvMesh;\n"
    else:
        body = rotatingDrum.dynamic_mesh_dict(omega)
    hc.foamfile(os.path.join(case, "constant/dynamicMeshDict"), "dynamicMeshDict", body)


def internal_field(path, width):
    """(n, values) of a volScalarField (width 1) or volVectorField (3):
    n None and one value (or vector) for a uniform field."""
    txt = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(?:scalar|vector)>\s*(\d+)\s*\(", txt)
    if m is None:
        m2 = re.search(r"internalField\s+uniform\s+\(?([^;)]*)\)?;", txt)
        return None, [float(v) for v in m2.group(1).split()]
    body = txt[m.end():]
    n = int(m.group(1))
    nums = re.findall(r"[-+0-9.eE]+", body.split("\n)\n", 1)[0])
    vals = [float(v) for v in nums[:n * width]]
    return n, vals


def drum_fields(case, shell_U, alpha=True):
    """0/U (shell: shell_U, e.g. "noSlip" or "movingWallVelocity; value
    uniform (0 0 0)"), 0/p_rgh (fixedFluxPressure) and, with alpha, 0/alpha.water
    uniform 1 of a drum_mesh case, at rest; frontAndBack empty."""
    sides = "    frontAndBack { type empty; }\n"
    if alpha:
        hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water",
                    "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 1;\n"
                    "boundaryField\n{\n    shell { type zeroGradient; }\n" + sides + "}\n",
                    cls="volScalarField")
    hc.foamfile(os.path.join(case, "0/U"), "U",
                "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
                f"boundaryField\n{{\n    shell {{ type {shell_U}; }}\n" + sides + "}\n",
                cls="volVectorField")
    hc.foamfile(os.path.join(case, "0/p_rgh"), "p_rgh",
                "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
                "boundaryField\n{\n    shell { type fixedFluxPressure; value uniform 0; }\n"
                + sides + "}\n", cls="volScalarField")


def pimple_entries(case, entries):
    """Add entries (text) at the top of fvSolution's PIMPLE dictionary."""
    fvs = os.path.join(case, "system/fvSolution")
    txt = open(fvs).read()
    open(fvs, "w").write(txt.replace("PIMPLE\n{", "PIMPLE\n{\n" + entries, 1))
