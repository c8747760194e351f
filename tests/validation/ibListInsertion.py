#!/usr/bin/env python3
"""demProperties 'insertion { <name> { type list; ... } }': particles at given
positions and orientations, and the omega/quaternion columns of forces.dat.

Three polyhedra (box 3 x 2 x 1 mm, body x = the long edge) inserted with
type list in the settling-cube case (tests/validation/ib/settlingCube,
gravity off), one demIbFoam step:
  A (0 90 0)                 a quarter turn about world y
  B (30 45 60) with velocity and omega   a combined rotation
  C (170 -60 250)            a combined one whose quaternion has w < 0
Checked, to 1e-12:
  - the DEM state written at the start (0/polyDEM/state): position,
    velocity, omega as given; the rotation of the quaternion equal to
    R = Rz(c) Ry(b) Rx(a) built here from elementary matrices (rotations
    about the world x, then y, then z axes, in degrees); A turns body x to
    world -z;
  - the polyhedra in 0/polyDEM/polyhedra.vtp: every vertex p satisfies
    |R^T (p - x)| = (1.5, 1, 0.5) mm (the box edges where the convention
    puts them);
  - postProcessing/ibForces/0/forces.dat (first row per body: the bodies at
    the start of the step): x y z, U, omega and q = (w x y z), w >= 0,
    against the same numbers; the header names the 24 columns.
Bad input (demFoam, no mesh needed): a particle without position, particles
as a dictionary, a misspelt keyword, an ill-formed vector and an unknown
insertion type each stop with a FatalIOError naming constant/demProperties
and the entry.
"""
import math
import os
import re
import shutil
import subprocess
import hedracase as hc

os.environ.setdefault("OMP_NUM_THREADS", "1")

TOL = 1e-12
EDGES = (1.5e-3, 1.0e-3, 0.5e-3)   # half edges along body x, y, z
PARTICLES = [
    # position, orientation (a b c) [deg], velocity, omega
    ((0.01, 0.01, 0.01), (0, 90, 0), (0, 0, 0), (0, 0, 0)),
    ((0.01, 0.01, 0.02), (30, 45, 60), (0.001, -0.002, 0.0005), (1, -2, 3)),
    ((0.01, 0.01, 0.03), (170, -60, 250), (0, 0, 0), (0, 0, 0)),
]

results = []


def report(ok, text):
    results.append(bool(ok))
    print(f"{'PASS' if ok else 'FAIL'}: {text}")


