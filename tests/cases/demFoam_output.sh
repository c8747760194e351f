#!/usr/bin/env bash
# demFoam's ParaView output (issue 11, item 6), on 15 polyhedra (10 rocks,
# 5 cubes) settling between a fixed floor, a fixed STL plate and a lid
# moving down at 0.1 m/s, written at 0, 0.01, 0.02, 0.03 s, then restarted
# to 0.05 s:
# - the fixed walls (floor, plate) are written once, 0/polyDEM/fixedWalls.vtp,
#   and walls.pvd refers to it at every time; walls.vtp at each time holds
#   the lid only, at z = 0.1 - 0.1 t (analytic)
# - polyhedra.vtp carries the particle fields of particles.vtp per face,
#   with the velocity, omega and force of the state file at that time, and
#   volumeEquivalentDiameter = (6 V/pi)^(1/3) (cubes of edge 3 mm: 3.7221 mm;
#   rocks made with equivalentDiameter 4 mm: 4 mm) in both files
# With the argument removedWall the plate is removed at 0.015 s
# (activeUntil): fixedWalls.vtp is written again at 0.02 (the floor only),
# walls.pvd names it from 0.02 on, and the restart at 0.03 keeps it.
. "$(dirname "$0")/common.sh"
variant="${1:-plain}"

copyCase settlingRocks
props=constant/demProperties
setEntry $props insertion/rocks/number 10
setEntry $props insertion/cubes/number 5
setEntry system/controlDict endTime 0.03
setEntry system/controlDict writeInterval 0.01
mkdir -p constant/triSurface
# A vertical plate of 4 triangles at x = 0.05 (beside the particles)
cat > constant/triSurface/plate.stl <<'STL'
solid plate
facet normal -1 0 0
 outer loop
  vertex 0.05 0 0
  vertex 0.05 0.04 0
  vertex 0.05 0.04 0.05
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0.05 0 0
  vertex 0.05 0.04 0.05
  vertex 0.05 0 0.05
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0.05 0 0.05
  vertex 0.05 0.04 0.05
  vertex 0.05 0.04 0.1
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0.05 0 0.05
  vertex 0.05 0.04 0.1
  vertex 0.05 0 0.1
 endloop
endfacet
endsolid plate
STL
setEntry $props walls/plate "{ type mesh; file \"plate.stl\"; material steel; }"
[ "$variant" = removedWall ] && setEntry $props walls/plate/activeUntil 0.015
setEntry $props walls/lid "{ type plane; point (0.02 0.02 0.1); normal (0 0 -1); material steel; displaySize 0.06; motion { type translation; velocity (0 0 -0.1); } }"

demFoam > log.demFoam.1 2>&1 || { tail -30 log.demFoam.1; fail "demFoam (to 0.03) failed"; }
setEntry system/controlDict endTime 0.05
demFoam > log.demFoam.2 2>&1 || { tail -30 log.demFoam.2; fail "demFoam (restart to 0.05) failed"; }
grep -q "restarting from" log.demFoam.2 || fail "the second run did not restart"

VARIANT="$variant" python3 - <<'PYEOF' || fail "output checks failed"
import glob, math, os, re, sys
import xml.etree.ElementTree as ET
ok = True
def check(what, cond):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond

times = ["0", "0.01", "0.02", "0.03", "0.04", "0.05"]
removed = os.environ["VARIANT"] == "removedWall"
# the fixed walls' file at each time, and its triangles (floor 2, plate 4)
if removed:
    want = {"0/polyDEM/fixedWalls.vtp": 6, "0.02/polyDEM/fixedWalls.vtp": 2}
    fixedAt = {t: "0/polyDEM/fixedWalls.vtp" if float(t) < 0.015 else "0.02/polyDEM/fixedWalls.vtp" for t in times}
else:
    want = {"0/polyDEM/fixedWalls.vtp": 6}
    fixedAt = {t: "0/polyDEM/fixedWalls.vtp" for t in times}
fixed = sorted(glob.glob("*/polyDEM/fixedWalls.vtp"))
check(f"fixedWalls.vtp in the time folders: {fixed}", fixed == sorted(want))

def piece(path):
    root = ET.parse(path).getroot()
    return root.find("PolyData/Piece")
def arrays(node):
    return {a.get("Name"): (int(a.get("NumberOfComponents", "1")), [float(x) for x in a.text.split()])
            for a in node.findall("DataArray")}

