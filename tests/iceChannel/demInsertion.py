#!/usr/bin/python3
"""CTest iceChannel.demInsertion: demFoam reads brashIceChannel's includes and
puts every block where the builder placed it; the iceHull STL loads as a DEM
`mesh` wall.

A small channel of cuboids (box types, some thicker than wide, so the engine's
principal-axis sort permutes their axes) and random plates (STL types) is
built, included into constant/demProperties with
    materials     { #include "brashIce/materials" }
    particleTypes { #include "brashIce/particleTypes" }
    insertion     { #include "brashIce/insertion" }
and the dummy hull as a wall; demFoam runs one DEM step.  Every vertex of
<0>/polyDEM/polyhedra.vtp (the engine's world-frame faces, written at the
start of a fresh run) must coincide with a vertex rebuilt here from the
insertion (position + R(orientation) x body vertices, docs/demProperties.md)
and vice versa, to 1e-9 m; and the counts must agree.  A wrong orientation
convention, axis order or centroid moves vertices by centimetres.  Together
with brashIceBuilder (the same rebuild from the written files satisfies the
overlap, draft and slab checks) this closes the chain builder -> files ->
engine.  Checked to fail: with the builder's engine-frame sort switched off,
the plate STLs no longer match the engine's body frame (FAILED).
The plates are built with `velocity (0.5 0.1 0)` (the ice's drift in a
hull-fixed frame), the cuboids without: after the one step every block's
horizontal velocity must be that, to 1e-12 m/s (no contact acts in the step).
Needs demFoam on PATH (./Allwmake; or source /work/main/etc/bashrc).
"""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from brashIceBuilder import read_case  # noqa: E402

TOOLS = os.path.join(HERE, "..", "..", "applications", "utilities", "brashIceChannel")

CHANNEL = """
channel { origin (0 -0.3); length 0.9; width 0.6; waterLevel 0.5; }
thickness { type uniform; value 0.1; }
blockThickness 0.1;
sizeDistribution { type uniform; min 0.06; max 0.16; }
sizeClasses 3;
shape { type %s; }
porosity 0.6;
seed 2;
iceDensity 920;
waterDensity 1010;
iceMaterial { youngsModulus 2e9; poissonsRatio 0.3; }
output { include constant/brashIce; }
%s
"""
DRIFT = {"cuboid": None, "plate": (0.5, 0.1, 0.0)}


def demProperties():
    return """FoamFile { version 2.0; format ascii; class dictionary; object demProperties; }
device cpu;
timeStep 1e-5;
gravity (0 0 -9.81);
contactModel { law overlapVolume; volumetricStiffness 1e8; }
materials
{
    #include "brashIce/materials"
    steel { youngsModulus 2e9; poissonsRatio 0.3; density 7800; }
}
interactions { default { restitution 0.3; friction 0.3; } }
particleTypes { #include "brashIce/particleTypes" }
walls
{
    hull { type mesh; file "hull.stl"; material steel; }
}
insertion { #include "brashIce/insertion" }
output { vtk true; }
"""


CONTROL = """FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application demFoam; startFrom startTime; startTime 0; stopAt endTime;
endTime 1e-5; deltaT 1e-5; writeControl timeStep; writeInterval 1;
writeFormat ascii; writePrecision 12; timeFormat general; timePrecision 8;
runTimeModifiable false;
"""


def vtp_points(path):
    with open(path) as f:
        txt = f.read()
    m = re.search(r"<Points>\s*<DataArray[^>]*>(.*?)</DataArray>", txt, re.S)
    return np.array(m.group(1).split(), dtype=float).reshape(-1, 3)


def main():
    fails = []
    for shape in ("cuboid", "plate"):
        case = tempfile.mkdtemp(prefix="demInsertion" + shape,
                                dir=os.environ.get("HEDRA_TEST_TMP"))
        os.makedirs(os.path.join(case, "system"))
        with open(os.path.join(case, "system", "brashIceChannelDict"), "w") as f:
            v = DRIFT[shape]
            f.write(CHANNEL % (shape, "" if v is None else "velocity (%g %g %g);" % v))
        with open(os.path.join(case, "system", "iceHullDict"), "w") as f:
            f.write("hull { type dummy; }\nplacement { stem (1.5 0 0.5); bowDirection -x; }\n")
        with open(os.path.join(case, "system", "controlDict"), "w") as f:
            f.write(CONTROL)
        os.makedirs(os.path.join(case, "constant"), exist_ok=True)
        with open(os.path.join(case, "constant", "demProperties"), "w") as f:
            f.write(demProperties())
        for tool in ("brashIceChannel", "iceHull"):
            subprocess.run([os.path.join(TOOLS, tool), "-case", case], check=True,
                           stdout=subprocess.DEVNULL)
        with open(os.path.join(case, "log.demFoam"), "w") as log:
            rc = subprocess.run(["demFoam", "-case", case], stdout=log,
                                stderr=subprocess.STDOUT).returncode
        if rc != 0:
            fails.append(f"{shape}: demFoam failed (rc {rc}), see {case}/log.demFoam")
            continue
        blocks, _ = read_case(case)
        want = np.unique(np.round(np.vstack([b["W"] for b in blocks]), 12), axis=0)
        got = np.unique(np.round(vtp_points(os.path.join(case, "0", "polyDEM",
                                                         "polyhedra.vtp")), 12), axis=0)
        d1 = cKDTree(got).query(want)[0].max()
        d2 = cKDTree(want).query(got)[0].max()
        print(f"{shape}: {len(blocks)} blocks, {len(want)} vertices rebuilt, {len(got)} in "
              f"polyhedra.vtp; largest distance {max(d1, d2):.2e} m (tolerance 1e-9)")
        if len(want) != len(got) or max(d1, d2) > 1e-9:
            fails.append(f"{shape}: engine and builder disagree by {max(d1, d2):.3e} m "
                         f"({len(got)} against {len(want)} vertices)")
        sys.path.insert(0, os.path.join(HERE, "..", "..", "tutorials", "demInterFoam", "common"))
        import demState
        st = demState.read_state(os.path.join(case, "1e-05", "polyDEM", "state"))
        want_v = DRIFT[shape] or (0.0, 0.0, 0.0)
        dv = max(max(abs(p["vx"] - want_v[0]), abs(p["vy"] - want_v[1]))
                 for p in st["particles"])
        print(f"{shape}: horizontal velocity after one step off {want_v[:2]} by at most "
              f"{dv:.2e} m/s over {len(st['particles'])} blocks (tolerance 1e-12)")
        if len(st["particles"]) != len(blocks) or dv > 1e-12:
            fails.append(f"{shape}: drift velocity off by {dv:.3e} m/s")
        with open(os.path.join(case, "log.demFoam")) as f:
            log = f.read()
        if "hull" not in log:
            fails.append(f"{shape}: the log does not mention the hull wall")
    for f_ in fails:
        print("FAIL:", f_)
    print("demInsertion:", "FAILED" if fails else "passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
