#!/usr/bin/env python3
"""demIbFoam: lubrication correction (ibLubrication, model Brenner).

Heavy spheres (d = 4 mm, rho_p = 1e6 kg/m3, so that their speed stays
nearly constant) in a quiescent fluid (nu = 1e-4 m2/s, rho = 1000: mu =
0.1 Pa s), gravity off, d/dx = 4 (the gaps below are far below what the
mesh resolves), cutoff h_c = 0.25 R, minGap 0.01 R:
  A  approaches the DEM floor (plane z = 0) at 10 mm/s from h = 0.3 R;
  B, C approach each other head-on at 5 mm/s each from h = 0.3 R.
Checks, every fluid step, from postProcessing/ibForces (the state the force
is evaluated from):
  1. A: F_L = 6 pi mu R^2 |w| (1/h - 1/h_c) f along +z (h = z - R, the
     analytic sphere-wall lubrication force less the part above the
     cutoff, Brenner 1961), f = m/(m + c dt) the implicit factor; zero for
     h >= h_c; to 1e-6 relative. The largest deviation of f from 1 is
     printed (how close F_L is to the explicit value).
  2. B, C: F_B = -F_C (momentum conserved) and |F_B| =
     6 pi mu (R/2)^2 |u_rel| (1/h - 1/h_c) f (R_eff = R/2, m_eff = m/2),
     along the line of centres; to 1e-6 relative.
  3. The force reaches the DEM: a run with model none gives A a final
     velocity w0; m (w - w0) = sum F_L dt to 2 %.
Printed, not checked: (F_IB + F_L) against 6 pi mu R^2 |w|/h at the
smallest gaps (0.998 here; the IB's own force alone 0.23-0.27).
"""
import glob
import math
import os
import re
import shutil
import hedracase as hc

os.environ.setdefault("OMP_NUM_THREADS", "1")

R, RHO_P, MU, NU, RHO_F = 2e-3, 1e6, 0.1, 1e-4, 1000.0
DT, T_END = 1e-3, 0.05
CUT, HMIN = 0.25, 0.01
m = RHO_P * 4 / 3 * math.pi * R**3
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingSphere")


