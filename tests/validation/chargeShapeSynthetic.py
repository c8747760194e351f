#!/usr/bin/env python3
"""chargeShape on synthetic charges whose shoulder, toe and centre of mass are
known by construction.

A smooth shell (D = 0.4 m, a 0.06 m slice along z, turning about +z) holds
10 mm spheres placed, not dropped, in rings next to the shell along an arc
that runs from a chosen toe angle through the bottom to a chosen shoulder
angle (chargeShape's angles: from the horizontal through the axis on the
rising side, positive with the rotation), plus a bulk of spheres inside the
arc's chord, away from the shell. demFoam runs two DEM steps of 1e-5 s (the
particles move by less than 1e-9 m); the function object's first sample
(t = 0) is compared with the construction:

  shoulder and toe: the arc covered by the ring next to the shell runs from
    the first particle centre less half the angular spacing to the last one
    plus half of it; both ends within half a bin (2.5 deg with 72 bins) --
    the function object's resolution;
  M, xc, yc: the particles' mass and centre of mass (xc towards the rising
    side, yc up), computed here from the list, to 1e-9 relative;
  gravityTorque = -g M xc sign(omega) to 1e-9 relative.

Three charges: a cascading one (toe 215, shoulder 35 deg), one whose shoulder
lies below the horizontal (toe 190, shoulder -10), and the first mirrored
(x -> -x) in a shell turning the other way (omega < 0), which must give the
same angles, the same xc and yc: the rising side follows the rotation.
"""
import math
import os
import sys

import hedracase as hc

here = os.path.dirname(os.path.abspath(__file__))
tutorial = os.path.join(here, "../../tutorials/demFoam/ballMill")

D, L, d, rho, g = 0.4, 0.06, 0.01, 7800.0, 9.81
R = D / 2
nBins = 72
binWidth = 360.0 / nBins
mass = rho * math.pi / 6 * d ** 3


def charge(toe, shoulder, mirror):
    """Sphere centres of a charge against the shell from toe through the
    bottom to shoulder (degrees in chargeShape's convention for a shell
    turning about +z: theta from +x, counter-clockwise); mirror: x -> -x.
    Returns the centres and the covered arc's ends (the ring next to the
    shell, which the function object's layer sees)."""
    gap = 1.05 * d
    zs = [-0.021, 0.0, 0.021]
    pts = []
    ends = None
    span = (shoulder + 360.0) - toe           # the arc through the bottom
    for j, r in enumerate([R - 0.0055, R - 0.0055 - gap]):
        step = math.degrees(gap / r)
        n = int(span / step) + 1
        s = span / (n - 1)                     # spread to fill the arc exactly
        if j == 0:
            ends = (toe - s / 2, shoulder + s / 2)
        for k in range(n):
            th = math.radians(toe + k * s)
            for z in zs:
                pts.append((r * math.cos(th), r * math.sin(th), z))
    # Bulk: a square grid inside the arc's chord, clear of the rings
    chordY = R * max(math.sin(math.radians(toe)), math.sin(math.radians(shoulder)))
    y = -R + 2 * gap + 0.5 * gap
    while y < chordY - 0.5 * gap:
        x = -R
        while x < R:
            if math.hypot(x, y) < R - 0.0055 - 2 * gap:
                for z in zs:
                    pts.append((x, y, z))
            x += gap
        y += gap
    if mirror:
        pts = [(-x, y, z) for (x, y, z) in pts]
    return pts, ends


def run(name, toe, shoulder, omegaSign, mirror):
    case = hc.workdir("chargeShape-" + name)
    pts, (toeEnd, shoulderEnd) = charge(toe, shoulder, mirror)
    rpm = 10.0 * omegaSign
    plist = "\n".join(f"            {{ position ({x:.9f} {y:.9f} {z:.9f}); }}" for (x, y, z) in pts)
    hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", f"""
