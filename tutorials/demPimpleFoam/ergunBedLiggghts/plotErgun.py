#!/usr/bin/env python3
"""dp across the bed against the superficial velocity, with Ergun's equation
for the bed's own height and voidage and the bed weight per area.
The bed (heights, voidage) from LIGGGHTS's dump of the poured bed
(constant/liggghts/settled.dump). Writes dpErgun.dat and dpErgun.png."""
import glob
import math
import os
import re

d, rhoP, rho, nu, g = 1e-3, 2000.0, 10.0, 1.5e-4, 9.81
mu = rho * nu
txt = open("system/blockMeshDict").read()
txt = txt[txt.index("vertices"):txt.index("blocks")]
xs = re.findall(r"\(([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)", txt)
W = max(float(x[0]) for x in xs)
H = max(float(x[2]) for x in xs)
zFloor = 0.004


def read_dump(path):
    """(radius, z) of the atoms of a LIGGGHTS 'custom' dump"""
    lines = open(path).read().split("\n")
    i = [k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")][0]
    cols = lines[i].split()[2:]
    r, z = cols.index("radius"), cols.index("z")
    return [(float(l.split()[r]), float(l.split()[z])) for l in lines[i + 1:] if l.strip()]


P = read_dump("constant/liggghts/settled.dump")
Vs = sum(4 / 3 * math.pi * r**3 for r, z in P)
tops = sorted(z + r for r, z in P)[-max(1, len(P) // 50):]
L = sum(tops) / len(tops) - zFloor
eps = 1 - Vs / (W * W * L)
weight = L * (1 - eps) * (rhoP - rho) * g


def ergun(U):
    return L * (150 * mu * (1 - eps)**2 * U / (eps**3 * d**2)
                + 1.75 * rho * (1 - eps) * U**2 / (eps**3 * d))


U_mf = 0
lo, hi = 0.0, 1.0
for _ in range(100):
    U_mf = 0.5 * (lo + hi)
    lo, hi = (U_mf, hi) if ergun(U_mf) < weight else (lo, U_mf)

f = glob.glob("postProcessing/inletP/*/surfaceFieldValue.dat")[0]
rows = []
for l in open(f):
    if l.startswith("#") or not l.strip():
        continue
    v = l.replace("(", " ").replace(")", " ").split()
    t, p, Uz = float(v[0]), float(v[1]), float(v[4])
    rows.append((Uz, rho * p - rho * g * H))
with open("dpErgun.dat", "w") as out:
    out.write(f"# L = {L:.6g} m, eps = {eps:.6g}, bed weight/area = {weight:.6g} Pa, U_mf(Ergun) = {U_mf:.6g} m/s\n")
    out.write("# U [m/s]  dp [Pa]  dp Ergun [Pa]\n")
    for U, dp in rows:
        out.write(f"{U:.6g} {dp:.6g} {ergun(U):.6g}\n")
print(f"bed: L = {L*1e3:.2f} mm, eps = {eps:.4f}, weight/area = {weight:.1f} Pa, U_mf = {U_mf:.5f} m/s")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    Us = [r[0] for r in rows]
    plt.plot(Us, [r[1] for r in rows], "o", ms=3, label="demPimpleFoam")
    uu = [i * max(Us) / 100 for i in range(101)]
    plt.plot(uu, [ergun(u) for u in uu], "-", label=f"Ergun (eps = {eps:.3f}, L = {L*1e3:.1f} mm)")
    plt.axhline(weight, ls="--", color="k", label="bed weight / area")
    plt.xlabel("superficial velocity U [m/s]")
    plt.ylabel("pressure drop [Pa]")
    plt.legend()
    plt.title("Packed bed: pressure drop against Ergun")
    plt.savefig("dpErgun.png", dpi=120)
    print("wrote dpErgun.png")
except ImportError:
    # Fall back on gnuplot (Debian's gnuplot-nox)
    import shutil
    import subprocess
    if shutil.which("gnuplot"):
        script = f"""
set terminal png size 800,600
set output 'dpErgun.png'
set xlabel 'superficial velocity U [m/s]'
set ylabel 'pressure drop [Pa]'
set key left top
set title 'Packed bed: pressure drop against Ergun'
L={L}; e={eps}; mu={mu}; rho={rho}; d={d}
f(u)=L*(150*mu*(1-e)**2*u/(e**3*d**2)+1.75*rho*(1-e)*u**2/(e**3*d))
plot 'dpErgun.dat' u 1:2 w p pt 7 ps 0.6 t 'demPimpleFoam', \\
     f(x) w l lw 2 t sprintf('Ergun (eps = %.3f, L = %.1f mm)', e, L*1e3), \\
     {weight} w l dt 2 lc rgb 'black' t 'bed weight / area'
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        print("wrote dpErgun.png (gnuplot)")
    else:
        print("neither matplotlib nor gnuplot found: dpErgun.dat only")
