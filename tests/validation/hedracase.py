import math
"""Hedra validation helpers: write small demPimpleFoam cases, run them, read
their results. Used by the validation scripts in this folder (CTest)."""
import os
import re
import shutil
import subprocess
import tempfile

HEADER = """FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    object      {obj};
}}
"""


def foamfile(path, obj, body, cls="dictionary"):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER.format(cls=cls, obj=obj))
        f.write(body)


def block_mesh(case, lo, hi, n, patches):
    """Box mesh lo..hi with n cells; patches: dict name -> (type, faces)
    faces from xmin xmax ymin ymax zmin zmax."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    faces = {
        "xmin": "(0 4 7 3)", "xmax": "(1 2 6 5)",
        "ymin": "(0 1 5 4)", "ymax": "(3 7 6 2)",
        "zmin": "(0 3 2 1)", "zmax": "(4 5 6 7)",
    }
    bnd = ""
    for name, (ptype, sides) in patches.items():
        fl = " ".join(faces[s] for s in sides)
        bnd += f"    {name} {{ type {ptype}; faces ({fl}); }}\n"
    body = f"""convertToMeters 1;
vertices
(
    ({x0} {y0} {z0}) ({x1} {y0} {z0}) ({x1} {y1} {z0}) ({x0} {y1} {z0})
    ({x0} {y0} {z1}) ({x1} {y0} {z1}) ({x1} {y1} {z1}) ({x0} {y1} {z1})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({n[0]} {n[1]} {n[2]}) simpleGrading (1 1 1) );
edges ();
boundary
(
{bnd});
"""
    foamfile(os.path.join(case, "system/blockMeshDict"), "blockMeshDict", body)


def control_dict(case, end, dt, write, extra=""):
    body = f"""application demPimpleFoam;
startFrom latestTime;
startTime 0;
stopAt endTime;
endTime {end};
deltaT {dt};
writeControl runTime;
writeInterval {write};
purgeWrite 0;
writeFormat ascii;
writePrecision 12;
writeCompression off;
timeFormat general;
timePrecision 8;
runTimeModifiable false;
{extra}
"""
    foamfile(os.path.join(case, "system/controlDict"), "controlDict", body)


def schemes_solution(case, nCorr=2, nOuter=1, pTol=1e-10, pRelTol=0.01):
    foamfile(os.path.join(case, "system/fvSchemes"), "fvSchemes", """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default Gauss linear;
    div(alphaPhi,U) Gauss limitedLinearV 1;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
wallDist { method meshWave; }
""")
    foamfile(os.path.join(case, "system/fvSolution"), "fvSolution", f"""
solvers
{{
    p {{ solver PCG; preconditioner DIC; tolerance {pTol}; relTol {pRelTol}; }}
    pFinal {{ $p; relTol 0; }}
    "(U|k|epsilon|omega)" {{ solver smoothSolver; smoother symGaussSeidel; tolerance 1e-10; relTol 0; }}
    "(U|k|epsilon|omega)Final" {{ $U; relTol 0; }}
}}
PIMPLE
{{
    momentumPredictor yes;
    nOuterCorrectors {nOuter};
    nCorrectors {nCorr};
    nNonOrthogonalCorrectors 0;
    pRefCell 0;
    pRefValue 0;
}}
""")
    foamfile(os.path.join(case, "system/decomposeParDict"), "decomposeParDict", """
numberOfSubdomains 2;
method simple;
coeffs { n (1 1 2); }
""")


def transport(case, nu, rho, g=(0, 0, -9.81)):
    foamfile(os.path.join(case, "constant/transportProperties"),
             "transportProperties",
             f"transportModel Newtonian;\nnu {nu};\nrho {rho};\n")
    foamfile(os.path.join(case, "constant/turbulenceProperties"),
             "turbulenceProperties", "simulationType laminar;\n")
    foamfile(os.path.join(case, "constant/g"), "g",
             f"dimensions [0 1 -2 0 0 0 0];\nvalue ({g[0]} {g[1]} {g[2]});\n",
             cls="uniformDimensionedVectorField")


def fields(case, Ubcs, pbcs, time="0"):
    def bc(d):
        return "".join(f"    {k} {{ {v} }}\n" for k, v in d.items())
    foamfile(os.path.join(case, time, "U"), "U",
             f"dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
             f"boundaryField\n{{\n{bc(Ubcs)}}}\n", cls="volVectorField")
    foamfile(os.path.join(case, time, "p"), "p",
             f"dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\n"
             f"boundaryField\n{{\n{bc(pbcs)}}}\n", cls="volScalarField")


def dem_properties(case, dt, density, diameter, walls, insertion,
                   E=5e6, restitution=0.5, friction=0.5, gravity=(0, 0, -9.81)):
    wall_txt = ""
    for name, (point, normal) in walls.items():
        wall_txt += (f"    {name} {{ type plane; point ({point[0]} {point[1]} {point[2]});"
                     f" normal ({normal[0]} {normal[1]} {normal[2]}); material mat; }}\n")
    body = f"""device cpu;