device cpu;
timeStep 1e-5;
gravity (0 {-g} 0);
contactModel {{ law linearSpringDashpot; normalStiffness 2e4; }}
materials {{ steel {{ youngsModulus 2e11; poissonsRatio 0.3; density {rho}; }} }}
interactions {{ default {{ restitution 0.6; friction 0.5; }} }}
particleTypes {{ ball {{ shape sphere; material steel; diameter {d}; }} }}
walls
{{
    shell
    {{
        type mesh; file "shell.stl"; material steel;
        motion {{ type rotation; origin (0 0 0); axis (0 0 1); rpm {rpm}; }}
    }}
    front {{ type plane; point (0 0 {L / 2}); normal (0 0 -1); material steel; }}
    back {{ type plane; point (0 0 {-L / 2}); normal (0 0 1); material steel; }}
}}
insertion
{{
    charge
    {{
        type list; particleType ball;
        particles
        (
{plist}
        );
    }}
}}
output {{ vtk false; }}
""")
    hc.foamfile(os.path.join(case, "system/controlDict"), "controlDict", f"""
application demFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime 2e-5;
deltaT 1e-5; writeControl timeStep; writeInterval 100;
writeFormat ascii; writePrecision 10; timeFormat general; timePrecision 8;
functions
{{
    charge
    {{
        type chargeShape; libs (demFunctionObjects);
        walls (shell); origin (0 0 0); axis (0 0 1); shellRadius {R};
        nBins {nBins}; steadyStart 0; nBatches 2;
    }}
}}
""")
    hc.run([sys.executable, os.path.join(tutorial, "makeGeometry.py"), "--D", str(D), "--L", str(L),
            "--lifters", "0"], case, "log.makeGeometry")
    hc.run("demFoam", case, "log.demFoam", timeout=300)
    with open(os.path.join(case, "postProcessing/charge/0/charge.dat")) as f:
        rows = [[float(v) for v in line.split()] for line in f if not line.startswith("#")]
    row = rows[0]
    assert row[0] == 0.0, "the first sample is at t = 0"

    # Expected centre of mass (xc towards the rising side: +x for omega > 0)
    rising = 1.0 if omegaSign > 0 else -1.0
    M = mass * len(pts)
    xc = sum(rising * p[0] for p in pts) / len(pts)
    yc = sum(p[1] for p in pts) / len(pts)
    return row, M, xc, yc, toeEnd, shoulderEnd, len(pts)


results = []
measured = {}
for name, toe, shoulder, omegaSign, mirror in [("cascading", 215.0, 35.0, 1, False),
                                                ("lowShoulder", 190.0, -10.0, 1, False),
                                                ("mirrored", 215.0, 35.0, -1, True)]:
    row, M, xc, yc, toeEnd, shoulderEnd, n = run(name, toe, shoulder, omegaSign, mirror)
    sh, to, Mf, xcf, ycf, gT = row[1], row[2], row[6], row[7], row[8], row[10]
    print(f"{name}: {n} spheres; shoulder {sh:.3f} deg (built {shoulderEnd:.3f}), "
          f"toe {to:.3f} deg (built {toeEnd:.3f}); M {Mf:.6g} kg, xc {xcf:.6g} m, yc {ycf:.6g} m")
    for label, v, ref in [("shoulder", sh, shoulderEnd), ("toe", to, toeEnd)]:
        ok = math.isfinite(v) and abs(v - ref) <= binWidth / 2
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {name} {label} {v:.3f} vs built {ref:.3f} deg "
              f"(error {v - ref:+.3f}, tolerance half a bin {binWidth / 2:g})")
    hc.check(f"{name} M", Mf, M, 1e-9, results)
    hc.check(f"{name} xc", xcf, xc, 1e-9, results)
    hc.check(f"{name} yc", ycf, yc, 1e-9, results)
    hc.check(f"{name} gravityTorque = -g M xc sign(omega)", gT, -g * M * xc * omegaSign, 1e-9, results)
    measured[name] = (sh, to, xcf, ycf)

# The mirrored charge in the reversed shell is the same charge for the function object
a, b = measured["cascading"], measured["mirrored"]
same = all(abs(x - y) <= 1e-6 * max(1.0, abs(x)) for x, y in zip(a, b))
results.append(same)
print(f"{'PASS' if same else 'FAIL'}: mirrored charge in the reversed shell gives the same "
      f"shoulder, toe, xc, yc: {a} vs {b}")
hc.finish(results)
