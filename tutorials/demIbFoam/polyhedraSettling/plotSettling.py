#!/usr/bin/env python3
"""Post-processing of the polyhedral settling study.

Usage: plotSettling.py CASE...          one line per case, series and plot
       plotSettling.py --table CASE...  also postProcessing/table.dat, the
                                        comparison plot and README.md's table

Per case (cases/CASE):
  reads postProcessing/ibForces/0/forces.dat (demIbFoam: every fluid step,
  position, velocity, IB fluid force F and torque T) and <time>/polyDEM/state
  (the DEM state at each write time: angular velocity, orientation);
  writes postProcessing/settling/settling.dat
      t z w |U_h| Fx Fy Fz          (every fluid step; w < 0 downwards)
  and postProcessing/settling/rotation.dat
      t omega_x omega_y omega_z |omega| tilt    (every write time; tilt =
      angle of the long axis, body x, above the horizontal [deg])
  and settling.png (gnuplot): settling velocity, fluid force, angular
  velocity and tilt against time.

Terminal velocity: the mean settling velocity over the plateau window, the
last `plateau` seconds (0.06 s polyhedra, 0.1 s cube, 0.5 s ellipsoid) before the
particle comes within 2 d_eq of the bottom (or the end of the run); the
drift over the window (linear fit, change across the window / mean) tells
whether it is a plateau. Maximum velocity: the largest instantaneous
settling velocity before that point, and the largest average over one cell
crossing (dx/w; the coarse-mesh velocity oscillates as cells switch in and
out of the body).
"""
import glob
import math
import os
import re
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))


def readInfo(case):
    info = {}
    for line in open(os.path.join(case, "caseInfo")):
        k, v = line.split(None, 1)
        v = v.strip()
        try:
            info[k] = float(v)
        except ValueError:
            info[k] = v
    return info


def cdHolzerSommerfeld(Re, phi, phiP):
    """Drag coefficient of a non-spherical particle (Holzer & Sommerfeld 2008,
    Powder Technol. 184:361), on the volume-equivalent sphere's diameter and
    cross-section; phi sphericity, phiP crosswise sphericity (for the flow
    direction)."""
    return (8 / Re / math.sqrt(phiP) + 16 / Re / math.sqrt(phi) + 3 / math.sqrt(Re) / phi**0.75
            + 0.42 * 10**(0.4 * (-math.log10(phi))**0.2) / phiP)


def terminalHS(info, case):
    """Terminal velocity from Holzer-Sommerfeld in an unbounded fluid, the
    particle falling along body z (H: broadside, as released) or body x (V)"""
    log = open(os.path.join(case, "shape.log")).read()
    phi = float(re.search(r"^sphericity\s+(\S+)", log, re.M).group(1))
    psi = [float(x) for x in re.search(r"^crosswiseSphericity\s+(\S+) (\S+) (\S+)", log,
                                       re.M).groups()]
    phiP = psi[2] if info["release"] == "H" else psi[0]
    d, rp, rf, mu = info["dEq"], info["rhoP"], info["rhoF"], info["muF"]
    v = 0.1
    for _ in range(300):
        Re = rf * v * d / mu
        v = math.sqrt(4.0 / 3 * 9.81 * d * abs(rp - rf) / rf / cdHolzerSommerfeld(Re, phi, phiP))
    return v


def tiltDeg(q):
    w, x, y, z = q
    ez = 2 * (x * z - w * y)          # world z component of R(q) e_x
    return math.degrees(math.asin(max(-1.0, min(1.0, ez))))