timeStep {dt};
gravity ({gravity[0]} {gravity[1]} {gravity[2]});
contactModel {{ law hertzMindlin; rolling none; }}
materials {{ mat {{ youngsModulus {E}; poissonsRatio 0.3; density {density}; }} }}
interactions {{ default {{ restitution {restitution}; friction {friction}; rollingFriction 0; rollingDamping 0.3; }} }}
particleTypes {{ beads {{ shape sphere; material mat; diameter {diameter}; }} }}
walls
{{
{wall_txt}}}
insertion
{{
{insertion}
}}
output {{ format ascii; vtk false; }}
"""
    foamfile(os.path.join(case, "constant/demProperties"), "demProperties", body)


def couette_case(case, h, L, n, gamma, nu, rho):
    """Plane Couette flow without gravity: walls at y = -h and +h moving at
    -gamma h and +gamma h along x, cyclic in x and z (periods L), n cells;
    the fluid starts with the steady profile u = gamma y at the cell centres
    (mesh, schemes, transport and fields; controlDict and the particles are
    the caller's)."""
    block_mesh(case, (0, -h, 0), (L, h, L), n, {
        "top": ("wall", ["ymax"]), "bottom": ("wall", ["ymin"]),
        "left": ("cyclic; neighbourPatch right", ["xmin"]),
        "right": ("cyclic; neighbourPatch left", ["xmax"]),
        "front": ("cyclic; neighbourPatch back", ["zmin"]),
        "back": ("cyclic; neighbourPatch front", ["zmax"])})
    schemes_solution(case)
    transport(case, nu, rho, g=(0, 0, 0))
    Uw = gamma * h
    cyc = {k: "type cyclic;" for k in ("left", "right", "front", "back")}
    fields(case, dict(cyc, top=f"type fixedValue; value uniform ({Uw} 0 0);",
                      bottom=f"type fixedValue; value uniform ({-Uw} 0 0);"),
           dict(cyc, top="type fixedFluxPressure;", bottom="type fixedFluxPressure;"))
    dy = 2 * h / n[1]
    cells = [f"({gamma * (-h + (j + 0.5) * dy):.12g} 0 0)"
             for k in range(n[2]) for j in range(n[1]) for i in range(n[0])]
    upath = os.path.join(case, "0", "U")
    txt = open(upath).read().replace(
        "internalField uniform (0 0 0);",
        f"internalField nonuniform List<vector> {len(cells)} (\n" + "\n".join(cells) + "\n);")
    with open(upath, "w") as f:
        f.write(txt)


def random_fill(name, number, lo, hi, velocity=(0, 0, 0), seed=1):
    return f"""    {name}
    {{
        type randomFill; particleType beads; number {number}; seed {seed};
        region {{ type box; min ({lo[0]} {lo[1]} {lo[2]}); max ({hi[0]} {hi[1]} {hi[2]}); }}
        velocity ({velocity[0]} {velocity[1]} {velocity[2]});
    }}"""


def coupling(case, text):
    foamfile(os.path.join(case, "constant/couplingProperties"),
             "couplingProperties", text)


def env():
    e = dict(os.environ)
    return e


def run(cmd, case, log, check=True, timeout=600):
    with open(os.path.join(case, log), "w") as f:
        r = subprocess.run(cmd, cwd=case, stdout=f, stderr=subprocess.STDOUT,
                           shell=isinstance(cmd, str), timeout=timeout)
    if check and r.returncode != 0:
        print(open(os.path.join(case, log)).read()[-3000:])
        raise SystemExit(f"FAILED: {cmd} (exit {r.returncode}), log {case}/{log}")
    return r.returncode


def read_summary(case):
    """Rows of postProcessing/demCloud/<t0>/summary.dat (latest start)."""
    base = os.path.join(case, "postProcessing/demCloud")
    rows = []
    for t in sorted(os.listdir(base), key=float):
        with open(os.path.join(base, t, "summary.dat")) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                rows.append([float(x) for x in line.split()])
    return rows


COLS = dict(t=0, n=1, nOut=2, F=slice(3, 6), Pc=slice(6, 9), Sf=slice(9, 12),
            relErr=12, Up=slice(13, 16), xp=slice(16, 19), alphaMin=19,
            weightCompletion=20)


_workdirs = []


def workdir(name):
    base = os.environ.get("HEDRA_TEST_TMP", tempfile.gettempdir())
    d = tempfile.mkdtemp(prefix=f"hedra-{name}-", dir=base)
    _workdirs.append(d)
    return d


def finish(results):
    """Exit 0 if all passed (removing the case folders unless HEDRA_KEEP is
    set), else 1 keeping them for inspection."""
    import sys
    ok = bool(results) and all(results)
    if ok and not os.environ.get("HEDRA_KEEP"):
        for d in _workdirs:
            shutil.rmtree(d, ignore_errors=True)
            shutil.rmtree(d + "-np2", ignore_errors=True)
    elif not ok:
        print("case folders kept:", " ".join(_workdirs))
    sys.exit(0 if ok else 1)


def check(label, value, ref, tol, results):
    err = abs(value - ref) / abs(ref) if ref != 0 else abs(value)
    ok = err <= tol
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label}: {value:.6g} vs {ref:.6g}"
          f" (rel. error {err:.3g}, tolerance {tol:g})")
    return ok


