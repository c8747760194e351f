#!/usr/bin/env python3
"""demInterFoam with adjustTimeStep yes and particles: the DEM keeps the
fluid's time.

Closed tank 0.03 x 0.03 x 0.06 m (6 x 6 x 12 cells of 5 mm), water 0.03 m
deep; 20 glass spheres (d = 2 mm) released at rest in the air above it fall
into the water (the fluid velocity, and so the Courant-limited step,
changes every step). maxCo 0.2, DEM step 2.5e-5 s, writeControl
adjustableRunTime every 0.05 s, to t = 0.2 s.

Before this check existed the DEM kept the number of DEM steps of the
first deltaT, so its clock drifted from the fluid's with every adjusted
step. Checked:
  1. every fluid step is a whole number of DEM steps (deltaT/timeStep
     within 1e-9 of an integer, from the log's 'deltaT =' lines);
  2. the time step did change (more than one distinct deltaT), so 1 is a
     test of the rounding and not of a fixed step;
  3. the DEM clock equals the fluid's at every sample: the DEM summary's
     time equals step x timeStep and the fluid time of that step (1e-9 s);
  4. every write time of the adjustable write control was hit to within
     half a DEM step (time folders 0.05 0.1 0.15 0.2).
  5. a step of a few DEM steps grows again: the same tank started at
     deltaT = 1 DEM step, to t = 0.01 s, must reach 10 DEM steps (the
     Courant limit, maxCo 0.2 on 5 mm cells, allows 4 m/s at that step;
     the fluid is nearly at rest). Rounding the damped growth (x 1.2) down
     to whole DEM steps kept any step of 4 or fewer DEM steps (the write-
     time balancing leaves such steps) there for the rest of the run.
"""
import os
import re
import hedracase as hc
import vofcase as vc

LO, HI, N = (0.0, 0.0, 0.0), (0.03, 0.03, 0.06), (6, 6, 12)
LEVEL = 0.03
DT_DEM = 2.5e-5
END, WRITE = 0.2, 0.05
results = []


def run_tank(name, end, dt, write):
    """The tank with its falling spheres, run to end from deltaT dt; the
    solver's log"""
    case = hc.workdir(name)
    vc.closed_tank(case, LO, HI, N)
    vc.water_field(case, LO, HI, N, LEVEL)
    vc.vof_dicts(case, end, dt, write, maxCo=0.2, adjust=True)
    hc.dem_properties(case, DT_DEM, 2500, 2e-3,
                      vc.box_walls(LO, HI),
                      hc.random_fill("drop", 20, (0.004, 0.004, 0.04), (0.026, 0.026, 0.055)),
                      E=2e6)
    hc.coupling(case, vc.SPHERES_COUPLING)
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", timeout=900)
    return case, open(os.path.join(case, "log.demInterFoam")).read()


case, log = run_tank("vofAdjustTimeStep", END, 5e-4, WRITE)

dts = [float(x) for x in re.findall(r"^deltaT = ([0-9.eE+-]+)", log, re.M)]
worst = max(abs(d / DT_DEM - round(d / DT_DEM)) for d in dts) if dts else 1.0
ok = bool(dts) and worst <= 1e-9
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: {len(dts)} adjusted fluid steps, each a whole number of DEM"
      f" steps: worst |deltaT/timeStep - round| = {worst:.3g} (tolerance 1e-9)")

distinct = sorted({round(d / DT_DEM) for d in dts})
ok = len(distinct) > 1
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the step changed: {len(distinct)} distinct step lengths"
      f" ({distinct[0] if distinct else '-'} .. {distinct[-1] if distinct else '-'} DEM steps)")

# DEM summary: time step ... (postProcessing/demFoam/0/summary.dat)
rows = []
with open(os.path.join(case, "postProcessing/demFoam/0/summary.dat")) as f:
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        v = line.split()
        rows.append((float(v[0]), int(v[1])))
fluidTimes = [0.0] + [float(x) for x in re.findall(r"^Time = ([0-9.eE+-]+)", log, re.M)]
clock = max(abs(t - s * DT_DEM) for t, s in rows)
# each sample is taken after a fluid step: its time must be a fluid time
# (printed with timePrecision 8: 1e-9 s is within that)
lag = max(min(abs(t - tf) for tf in fluidTimes) for t, s in rows)
ok = len(rows) > 2 and clock <= 1e-9 and lag <= 1e-9
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: DEM clock: max |t - step x timeStep| = {clock:.3g} s,"
      f" max distance of a DEM sample from a fluid time {lag:.3g} s over {len(rows)} samples"
      f" (tolerance 1e-9 s)")

times = sorted(float(t) for t in os.listdir(case) if re.match(r"^[0-9.]+$", t) and float(t) > 0)
want = [WRITE * k for k in range(1, int(round(END / WRITE)) + 1)]
miss = max(min(abs(t - w) for t in times) for w in want) if times else 1.0
ok = len(times) == len(want) and miss <= 0.5 * DT_DEM
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: write times {times} against {want}: worst miss {miss:.3g} s"
      f" (tolerance half a DEM step, {0.5 * DT_DEM:g} s)")

# 5. growth from one DEM step
_, log2 = run_tank("vofAdjustTimeStepGrowth", 0.01, DT_DEM, 0.01)
steps2 = [round(float(x) / DT_DEM) for x in re.findall(r"^deltaT = ([0-9.eE+-]+)", log2, re.M)]
cos = [float(x) for x in re.findall(r"^Courant Number mean: \S+ max: (\S+)", log2, re.M)]
ok = bool(steps2) and max(steps2) >= 10
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: from deltaT = 1 DEM step the step grew to {max(steps2) if steps2 else 0}"
      f" DEM steps in {len(steps2)} fluid steps (at least 10 wanted; largest Courant number"
      f" {max(cos) if cos else float('nan'):.3g} against maxCo 0.2)")
hc.finish(results)
