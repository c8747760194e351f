#!/usr/bin/env python3
"""Settle serially, decompose, run on 2 ranks, reconstruct, continue serially:
no particle and no contact spring is lost, and the result is that of an
unbroken serial run.

150 glass spheres (d = 1 mm) are poured by demFoam (DEM only, serial) for
0.1 s (10000 DEM steps) into an 8 x 8 mm box of DEM walls: a bed of 120,
resting on the floor and the walls (wall springs) and on each other (pair
springs), and a cloud of 30 added at 0.08 s, still falling. Water is then added (U, p at 0.1) and demPimpleFoam runs
0.1 -> 0.12 s in two ways:
  reference: serial, in one go;
  round trip: decomposePar (simple (2 1 1): the split plane x = 10 mm goes
  through the bed and the cloud), mpirun -np 2 demPimpleFoam -parallel to
  0.11, reconstructPar, serial demPimpleFoam 0.11 -> 0.12.
Checks:
  - the parallel run restarted from the settled bed in the case folder
    (0.1/polyDEM/state: the DEM is not decomposed), with all 150 particles;
    the serial continuation restarted from 0.11/polyDEM/state and its forces;
  - the DEM state and particle output are in the case folder only: no
    polyDEM/, particles.pvd, walls.pvd or postProcessing/demFoam under
    processor*/; particles.pvd lists 0.1, 0.11 and 0.12;
  - at 0.11 and 0.12: the same particle ids as the reference, positions to
    1e-6 of the largest displacement since 0.1 (the fluid forces are summed
    over the ranks in another order, as in parallelAgreement); at 0.11 the
    same pair and wall contacts, springs to 1e-6 of the largest spring;
  - a decomposed case whose restart time lacks its DEM state stops with a
    FatalIOError naming the state and freshStart (it used to insert 150 new
    particles and exit 0);
  - demFoam -parallel runs in the decomposed case (DEM on the master) and
    writes its state in the case folder.
"""
import glob
import math
import os
import re
import shutil
import hedracase as hc

