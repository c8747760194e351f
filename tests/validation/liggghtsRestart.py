#!/usr/bin/env python3
"""Restart with the LIGGGHTS back end continues the unbroken run.

The settling sphere of liggghtsSettlingSphere.py (demPimpleFoam,
demBackend liggghts) run 0 -> 0.04 s, and 0 -> 0.02 s then restarted from
0.02 s to 0.04 s. At the write time 0.02 the back end writes
0.02/liggghts/liggghts.restart (LIGGGHTS write_restart) and the fluid force
held for the next advance (0.02/polyDEM/fluidForces); the restarted run
runs restartScript (read_restart ${restartFile}) and start() hands that
force over again. The same split on 2 ranks (decomposePar; LIGGGHTS on
both, its restart file and the held forces in the case folder's 0.02, as
in a serial run, none under processor0/) against the
serial unbroken run (pressure solved to 1e-12, relTol 0, so that the
decomposed fluid solve agrees with the serial one). Checked: the sphere's velocity and position at every
fluid step after the restart equal the unbroken run's to 1e-9 of |Up| and
of the displacement
(the DEM state is restored bit for bit by LIGGGHTS's binary restart; the
fluid fields are written with 12 digits, writePrecision 12, so the fluid
side of the restarted run starts from rounded fields: its forces differ
in the 12th digit).
"""
import os
import hedracase as hc
import liggghtscase as lc

rho, nu, rhoP, d = 1000.0, 1e-6, 2500.0, 5e-4
box = ((0, 0, 0), (0.03, 0.03, 0.1))
centre = (0.0125, 0.0125, 0.085)
COUPLING = """formulation setI;
momentumCoupling implicit;
voidFractionModel divided;
forceModels (SchillerNaumann pressureGradient);
""" + lc.coupling_lines(restart="constant/liggghts/in.liggghts_restart")


def make_case(name, end, write):
    case = hc.workdir(f"liggghts-restart-{name}")
    hc.block_mesh(case, *box, (6, 6, 20),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, end, 1e-3, write)
    hc.schemes_solution(case, pTol=1e-12, pRelTol=0)
    hc.transport(case, nu, rho)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    lc.script(case, box, 5e-6, rhoP, d, [centre], floor_z=0.0, couple_every=200)
    lc.script(case, box, 5e-6, rhoP, d, [centre], floor_z=0.0, couple_every=200, restart=True,
              name="in.liggghts_restart")
    hc.coupling(case, COUPLING)
    hc.run("blockMesh", case, "log.blockMesh")
    return case


whole = make_case("whole", 0.04, 1)
hc.run("demPimpleFoam", whole, "log.demPimpleFoam")
split = make_case("split", 0.02, 0.02)
hc.run("demPimpleFoam", split, "log.demPimpleFoam.1")
results = []
for f in ("0.02/liggghts/liggghts.restart", "0.02/polyDEM/fluidForces"):
    ok = os.path.isfile(os.path.join(split, f))
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {f} written")
hc.control_dict(split, 0.04, 1e-3, 1)
hc.run("demPimpleFoam", split, "log.demPimpleFoam.2")
log = open(os.path.join(split, "log.demPimpleFoam.2")).read()
ok = "liggghtsBackend: restart from" in log and "in.liggghts_restart" in log
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the restarted run read the LIGGGHTS restart file"
      " with restartScript")

a = {round(r[0], 9): r for r in hc.read_summary(whole)}
b = {round(r[0], 9): r for r in hc.read_summary(split)}
later = sorted(t for t in b if t > 0.02 + 1e-9)
ok = len(later) == 20 and all(t in a for t in later)
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: {len(later)} steps after the restart")
# Vector differences against the vector's size (the lateral components are
# round-off noise, ~1e-7 m/s: no relative measure of their own)
import math
x0 = a[min(a)][hc.COLS["xp"]]
worstU = worstX = 0.0
for t in later:
    ua, ub = a[t][hc.COLS["Up"]], b[t][hc.COLS["Up"]]
    xa, xb = a[t][hc.COLS["xp"]], b[t][hc.COLS["xp"]]
    worstU = max(worstU, math.dist(ua, ub) / math.hypot(*ua))
    worstX = max(worstX, math.dist(xa, xb) / math.dist(xa, x0))
for label, v in (("max |dUp| / |Up|", worstU), ("max |dxp| / displacement", worstX)):
    ok = v <= 1e-9 and bool(later)
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: after the restart, {label} = {v:.3g} (tolerance 1e-9)")

# The split on 2 ranks
par = make_case("split-np2", 0.02, 0.02)
hc.run("decomposePar", par, "log.decomposePar")
hc.run("mpirun -np 2 demPimpleFoam -parallel", par, "log.demPimpleFoam.1")
for f in ("0.02/liggghts/liggghts.restart", "0.02/polyDEM/fluidForces"):
    ok = os.path.isfile(os.path.join(par, f)) \
        and not os.path.exists(os.path.join(par, "processor0", f))
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: 2 ranks: {f} written in the case folder (not processor0)")
hc.control_dict(par, 0.04, 1e-3, 1)
hc.run("mpirun -np 2 demPimpleFoam -parallel", par, "log.demPimpleFoam.2")
log = open(os.path.join(par, "log.demPimpleFoam.2")).read()
ok = "liggghtsBackend: restart from" in log and "LIGGGHTS on 2 rank(s)" in log
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: 2 ranks: restarted from the LIGGGHTS restart file")
c = {round(r[0], 9): r for r in hc.read_summary(par)}
laterP = sorted(t for t in c if t > 0.02 + 1e-9)
worstU = worstX = 0.0
for t in laterP:
    ua, uc = a[t][hc.COLS["Up"]], c[t][hc.COLS["Up"]]
    xa, xc = a[t][hc.COLS["xp"]], c[t][hc.COLS["xp"]]
    worstU = max(worstU, math.dist(ua, uc) / math.hypot(*ua))
    worstX = max(worstX, math.dist(xa, xc) / math.dist(xa, x0))
for label, v in (("max |dUp| / |Up|", worstU), ("max |dxp| / displacement", worstX)):
    ok = v <= 1e-9 and len(laterP) == 20
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: 2 ranks, restarted, against serial unbroken: {label} ="
          f" {v:.3g} (tolerance 1e-9)")
hc.finish(results)