def analyse(name):
    case = os.path.join(here, "cases", name)
    info = readInfo(case)
    files = sorted(glob.glob(os.path.join(case, "postProcessing", "ibForces", "*", "forces.dat")))
    if not files:
        return None
    rows = {}
    for fn in files:
        for line in open(fn):
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            rows[v[0]] = v
    t = sorted(rows)
    z = [rows[x][4] for x in t]
    w = [rows[x][7] for x in t]
    uh = [math.hypot(rows[x][5], rows[x][6]) for x in t]
    F = [rows[x][8:11] for x in t]

    rot = []
    for sd in glob.glob(os.path.join(case, "*", "polyDEM", "state")):
        try:
            tt = float(sd.split(os.sep)[-3])
        except ValueError:
            continue
        lines = open(sd).read().split("\n")
        p = lines[lines.index("data") + 1].split()
        q = [float(x) for x in p[10:14]]
        om = [float(x) for x in p[17:20]]
        rot.append((tt, om, math.sqrt(sum(o * o for o in om)), tiltDeg(q)))
    rot.sort()

    out = os.path.join(case, "postProcessing", "settling")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "settling.dat"), "w") as f:
        f.write("# %s: t [s], z [m], w [m/s] (settling velocity, < 0 down), |U_h| [m/s],"
                " IB fluid force Fx Fy Fz [N]\n" % name)
        for i in range(len(t)):
            f.write("%g %.6e %.6e %.6e %.6e %.6e %.6e\n"
                    % (t[i], z[i], w[i], uh[i], F[i][0], F[i][1], F[i][2]))
    with open(os.path.join(out, "rotation.dat"), "w") as f:
        f.write("# %s: t [s], omega_x omega_y omega_z |omega| [1/s], tilt of the long"
                " axis above the horizontal [deg]\n" % name)
        for tt, om, mag, tl in rot:
            f.write("%g %.6e %.6e %.6e %.6e %.4f\n" % (tt, om[0], om[1], om[2], mag, tl))

    d, dx = info["dEq"], info["dx"]
    ell = info["name"] == "ellipsoid"
    plateau = 0.5 if ell else 0.1 if info["name"] == "cube" else 0.06
    # end of the useful record: 2 d above the bottom
    iEnd = len(t)
    for i in range(len(t)):
        if z[i] < 2 * d:
            iEnd = i
            break
    tE = t[iEnd - 1]
    win = [i for i in range(iEnd) if t[i] >= tE - plateau]
    wT = -sum(w[i] for i in win) / len(win)
    # drift: least-squares slope over the window
    tm = sum(t[i] for i in win) / len(win)
    sxx = sum((t[i] - tm) ** 2 for i in win)
    slope = -sum((t[i] - tm) * (w[i] + wT) for i in win) / sxx if sxx else 0.0
    drift = slope * plateau / wT if wT else 0.0
    wMaxI = max(range(iEnd), key=lambda i: -w[i])
    wMax = -w[wMaxI]
    cross = dx / max(wT, 1e-9)
    avg = []
    for i in range(iEnd):
        v = [w[j] for j in range(iEnd) if abs(t[j] - t[i]) <= 0.5 * cross + 1e-12]
        avg.append(-sum(v) / len(v))
    wMaxS = max(avg)
    tMaxS = t[avg.index(wMaxS)]
    tiltMax = max((abs(r[3]) for r in rot if r[0] <= tE), default=float("nan"))
    tiltEnd = min((r for r in rot if r[0] <= tE), key=lambda r: abs(r[0] - tE),
                  default=(0, 0, 0, float("nan")))[3]
    tiltAtMax = min(rot, key=lambda r: abs(r[0] - t[wMaxI]),
                    default=(0, 0, 0, float("nan")))[3]
    omMax = max((r[2] for r in rot if r[0] <= tE), default=float("nan"))
    # first time the long axis is less than 60 deg above the horizontal
    tBelow60 = min((r[0] for r in rot if abs(r[3]) < 60), default=float("nan"))
    Fnet = info["netWeight"]
    Fz = sum(F[i][2] for i in win) / len(win)
    wall = float("nan")
    rtf = os.path.join(case, "runTime")
    if os.path.exists(rtf):
        wall = float(open(rtf).read().split()[0])
    cpu = float("nan")
    info.setdefault("refine", 0)
    cellsMax = int(info["cells"])
    logf = os.path.join(case, "log.demIbFoam")
    if os.path.exists(logf):
        logText = open(logf).read()
        m = re.findall(r"ExecutionTime = (\S+) s", logText)
        if m:
            cpu = float(m[-1])
        # dynamicRefineFvMesh: "Refined from A to B cells." / "Unrefined from ..."
        n = [int(x) for x in re.findall(r"efined from \d+ to (\d+) cells", logText)]
        if n:
            cellsMax = max(n)
    wHS = terminalHS(info, case)
    res = dict(name=name, info=info, wT=wT, wHS=wHS, drift=drift, win=(t[win[0]], tE), wMax=wMax,
               tMax=t[wMaxI], wMaxS=wMaxS, tMaxS=tMaxS, tiltAtMax=tiltAtMax, tiltMax=tiltMax, tiltEnd=tiltEnd,
               omMax=omMax, FzOverW=Fz / Fnet, tLast=t[-1], cpu=cpu, wall=wall, cellsMax=cellsMax, tBelow60=tBelow60,
               reachedBottom=iEnd < len(t))
    print("%s: d/dx %.2f near the body (%d refinement levels), %d cells (base; at most %d),"
          " dt %g, t = 0 ... %g s; terminal w %.4f m/s (mean over"
          " t = %.3f ... %.3f s, drift %+.1f %% over the window), F_z/(net weight) %.3f;"
          " max w %.4f m/s at %.3f s (cell-crossing average %.4f at %.3f s); max |omega|"
          " %.2f 1/s, max |tilt| %.1f deg, |tilt| at max w %.1f deg, tilt at the end %.1f deg; CPU %.0f s, wall %.0f s"
          % (name, info["dOverDx"], info["refine"], info["cells"], cellsMax, info["deltaT"],
             t[-1], wT, t[win[0]],
             tE, 100 * drift, Fz / Fnet, wMax, t[wMaxI], wMaxS, tMaxS, omMax, tiltMax,
             abs(tiltAtMax), tiltEnd, cpu, wall))
    print("  Holzer-Sommerfeld (2008) terminal velocity, unbounded, falling %s: %.4f m/s;"
          " measured / that = %.3f; Re = %.0f (measured), %.0f (Holzer-Sommerfeld)"
          % ("face-on" if info["name"] == "cube" else "broadside" if info["release"] == "H"
             else "along the long axis", wHS, wT / wHS, info["rhoF"] * wT * info["dEq"]
             / info["muF"], info["rhoF"] * wHS * info["dEq"] / info["muF"]))
    plot(case, name, info, Fnet)
    return res