T0, T1, T2 = 0.1, 0.11, 0.12
N = 150
case = hc.workdir("roundTrip")
hc.block_mesh(case, (0, 0, 0), (0.02, 0.02, 0.04), (8, 8, 16),
              {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
hc.control_dict(case, T0, 1e-3, T0)
hc.schemes_solution(case, pTol=1e-12, pRelTol=0)
hc.foamfile(os.path.join(case, "system/decomposeParDict"), "decomposeParDict",
            "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (2 1 1); }\n")
hc.transport(case, 1e-6, 1000)
bed = hc.random_fill("bed", N - 30, (0.006, 0.006, 0.0006), (0.014, 0.014, 0.012))
cloud = hc.random_fill("cloud", 30, (0.0065, 0.0065, 0.022), (0.0135, 0.0135, 0.035), seed=2)
cloud = cloud.replace("seed 2;", "seed 2; time 0.08;")
# an 8 x 8 mm DEM box in the middle of the fluid's: a bed of about two layers
box = {"floor": ((0, 0, 0), (0, 0, 1)),
       "x0": ((0.006, 0, 0), (1, 0, 0)), "x1": ((0.014, 0, 0), (-1, 0, 0)),
       "y0": ((0, 0.006, 0), (0, 1, 0)), "y1": ((0, 0.014, 0), (0, -1, 0))}
hc.dem_properties(case, 1e-5, 2500, 1e-3, box, bed + "\n" + cloud)
props = os.path.join(case, "constant/demProperties")
txt = open(props).read().replace("vtk false;", "vtk true;")
open(props, "w").write(txt)
hc.coupling(case, """formulation setI;
voidFractionModel divided;
forceModels (DiFelice pressureGradient);
""")
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demFoam", case, "log.demFoam")
hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"}, time=f"{T0:g}")


def set_end(c, t):
    p = os.path.join(c, "system/controlDict")
    txt = open(p).read()
    open(p, "w").write(re.sub(r"\nendTime [^;]*;", f"\nendTime {t};", txt))


def set_write(c, t):
    p = os.path.join(c, "system/controlDict")
    txt = open(p).read()
    open(p, "w").write(re.sub(r"\nwriteInterval [^;]*;", f"\nwriteInterval {t};", txt))


def copy(name):
    d = hc.workdir(name)
    shutil.rmtree(d)
    shutil.copytree(case, d)
    return d


ref, par, lost = copy("roundTripRef"), copy("roundTripPar"), copy("roundTripLost")
for c in (ref, par, lost):
    set_write(c, T1 - T0)

# reference: serial, in one go
set_end(ref, T2)
hc.run("demPimpleFoam", ref, "log.demPimpleFoam")

# round trip
set_end(par, T1)
hc.run("decomposePar", par, "log.decomposePar")
hc.run("mpirun -np 2 demPimpleFoam -parallel", par, "log.demPimpleFoam.parallel")
hc.run("reconstructPar", par, "log.reconstructPar")
set_end(par, T2)
hc.run("demPimpleFoam", par, "log.demPimpleFoam.serial")


def read_state(path):
    """ids -> position; pair springs (idA, idB) -> tangential; wall springs
    (id, wall, triangle) -> tangential"""
    with open(path) as f:
        lines = f.read().split("\n")
    head = {l.split()[0]: l.split()[1:] for l in lines[:lines.index("data")] if l}
    n, npair, nwall = (int(head[k][0]) for k in ("particles", "pairs", "walls"))
    i = lines.index("data") + 1
    x = {int(l.split()[0]): tuple(float(v) for v in l.split()[7:10]) for l in lines[i:i + n]}
    pairs = {(int(l.split()[0]), int(l.split()[1])): tuple(float(v) for v in l.split()[2:5])
             for l in lines[i + n:i + n + npair]}
    walls = {tuple(int(v) for v in l.split()[0:3]): tuple(float(v) for v in l.split()[6:9])
             for l in lines[i + n + npair:i + n + npair + nwall]}
    return x, pairs, walls


results = []


def report(ok, text):
    results.append(bool(ok))
    print(f"{'PASS' if ok else 'FAIL'}: {text}")


logPar = open(os.path.join(par, "log.demPimpleFoam.parallel")).read()
logSer = open(os.path.join(par, "log.demPimpleFoam.serial")).read()
report(f'restarting from "{par}/{T0:g}/polyDEM/state"' in logPar and f"DEM: {N} particles" in logPar,
       f"the 2-rank run restarted from the settled bed in the case folder ({N} particles)")
report(f'restarting from "{par}/{T1:g}/polyDEM/state"' in logSer
       and "fluid forces of the restart read" in logSer,
       f"the serial continuation restarted from {T1:g}/polyDEM/state and its fluid forces")

inProcs = [p for pat in ("processor*/**/polyDEM", "processor*/*.pvd", "processor*/postProcessing/demFoam")
           for p in glob.glob(os.path.join(par, pat), recursive=True)]
report(not inProcs, "no DEM state or particle output under processor*/"
       + (f" (found {', '.join(os.path.relpath(p, par) for p in inProcs)})" if inProcs else ""))
pvd = open(os.path.join(par, "particles.pvd")).read() if os.path.isfile(os.path.join(par, "particles.pvd")) else ""
report(all(f'file="{t:g}/polyDEM/particles.vtp"' in pvd for t in (T0, T1, T2))
       and os.path.isfile(os.path.join(par, "walls.pvd"))
       and os.path.isfile(os.path.join(par, f"postProcessing/demFoam/{T0:g}/summary.dat")),
       f"particles.pvd ({T0:g}, {T1:g}, {T2:g}), walls.pvd and postProcessing/demFoam/{T0:g} in the case folder")

x0, p0, w0 = read_state(os.path.join(case, f"{T0:g}/polyDEM/state"))
print(f"settled bed at {T0:g} s: {len(x0)} particles, {len(p0)} pair springs, {len(w0)} wall springs")
report(len(x0) == N and len(p0) > 0 and len(w0) > 0, "the settled bed has pair and wall springs to carry")
for t in (T1, T2):
    xr, pr, wr = read_state(os.path.join(ref, f"{t:g}/polyDEM/state"))
    xp, pp, wp = read_state(os.path.join(par, f"{t:g}/polyDEM/state"))
    report(sorted(xr) == sorted(xp) and len(xp) == N, f"t = {t:g}: the same {len(xr)} particle ids ({len(xp)} round trip)")
    disp = max(math.dist(xr[i], x0[i]) for i in xr)
    dev = max((math.dist(xr[i], xp[i]) for i in xr if i in xp), default=math.inf)
    straddle = sum(1 for i in xr if abs(xr[i][0] - 0.01) < 0.0005)
    report(dev < 1e-6 * disp, f"t = {t:g}: max |x_round trip - x_reference| = {dev:.3g} m, "
           f"max displacement {disp:.3g} m (ratio < 1e-6); {straddle} particles straddle x = 10 mm")
    if t == T1:
        for what, r, p in (("pair", pr, pp), ("wall", wr, wp)):
            scale = max((math.hypot(*v) for v in r.values()), default=0)
            dev = max((math.dist(r[k], p[k]) for k in r if k in p), default=0)
            report(sorted(r) == sorted(p) and len(r) > 0 and dev <= 1e-6 * scale,
                   f"t = {t:g}: {len(p)} {what} springs ({len(r)} reference), "
                   f"max difference {dev:.3g} (largest spring {scale:.3g}, ratio < 1e-6)")

# A decomposed case whose restart time lost its DEM state
hc.run("decomposePar", lost, "log.decomposePar")
shutil.rmtree(os.path.join(lost, f"{T0:g}/polyDEM"))
rc = hc.run("mpirun -np 2 demPimpleFoam -parallel", lost, "log.demPimpleFoam", check=False)
log = open(os.path.join(lost, "log.demPimpleFoam")).read()
report(rc != 0 and "FOAM FATAL IO ERROR" in log and f"{T0:g}/polyDEM/state" in log and "freshStart" in log,
       f"a restart time without its DEM state stops (exit {rc}) with a FatalIOError naming the state and freshStart")

# demFoam -parallel in the decomposed case: the DEM on the master, output in the case folder
set_end(par, T1 + 0.001)
set_write(par, 0.001)
rc = hc.run("mpirun -np 2 demFoam -parallel", par, "log.demFoam.parallel", check=False)
log = open(os.path.join(par, "log.demFoam.parallel")).read()
tn = f"{T1 + 0.001:g}"
report(rc == 0 and "DEM on the master rank only" in log
       and os.path.isfile(os.path.join(par, tn, "polyDEM/state"))
       and not glob.glob(os.path.join(par, "processor*", tn, "polyDEM")),
       f"demFoam -parallel (exit {rc}) restarted in the decomposed case and wrote {tn}/polyDEM/state in the case folder")
hc.finish(results)