def make(case, model):
    hc.block_mesh(case, (0, 0, 0), (0.024, 0.012, 0.012), (24, 12, 12),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    for f in ("fvSchemes", "fvSolution"):
        shutil.copy(os.path.join(src, "system", f), os.path.join(case, "system", f))
    hc.foamfile(os.path.join(case, "system/controlDict"), "controlDict", f"""
application demIbFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime {T_END};
deltaT {DT};
writeControl runTime; writeInterval {T_END};
writeFormat ascii; writePrecision 17; timeFormat general; timePrecision 6;
runTimeModifiable false;
""")
    hc.foamfile(os.path.join(case, "constant/transportProperties"), "transportProperties",
                f"nu {NU};\nrho {RHO_F};\n")
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type zeroGradient;"})
    hc.foamfile(os.path.join(case, "constant/ibProperties"), "ibProperties", f"""
demBackend polyDEM;
directForcing {{ nSubSamples 4; integralForcing true; }}
lubrication {{ model {model}; cutoff {CUT}; minGap {HMIN}; }}
""")
    g = 1e-9  # a region just wider than the sphere: the centre is where we want it

    def one(name, x, y, z, u):
        return f"""    {name}
    {{
        type randomFill; particleType bead; number 1; seed 1;
        region {{ type box; min ({x-R-g} {y-R-g} {z-R-g}); max ({x+R+g} {y+R+g} {z+R+g}); }}
        velocity ({u[0]} {u[1]} {u[2]});
    }}
"""
    h0 = 0.3 * R
    ins = (one("A", 0.006, 0.006, R + h0, (0, 0, -0.01))
           + one("B", 0.018 - R - h0 / 2, 0.006, 0.007, (0.005, 0, 0))
           + one("C", 0.018 + R + h0 / 2, 0.006, 0.007, (-0.005, 0, 0)))
    hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", f"""
device cpu;
timeStep 1e-5;
gravity (0 0 0);
contactModel {{ law hertzMindlin; }}
materials {{ heavy {{ youngsModulus 5e6; poissonsRatio 0.3; density {RHO_P}; }} }}
interactions {{ default {{ restitution 0.5; friction 0.5; }} }}
particleTypes {{ bead {{ shape sphere; material heavy; diameter {2*R}; }} }}
walls {{ floor {{ type plane; point (0 0 0); normal (0 0 1); material heavy; }} }}
insertion
{{
{ins}}}
output {{ format ascii; vtk false; }}
""")
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demIbFoam", case, "log.demIbFoam")
    rows = []
    for fn in glob.glob(os.path.join(case, "postProcessing/ibForces/*/forces.dat")):
        for line in open(fn):
            if not line.startswith("#") and line.strip():
                rows.append([float(x) for x in line.split()])
    return rows


def coeff(Reff, Rmin, h, mEff):
    hc_ = CUT * Rmin
    if h >= hc_:
        return 0.0
    c = 6 * math.pi * MU * Reff**2 * (1 / max(h, HMIN * Rmin) - 1 / hc_)
    return c * mEff / (mEff + c * DT)


case = hc.workdir("ibLubrication")
rows = make(case, "Brenner")
results = []
ids = sorted({int(r[1]) for r in rows})
byId = {i: [r for r in rows if int(r[1]) == i] for i in ids}
first = {i: byId[i][0] for i in ids}
a = min(ids, key=lambda i: first[i][4])          # the one near the floor
b, c = sorted((i for i in ids if i != a), key=lambda i: first[i][2])

# 1. wall
err, nIn, fdev, ratio = 0.0, 0, 0.0, []
for r in byId[a]:
    z, w, FL = r[4], r[7], r[14:17]
    h = z - R
    cc = coeff(R, R, h, m)
    exp = -cc * w
    scale = 6 * math.pi * MU * R**2 * abs(w) / (CUT * R)
    err = max(err, abs(FL[2] - exp) / max(abs(exp), scale), abs(FL[0]) / scale, abs(FL[1]) / scale)
    if h < CUT * R:
        nIn += 1
        craw = 6 * math.pi * MU * R**2 * (1 / max(h, HMIN * R) - 1 / (CUT * R))
        fdev = max(fdev, 1 - cc / craw)
        ratio.append((h / R, FL[2] / (6 * math.pi * MU * R**2 * abs(w) / h)))
ok = err < 1e-6 and nIn >= 20
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: sphere-wall: F_L = 6 pi mu R^2 |w| (1/h - 1/h_c) f on {nIn} steps"
      f" below the cutoff, max rel. error {err:.3g} (< 1e-6); implicit factor f >= {1-fdev:.6f}")
for hR, q in ratio[::max(1, len(ratio) // 5)] + ratio[-1:]:
    print(f"    h/R = {hR:.4f}: F_L / (6 pi mu R^2 |w|/h) = {q:.4f} (1 - h/h_c = {1 - hR/CUT:.4f})")
# (information) the IB's own force at this d/dx hardly grows as the gap closes;
# with F_L the total follows the 1/h law of the unresolved squeeze flow
for r in byId[a][-3:]:
    h, w = r[4] - R, r[7]
    print(f"    h/R = {h/R:.4f}: (F_IB + F_L) / (6 pi mu R^2 |w|/h) = "
          f"{(r[10] + r[16]) / (6 * math.pi * MU * R**2 * abs(w) / h):.4f} (F_IB alone {r[10] / (6 * math.pi * MU * R**2 * abs(w) / h):.4f})")

# 2. pair
err, asym, nIn = 0.0, 0.0, 0
for rb, rc in zip(byId[b], byId[c]):
    xb, xc = rb[2:5], rc[2:5]
    d = [q - p for p, q in zip(xb, xc)]
    dist = math.hypot(*d)
    n = [x / dist for x in d]
    un = sum((uc - ub) * k for ub, uc, k in zip(rb[5:8], rc[5:8], n))
    h = dist - 2 * R
    cc = coeff(R / 2, R, h, m / 2)
    exp = [cc * un * k for k in n]
    FB, FC = rb[14:17], rc[14:17]
    scale = 6 * math.pi * MU * (R / 2)**2 * abs(un) / (CUT * R)
    err = max(err, max(abs(p - q) for p, q in zip(FB, exp)) / max(math.hypot(*exp), scale))
    asym = max(asym, max(abs(p + q) for p, q in zip(FB, FC)) / scale)
    nIn += h < CUT * R
ok = err < 1e-6 and asym < 1e-12 and nIn >= 20
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: sphere-sphere ({nIn} steps below the cutoff): F_B vs"
      f" 6 pi mu (R/2)^2 u_n (1/h - 1/h_c) f n max rel. error {err:.3g} (< 1e-6);"
      f" |F_B + F_C| / scale = {asym:.3g} (< 1e-12)")

# 3. into the DEM
case0 = case + "-np2"  # (removed with the case by hc.finish)
os.makedirs(case0)
rows0 = make(case0, "none")
r0 = [r for r in rows0 if int(r[1]) == a]
ra = byId[a]
impulse = sum(r[16] for r in ra[:-1]) * DT
dmw = m * (ra[-1][7] - r0[-1][7])
rel = abs(dmw - impulse) / abs(impulse)
ok = rel < 0.02 and all(abs(r[16]) == 0 for r in r0)
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the DEM gets the force: m (w - w_none) = {dmw:.4g} N s,"
      f" sum F_L dt = {impulse:.4g} N s (rel. difference {rel:.3g} < 0.02)")
hc.finish(results)
