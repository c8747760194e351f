#!/usr/bin/env python3
"""Wall loads and chargeShape: the torque of a mill's shell balances gravity.

A small mill slice (D = 0.4 m, 0.06 m long, six 15 x 15 mm lifters, made by
tutorials/demFoam/ballMill/makeGeometry.py) between fixed frictionless end
planes, 35 % filled with 20 mm steel balls, turns at 10 rpm (15 % of the
critical speed 42.3/sqrt(D) rpm: a cascading charge). At a steady state the
charge's angular momentum about the axis does not grow, so the time mean of
the torque of the walls on the charge balances gravity's torque about the
axis:  T_wall = M g xc  (xc the horizontal offset of the charge's centre of
mass from the axis), i.e. the power from the wall torque,
P = -omega T.a (chargeShape column power, the engine's wall loads summed over
every DEM step), equals M g xc omega (column powerGravity, from the particle
positions alone).

Checks (means over t >= 4 s, 8 s in all):
  |P - P_gravity| / P_gravity <= 3 %   (the charge's momentum change over the
  window and the sampling of xc every 0.02 s: both well below 1 %; 3 %
  leaves room for the batch-means error, reported)
  the shoulder and toe were found in every steady sample, with the toe on
  the falling side below the horizontal (180-270 deg) and the shoulder on
  the rising side (-45-90 deg: a sparse sample may put it just below the
  horizontal) -- the definitions of chargeShape
  P > 0 (the motor drives the charge)
  energy balance: P = dissipation + dE/dt within 2 % (dissipation: the
  engine's energy flows, every contact's dashpots, sliding and rolling
  resistance summed over every DEM step; E: kinetic + gravitational energy
  of the charge, its change over the window); and the walls' work rate at
  their contacts (force . wall velocity) = P within 1e-3 (one quantity seen
  through the contacts and through the torque about the axis)
The DEM step is 5e-5 s, 54 steps per ball-ball contact (2.7 ms): the
dissipation is evaluated at the contacts' velocities half a step before the
force's time, and its error falls with the step (measured over 4-6 s,
restarted from the 1e-4 s run's state at 4 s: (P - D - dE/dt)/P = -1.85,
-1.30, -0.94, -0.74 % at 1e-4, 5e-5, 2.5e-5, 1.25e-5 s)
  a restart from the state written at 4 s gives the rows of 4-8 s (shoulder,
  toe, centre of mass, wall torque, power) identical to the continuous
  run's, character for character (the wall loads are summed in particle
  order, which a restart keeps)
"""
import math
import os
import shutil
import subprocess
import sys

import hedracase as hc

here = os.path.dirname(os.path.abspath(__file__))
tutorial = os.path.join(here, "../../tutorials/demFoam/ballMill")
case = hc.workdir("millTorque")

D, L, rpm, d = 0.4, 0.06, 10.0, 0.02
# 35 % filling, bed solid fraction 0.6, balls d +- 5 %
nBalls = int(round(0.35 * math.pi * D * D / 4 * L * 0.6 / (math.pi / 6 * d ** 3)))

hc.foamfile(os.path.join(case, "constant/demProperties"), "demProperties", f"""
device cpu;
timeStep 5e-5;
gravity (0 -9.81 0);
contactModel {{ law linearSpringDashpot; normalStiffness 2e4; rolling elasticPlastic; }}
materials
{{
    ball {{ youngsModulus 5e5; poissonsRatio 0.45; density 7200; }}
    liner {{ youngsModulus 5e5; poissonsRatio 0.45; density 7200; }}
    endWall {{ youngsModulus 5e5; poissonsRatio 0.45; density 7200; }}
}}
interactions
{{
    default {{ restitution 0.6; friction 0.5; rollingFriction 0.01; rollingDamping 0.3; }}
    ends {{ materials (ball endWall); restitution 0.6; friction 0; rollingFriction 0; }}
}}
particleTypes {{ ball {{ shape sphere; material ball; diameter {1.05 * d}; }} }}
walls
{{
    shell
    {{
        type mesh; file "shell.stl"; material liner;
        motion {{ type rotation; origin (0 0 0); axis (0 0 1); rpm {rpm}; }}
    }}
    front {{ type plane; point (0 0 {L / 2}); normal (0 0 -1); material endWall; }}
    back {{ type plane; point (0 0 {-L / 2}); normal (0 0 1); material endWall; }}
}}
insertion
{{
    // in two halves, the second on the settled first (random sequential
    // addition would jam in a slice this thin)
    first
    {{
        type randomFill; particleType ball; number {nBalls // 2}; seed 5;
        region {{ type stl; file "fillRegion.stl"; }}
        diameterDistribution {{ type uniform; min {0.95 * d}; max {1.05 * d}; }}
    }}
    second
    {{
        type randomFill; particleType ball; number {nBalls - nBalls // 2}; seed 6; time 0.5;
        region {{ type stl; file "fillRegion.stl"; }}
        diameterDistribution {{ type uniform; min {0.95 * d}; max {1.05 * d}; }}
    }}
}}
""")
hc.foamfile(os.path.join(case, "system/controlDict"), "controlDict", f"""
application demFoam;
startFrom latestTime; startTime 0; stopAt endTime; endTime 8;
deltaT 0.01; writeControl runTime; writeInterval 4;
writeFormat ascii; writePrecision 8; timeFormat general; timePrecision 6;
functions
{{
    charge
    {{
        type chargeShape; libs (demFunctionObjects);
        walls (shell front back);
        origin (0 0 0); axis (0 0 1); shellRadius {D / 2};
        steadyStart 4; nBatches 8; interval 0.02;
    }}
}}
""")
hc.run([sys.executable, os.path.join(tutorial, "makeGeometry.py"), "--D", str(D), "--L", str(L),
        "--lifters", "6", "--height", "0.015", "--width", "0.015", "--margin", "0.005"],
       case, "log.makeGeometry")
