#!/usr/bin/python3
"""CTest iceChannel.snappyHull: the dummy hull STL (iceHull) meshed into a
reduced channel by Debian's snappyHexMesh with the iceChannelMesh set-up.

Checks: snappyHexMesh finishes without errors; the mesh has a `hull` patch of
type wall with faces; checkMesh says "Mesh OK"; and the hole the hull leaves
in the fluid mesh has the hull's analytic volume, V_box - V_mesh = V_hull =
(L - R) B D + pi R^2 D / 2, within 3 % (a snapped mesh of cells 1/2 of the
bow radius on the hull reproduces it to ~0.1-1 %; a missing or mislocated
hull, a hull meshed from the inside, or no snapping miss it by far more).
Reduced size: 0.1 m cells, one refinement level at the hull and the surface.
"""
import os
import re
import subprocess
import sys
import tempfile
import math

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.join(HERE, "..", "..", "applications", "utilities", "brashIceChannel")


def sh(cmd, case, log):
    with open(os.path.join(case, log), "w") as f:
        r = subprocess.run(cmd, cwd=case, stdout=f, stderr=subprocess.STDOUT, shell=True)
    with open(os.path.join(case, log)) as f:
        return r.returncode, f.read()


def main():
    case = tempfile.mkdtemp(prefix="snappyHull", dir=os.environ.get("HEDRA_TEST_TMP"))
    os.makedirs(os.path.join(case, "system"))
    box = ((0.0, -0.5, 0.0), (3.0, 0.5, 1.2))
    with open(os.path.join(case, "system", "iceHullDict"), "w") as f:
        f.write("hull { type dummy; }\nplacement { stem (1.0 0 0.6); bowDirection -x; }\n"
                "resolution { bowPoints 48; levels 4; }\n")
    with open(os.path.join(case, "system", "iceChannelMeshDict"), "w") as f:
        f.write(f"domain {{ min ({box[0][0]} {box[0][1]} {box[0][2]}); "
                f"max ({box[1][0]} {box[1][1]} {box[1][2]}); }}\n"
                "cellSize 0.1;\nwaterLevel 0.6;\nhullLevel 1;\nfreeSurfaceLevel 1;\n")
    fails = []
    for tool in ("iceHull", "iceChannelMesh"):
        subprocess.run([os.path.join(TOOLS, tool), "-case", case], check=True)
    steps = [("surfaceFeatureExtract", "log.surfaceFeatureExtract"),
             ("blockMesh", "log.blockMesh"),
             ("snappyHexMesh -overwrite", "log.snappyHexMesh"),
             ("checkMesh", "log.checkMesh")]
    logs = {}
    for cmd, log in steps:
        rc, logs[cmd] = sh(cmd, case, log)
        if rc != 0:
            fails.append(f"{cmd} failed (rc {rc}), see {case}/{log}")
            break
    if not fails:
        if "Finished meshing without any errors" not in logs["snappyHexMesh -overwrite"]:
            fails.append("snappyHexMesh reported errors")
        with open(os.path.join(case, "constant", "polyMesh", "boundary")) as f:
            b = f.read()
        m = re.search(r"\n\s*hull\s*\{([^}]*)\}", b)
        if not m:
            fails.append("no patch `hull` in constant/polyMesh/boundary")
        else:
            nf = int(re.search(r"nFaces\s+(\d+);", m.group(1)).group(1))
            typ = re.search(r"type\s+(\w+);", m.group(1)).group(1)
            print(f"hull patch: type {typ}, {nf} faces")
            if typ != "wall" or nf == 0:
                fails.append(f"hull patch: type {typ}, {nf} faces")
        chk = logs["checkMesh"]
        if "Mesh OK." not in chk:
            fails.append("checkMesh: not 'Mesh OK.'")
        vm = float(re.search(r"Total volume = ([0-9]+\.?[0-9]*(?:[eE][+-]?[0-9]+)?)", chk).group(1))
        vbox = math.prod(box[1][i] - box[0][i] for i in range(3))
        R, L, D = 0.1, 1.2, 0.5
        vhull = (L - R) * 2 * R * D + math.pi * R * R * D / 2
        err = abs((vbox - vm) - vhull) / vhull
        print(f"hull volume from the mesh {vbox - vm:.6g} m3, analytic {vhull:.6g} m3, "
              f"relative error {err:.3e} (tolerance 3e-2)")
        if err > 3e-2:
            fails.append(f"hull volume from the mesh off by {err:.3e}")
        cells = re.search(r"cells:\s+(\d+)", chk)
        print(f"cells: {cells.group(1) if cells else '?'}")
    for f_ in fails:
        print("FAIL:", f_)
    print("snappyHull:", "FAILED" if fails else "passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
