#!/usr/bin/env python3
"""convergence.png (gnuplot) from the fixed-cube tables of
tests/validation/README.md: |C_d/C_d,ref - 1| against cells per edge for the
face-on cube at Re 20 and 100 (cube faces on cell faces; open surface), the same
with the closed surface at Re 20, 100 and 200 (its own table), the edge-on (45 deg)
cube with the closed surface at Re 20 and 100 (its own table), and |C_a/C_a,ref - 1|
for the cube (face-on) and the sphere accelerated from rest, with a first-order
slope for comparison."""
import os
import re
import subprocess

here = os.path.dirname(os.path.abspath(__file__))
txt = open(os.path.join(here, "../../README.md")).read()
txt = txt[txt.index("## Fixed cube and cube added mass"):]
series = {"Cd20": [], "Cd100": [], "CaCube": [], "CaSphere": []}
for line in txt.splitlines():
    c = [x.strip().strip("*") for x in line.strip().strip("|").split("|")]
    if len(c) == 8 and c[0].isdigit() and c[1] in ("20", "100") and c[2] == "face-on" \
            and c[3] != "0.25" \
            and c[3] != "0.75" and not c[3].startswith("0.5 (faces through"):
        err = abs(float(c[4]) / float(c[5]) - 1)
        series["Cd%s" % c[1]].append((int(c[0]), err))
    if len(c) == 9 and c[1].isdigit():
        err = abs(float(c[4]) / float(c[6]) - 1)
        if c[0] == "cube" and c[2] in ("face-on / 0", "face-on / 0.5") and c[3] == "1.000":
            series["CaCube"].append((int(c[1]), err))
        if c[0].startswith("sphere"):
            series["CaSphere"].append((int(c[1]), err))
# The closed surface (demIbFoam's default since 2026-12-04): its own table
closedTxt = txt[txt.index("**Convergence with the closed surface**"):]
closedTxt = closedTxt[:closedTxt.index("\nConvergence (8-12-16")]
for re_ in ("20", "100", "200"):
    series["Cd%sClosed" % re_] = []
for line in closedTxt.splitlines():
    c = [x.strip().strip("*") for x in line.strip().strip("|").split("|")]
    if len(c) == 10 and c[0].isdigit() and c[2] == "face-on" and c[4] == "closed":
        err = abs(float(c[6]) / float(c[7].split()[0]) - 1)
        series["Cd%sClosed" % c[1]].append((int(c[0]), err))
# Edge-on (45 deg), closed surface: its own table
edgeTxt = txt[txt.index("**Edge-on convergence with the closed surface**"):]
edgeTxt = edgeTxt[:edgeTxt.index("\n\n", edgeTxt.index("|---"))]
edgeRef = {}
for re_ in ("20", "100"):
    series["Cd%sEdgeOn" % re_] = []
for line in edgeTxt.splitlines():
    c = [x.strip().strip("*") for x in line.strip().strip("|").split("|")]
    if len(c) == 10 and c[0].isdigit() and c[2].startswith("edge-on") and c[4] == "closed":
        err = abs(float(c[6]) / float(c[7].split()[0]) - 1)
        series["Cd%sEdgeOn" % c[1]].append((int(c[0]), err))
        edgeRef[c[1]] = c[7].split()[0]
dat = os.path.join(here, "convergence.dat")
with open(dat, "w") as f:
    for k, v in series.items():
        f.write("# %s: cells per edge (diameter), |relative error|\n" % k)
        for n, e in sorted(v):
            f.write("%d %.5f\n" % (n, e))
        f.write("\n\n")
gp = """set terminal pngcairo size 800,560
set output '%s'
set logscale xy
set xrange [4:18]
set yrange [0.005:1.2]
set xlabel 'cells per edge (sphere: per diameter)'
set ylabel '|relative error|'
set key top right
set grid
plot '%s' index 0 w lp pt 7 t 'C_d, cube face-on, Re 20 (ref 3.32)', \\
     '' index 1 w lp pt 5 t 'C_d, cube face-on, Re 100 (ref 1.339)', \\
     '' index 2 w lp pt 9 t 'C_a, cube face-on (ref 0.643)', \\
     '' index 3 w lp pt 11 t 'C_a, sphere (ref 0.5)', \\
     '' index 4 w lp pt 6 dt 3 lc rgb 'black' t 'C_d, Re 20, closed surface (default)', \\
     '' index 5 w lp pt 4 dt 3 t 'C_d, Re 100, closed surface', \\
     '' index 6 w lp pt 8 dt 3 t 'C_d, Re 200, closed surface (ref 0.979)', \\
     '' index 7 w lp pt 13 dt 4 t 'C_d, Re 20, edge-on, closed (ref %s)', \\
     '' index 8 w lp pt 12 dt 4 t 'C_d, Re 100, edge-on, closed (ref %s)', \\
     0.3/x w l dt 2 t 'first order'
""" % (os.path.join(here, "convergence.png"), dat, edgeRef["20"], edgeRef["100"])
subprocess.run(["gnuplot"], input=gp.encode(), check=True)
print(open(dat).read())