def gnuplot(script, cwd):
    try:
        subprocess.run(["gnuplot"], input=script, text=True, check=True, cwd=cwd,
                       capture_output=True)
        return True
    except (OSError, subprocess.CalledProcessError) as e:
        print("gnuplot failed (%s): no PNG" % e)
        return False


def plot(case, name, info, Fnet):
    script = """set terminal pngcairo size 1000,700 noenhanced
set output 'settling.png'
set multiplot layout 2,2 title '%s (d/dx %.1f)'
set xlabel 't [s]'
set key bottom right
set ylabel 'velocity [m/s]'
plot 'postProcessing/settling/settling.dat' u 1:(-$3) w l lw 2 t 'settling -w', \
     '' u 1:4 w l t 'horizontal |U_h|'
set ylabel 'IB fluid force [N]'
plot 'postProcessing/settling/settling.dat' u 1:7 w l lw 2 t 'F_z', \
     '' u 1:(sqrt($5**2+$6**2)) w l t '|F_h|', \
     %g w l dt 2 lc rgb 'black' t '(rho_p - rho_f) V g'
set ylabel 'angular velocity [1/s]'
set key top left
plot 'postProcessing/settling/rotation.dat' u 1:5 w lp pt 7 ps 0.4 lw 2 t '|omega|', \
     '' u 1:2 w l t 'omega_x', '' u 1:3 w l t 'omega_y', '' u 1:4 w l t 'omega_z'
set ylabel 'long axis above horizontal [deg]'
plot 'postProcessing/settling/rotation.dat' u 1:6 w lp pt 7 ps 0.4 lw 2 notitle
unset multiplot
""" % (name, info["dOverDx"], Fnet)
    gnuplot(script, case)


def facets(i):
    f = i["facets"]
    return "%d" % f if isinstance(f, float) else f


