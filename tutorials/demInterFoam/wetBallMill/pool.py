#!/usr/bin/env python3
"""The slurry pool over the settled charge (run in a case folder, after the
dry filling): the level y = h below which the fluid (the mesh's
circle less the balls) holds the slurry volume of case.info, from
the DEM state <tCouple>/polyDEM/state (each ball's volume below h exactly:
a spherical cap); writes system/setAlphaFieldDict (setAlphaField then cuts
each cell at h: alpha is the water fraction of the cell, and the solver's
water int eps alpha dV differs from this by how the balls' volume is spread
over the cut cells) and appends pool lines to case.info."""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
from demState import read_state  # noqa: E402
from rotatingDrum import polygon_area_below  # noqa: E402

info = dict(l.split() for l in open("case.info") if l.strip())
R, L = float(info["R"]), float(info["L"])
target = float(info["slurryVolume"])
t = info["tCouple"]
st = read_state(os.path.join(t, "polyDEM", "state"))
balls = [(p["py"], p["radius"]) for p in st["particles"]]
# the smooth shell (the fluid mesh's cut cells follow it to within the cell
# size; the solver's own water volume is in waterVolume.dat)
poly = [(R * math.cos(2 * math.pi * k / 720), R * math.sin(2 * math.pi * k / 720)) for k in range(720)]


def ballsBelow(h):
    v = 0.0
    for y, r in balls:
        d = h - (y - r)
        if d <= 0:
            continue
        d = min(d, 2 * r)
        v += math.pi * d * d * (3 * r - d) / 3
    return v


def water(h):
    return polygon_area_below(poly, h) * L - ballsBelow(h)


lo, hi = -R, R
for _ in range(100):
    mid = 0.5 * (lo + hi)
    if water(mid) < target:
        lo = mid
    else:
        hi = mid
h = 0.5 * (lo + hi)
solid = sum(4 / 3 * math.pi * r ** 3 for _, r in balls)
# the bed: below the highest ball top of the settled charge is not a good
# measure in a tumbling charge; report the balls' volume below the level
below = ballsBelow(h)
with open("system/setAlphaFieldDict", "w") as f:
    f.write(f"""FoamFile {{ version 2.0; format ascii; class dictionary; object setAlphaFieldDict; }}
// The slurry pool over the charge at t = {t} s (pool.py): {target:.6f} m3 of
// slurry below y = {h:.6f} m, around {below:.6f} m3 of balls
field       alpha.water;
type        plane;
origin      (0 {h:.12g} 0);
direction   (0 1 0);
""")
with open("case.info", "a") as f:
    f.write(f"poolLevel {h:.9g}\nballs {len(balls)}\nballVolume {solid:.9g}\n"
            f"ballVolumeBelowLevel {below:.9g}\n")
print(f"pool: {target:.6f} m3 of slurry below y = {h:.4f} m ({R + h:.3f} m above the bottom),"
      f" with {below:.6f} m3 of the {solid:.6f} m3 of balls below it")
