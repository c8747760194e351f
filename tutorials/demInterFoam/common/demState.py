"""Readers for the demInterFoam tutorials' post-processing (damBreakRockPile,
damBreakCubes): the polyDEM state file <case>/<time>/polyDEM/state (ASCII,
src/polyDEM/src/host/StateIO.cpp), the alpha.water field, the demCloud
summary. Plain python3, no OpenFOAM needed."""
import os
import re

# Particle row of the state file (StateIO.cpp, visitParticle)
COLS = ("id type radius mass Ix Iy Iz px py pz qw qx qy qz vx vy vz wx wy wz "
        "fx fy fz tx ty tz rx ry rz").split()


def read_state(path):
    """dict: time, particles (list of dicts by COLS, plus 'fext' when the
    state carries external forces), pairs (idA, idB, |tangential spring|),
    walls (id, wall index) of the contacts with walls."""
    with open(path) as f:
        lines = f.read().split("\n")
    head = {}
    i = 0
    while lines[i] != "data":
        w = lines[i].split()
        if w and w[0] in ("time", "step", "particles", "pairs", "walls", "external", "forcesValid"):
            head[w[0]] = w[1:]
        i += 1
    i += 1
    n, npair, nwall = int(head["particles"][0]), int(head["pairs"][0]), int(head["walls"][0])
    ext = head.get("external", ["0", "0"])
    parts = []
    for l in lines[i:i + n]:
        v = l.split()
        p = {k: float(x) for k, x in zip(COLS, v)}
        p["id"], p["type"] = int(v[0]), int(v[1])
        parts.append(p)
    i += n
    pairs = []
    for l in lines[i:i + npair]:
        v = l.split()
        t = [float(x) for x in v[2:5]]
        pairs.append((int(v[0]), int(v[1]), sum(x*x for x in t) ** 0.5))
    i += npair
    walls = []
    for l in lines[i:i + nwall]:
        v = l.split()
        walls.append((int(v[0]), int(v[1])))
    i += nwall
    if ext[0] == "1":
        for p, l in zip(parts, lines[i:i + n]):
            p["fext"] = [float(x) for x in l.split()]
        i += n
    return dict(time=float(head["time"][0]), particles=parts, pairs=pairs, walls=walls)


def times(case):
    """Numeric time folders of a case holding a DEM state, sorted."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, d, "polyDEM", "state")):
            out.append((t, d))
    return sorted(out)


def contact_force(p, g=(0.0, 0.0, -9.81)):
    """Resultant of the contact forces on a particle: the state's total force
    less gravity and the fluid force (fext)."""
    fe = p.get("fext", [0.0, 0.0, 0.0])
    return [p["f" + c] - p["mass"]*gc - fc for c, gc, fc in zip("xyz", g, fe)]


def read_scalar_field(path):
    """internalField of an ASCII volScalarField (uniform or nonuniform)."""
    txt = open(path).read()
    m = re.search(r"internalField\s+uniform\s+([-+.\deE]+)", txt)
    if m:
        return None, float(m.group(1))
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", txt)
    n = int(m.group(1))
    vals = txt[m.end():].split(None, n)[:n]
    return [float(v) for v in vals], None


def read_summary(case):
    """Rows of postProcessing/demCloud/<t0>/summary.dat: t, n, nOut, F (3),
    Pc (3), Sf (3), relErr, Up (3), xp (3), alphaMin."""
    base = os.path.join(case, "postProcessing", "demCloud")
    rows = []
    for t in sorted(os.listdir(base), key=float):
        for l in open(os.path.join(base, t, "summary.dat")):
            if l.strip() and not l.startswith("#"):
                rows.append([float(x) for x in l.split()])
    return rows


def write_network_vtk(path, state):
    """Legacy VTK polydata: the rock centres as points (point data: the
    magnitude of the resultant contact force, the fluid force, the speed,
    the id) and one line per particle pair in contact (the pairs that carry
    a tangential spring in the state; cell data: the spring's length).
    polyDEM does not write the force of each contact: the lines show which
    rocks touch, not how hard (README)."""
    ps = state["particles"]
    index = {p["id"]: k for k, p in enumerate(ps)}
    lines = [(index[a], index[b], s) for a, b, s in state["pairs"] if a in index and b in index]
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 3.0\ncontact network t = %.6g s\nASCII\nDATASET POLYDATA\n"
                % state["time"])
        f.write("POINTS %d double\n" % len(ps))
        for p in ps:
            f.write("%.9g %.9g %.9g\n" % (p["px"], p["py"], p["pz"]))
        f.write("VERTICES %d %d\n" % (len(ps), 2*len(ps)))
        for k in range(len(ps)):
            f.write("1 %d\n" % k)
        f.write("LINES %d %d\n" % (len(lines), 3*len(lines)))
        for a, b, _ in lines:
            f.write("2 %d %d\n" % (a, b))
        f.write("CELL_DATA %d\n" % (len(ps) + len(lines)))
        f.write("SCALARS tangentialSpring double 1\nLOOKUP_TABLE default\n")
        for _ in ps:
            f.write("0\n")
        for _, _, s in lines:
            f.write("%.9g\n" % s)
        f.write("POINT_DATA %d\n" % len(ps))
        for name, fn in (("contactForce", lambda p: sum(c*c for c in contact_force(p)) ** 0.5),
                         ("fluidForce", lambda p: sum(c*c for c in p.get("fext", [0, 0, 0])) ** 0.5),
                         ("speed", lambda p: (p["vx"]**2 + p["vy"]**2 + p["vz"]**2) ** 0.5),
                         ("id", lambda p: p["id"])):
            f.write("SCALARS %s double 1\nLOOKUP_TABLE default\n" % name)
            for p in ps:
                f.write("%.9g\n" % fn(p))
    return len(lines)
