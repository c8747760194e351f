#!/usr/bin/env python3
"""damBreakRockPile post-processing (Allrun): from coupled/ and dem/ writes

  postProcessing/rockDisplacement.dat  t, mean and max |x - x(tCouple)| of
                                       the rocks, mean x-displacement, moving rocks
  postProcessing/fluidForce.dat        t, fluid force on the pile Fx Fy Fz
                                       (sum over the rocks, demCloud summary)
  postProcessing/waterFront.dat        t, furthest floor cell with alpha > 0.5
  postProcessing/contactNetwork/network_<t>.vtk   contact pairs and forces
  postProcessing/pile.dat              pile before/after numbers (README)
and the PNG plots (plot.py).

    python3 postProcess.py
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import demState as ds

info = {k: v for k, v in (l.split() for l in open("case.info"))}
f = {k: float(v) for k, v in info.items() if k not in ("mode", "coupling")}
resolved = info.get("coupling") == "resolved"
nx, ny = int(f["nx"]), int(f["ny"])
os.makedirs("postProcessing/contactNetwork", exist_ok=True)

# ---- rock displacement ----------------------------------------------------
T = ds.times("coupled")
s0 = ds.read_state(os.path.join("coupled", T[0][1], "polyDEM", "state"))
x0 = {p["id"]: (p["px"], p["py"], p["pz"]) for p in s0["particles"]}
disp = []
states = {}
for t, d in T:
    s = ds.read_state(os.path.join("coupled", d, "polyDEM", "state"))
    states[t] = s
    dd = [math.dist((p["px"], p["py"], p["pz"]), x0[p["id"]]) for p in s["particles"]]
    dxs = [p["px"] - x0[p["id"]][0] for p in s["particles"]]
    moved = sum(1 for v in dd if v > 0.5*f["d"])
    disp.append((t - f["tCouple"], sum(dd)/len(dd), max(dd), sum(dxs)/len(dxs), moved))
with open("postProcessing/rockDisplacement.dat", "w") as o:
    o.write("# t-tCouple [s]  mean|dx| [m]  max|dx| [m]  mean x-displacement [m]"
            "  rocks moved more than d_eq/2\n")
    for r in disp:
        o.write("%.4f %.6g %.6g %.6g %d\n" % r)

# ---- fluid force ----------------------------------------------------------
# rows: (t, -, rocks removed, Fx, Fy, Fz) per fluid step
if resolved:
    # The whole fluid force on each rock as the DEM gets it (forces.dat's
    # FD: the full stress on its surface, hydrostatics included, with the
    # inside fluid's weight and momentum change), summed over the rocks per
    # step; the rocks removed from the DEM's particle balance
    byT = {}
    for t0 in sorted(os.listdir("coupled/postProcessing/ibForces"), key=float):
        for l in open(os.path.join("coupled/postProcessing/ibForces", t0, "forces.dat")):
            if l.strip() and not l.startswith("#"):
                v = [float(x) for x in l.split()]
                F = byT.setdefault(v[0], [0.0, 0.0, 0.0])
                for k in range(3):
                    F[k] += v[24 + k]
    removed = 0
    for t0 in os.listdir("coupled/postProcessing/demFoam"):
        for l in open(os.path.join("coupled/postProcessing/demFoam", t0, "particleBalance.dat")):
            if l.strip() and not l.startswith("#"):
                removed = max(removed, int(float(l.split()[4])))
    rows = [[t, 0, removed] + F for t, F in sorted(byT.items())]
    forceNote = "immersed boundary: the full stress on the rocks' surfaces"
else:
    rows = ds.read_summary("coupled")
    forceNote = "drag + pressure, with the buoyancy of their submerged volume"
with open("postProcessing/fluidForce.dat", "w") as o:
    o.write(f"# t-tCouple [s]  Fx Fy Fz [N]: fluid force on all rocks ({forceNote})\n")
    for r in rows:
        o.write("%.5f %.6g %.6g %.6g\n" % (r[0] - f["tCouple"], r[3], r[4], r[5]))

# ---- water front on the floor --------------------------------------------
fr = []
for t, d in T:
    a, u = ds.read_scalar_field(os.path.join("coupled", d, "alpha.water"))
    if a is None:
        continue
    x = 0.0
    if resolved:
        # The refining mesh numbers its cells anew: the floor cells from
        # their centres and volumes (cubes; writeCellCentres and
        # writeCellVolumes, run by Allrun)
        cx, _ = ds.read_scalar_field(os.path.join("coupled", d, "Cx"))
        cz, _ = ds.read_scalar_field(os.path.join("coupled", d, "Cz"))
        vol, _ = ds.read_scalar_field(os.path.join("coupled", d, "V"))
        for k, ak in enumerate(a):
            h = vol[k]**(1.0/3.0)
            if ak > 0.5 and abs(cz[k] - h/2) < 1e-3*h:
                x = max(x, cx[k] + h/2)
    else:
        for i in range(nx):
            if any(a[j*nx + i] > 0.5 for j in range(ny)):
                x = (i + 1)*f["dx"]
    fr.append((t - f["tCouple"], x))
with open("postProcessing/waterFront.dat", "w") as o:
    o.write("# t-tCouple [s]  front [m] (downstream face of the furthest floor cell with"
            " alpha.water > 0.5); Ritter 2 sqrt(g h0) t from x = %g m\n" % f["waterW"])
    for r in fr:
        o.write("%.4f %.4f\n" % r)

# ---- contact network: before the water, at the largest force, at the end ---
tImpact = max(rows, key=lambda r: abs(r[3]))[0]
chosen = sorted({T[0][0], min(states, key=lambda t: abs(t - tImpact)), T[-1][0]})
net = []
for t in chosen:
    n = ds.write_network_vtk("postProcessing/contactNetwork/network_%g.vtk" % t, states[t])
    cf = [math.sqrt(sum(c*c for c in ds.contact_force(p))) for p in states[t]["particles"]]
    net.append((t, n, len(states[t]["walls"]), max(cf), sum(cf)/len(cf)))
with open("postProcessing/contactNetwork/summary.dat", "w") as o:
    o.write("# t [s]  rock-rock pairs  rock-wall contacts  max and mean |resultant contact force| [N]\n")
    for r in net:
        o.write("%.4g %d %d %.4g %.4g\n" % r)

# ---- pile numbers ---------------------------------------------------------
def extent(s):
    xs = [p["px"] for p in s["particles"]]
    zs = [p["pz"] + p["radius"] for p in s["particles"]]
    return min(xs), max(xs), max(zs)

sd = ds.read_state(os.path.join("dem", "%g" % f["tRelease"], "polyDEM", "state"))
_, _, hCol = extent(sd)
a0, b0, h0 = extent(s0)
a1, b1, h1 = extent(states[T[-1][0]])
Fmax = max(rows, key=lambda r: abs(r[3]))
with open("postProcessing/pile.dat", "w") as o:
    o.write(f"rocks {len(s0['particles'])}\n")
    o.write(f"columnTop_at_release {hCol:.4f}  # m, highest rock centre + its bounding radius\n")
    o.write(f"pile_before x {a0:.3f} .. {b0:.3f}  top {h0:.3f}  # m, rock centres; top: centre + bounding radius\n")
    o.write(f"pile_after  x {a1:.3f} .. {b1:.3f}  top {h1:.3f}\n")
    o.write(f"max_Fx {Fmax[3]:.4g} N at t - tCouple = {Fmax[0] - f['tCouple']:.4f} s\n")
    o.write(f"displacement_end mean {disp[-1][1]:.4f} max {disp[-1][2]:.4f} m, moved {disp[-1][4]}\n")
print(open("postProcessing/pile.dat").read())
print(open("postProcessing/contactNetwork/summary.dat").read())

# ---- checks (printed always; with -check a failure exits 1) ---------------
results, out = [], []


def report(ok, text):
    results.append(ok)
    out.append(("PASS: " if ok else "FAIL: ") + text)
    print(out[-1])


# 1. the hand-over: the coupled run starts from the DEM state of dem/
sd = ds.read_state(os.path.join("dem", "%g" % f["tCouple"], "polyDEM", "state"))
byId = {p["id"]: p for p in sd["particles"]}
dmax = max(math.dist((p["px"], p["py"], p["pz"]), (byId[p["id"]]["px"], byId[p["id"]]["py"],
                                                  byId[p["id"]]["pz"])) for p in s0["particles"])
report(len(sd["particles"]) == len(s0["particles"]) == int(f["n"]) and dmax <= 1e-12,
       f"hand-over DEM -> coupled at t = {f['tCouple']:g} s: {len(sd['particles'])} and"
       f" {len(s0['particles'])} rocks (of {int(f['n'])}), positions equal to {dmax:.2g} m (tolerance 1e-12)")
# 2. no rock lost
nOut = max(r[2] for r in rows)
nEnd = len(states[T[-1][0]]["particles"])
report(nOut == 0 and nEnd == int(f["n"]), f"rocks at the end {nEnd}, outside the domain {int(nOut)}")
# 3. water balance: volume in the flume + what left through the open top
#    (the splash over the pile reaches it) = the start, to the continuity
#    error the pressure tolerances allow; alpha bounds
import waterBalance as wb
# (the resolved case's time step varies: the solver's own outflow column)
Wb, W0 = wb.balance("coupled", None if resolved else f["dtCfd"])
drift = max(abs(r[3] - W0) for r in Wb)/W0
report(drift <= 1e-5, f"water balance: max |W + out - W0|/W0 = {drift:.3g} (tolerance 1e-5); water left"
       f" through the top by the end {Wb[-1][2]:.4g} m3 = {100*Wb[-1][2]/W0:.2f} % of W0 = {W0:.5g} m3")
aMin, aMax = min(r[4] for r in Wb), max(r[5] for r in Wb)
report(aMin >= -1e-6 and aMax <= 1 + 1e-6, f"alpha.water bounds: min {aMin:.3g}, max - 1 = {aMax - 1:.3g}"
       f" (tolerance 1e-6)")
# 4. no push before the water: the fluid force on the pile while the front
#    is more than 2 d_eq upstream of the rock nearest to it is below 1 % of
#    the pile's weight (air only: its buoyancy and the draught of the front)
xNear = min(p["px"] for p in s0["particles"])
iNear = min([i for i, (t, x) in enumerate(fr) if x >= xNear - 2*f["d"]], default=len(fr))
tNear = fr[max(iNear - 1, 0)][0]     # the last write before that
weight = sum(p["mass"] for p in s0["particles"])*9.81
Fair = max(math.sqrt(r[3]**2 + r[4]**2 + r[5]**2) for r in rows if r[0] - f["tCouple"] < tNear)
report(Fair < 0.01*weight, f"fluid force before the front comes within 2 d_eq of the pile"
       f" (t - tCouple < {tNear:g} s): max {Fair:.3g} N (< 1 % of the weight {weight:.4g} N)")
# 5. the water moves the pile
report(disp[-1][2] > 0.5*f["d"], f"largest rock displacement at the end {disp[-1][2]:.3f} m (> d_eq/2)")
with open("postProcessing/checks.dat", "w") as o:
    o.write("\n".join(out) + "\n")
if "-check" in sys.argv and not all(results):
    sys.exit("SOME CHECKS FAILED")
