#!/usr/bin/env python3
"""Dam-break surge front of demInterFoam against the experiment of Martin &
Moyce (1952).

Reference: J. C. Martin and W. J. Moyce, "Part IV. An experimental study of
the collapse of liquid columns on a rigid horizontal plane", Phil. Trans.
R. Soc. Lond. A 244 (1952) 312-324, Fig. 3: the two-dimensional column of
width a and height 2a (n^2 = 2) against a back wall, released at t = 0;
the front's distance Z from the back wall against time, as Z/a over
T = t sqrt(2 g / a), for a = 2.25 in and a = 1.125 in. The points below
are the values digitised from that figure as published with the PySPH
project's dam-break example (numbers, i.e. facts of the experiment).

The case: demInterFoam (unresolved coupling switched on, no particles)
with water and air, a = 2.25 in = 0.05715 m, 2D (one cell thick, empty
front and back), the column at x in [0, a], z in [0, 2a], a tank 16 a long
and 3 a high, closed by no-slip walls and open at the top (atmosphere),
a/20 cells, adjustable time step (Courant 0.5), to T = 9.5.

The front is read from the row of cells on the floor: the first cell,
going out from the back wall, with alpha below 0.5, the crossing
interpolated linearly (spray ahead of the body of water is ignored, as
it is in the photographs the experiment was read from).

What counts as agreement. The two column sizes, which should collapse on
one curve in Z/a over T, differ by up to S (computed below from the
digitised points, T >= 1.5: 8.6 %); digitising adds about 2 %. The
simulated front runs parallel to the measured ones but ahead of them by a
nearly constant time (measured 2026-12-03: +11 to +14 % in Z/a at T = 2-4,
+5 % at T = 5-9, the same at a/20 and a/30 cells to 0.5 %: not the mesh).
A release that is not instantaneous (the experiment's, not modelled here)
delays the measured front by such a constant time, so the comparison
takes the experiment's time origin as the one free parameter: T0, fitted
by least squares to both series (T >= 1.5), the simulation compared at
T - T0. Checks:
  - 0 <= T0 <= 0.5 (the experiment late, not early; 0.5 is 27 ms at
    a = 2.25 in, a tenth of the time the front takes for its first 4 a:
    a larger shift would hide a wrong front speed, not a release);
  - without the shift the simulated front leads every measured point of
    the a = 2.25 in series with T >= 1.5 (a delay cannot make it lag);
  - with the shift, every measured point of both series with T >= 1.5
    within S + 2 % (before T = 1.5 the front is within a few cells of the
    column and the release dominates);
  - with the shift, the mean relative difference over those points
    within S / 2 (no systematic lead or lag beyond half the scatter);
  - the water volume is kept to 1e-8 relative and alpha stays in
    [-1e-5, 1 + 1e-5]: with no particle in the tank this is interFoam's
    own MULES bound (demInterFoam is interFoam to round-off here,
    vofDamBreakInterFoam.py); with 20 limiter iterations (5 is MULES's
    default) measured 1 + 2.2e-6 at a/20 and 1 + 4e-7 at a/30 at the
    splash on the far wall.
Writes postProcessing/front.dat (T, Z/a) and front.png in the case
folder (kept with HEDRA_KEEP=1).
"""
import math
import os
import re
import sys

import hedracase as hc
import vofcase as vc

A = 2.25 * 0.0254              # column width, m
G = 9.81
RES = int(os.environ.get("HEDRA_DAMBREAK_RES", "20"))   # cells per column width
T_END = 9.5
T_CHECK = 1.5
DIGITISING = 0.02              # allowance for reading the figure

# Martin & Moyce (1952), Fig. 3, n^2 = 2: (T, Z/a)
MM_A2 = [(0.832, 1.217), (1.219, 1.474), (1.997, 2.292), (2.547, 2.995),
         (3.345, 4.134), (4.034, 4.944), (4.418, 5.881), (5.091, 6.980),
         (5.685, 7.945), (6.306, 8.966), (6.822, 9.986), (7.439, 10.963),
         (8.031, 11.977), (8.633, 13.005), (9.237, 13.970)]   # a = 2.25 in
MM_A1 = [(0.849, 1.245), (1.212, 1.443), (1.602, 1.884), (2.283, 2.689),
         (2.950, 3.728), (3.598, 4.528), (3.905, 4.999), (4.592, 5.841),
         (4.961, 6.271), (5.316, 6.717)]                         # a = 1.125 in