def matmul(A, B):
    return [[sum(A[i][k]*B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def euler_matrix(abc):
    """R = Rz(c) Ry(b) Rx(a): about world x by a, then y by b, then z by c."""
    a, b, c = (math.radians(t) for t in abc)
    Rx = [[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]]
    Ry = [[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]]
    Rz = [[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]]
    return matmul(Rz, matmul(Ry, Rx))


def quat_matrix(q):
    w, x, y, z = q
    return [[1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
            [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
            [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]]


def matrix_quat(R):
    """Unit quaternion (w >= 0) of R, from the largest of w, x, y, z."""
    tr = R[0][0] + R[1][1] + R[2][2]
    four = [1 + tr, 1 + 2*R[0][0] - tr, 1 + 2*R[1][1] - tr, 1 + 2*R[2][2] - tr]
    k = max(range(4), key=lambda i: four[i])
    s = 0.5*math.sqrt(four[k])   # the largest component
    d = [R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]]
    o = [R[0][1] + R[1][0], R[0][2] + R[2][0], R[1][2] + R[2][1]]
    if k == 0:
        q = [s, d[0]/(4*s), d[1]/(4*s), d[2]/(4*s)]
    elif k == 1:
        q = [d[0]/(4*s), s, o[0]/(4*s), o[1]/(4*s)]
    elif k == 2:
        q = [d[1]/(4*s), o[0]/(4*s), s, o[2]/(4*s)]
    else:
        q = [d[2]/(4*s), o[1]/(4*s), o[2]/(4*s), s]
    return [-x for x in q] if q[0] < 0 else q


def maxdiff(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def flat(R):
    return [x for row in R for x in row]


# ---------------------------------------------------------------------------
# The case: settlingCube with the box particles, gravity off, one step
# ---------------------------------------------------------------------------
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingCube")
case = hc.workdir("ibListInsertion")
shutil.rmtree(case)
shutil.copytree(src, case)
shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))

plist = "\n".join(
    f"            {{ position ({x[0]} {x[1]} {x[2]}); orientation ({o[0]} {o[1]} {o[2]});"
    f" velocity ({u[0]} {u[1]} {u[2]}); omega ({w[0]} {w[1]} {w[2]}); }}"
    for x, o, u, w in PARTICLES)
INSERTION = f"""insertion
{{
    release
    {{
        type list;
        particleType plate;
        particles
        (
{plist}
        );
    }}
}}
"""


def dem_properties(insertion, folder):
    p = os.path.join(folder, "constant/demProperties")
    txt = open(os.path.join(src, "constant/demProperties")).read()
    txt = re.sub(r"gravity\s+\([^)]*\);", "gravity (0 0 0);", txt)
    txt = re.sub(r"particleTypes\s+\{.*?\}\s*\}\s*\}",
                 "particleTypes { plate { shape polyhedron; material glass;"
                 " geometry { type box; size (3e-3 2e-3 1e-3); } } }", txt, flags=re.S)
    txt = re.sub(r"insertion\s*\{.*?\n\}\n", insertion, txt, flags=re.S)
    txt = re.sub(r"vtk\s+false", "vtk true", txt)
    os.makedirs(os.path.dirname(p), exist_ok=True)
    open(p, "w").write(txt)


def control_dict(folder, app):
    p = os.path.join(folder, "system/controlDict")
    txt = open(os.path.join(src, "system/controlDict")).read()
    txt = re.sub(r"application\s+\w+;", f"application {app};", txt)
    txt = re.sub(r"endTime\s+[^;]*;", "endTime 1e-3;", txt)
    txt = re.sub(r"deltaT\s+[^;]*;", "deltaT 1e-3;", txt)
    txt = re.sub(r"writeInterval\s+[^;]*;", "writeInterval 1e-3;", txt)
    txt = re.sub(r"writePrecision\s+[^;]*;", "writePrecision 17;", txt)
    os.makedirs(os.path.dirname(p), exist_ok=True)
    open(p, "w").write(txt)


dem_properties(INSERTION, case)
control_dict(case, "demIbFoam")
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demIbFoam", case, "log.demIbFoam", timeout=120)
log = open(os.path.join(case, "log.demIbFoam")).read()
report("DEM insertion 'release': 3 polyhedra (list)" in log,
       "log: DEM insertion 'release': 3 polyhedra (list)")

expected = {}
for i, (x, o, u, w) in enumerate(PARTICLES):
    R = euler_matrix(o)
    expected[i] = dict(x=x, R=R, q=matrix_quat(R), u=u, w=w, o=o)

# A: a quarter turn about world y takes body x to world -z, body z to +x
RA = expected[0]["R"]
report(maxdiff([RA[0][0], RA[1][0], RA[2][0]], [0, 0, -1]) < TOL
       and maxdiff([RA[0][2], RA[1][2], RA[2][2]], [1, 0, 0]) < TOL,
       "(0 90 0): R e_x = -e_z, R e_z = e_x (the convention as documented)")

# ---------------------------------------------------------------------------
# The DEM state at the start
# ---------------------------------------------------------------------------
state = open(os.path.join(case, "0/polyDEM/state")).read().split("data\n", 1)[1]
rows = {}
for line in state.splitlines()[:len(PARTICLES)]:
    v = line.split()
    rows[int(v[0])] = [float(t) for t in v]
report(sorted(rows) == list(range(len(PARTICLES))),
       f"0/polyDEM/state holds particles {sorted(rows)}")
Rstate = {}
for i, e in expected.items():
    r = rows.get(i)
    if r is None:
        report(False, f"particle {i} missing in the state")
        continue
    q = r[10:14]
    Rstate[i] = quat_matrix(q)
    dx = maxdiff(r[7:10], e["x"])
    dR = maxdiff(flat(Rstate[i]), flat(e["R"]))
    dn = abs(sum(t*t for t in q) - 1)
    du = maxdiff(r[14:17], e["u"])
    dw = maxdiff(r[17:20], e["w"])
    report(max(dx, dR, dn, du, dw) < TOL,
           f"state, particle {i} orientation {e['o']}: |dx| {dx:.2g} m, |dR| {dR:.2g},"
           f" | |q| - 1 | {dn:.2g}, |dU| {du:.2g}, |d omega| {dw:.2g} (< {TOL:g})"
           f"; q = ({', '.join(f'{t:.6f}' for t in q)})")

# ---------------------------------------------------------------------------
# The polyhedra as written for ParaView: vertices where the convention says
# ---------------------------------------------------------------------------
vtp = open(os.path.join(case, "0/polyDEM/polyhedra.vtp")).read()


def data_array(name):
    m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, vtp, re.S)
    return m.group(1).split()


pts = [float(t) for t in data_array("points")]
conn = [int(t) for t in data_array("connectivity")]
offs = [int(t) for t in data_array("offsets")]
pid = [int(t) for t in data_array("particleId")]
owner = {}
start = 0
for c, end in enumerate(offs):
    for k in conn[start:end]:
        owner[k] = pid[c]
    start = end
worst, count = 0.0, {i: 0 for i in expected}
for k, i in owner.items():
    p = pts[3*k:3*k + 3]
    e = expected[i]
    d = [p[j] - e["x"][j] for j in range(3)]
    body = [sum(e["R"][j][m]*d[j] for j in range(3)) for m in range(3)]  # R^T d
    worst = max(worst, maxdiff([abs(t) for t in body], EDGES))
    count[i] += 1
report(all(n == 8 for n in count.values()) and worst < TOL,
       f"polyhedra.vtp: {sum(count.values())} vertices, |R^T (p - x)| = (1.5, 1, 0.5) mm"
       f" to {worst:.2g} m (< {TOL:g})")

# ---------------------------------------------------------------------------
# forces.dat: first row per body = the bodies at the start of the step
# ---------------------------------------------------------------------------
fn = os.path.join(case, "postProcessing/ibForces/0/forces.dat")
lines = open(fn).read().splitlines()
header = lines[0].lstrip("#").split()
report(len(header) == 30 and header[17:24] == ["omegax", "omegay", "omegaz", "qw", "qx", "qy", "qz"]
       and header[:17] == "time id x y z Ux Uy Uz Fx Fy Fz Tx Ty Tz FLx FLy FLz".split()
       and header[24:] == "FDx FDy FDz TDx TDy TDz".split(),
       f"forces.dat header: {len(header)} columns, ... {' '.join(header[14:])}")
first = {}
for line in lines[1:]:
    v = [float(t) for t in line.split()]
    if len(v) != 30:
        report(False, f"forces.dat row with {len(v)} columns: {line[:60]}")
        continue
    first.setdefault(int(v[1]), v)
for i, e in expected.items():
    v = first.get(i)
    if v is None:
        report(False, f"forces.dat: no row for body {i}")
        continue
    dx = maxdiff(v[2:5], e["x"])
    du = maxdiff(v[5:8], e["u"])
    dw = maxdiff(v[17:20], e["w"])
    dq = maxdiff(v[20:24], e["q"])
    report(max(dx, du, dw, dq) < TOL and v[20] >= 0,
           f"forces.dat, body {i}: |dx| {dx:.2g}, |dU| {du:.2g}, |d omega| {dw:.2g},"
           f" |dq| {dq:.2g} (< {TOL:g}, qw >= 0)")

# ---------------------------------------------------------------------------
# Bad input: demFoam stops with a FatalIOError naming the file and the entry
# ---------------------------------------------------------------------------
good = ("{ position (0.01 0.01 0.01); orientation (0 90 0); }")
BAD = [
    ("particle without position", "type list; particleType plate;"
     " particles ( { orientation (0 90 0); } );",
     ["insertion/release/particles[0]/position", "is missing"]),
    ("particles a dictionary", "type list; particleType plate;"
     " particles { a { position (0.01 0.01 0.01); } };",
     ["insertion/release/particles", "must be a list"]),
    ("particles not dictionaries", "type list; particleType plate;"
     " particles ( (0.01 0.01 0.01) );",
     ["insertion/release/particles", "list of particle dictionaries"]),
    ("misspelt keyword", "type list; particleType plate;"
     " particles ( " + good + " { position (0.01 0.01 0.02); orientaton (0 90 0); } );",
     ["Unknown keyword 'orientaton'", "insertion/release/particles[1]"]),
    ("ill-formed orientation", "type list; particleType plate;"
     " particles ( { position (0.01 0.01 0.01); orientation (0 90); } );",
     ["insertion/release/particles[0]/orientation", "orientation (a b c)"]),
    ("unknown insertion type", "type lst; particleType plate;"
     " particles ( " + good + " );",
     ["Unknown insertion type 'lst'", "list"]),
]
for label, body, needles in BAD:
    bad = hc.workdir("ibListInsertionBad")
    control_dict(bad, "demFoam")
    dem_properties("insertion\n{\n    release\n    {\n        " + body
                   + "\n    }\n}\n", bad)
    rc = hc.run("demFoam", bad, "log.demFoam", check=False, timeout=60)
    out = open(os.path.join(bad, "log.demFoam")).read()
    fatal = out[out.find("FOAM FATAL"):] if "FOAM FATAL" in out else ""
    ok = (rc != 0 and "FOAM FATAL IO ERROR" in out
          and os.path.join(bad, "constant/demProperties") in fatal
          and all(n in fatal for n in needles))
    msg = " | ".join(l.strip() for l in fatal.splitlines()[1:4] if l.strip())
    report(ok, f"bad input ({label}): exit {rc}: {msg[:200]}")

hc.finish(results)