def measure_bed(case, tstr, tEnd, W, zFloor, d):
    """Bed of a packed-bed case from the DEM state files: particle volume Vs,
    cross-section A, height L (mean top of the highest 2 % of particles),
    voidage 1 - Vs/(A L) and the voidage of the core slab; prints them and the
    largest vertical particle displacement between tstr and tEnd."""
    def read_state(path):
        with open(path) as f:
            lines = f.read().split("\n")
        i = lines.index("data")
        n = int([l for l in lines if l.startswith("particles ")][0].split()[1])
        P = []
        for l in lines[i + 1:i + 1 + n]:
            v = l.split()
            P.append((float(v[2]), float(v[7]), float(v[8]), float(v[9]), int(v[0])))
        return P

    def cap(r, h):  # volume of a sphere cap of height h
        h = min(max(h, 0.0), 2 * r)
        return math.pi * h * h * (3 * r - h) / 3

    def slab_volume(r, zc, za, zb):  # part of the sphere between za and zb
        return cap(r, zb - (zc - r)) - cap(r, za - (zc - r))

    P = read_state(os.path.join(case, tstr, "polyDEM/state"))
    Pend = read_state(os.path.join(case, f"{tEnd:g}", "polyDEM/state"))
    Vs = sum(4 / 3 * math.pi * r**3 for r, x, y, z, i in P)
    A = W * W
    ztop = sorted(z + r for r, x, y, z, i in P)[-max(1, len(P) // 50):]
    zTop = sum(ztop) / len(ztop)
    za, zb = zFloor + 2 * d, zTop - 2 * d
    epsCore = 1 - sum(slab_volume(r, z, za, zb) for r, x, y, z, i in P) / (A * (zb - za))
    L = zTop - zFloor
    eps = 1 - Vs / (A * L)
    print(f"bed: {len(P)} particles, height L {L*1e3:.3f} mm (mean top of the highest 2 %),"
          f" mean voidage 1 - Vs/(A L) = {eps:.4f} (core slab voidage {epsCore:.4f})")
    zEnd = {p[4]: p[3] for p in Pend}
    shift = max(abs(p[3] - zEnd[p[4]]) for p in P)
    print(f"largest vertical particle displacement during the flow: {shift*1e3:.4f} mm")
    return {"Vs": Vs, "A": A, "L": L, "eps": eps, "epsCore": epsCore}


def ergun_dp(U, L, eps, d, mu, rho):
    """Ergun (1952) pressure drop [Pa] of a packed bed of height L, voidage
    eps, particle diameter d, at superficial velocity U."""
    return L * (150 * mu * (1 - eps)**2 * U / (eps**3 * d**2)
                + 1.75 * rho * (1 - eps) * U**2 / (eps**3 * d))


def read_inlet_p(case, tstr):
    """(t, p_inlet) rows of the inletP surfaceFieldValue function object."""
    rows = []
    pp = os.path.join(case, "postProcessing/inletP", tstr, "surfaceFieldValue.dat")
    with open(pp) as f:
        for l in f:
            if l.startswith("#") or not l.strip():
                continue
            t, pin = l.split()[:2]
            rows.append((float(t), float(pin)))
    return rows