def interp(series, T):
    """Linear interpolation of (T, Z) points; None outside their range."""
    for (t0, z0), (t1, z1) in zip(series, series[1:]):
        if t0 <= T <= t1:
            return z0 + (z1 - z0) * (T - t0) / (t1 - t0)
    return None


def series_scatter():
    """Largest relative difference between the two column sizes where
    both were measured (each point of one series against the other
    interpolated)."""
    worst = 0.0
    for a, b in ((MM_A1, MM_A2), (MM_A2, MM_A1)):
        for T, z in a:
            zb = interp(b, T)
            if zb is not None and T >= T_CHECK:
                worst = max(worst, abs(z - zb) / zb)
    return worst


def write_case(case):
    nx, nz = 16 * RES, 3 * RES
    L, H, W = 16 * A, 3 * A, A / RES
    hc.foamfile(os.path.join(case, "system/blockMeshDict"), "blockMeshDict", f"""
convertToMeters 1;
vertices
(
    (0 0 0) ({L} 0 0) ({L} {W} 0) (0 {W} 0)
    (0 0 {H}) ({L} 0 {H}) ({L} {W} {H}) (0 {W} {H})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} 1 {nz}) simpleGrading (1 1 1) );
edges ();
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 3 2 1)); }}
    atmosphere {{ type patch; faces ((4 5 6 7)); }}
    frontBack {{ type empty; faces ((0 1 5 4) (3 7 6 2)); }}
);
""")
    vc.vof_dicts(case, T_END / math.sqrt(2 * G / A), 1e-4, 0.25 / math.sqrt(2 * G / A),
                 maxCo=0.5, adjust=True, pTol=1e-9)
    # MULES: 20 limiter iterations keep alpha in [0, 1] to ~1e-8 (the
    # default 5 lets it overshoot by ~1e-4 at the splash: docs/models.md)
    fvs = os.path.join(case, "system/fvSolution")
    txt = open(fvs).read()
    open(fvs, "w").write(txt.replace("nLimiterIter 5;", "nLimiterIter 20;"))
    hc.foamfile(os.path.join(case, "system/setFieldsDict"), "setFieldsDict", f"""
defaultFieldValues ( volScalarFieldValue alpha.water 0 );
regions
(
    boxToCell
    {{
        box (-1 -1 -1) ({A} 1 {2 * A});
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
);
""")
    empty = "    frontBack { type empty; }\n"
    hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water",
                "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0;\n"
                "boundaryField\n{\n    walls { type zeroGradient; }\n"
                "    atmosphere { type inletOutlet; inletValue uniform 0; value uniform 0; }\n"
                + empty + "}\n", cls="volScalarField")
    hc.foamfile(os.path.join(case, "0/U"), "U",
                "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
                "boundaryField\n{\n    walls { type noSlip; }\n"
                "    atmosphere { type pressureInletOutletVelocity; value uniform (0 0 0); }\n"
                + empty + "}\n", cls="volVectorField")
    hc.foamfile(os.path.join(case, "0/p_rgh"), "p_rgh",
                "dimensions [1 -1 -2 0 0 0 0];\ninternalField uniform 0;\n"
                "boundaryField\n{\n    walls { type fixedFluxPressure; value uniform 0; }\n"
                "    atmosphere { type totalPressure; p0 uniform 0; value uniform 0; }\n"
                + empty + "}\n", cls="volScalarField")
    # The coupling is on, with no particle in the tank: the solver the
    # rock-pile and cube tutorials use, on the experiment without them
    vc.coupling_without_particles(case, (0, 0, 1))
    return nx, nz


def read_alpha(path, n):
    txt = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", txt)
    if m is None:
        m2 = re.search(r"internalField\s+uniform\s+([-\d.eE+]+)", txt)
        return [float(m2.group(1))] * n
    vals = txt[m.end():].split(")", 1)[0].split()
    return [float(v) for v in vals[:int(m.group(1))]]


def front(alpha_floor):
    """Distance of the front from the back wall, from the floor row."""
    dx = A / RES
    for i, al in enumerate(alpha_floor):
        if al < 0.5:
            if i == 0:
                return 0.0
            a0 = alpha_floor[i - 1]
            return (i - 0.5) * dx + (a0 - 0.5) / (a0 - al) * dx
    return len(alpha_floor) * dx


results = []
case = hc.workdir("damBreakFront")
nx, nz = write_case(case)
hc.run("blockMesh", case, "log.blockMesh")
hc.run("setFields", case, "log.setFields")
hc.run("demInterFoam", case, "log.demInterFoam", timeout=1200)

