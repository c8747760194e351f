#!/usr/bin/env python3
"""Fluidised bed of cubes: pressure drop across the bed and bed height
against time, with the bed weight per area. Writes pressureDrop.dat, bedHeight.dat and
pressureDrop.png (matplotlib; gnuplot as a fall-back)."""
import glob
import math
import re

rho, nu, g = 1.2, 1.5e-5, 9.81          # air (constant/transportProperties)
mu = rho * nu
dem = open("constant/demProperties").read()
a = float(re.search(r"edge\s+([0-9.e-]+);", dem).group(1))
rhoP = float(re.search(r"grain\s*\{[^}]*density\s+([0-9.e+-]+);", dem).group(1))
zFloor = float(re.search(r"floor\s*\{[^}]*point \(0 0 ([0-9.e-]+)\)", dem).group(1))
Vp = a**3
dv = (6 * Vp / math.pi) ** (1 / 3)       # volume-equivalent diameter
phi = math.pi ** (1 / 3) * (6 * Vp) ** (2 / 3) / (6 * a * a)   # sphericity of a cube

txt = open("system/blockMeshDict").read()
txt = txt[txt.index("vertices"):txt.index("blocks")]
xs = re.findall(r"\(([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)", txt)
W, D, H = (max(float(x[i]) for x in xs) for i in range(3))
ctl = open("system/controlDict.settle").read()
tSettle = float(re.search(r"endTime\s+([0-9.e-]+);", ctl).group(1))
Uin = float(re.findall(r"\(0 0 ([0-9.e-]+)\)\)\)", open(f"{tSettle:g}/U").read())[-1])


def umf(phi_, eps=0.45):
    """Ergun with sphericity (d = phi d_v), and Wen & Yu (1966)."""
    Ar = rho * (rhoP - rho) * g * dv**3 / mu**2
    A, B = 1.75 / (eps**3 * phi_), 150 * (1 - eps) / (eps**3 * phi_**2)
    Re = (-B + math.sqrt(B * B + 4 * A * Ar)) / (2 * A)
    ReWY = math.sqrt(33.7**2 + 0.0408 * Ar) - 33.7
    return Re * mu / (rho * dv), ReWY * mu / (rho * dv)


def table(pattern):
    rows = []
    for line in open(sorted(glob.glob(pattern))[-1]):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(v) for v in line.replace("(", " ").replace(")", " ").split()])
    return rows


P = table(f"postProcessing/inletP/{tSettle:g}/surfaceFieldValue.dat")
tP = [r[0] for r in P]
dp = [rho * r[1] - rho * g * H for r in P]          # bed: inlet - outlet - gas head
B = table(f"postProcessing/bed/{tSettle:g}/bed.dat")
tB = [r[0] for r in B]
N = int(B[-1][1])
hMean = [2 * (r[10] - zFloor) for r in B]           # twice the centre of mass height
hTop = [r[11] for r in B]                           # top of the highest particle
weight = N * Vp * (rhoP - rho) * g / (W * D)

t0 = tSettle + 0.15                                 # after the ramp (0.1 s) + 0.05 s
sel = [p for t, p in zip(tP, dp) if t >= t0]
mean = sum(sel) / len(sel)
std = math.sqrt(sum((p - mean) ** 2 for p in sel) / len(sel))
h0 = hMean[0]
hs = [h for t, h in zip(tB, hMean) if t >= t0]
umfE, umfWY = umf(phi)
umfModel = umf(1.0)[0]
summary = (f"# {N} cubes a = {a*1e3:g} mm, d_v = {dv*1e3:.3f} mm, sphericity {phi:.3f}, "
           f"rho_p = {rhoP:g} kg/m3; column {W*1e3:g} x {D*1e3:g} mm\n"
           f"# U_mf: Ergun (phi {phi:.3f}, eps 0.45) {umfE:.3f} m/s, Wen-Yu {umfWY:.3f} m/s, "
           f"Ergun with d_v (Gidaspow as used) {umfModel:.3f} m/s; U = {Uin:g} m/s\n"
           f"# bed weight/area {weight:.1f} Pa; mean dp (t >= {t0:g} s) {mean:.1f} Pa "
           f"(+- {std:.1f} std) = {mean/weight:.3f} x weight\n"
           f"# bed height (2 x centre of mass): settled {h0*1e3:.1f} mm, "
           f"fluidised mean {sum(hs)/len(hs)*1e3:.1f} mm\n")
with open("pressureDrop.dat", "w") as out:
    out.write(summary)
    out.write("# time [s]  dp [Pa]\n")
    for t, p in zip(tP, dp):
        out.write(f"{t:.6g} {p:.6g}\n")
with open("bedHeight.dat", "w") as out:
    out.write("# time [s]  2 x (centre of mass - floor) [m]  top of the highest cube [m]\n")
    for t, h, top in zip(tB, hMean, hTop):
        out.write(f"{t:.6g} {h:.6g} {top:.6g}\n")
print(summary, end="")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 7))
    ax1.plot(tP, dp, "-", lw=0.8, label="dp across the bed (demPimpleFoam)")
    ax1.axhline(weight, ls="--", color="k", label=f"bed weight / area = {weight:.0f} Pa")
    ax1.axhline(mean, ls=":", color="r", label=f"mean dp (t > {t0:g} s) = {mean:.0f} Pa")
    ax1.set_ylabel("pressure drop [Pa]")
    ax1.set_ylim(0, 2.5 * weight)
    ax1.legend(loc="upper right", fontsize=8)
    ax1.set_title(f"Fluidised bed: {N} cubes, U = {Uin:g} m/s "
                  f"(U_mf Wen-Yu {umfWY:.2f}, Ergun(phi) {umfE:.2f} m/s)", fontsize=10)
    ax2.plot(tB, [h * 1e3 for h in hMean], label="bed height: 2 x centre of mass")
    ax2.plot(tB, [h * 1e3 for h in hTop], lw=0.7, label="top of the highest cube")
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("height above floor [mm]")
    ax2.set_ylim(0, H * 1e3)
    ax2.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig("pressureDrop.png", dpi=110)
    print("wrote pressureDrop.png")
except ImportError:
    # Fall back on gnuplot (Debian's gnuplot-nox): same two panels
    import shutil
    import subprocess
    if shutil.which("gnuplot"):
        script = f"""
set terminal pngcairo size 880,760 font ',10' noenhanced
set output 'pressureDrop.png'
set multiplot layout 2,1
set title 'Fluidised bed: {N} cubes, U = {Uin:g} m/s (U_mf Wen-Yu {umfWY:.2f}, Ergun(phi) {umfE:.2f} m/s)'
set ylabel 'pressure drop [Pa]'
set yrange [0:{2.5*weight}]
set key top right
plot 'pressureDrop.dat' u 1:2 w l lw 1 t 'dp across the bed (demPimpleFoam)', \\
     {weight} w l dt 2 lw 2 lc rgb 'black' t 'bed weight / area = {weight:.0f} Pa', \\
     {mean} w l dt 3 lw 2 lc rgb 'red' t 'mean dp (t > {t0:g} s) = {mean:.0f} Pa'
set title ''
set xlabel 'time [s]'
set ylabel 'height above floor [mm]'
set yrange [0:{H*1e3}]
plot 'bedHeight.dat' u 1:($2*1e3) w l lw 2 t 'bed height: 2 x centre of mass', \\
     'bedHeight.dat' u 1:($3*1e3) w l lw 1 t 'top of the highest cube'
unset multiplot
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        print("wrote pressureDrop.png (gnuplot)")
    else:
        print("neither matplotlib nor gnuplot: pressureDrop.dat, bedHeight.dat only")