def table(results):
    os.makedirs(os.path.join(here, "postProcessing"), exist_ok=True)
    head = ("case AR C release d/dx levels cells cellsMax deltaT endTime wTerminal plateauFrom plateauTo"
            " drift wHolzerSommerfeld wMax tMax wMaxCellAvg maxOmega maxTilt tiltAtMaxW tiltEnd FzOverNetWeight cpu_s wall_s")
    with open(os.path.join(here, "postProcessing", "table.dat"), "w") as f:
        f.write("# " + head + "\n")
        for r in results:
            i = r["info"]
            f.write("%s %g %s %s %.3g %d %d %d %g %g %.5f %.4f %.4f %.4f %.5f %.5f %.4f %.5f %.3f %.2f"
                    " %.2f %.2f %.4f %.0f %.0f\n"
                    % (r["name"], i["AR"], facets(i), i["release"], i["dOverDx"],
                       i["refine"], i["cells"], r["cellsMax"], i["deltaT"], r["tLast"], r["wT"], r["win"][0], r["win"][1],
                       r["drift"], r["wHS"], r["wMax"], r["tMax"], r["wMaxS"], r["omMax"],
                       r["tiltMax"], abs(r["tiltAtMax"]), r["tiltEnd"], r["FzOverW"], r["cpu"],
                       r["wall"]))
    md = ["| case | AR | C | release | d/dx near body | levels | cells (base / max) | dt [s] | t_end [s] | terminal w [m/s] "
          "(plateau window, drift) | Hölzer–Sommerfeld w [m/s] | max w [m/s] (t) | max w, cell-avg. | w_max / w_term | "
          "max tilt [deg] | tilt at max w [deg] | F_z / net weight (plateau) | CPU / wall [s] |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        i = r["info"]
        md.append("| %s | %g | %s | %s | %.3g | %d | %d / %d | %g | %g | %.4f (%.2f–%.2f s, %+.1f %%) | %.3f |"
                  " %.4f (%.3f s) | %.4f | %.2f | %.1f | %.1f | %.3f | %.0f / %.0f |"
                  % (r["name"], i["AR"], facets(i), i["release"], i["dOverDx"], i["refine"],
                     i["cells"], r["cellsMax"], i["deltaT"], r["tLast"], r["wT"], r["win"][0], r["win"][1],
                     100 * r["drift"], r["wHS"], r["wMax"], r["tMax"], r["wMaxS"], r["wMax"] / r["wT"],
                     r["tiltMax"], abs(r["tiltAtMax"]), r["FzOverW"], r["cpu"], r["wall"]))
    text = "\n".join(md)
    print(text)
    readme = os.path.join(here, "README.md")
    if os.path.exists(readme):
        s = open(readme).read()
        a, b = "<!-- table: plotSettling.py --table -->", "<!-- end of table -->"
        if a in s and b in s:
            s = s[:s.index(a) + len(a)] + "\n" + text + "\n" + s[s.index(b):]
            open(readme, "w").write(s)
            print("updated the table in README.md")
    summary(results)
    # comparison plot of the polyhedra: colour = AR, thin C 20 / thick C 50,
    # solid H / dashed V; cases at another resolution than the first dotted
    colours = {1.25: "#7b2cbf", 1.5: "#2a9d8f", 1.75: "#1d70c2", 2.0: "#e76f51"}
    poly = [r for r in results if r["info"]["name"] not in ("ellipsoid", "cube")]
    n0 = poly[0]["info"]["dOverDx"] if poly else 0
    curves = ", ".join(
        "'cases/%s/postProcessing/settling/settling.dat' u 1:(-$3) w l lc rgb '%s' lw %g dt %d"
        " t '%s'" % (r["name"], colours.get(r["info"]["AR"], "black"),
                     1.5 if facets(r["info"]) == "20" else 3.0,
                     3 if abs(r["info"]["dOverDx"] - n0) > 0.01 else
                     (1 if r["info"]["release"] == "H" else 2), r["name"])
        for r in poly)
    if curves:
        gnuplot("""set terminal pngcairo size 1000,550 noenhanced
set output 'postProcessing/settling.png'
set xlabel 't [s]'
set ylabel 'settling velocity -w [m/s]'
set key outside right
plot %s
""" % curves, here)


def summary(results):
    """The README's two summary tables, from the cases of the default matrix
    (names A<AR>C<C><H|V> without a suffix): horizontal terminal velocities
    against Holzer-Sommerfeld, and vertical against horizontal maxima."""
    by = {r["name"]: r for r in results}
    ARs = ("1.25", "1.5", "1.75", "2.0")
    md = []
    if all("A%sC%s%s" % (a, c, o) in by for a in ARs for c in ("20", "50") for o in "H"):
        n = by["A1.25C20H"]["info"]["dOverDx"]
        md += ["Summary of the horizontal releases (terminal velocity, m/s, d/dx = %.3g near the"
               " body; in brackets: / Hölzer–Sommerfeld):" % n, "",
               "| AR | C = 20 | C = 50 | C50 / C20 | Hölzer–Sommerfeld C20 / C50 |",
               "|---|---|---|---|---|"]
        for a in ARs:
            r20, r50 = by["A%sC20H" % a], by["A%sC50H" % a]
            md.append("| %g | %.3f (%.2f) | %.3f (%.2f) | %.3f | %.3f / %.3f |"
                      % (float(a), r20["wT"], r20["wT"] / r20["wHS"], r50["wT"],
                         r50["wT"] / r50["wHS"], r50["wT"] / r20["wT"], r20["wHS"], r50["wHS"]))
        md.append("")
    if all("A%sC%s%s" % (a, c, o) in by for a in ARs for c in ("20", "50") for o in "HV"):
        md += ["Vertical against horizontal release (maximum settling velocity, m/s; tilt of the"
               " long axis above the horizontal at the maximum; time at which the tilt falls"
               " below 60°):", "",
               "| AR | C | max w, V | max w, H | V / H | tilt at max | tilt < 60° at |",
               "|---|---|---|---|---|---|---|"]
        for a in ARs:
            for c in ("20", "50"):
                v, h = by["A%sC%sV" % (a, c)], by["A%sC%sH" % (a, c)]
                md.append("| %g | %s | %.3f | %.3f | %.2f | %.0f° | %.3f s |"
                          % (float(a), c, v["wMax"], h["wMax"], v["wMax"] / h["wMax"],
                             abs(v["tiltAtMax"]), v["tBelow60"]))
    # the settling cube at two or more resolutions: terminal velocities and
    # their differences from the finest (the 3 % of issue 18)
    cubes = sorted((r for r in results if r["info"]["name"] == "cube"),
                   key=lambda r: (r["info"]["dOverDx"], r["info"].get("interval", 1)))
    mc = []
    if len(cubes) >= 2:
        fine = cubes[-1]

        def wAt(r, tt):
            # settling velocity at the row nearest tt
            rows = [[float(x) for x in l.split()[:3]] for l in open(os.path.join(
                here, "cases", r["name"], "postProcessing", "settling", "settling.dat"))
                if l.strip() and not l.startswith("#")]
            return -min(rows, key=lambda v: abs(v[0] - tt))[2]
        mc += ["Settling cube (terminal w: mean over the last 0.1 s; difference from the"
               " finest, %s):" % fine["name"], "",
               "| case | d/dx near body | levels | refine every | cells (base / max) | dt [s] |"
               " terminal w [m/s] (window, drift) | Re | / Hölzer–Sommerfeld | difference |"
               " F_z / net weight | w at 0.1 / 0.2 / 0.4 s [m/s] (difference) | wall [s] |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in cubes:
            i = r["info"]
            mc.append("| %s | %.3g | %d | %d steps | %d / %d | %g | %.4f (%.2f–%.2f s, %+.1f %%) |"
                      " %.0f | %.3f | %+.2f %% | %.3f | %s | %.0f |"
                      % (r["name"], i["dOverDx"], i["refine"], i.get("interval", 1), i["cells"],
                         r["cellsMax"], i["deltaT"], r["wT"], r["win"][0], r["win"][1],
                         100 * r["drift"], i["rhoF"] * r["wT"] * i["dEq"] / i["muF"],
                         r["wT"] / r["wHS"], 100 * (r["wT"] / fine["wT"] - 1), r["FzOverW"],
                         " / ".join("%.4f (%+.1f %%)" % (wAt(r, tt), 100 * (wAt(r, tt) / wAt(fine, tt) - 1))
                                    for tt in (0.1, 0.2, 0.4)),
                         r["wall"]))
        gnuplot("""set terminal pngcairo size 900,500 noenhanced
set output 'postProcessing/cubeConvergence.png'
set xlabel 't [s]'
set ylabel 'settling velocity -w [m/s]'
set key bottom right
set grid
plot %s, %g w l lc rgb 'black' dt 2 t 'Hölzer–Sommerfeld (unbounded)'
""" % (", ".join("'cases/%s/postProcessing/settling/settling.dat' u 1:(-$3) w l lw 2 t '%s,"
                 " d/dx %.3g'" % (r["name"], r["name"], r["info"]["dOverDx"]) for r in cubes),
       fine["wHS"]), here)
    for lines, a, b in ((md, "<!-- summary: plotSettling.py --table -->", "<!-- end of summary -->"),
                        (mc, "<!-- cube: plotSettling.py --table -->", "<!-- end of cube -->")):
        if not lines:
            continue
        text = "\n".join(lines).strip()
        print(text)
        readme = os.path.join(here, "README.md")
        if os.path.exists(readme):
            s = open(readme).read()
            if a in s and b in s:
                s = s[:s.index(a) + len(a)] + "\n" + text + "\n" + s[s.index(b):]
                with open(readme, "w") as f:
                    f.write(s)
                print("updated %s in README.md" % a)


def main():
    args = sys.argv[1:]
    doTable = "--table" in args
    names = [a for a in args if not a.startswith("--")]
    results = []
    for n in names:
        r = analyse(n)
        if r is None:
            print("%s: no forces.dat (not run?)" % n)
        else:
            results.append(r)
    if doTable:
        table(results)


if __name__ == "__main__":
    main()