for f, nTri in want.items():
    if f not in fixed:
        continue
    p = piece(f)
    walls = arrays(p.find("CellData"))["wall"][1]
    check(f"{f}: {nTri} triangles (floor 2, plate 4), got {p.get('NumberOfPolys')}",
          int(p.get("NumberOfPolys")) == nTri and len(walls) == nTri)

pvd = ET.parse("walls.pvd").getroot().findall("Collection/DataSet")
entries = {}
for d in pvd:
    entries.setdefault(float(d.get("timestep")), []).append((int(d.get("part")), d.get("file")))
for t in times:
    e = sorted(entries.get(float(t), []))
    check(f"walls.pvd at t = {t}: {e}",
          e == [(0, fixedAt[t]), (1, f"{t}/polyDEM/walls.vtp")])
    lid = piece(f"{t}/polyDEM/walls.vtp")
    z = arrays(lid.find("Points"))["points"][1][2::3]
    zLid = 0.1 - 0.1*float(t)
    check(f"{t}/polyDEM/walls.vtp: the lid only (2 triangles) at z = {zLid:.4f} (max error {max(abs(v - zLid) for v in z):.1e})",
          int(lid.get("NumberOfPolys")) == 2 and max(abs(v - zLid) for v in z) < 1e-12)

# polyhedra.vtp against the state (ASCII records: id type radius mass I(3)
# x(3) q(4) v(3) omega(3) f(3) torque(3)) and particles.vtp
for t in ["0.03", "0.05"]:
    head, body = open(f"{t}/polyDEM/state").read().split("\ndata\n", 1)
    n = int(re.search(r"^particles (\d+)$", head, re.M).group(1))
    rec = {int(l.split()[0]): [float(x) for x in l.split()] for l in body.split("\n")[:n]}
    p = piece(f"{t}/polyDEM/polyhedra.vtp")
    nf = int(p.get("NumberOfPolys"))
    c = arrays(p.find("CellData"))
    need = {"id": 1, "particleId": 1, "type": 1, "radius": 1, "diameter": 1, "mass": 1,
            "volumeEquivalentDiameter": 1, "velocity": 3, "omega": 3, "force": 3, "torque": 3,
            "orientation": 4}
    for name, k in need.items():
        check(f"{t} polyhedra.vtp: {name} with {nf} tuples of {k}",
              name in c and c[name][0] == k and len(c[name][1]) == k*nf)
    if not ok:
        sys.exit(1)
    ids = [int(x) for x in c["id"][1]]
    check(f"{t}: every one of the {n} particles has faces", sorted(set(ids)) == sorted(rec))
    for name, col in (("velocity", 14), ("omega", 17), ("force", 20)):
        v = c[name][1]
        err = max(abs(v[3*f + j] - rec[ids[f]][col + j]) for f in range(nf) for j in range(3))
        scale = max(abs(rec[i][col + j]) for i in rec for j in range(3))
        check(f"{t}: polyhedra.vtp {name} = the state's (max difference {err:.1e}, values up to {scale:.2e})",
              err == 0 and scale > 0)
    # volume-equivalent diameter: analytic for the cubes, the rocks' input value
    pp = arrays(piece(f"{t}/polyDEM/particles.vtp").find("PointData"))
    types = [int(x) for x in pp["type"][1]]
    dv, db = pp["volumeEquivalentDiameter"][1], pp["diameter"][1]
    cube = (6*27e-9/math.pi)**(1/3)
    # type index -> name, from the state's header ("type <name> <checksum>")
    names = re.findall(r"^type (\S+) [0-9a-f]+$", head, re.M)
    types = [names[ty] for ty in types]
    for kind, want in (("rocks", 4e-3), ("cubes", cube)):
        got = [d for d, ty in zip(dv, types) if ty == kind]
        err = max(abs(d - want)/want for d in got)
        check(f"{t} particles.vtp: {len(got)} {kind} volumeEquivalentDiameter {want*1e3:.4f} mm (relative error {err:.1e} <= 1e-9)",
              len(got) > 0 and err <= 1e-9)
    bc = [d for d, ty in zip(db, types) if ty == "cubes"]
    check(f"{t}: cubes' diameter is the bounding one (3 sqrt(3) mm), not d_v",
          all(abs(d - 3e-3*math.sqrt(3)) < 1e-9 for d in bc))
    fdv = c["volumeEquivalentDiameter"][1]
    byId = dict(zip([int(x) for x in pp["id"][1]], dv))
    check(f"{t}: polyhedra.vtp volumeEquivalentDiameter = particles.vtp's",
          all(fdv[f] == byId[ids[f]] for f in range(nf)))
sys.exit(0 if ok else 1)
PYEOF
echo "PASS"
