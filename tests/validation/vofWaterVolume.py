#!/usr/bin/env python3
"""Water volume with moving particles (demInterFoam, unresolved mode).

Closed tank 0.06 x 0.06 x 0.08 m (12 x 12 x 16 cells of 5 mm), water
0.04 m deep; 200 glass spheres (d = 2 mm, 2500 kg/m3) released in the air
above it fall through the free surface into the water and sink. divided
void fraction, SchillerNaumann + freeSurfacePressure, to t = 0.25 s.

The solver transports ddt(eps alpha) + div(phi alpha) + compression =
Sp alpha with the flux projected on the new void fraction each step, so
the water volume int eps alpha dV changes only by Sp's share, the pressure
solver's tolerance (1e-12 here).
Checked (tolerances): max_t |W(t) - W(0)|/W(0) <= 1e-8; -1e-6 <= alpha
<= 1 + 1e-6 at every step; the particles reached the water (mean height
below the initial surface at the end).

-refine: the same on a mesh that refines itself at the free surface
(dynamicRefineFvMesh on alpha.water, one level, interFoam's usual set-up):
the particles fall through refined cells, and the same checks hold across
the refinements (at least one refinement must happen). Before the solver
rebuilt eps rho on the new cells it blew up at the first refinement.
"""
import math
import os
import sys

import hedracase as hc
import vofcase as vc

refine = "-refine" in sys.argv[1:]

LO, HI, N = (0.0, 0.0, 0.0), (0.06, 0.06, 0.08), (12, 12, 16)
LEVEL = 0.04
results = []
case = hc.workdir("vofWaterVolumeRefined" if refine else "vofWaterVolume")
vc.closed_tank(case, LO, HI, N)
if refine:
    vc.refine_at_surface(case)
vc.water_field(case, LO, HI, N, LEVEL)
vc.vof_dicts(case, 0.25, 5e-4, 0.25)
hc.dem_properties(case, 2.5e-5, 2500, 2e-3,
                  vc.box_walls(LO, HI),
                  hc.random_fill("drop", 200, (0.005, 0.005, 0.05), (0.055, 0.055, 0.075)), E=2e6)
hc.coupling(case, vc.SPHERES_COUPLING)
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)
if refine:
    log = open(os.path.join(case, "log.demInterFoam")).read()
    nRefined, nUnrefined = log.count("Refined from"), log.count("Unrefined from")
    ok = nRefined >= 1
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: the mesh refined itself {nRefined} times and unrefined "
          f"{nUnrefined} times")
rows = vc.read_water(case)
W0 = rows[0][1]
drift = max(abs(r[1] - W0) for r in rows) / W0
ok = drift <= 1e-8
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: water volume int eps alpha dV: max relative change {drift:.3g}"
      f" over {len(rows)} steps (W0 = {W0:.9g} m3; tolerance 1e-8)")
aMin = min(r[2] for r in rows)
aMax = max(r[3] for r in rows)
ok = aMin >= -1e-6 and aMax <= 1 + 1e-6
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: alpha bounds over the run: min {aMin:.3g}, max - 1 = {aMax - 1:.3g}"
      f" (tolerance 1e-6)")
solid = [r[4] for r in rows]
print(f"info: solid volume in the mesh {min(solid):.9g} .. {max(solid):.9g} m3"
      f" (200 spheres: {200 * math.pi / 6 * 8e-9:.9g})")
summ = hc.read_summary(case)
zEnd = summ[-1][hc.COLS["xp"]][2]
ok = zEnd < LEVEL
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: mean particle height at the end {zEnd:.4f} m (< surface {LEVEL} m:"
      f" the particles crossed the free surface)")
hc.finish(results)