hc.run("demFoam", case, "log.demFoam", timeout=900)

# The same run restarted from its state at 4 s: the wall loads (and so the
# torque and power columns) must continue to the bit
restart = case + "-np2"   # (removed with the case by hc.finish)
shutil.copytree(case, restart, ignore=shutil.ignore_patterns("8", "postProcessing"))
hc.run("demFoam", restart, "log.demFoam.restart", timeout=900)

means = {}
with open(os.path.join(case, "postProcessing/charge/0/chargeMean.dat")) as f:
    for line in f:
        if line.startswith("#"):
            continue
        q, m, e, n = line.split()
        means[q.split("[")[0]] = (float(m), float(e), int(n))
rows = []
with open(os.path.join(case, "postProcessing/charge/0/charge.dat")) as f:
    for line in f:
        if not line.startswith("#"):
            rows.append([float(x) for x in line.split()])
steady = [r for r in rows if r[0] >= 4 - 1e-9]

results = []
P, Perr, n = means["power"]
Pg, Pgerr, _ = means["powerGravity"]
print(f"{nBalls} balls, M = {means['M'][0]:.4g} kg, {n} steady samples")
print(f"power from the wall torque {P:.5g} +- {Perr:.2g} W, "
      f"M g xc omega {Pg:.5g} +- {Pgerr:.2g} W (batch-means errors)")
print(f"shoulder {means['shoulder'][0]:.2f} +- {means['shoulder'][1]:.2f} deg, "
      f"toe {means['toe'][0]:.2f} +- {means['toe'][1]:.2f} deg")
hc.check("power from the wall torque against M g xc omega", P, Pg, 0.03, results)

# Energy balance: the power drawn is the work done on the charge, which at a
# steady state the contacts dissipate (engine energy flows, summed over every
# DEM step): P = dissipation + d(kinetic + gravitational energy)/dt
D, Derr, _ = means["dissipation"]
W, _, _ = means["wallWorkRate"]
dEdt = means["energyRate"][0]
balance = means["energyBalance"][0]
print(f"dissipation {D:.5g} +- {Derr:.2g} W, work rate of the walls {W:.5g} W, "
      f"dE/dt over the window {dEdt:.3g} W: (P - D - dE/dt)/P = {balance:.3e}")
hc.check("power drawn against dissipation + dE/dt (energy balance)", P, D + dEdt, 0.02, results)
# The same work seen from the contacts (force . wall velocity at the contact
# point, all walls) and from the shell's torque about the axis: one sum
# (to the overlap: the wall's velocity is taken at its surface point, the
# torque's arm ends half an overlap further in; overlap/radius ~ 1e-3)
hc.check("work rate of the walls at their contacts against omega x torque", W, P, 1e-3, results)
ok = P > 0
results.append(ok)
print(f"{'PASS' if ok else 'FAIL'}: the power is positive ({P:.4g} W)")
found = all(math.isfinite(r[1]) and math.isfinite(r[2]) for r in steady)
inRange = all(-45 < r[1] < 90 and 180 < r[2] < 270 for r in steady if math.isfinite(r[1]))
results.append(found and inRange and len(steady) > 100)
print(f"{'PASS' if found and inRange else 'FAIL'}: shoulder in (-45, 90) and toe in (180, 270) deg "
      f"in all {len(steady)} steady samples")

def dataRows(path, t0):
    with open(path) as f:
        return [line for line in f if not line.startswith("#") and float(line.split()[0]) > t0 + 1e-9]


cont = dataRows(os.path.join(case, "postProcessing/charge/0/charge.dat"), 4)
rest = dataRows(os.path.join(restart, "postProcessing/charge/4/charge.dat"), 4)
same = len(cont) == len(rest) and len(cont) > 100 and cont == rest
results.append(same)
print(f"{'PASS' if same else 'FAIL'}: restart at 4 s: the {len(rest)} rows of 4-8 s "
      f"identical to the continuous run's ({len(cont)} rows)")
hc.finish(results)
