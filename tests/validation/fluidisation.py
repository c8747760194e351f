#!/usr/bin/env python3
"""Fluidisation: minimum fluidisation velocity and the pressure drop of the
fluidised bed.

Same bed and set-up as ergunBed.py (2000 spheres d = 1 mm, rho_p = 2000,
gas rho 10, nu 1.5e-4, setI, Gidaspow + pressureGradient, divided, 1D
column). Inlet velocity plateaus: 0.004, 0.008 m/s (fixed bed, 0.02 s each),
then 0.025, 0.03 m/s (fluidised, 0.05 s each).

Checks:
  - dp of the fluidised bed (time average over the second half of each
    fluidised plateau) equals the buoyant bed weight per area,
    Vs (rho_p - rho) g / A, within 5 %;
  - U_mf: the fixed-bed curve dp = a U + b U^2 through the two fixed-bed
    plateaus meets the fluidised level at U_mf(sim); compared with Ergun's
    U_mf for the bed's own height and voidage (as in ergunBed.py) within 10 %.
"""
import math
import os
import shutil
import sys
import hedracase as hc

d, rhoP, rho, nu = 1e-3, 2000.0, 10.0, 1.5e-4
mu = rho * nu
W, H, zFloor = 0.012, 0.04, 0.004
N = int(os.environ.get("ERGUN_N", 2000))
U_levels = [0.004, 0.008, 0.025, 0.03]
plateaus = [0.02, 0.02, 0.05, 0.05]
tSettle, dtF = 0.25, 1e-4

case = hc.workdir("fluidisation")
print("case:", case)
hc.block_mesh(case, (0, 0, 0), (W, W, H), (1, 1, 20),
              {"inlet": ("patch", ["zmin"]), "outlet": ("patch", ["zmax"]),
               "sides": ("empty", ["xmin", "xmax", "ymin", "ymax"])})
walls = {"floor": ((0, 0, zFloor), (0, 0, 1)),
         "x0": ((0, 0, 0), (1, 0, 0)), "x1": ((W, 0, 0), (-1, 0, 0)),
         "y0": ((0, 0, 0), (0, 1, 0)), "y1": ((0, W, 0), (0, -1, 0))}
hc.dem_properties(case, 1e-5, rhoP, d, walls,
                  hc.random_fill("bed", N, (0, 0, zFloor + 1e-4), (W, W, H)),
                  E=5e6, restitution=0.3, friction=0.5)
hc.transport(case, nu, rho)
hc.schemes_solution(case, nCorr=2, nOuter=1)

# 1. Settle (DEM only)
hc.control_dict(case, tSettle, 1e-3, tSettle)
with open(os.path.join(case, "system/controlDict")) as f:
    txt = f.read().replace("demPimpleFoam", "demFoam")
with open(os.path.join(case, "system/controlDict"), "w") as f:
    f.write(txt)
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demFoam", case, "log.demFoam")

# 2. Flow through the settled bed
t0 = tSettle
starts = [t0 + sum(plateaus[:k]) for k in range(len(plateaus))]
tEnd = t0 + sum(plateaus)
table = []
for k, Uk in enumerate(U_levels):
    a = starts[k]
    table += [f"({a + (1e-9 if k else 0):.9g} (0 0 {Uk}))", f"({a + plateaus[k]:.9g} (0 0 {Uk}))"]
tstr = f"{t0:g}"
hc.fields(case,
          {"inlet": "type uniformFixedValue; uniformValue table (" + " ".join(table) + ");",
           "outlet": "type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0);",
           "sides": "type empty;"},
          {"inlet": "type fixedFluxPressure;", "outlet": "type fixedValue; value uniform 0;",
           "sides": "type empty;"}, time=tstr)
fo = """functions
{
    inletP
    {
        type surfaceFieldValue; libs ("libfieldFunctionObjects.so");
        writeControl timeStep; writeInterval 1; log false;
        writeFields false; regionType patch; name inlet;
        operation areaAverage; fields (p);
    }
}
"""
hc.control_dict(case, tEnd, dtF, tEnd - t0, extra=fo)
hc.coupling(case, """formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel divided;
smoothingModel none;
forceModels (Gidaspow pressureGradient);
demStepsPerFluidStep 10;
""")
hc.run("demPimpleFoam", case, "log.demPimpleFoam")

# 3. Bed voidage and height from the particles at the start of the flow
bed = hc.measure_bed(case, tstr, tEnd, W, zFloor, d)
Vs, A, L, eps = bed["Vs"], bed["A"], bed["L"], bed["eps"]

def ergun(U):
    return hc.ergun_dp(U, L, eps, d, mu, rho)

# 4. Pressure drop at the end of each plateau
rows = hc.read_inlet_p(case, tstr)
results = []
W = Vs * (rhoP - rho) * 9.81 / A
dps = []
for k, Uk in enumerate(U_levels):
    a, e = starts[k], starts[k] + plateaus[k]
    if k < 2:
        t, pin = min(rows, key=lambda r: abs(r[0] - e))
        dp = rho * pin - rho * 9.81 * H
    else:
        sel = [pin for t, pin in rows if a + plateaus[k] / 2 <= t <= e + 1e-9]
        dp = rho * sum(sel) / len(sel) - rho * 9.81 * H
    dps.append(dp)
    print(f"U = {Uk} m/s: dp = {dp:.3f} Pa" + (" (time average)" if k >= 2 else ""))
for k in (2, 3):
    hc.check(f"fluidised dp at U = {U_levels[k]} m/s vs bed weight per area [Pa]",
             dps[k], W, 0.05, results)
# fixed-bed curve through the two fixed-bed points: dp = a U + b U^2
U1, U2 = U_levels[0], U_levels[1]
bq = (dps[1] / U2 - dps[0] / U1) / (U2 - U1)
aq = dps[0] / U1 - bq * U1
level = 0.5 * (dps[2] + dps[3])
Umf_sim = (-aq + math.sqrt(aq * aq + 4 * bq * level)) / (2 * bq) if bq > 0 else level / aq
lo, hi = 0.0, 1.0
for _ in range(100):
    Umf = 0.5 * (lo + hi)
    lo, hi = (Umf, hi) if ergun(Umf) < W else (lo, Umf)
hc.check("U_mf [m/s] (simulated fixed-bed curve meets fluidised level) vs Ergun",
         Umf_sim, Umf, 0.10, results)

summary = hc.read_summary(case)
worst = max(r[hc.COLS["relErr"]] for r in summary)
ok = worst < 1e-10
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: momentum exchange balance, worst relErr {worst:.3g} (< 1e-10)")
print("bed weight per area:", L * (1 - eps) * (rhoP - rho) * 9.81, "Pa")
hc.finish(results)
