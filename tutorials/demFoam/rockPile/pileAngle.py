#!/usr/bin/env python3
"""Angle of repose of a pile on a circular plate, from the last written time
of a demFoam case (no third-party modules needed).

    python3 pileAngle.py [case] [plateRadius] [binWidth]

Surface points: the vertices of every polyhedron in polyhedra.vtp (the true
shapes), or the tops of the spheres (centre + radius) from particles.vtp.
The plate (radius R, centred on the z axis) is cut into rings of width
binWidth and eight sectors; in each ring the surface height is the median
over the sectors of the highest point. The flank is the straight line
h = a - b r fitted by least squares to the rings outside the shoulder (the
outermost ring still at >= 90 % of the highest ring: the apex, or the edge
of the plateau a wide pour leaves) up to the rim, at least the outer 50 %
of R; the angle of repose is atan(b). The spread of the same fit done per
sector gives an uncertainty. No pile (fewer than 20 surface points on the
plate) gives angle 0.

Prints the angle and writes <case>/postProcessing/pileProfile.dat
(r, surface height, per ring) and <case>/postProcessing/pileAngle.dat.
"""
import math
import os
import re
import statistics
import sys


def arrays(path):
    """Named DataArrays (and the Points) of an ascii .vtp as lists of floats"""
    text = open(path).read()
    out = {}
    for m in re.finditer(r'<DataArray([^>]*)>(.*?)</DataArray>', text, re.S):
        head, body = m.group(1), m.group(2)
        name = re.search(r'Name="([^"]*)"', head)
        name = name.group(1) if name else "Points"
        out.setdefault(name, [float(v) for v in body.split()])
    # The Points array has no Name in some writers: take the one inside <Points>
    pm = re.search(r'<Points>\s*<DataArray[^>]*>(.*?)</DataArray>', text, re.S)
    if pm:
        out["Points"] = [float(v) for v in pm.group(1).split()]
    return out


def latestTime(case):
    times = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, d, "polyDEM")):
            times.append((t, d))
    if not times:
        sys.exit("pileAngle.py: no time folder with polyDEM/ in %s" % case)
    return max(times)[1]


def surfacePoints(case, time):
    d = os.path.join(case, time, "polyDEM")
    poly = os.path.join(d, "polyhedra.vtp")
    p = arrays(poly).get("Points", []) if os.path.isfile(poly) else []
    if p:
        return [(p[i], p[i + 1], p[i + 2]) for i in range(0, len(p), 3)], "polyhedra"
    a = arrays(os.path.join(d, "particles.vtp"))
    p, r = a["Points"], a["radius"]
    return [(p[3*i], p[3*i + 1], p[3*i + 2] + r[i]) for i in range(len(r))], "spheres"


def fit(rs, hs):
    n = len(rs)
    if n < 2:
        return float("nan"), float("nan")
    mr, mh = sum(rs)/n, sum(hs)/n
    srr = sum((r - mr)**2 for r in rs)
    if srr <= 0:
        return float("nan"), float("nan")
    b = sum((r - mr)*(h - mh) for r, h in zip(rs, hs))/srr
    return mh - b*mr, b


def analyse(case, R=0.03, w=0.0025, nSectors=8):
    time = latestTime(case)
    pts, kind = surfacePoints(case, time)
    onPlate = [p for p in pts if math.hypot(p[0], p[1]) < R and p[2] >= 0]
    nBins = int(math.ceil(R/w))
    top = [[-1.0]*nSectors for _ in range(nBins)]
    for x, y, z in pts:
        r = math.hypot(x, y)
        if r >= R or z < 0:
            continue
        k = min(nBins - 1, int(r/w))
        s = int((math.atan2(y, x) + math.pi)/(2*math.pi)*nSectors) % nSectors
        top[k][s] = max(top[k][s], z)
    rc = [(k + 0.5)*w for k in range(nBins)]
    h = [statistics.median([v for v in top[k] if v >= 0]) if any(v >= 0 for v in top[k])
         else float("nan") for k in range(nBins)]
    valid = [k for k in range(nBins) if h[k] == h[k]]
    if len(onPlate) < 20 or len(valid) < 3:
        use, a, b, angle = [], 0.0, 0.0, 0.0
    else:
        hMax = max(h[k] for k in valid)
        shoulder = max(k for k in valid if h[k] >= 0.9*hMax)
        first = min(shoulder + 1, int(0.5*R/w))
        use = [k for k in valid if k >= first]
        a, b = fit([rc[k] for k in use], [h[k] for k in use])
        angle = math.degrees(math.atan(-b)) if b == b else 0.0
    # Per sector, for the spread
    sectorAngles = []
    for s in range(nSectors):
        ks = [k for k in use if top[k][s] >= 0]
        _, bs = fit([rc[k] for k in ks], [top[k][s] for k in ks])
        if bs == bs:
            sectorAngles.append(math.degrees(math.atan(-bs)))
    spread = statistics.stdev(sectorAngles) if len(sectorAngles) > 1 else 0.0
    rMin = rc[use[0]] - 0.5*w if use else 0.0

    pp = os.path.join(case, "postProcessing")
    os.makedirs(pp, exist_ok=True)
    with open(os.path.join(pp, "pileProfile.dat"), "w") as f:
        f.write("# pile surface at t = %s (%s): ring centre r [m], median over %d sectors"
                " of the highest point [m]\n" % (time, kind, nSectors))
        for k in range(nBins):
            f.write("%.6g %.6g\n" % (rc[k], h[k]))
    with open(os.path.join(pp, "pileAngle.dat"), "w") as f:
        f.write("# time kind angle[deg] sectorStd[deg] apexHeight[m] fitIntercept[m] slope "
                "surfacePointsOnPlate\n")
        f.write("%s %s %.3f %.3f %.6g %.6g %.6g %d\n"
                % (time, kind, angle, spread, max([v for v in h if v == v] or [0]), a, b,
                   len(onPlate)))
    return dict(time=time, kind=kind, angle=angle, spread=spread, r=rc, h=h, a=a, b=b,
                fitRange=(rMin, R), points=pts, n=len(onPlate))


if __name__ == "__main__":
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    R = float(sys.argv[2]) if len(sys.argv) > 2 else 0.03
    w = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0025
    res = analyse(case, R, w)
    print("%s: t = %s s, %s: angle of repose %.1f deg (sector spread %.1f deg)"
          % (case, res["time"], res["kind"], res["angle"], res["spread"]))
