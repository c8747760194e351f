#!/usr/bin/env python3
"""Closed surface with fluid trapped between bodies (demInterFoam couplingMode
resolved, directForcing { closedSurface true; }).

Two blocks A and B (20 x 19 x 15 mm, 2000 kg/m3) stand on the floor of a
tank 80 x 20 x 60 mm (dx 2.5 mm) with a gap of 7.5 mm (3 cells) between
them, and a third block C of the same size lies across them. The blocks
span the tank's depth to within 0.5 mm of its front and back walls, so the
cells of the gap (3 x 6 x 8 = 144) are fluid cells that the full cells of
A, B and C, the floor and the two walls enclose: with every face of a full
cell closed (rigid flux, no pressure coupling), that pocket's pressure
equation has no fixed level, and where the blocks move (here they settle
0.3 mm onto the floor and onto each other) the rigid fluxes through its
faces do not balance. Before the fix (2026-12-08) its pressure ran away on
the first step: in the rock pile (damBreakRockPile -test -resolved with
closedSurface true) 6 such cells gave two rocks 7.6e10 N and the DEM
stopped. Now such fluid keeps its faces to the bodies open
(directForcingIB::trappedFluidCells) and takes its level from the bodies'
held pressure.

Water 50 mm deep over the blocks (their tops at 30.6 mm), the top open to
the atmosphere. Run 0.05 s (dt 1 ms): the blocks, released from rest, fall
0.3 mm onto the floor and onto each other (about 0.015 s) and come to rest.
Checked:
- the run ends (no FatalError) and the log names the trapped cells (the
  gap's 144);
- on every step after the first, each block's vertical fluid force FDz
  between half of Archimedes' rho_w g V and the block's weight
  rho_b g V = 2 rho_w g V: released from rest and falling, the fluid
  holds a block up by its buoyancy and a resistance that cannot exceed its
  weight while it still gains speed; landed in still water, by its
  buoyancy alone (a force beyond the weight would lift it off the floor);
- each block's horizontal fluid force below half its weight (the set-up
  is symmetric but for the mesh).
The landing also checks directForcingIB::balanceClosedFaces: the blocks'
full cells reach the floor (the 0.3 mm gap under them is below half a
cell), where the wall carries none of their rigid flux. Without the
balance the fluid followed a block down at its top with nothing pushed
out below, and the blocks' velocity and fluid force oscillated with a
period of two steps, growing (measured 2026-12-08: FDx of block A 0.008 N
at 0.011 s, 0.22 N at 0.031 s, 4.8 N at 0.05 s; in a closed tank from the
second step on). With it: FDz in [0.049, 0.087] N, horizontal at most
0.033 N.
About 10 s on one core.
"""
import math
import os
import re
import hedracase as hc
import vofcase as vc

DX = 0.0025
LO, HI = (0.0, 0.0, 0.0), (0.08, 0.02, 0.06)
N = (32, 8, 24)
LEVEL = 0.05
SIZE = (0.02, 0.019, 0.015)      # the blocks span y to within 0.5 mm of the walls
RHO_B = 2000.0
GAP = 0.0075
X0 = 0.0103                      # A's left face, off the cell faces
LIFT = 0.0003                    # each block 0.3 mm above what it rests on
DT = 1e-3
END = 0.05
G = 9.81
YC = 0.5 * (LO[1] + HI[1])


def centres():
    a = (X0 + SIZE[0] / 2, YC, LIFT + SIZE[2] / 2)
    b = (X0 + 1.5 * SIZE[0] + GAP, YC, LIFT + SIZE[2] / 2)
    c = (X0 + SIZE[0] + GAP / 2, YC, 2 * LIFT + 1.5 * SIZE[2])
    return [a, b, c]


def box(c):
    return (tuple(c[k] - SIZE[k] / 2 for k in range(3)),
            tuple(c[k] + SIZE[k] / 2 for k in range(3)))


def run(name, open_top):
    case = hc.workdir(name)
    vc.closed_tank(case, LO, HI, N, open_top=open_top)
    blocks = centres()
    vc.water_field(case, LO, HI, N, LEVEL, [box(c) for c in blocks])
    vc.vof_dicts(case, END, DT, END, limiterIter=20)
    vc.dem_blocks(case, 1e-4, RHO_B, blocks, SIZE, (LO, HI))
    hc.coupling(case, vc.RESOLVED_CUBE_COUPLING.replace(
        "interface penalised;", "interface penalised;\n    closedSurface true;"))
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", check=False, timeout=600)
    return case


results = []
V = SIZE[0] * SIZE[1] * SIZE[2]
buoyancy = vc.RHO_W * G * V
weight = RHO_B * G * V
case = run("vofTrappedFluid", True)
log = open(os.path.join(case, "log.demInterFoam")).read()
ended = "FOAM FATAL" not in log and re.search(r"^End\s*$", log, re.M) is not None
results.append(ended)
print(f"{'PASS' if ended else 'FAIL'}: the run ends (no FatalError)")
trapped = [int(m) for m in re.findall(r"^Closed surface: (\d+) fluid cells trapped", log, re.M)]
ok = len(trapped) > 0
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the trapped fluid is found"
      f" ({min(trapped) if trapped else 0}-{max(trapped) if trapped else 0} cells;"
      f" the gap holds 144)")
# FD per block and step (forces.dat columns 25-27)
lowest, highest, sideways, nRows = math.inf, -math.inf, 0.0, 0
base = os.path.join(case, "postProcessing/ibForces")
for t in sorted(os.listdir(base), key=float) if os.path.isdir(base) else []:
    for line in open(os.path.join(base, t, "forces.dat")):
        if line.startswith("#") or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        if v[0] < 1.5 * DT:
            continue
        nRows += 1
        lowest, highest = min(lowest, v[26]), max(highest, v[26])
        sideways = max(sideways, math.hypot(v[24], v[25]))
ok = nRows == 3 * round(END / DT - 1) and lowest >= 0.5 * buoyancy and highest <= weight
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: vertical fluid force FDz on the blocks in"
      f" [{lowest:.4g}, {highest:.4g}] N over {nRows} block-steps (bounds: half of"
      f" Archimedes' {buoyancy:.4g} N = {0.5 * buoyancy:.4g} N, the weight {weight:.4g} N)")
ok = nRows > 0 and sideways <= 0.5 * weight
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: horizontal fluid force on the blocks at most"
      f" {sideways:.4g} N (bound: half the weight, {0.5 * weight:.4g} N)")
hc.finish(results)