scale = math.sqrt(2 * G / A)
times = sorted((d for d in os.listdir(case) if re.fullmatch(r"[\d.eE+-]+", d) and float(d) > 0),
               key=float)
curve = [(0.0, 1.0)]
for t in times:
    al = read_alpha(os.path.join(case, t, "alpha.water"), nx * nz)
    curve.append((float(t) * scale, front(al[:nx]) / A))
os.makedirs(os.path.join(case, "postProcessing"), exist_ok=True)
with open(os.path.join(case, "postProcessing/front.dat"), "w") as f:
    f.write("# T = t sqrt(2g/a)   Z/a   (demInterFoam; Martin & Moyce 1952 n^2 = 2)\n")
    for T, z in curve:
        f.write(f"{T:.6f} {z:.6f}\n")

S = series_scatter()
tol = S + DIGITISING
print(f"Martin & Moyce's two column sizes differ by up to {100 * S:.1f} % (T >= {T_CHECK}):"
      f" pointwise tolerance {100 * tol:.1f} %, mean {100 * S / 2:.1f} %")

# Unshifted: the simulated front against the a = 2.25 in series
lead = True
for T, zexp in MM_A2:
    zsim = interp(curve, T)
    print(f"  T = {T:6.3f}  Z/a experiment {zexp:6.3f}  demInterFoam {zsim:6.3f}"
          f"  ({100 * (zsim - zexp) / zexp:+.1f} %)")
    if T >= T_CHECK:
        lead = lead and zsim > zexp
results.append(lead)
print(f"{'PASS' if lead else 'FAIL'}: unshifted, the simulated front leads every measured"
      f" point (a = 2.25 in, T >= {T_CHECK})")

# The experiment's time origin T0: least squares over both series
points = [(T, z) for T, z in MM_A2 + MM_A1 if T >= T_CHECK]


def deviations(T0):
    return [(interp(curve, T - T0) - z) / z for T, z in points]


T0 = min((k * 0.005 for k in range(0, 201)), key=lambda s: sum(d * d for d in deviations(s)))
ok = 0.0 <= T0 <= 0.5
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the experiment's time origin T0 = {T0:.3f}"
      f" ({1000 * T0 / math.sqrt(2 * G / A):.1f} ms; tolerance 0 <= T0 <= 0.5)")
devs = deviations(T0)
for (T, z), d in zip(points, devs):
    ok = abs(d) <= tol
    results.append(ok)
    series = "2.25" if (T, z) in MM_A2 else "1.125"
    print(f"{'PASS' if ok else 'FAIL'}: a = {series:5s} in, T = {T:6.3f}: Z/a {z:6.3f},"
          f" demInterFoam at T - T0 {z * (1 + d):6.3f} ({100 * d:+.1f} %, tolerance {100 * tol:.1f} %)")
mean = sum(devs) / len(devs)
ok = abs(mean) <= S / 2
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: mean relative difference with the shift: {100 * mean:+.2f} %"
      f" (tolerance {100 * S / 2:.1f} %)")

rows = vc.read_water(case)
v0 = rows[0][1]
drift = max(abs(r[1] - v0) for r in rows) / v0
amin, amax = min(r[2] for r in rows), max(r[3] for r in rows)
ok = drift <= 1e-8
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: water volume drift {drift:.2e} (tolerance 1e-8)")
ok = amin >= -1e-5 and amax <= 1 + 1e-5
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: alpha in [{amin:.3g}, 1 + {amax - 1:.3g}] (tolerance 1e-5)")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(*zip(*curve), "-", color="C0", label=f"demInterFoam, a = 2.25 in, a/{RES} cells")
    ax.plot([T + T0 for T, _ in curve], [z for _, z in curve], "--", color="C0",
            label=f"the same, experiment's time origin T0 = {T0:.2f}")
    ax.plot(*zip(*MM_A2), "o", color="k", mfc="none", label="Martin & Moyce 1952, a = 2.25 in")
    ax.plot(*zip(*MM_A1), "s", color="0.5", mfc="none", label="Martin & Moyce 1952, a = 1.125 in")
    ax.set_xlabel(r"$T = t\,\sqrt{2g/a}$")
    ax.set_ylabel("front position Z/a")
    ax.set_title("Dam break, column 2a high: surge front")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(case, "postProcessing/front.png"), dpi=100)
except ImportError:
    print("matplotlib not found: no front.png")

if os.environ.get("HEDRA_KEEP"):
    print("case folder:", case)
hc.finish(results)
