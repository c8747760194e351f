#!/usr/bin/python3
"""CTest iceChannel.fsicrHandExample: the FSICR channel resistance tool against
examples worked by hand (intermediate values below, rounded to 6-7 digits, so
the tolerance is 2e-5 relative; the tool carries full precision).

Example 1 -- ice class IA (H_M = 1.0 m), C1 = C2 = 0:
  L 150 m, B 24 m, T 9 m, L_PAR 70 m, L_BOW 40 m, A_wf 720 m^2,
  alpha 22 deg, phi1 30 deg, phi2 45 deg
  H_F   = 0.26 + sqrt(1.0 x 24) = 0.26 + 4.898979 = 5.158979 m
  psi   = atan(tan 45 / sin 22) = atan(1 / 0.374607) = atan(2.669467) = 69.46372 deg
  sin psi = 2.669467 / sqrt(1 + 2.669467^2) = 2.669467 / 2.850624 = 0.936450
  Cmu   = 0.15 cos 45 + sin psi sin 22 = 0.106066 + 0.936450 x 0.374607
        = 0.106066 + 0.350800 = 0.456866        (>= 0.45: kept)
  Cpsi  = 0.047 x 69.46372 - 2.115 = 3.264795 - 2.115 = 1.149795   (psi > 45)
  (H_F + H_M)^2 = 6.158979^2 = 37.93303
  B + Cpsi H_F  = 24 + 1.149795 x 5.158979 = 24 + 5.931768 = 29.93177
  term3 = 845 x 0.456866 x 37.93303 x 29.93177 = 386.0518 x 37.93303 x 29.93177
        = 14644.12 x 29.93177 = 438324.5 N
  term4 = 42 x 70 x 5.158979^2 = 2940 x 26.61506 = 78248.3 N
  (L T / B^2)^3 = (1350 / 576)^3 = 2.34375^3 = 12.87460   (inside 5..20)
  term5 = 825 x 12.87460 x 720 / 150 = 825 x 12.87460 x 4.8 = 50983.4 N
  R_CH  = 438324.5 + 78248.3 + 50983.4 = 567556.2 N;   model 1:100: 0.5675562 N
Example 1 as IA Super (same H_M = 1.0 m) adds
  C1 = 23 x 24 x 70 / (2 x 9/24 + 1) + (1 + 0.021 x 30)(45.8 x 24 + 14.7 x 40 + 29 x 24 x 40)
     = 38640 / 1.75 + 1.63 x (1099.2 + 588 + 27840) = 22080 + 1.63 x 29527.2
     = 22080 + 48129.34 = 70209.34 N
  C2 = (1 + 0.063 x 30)(1530 + 170 x 24) + 400 (1 + 1.2 x 9/24) 24^2 / sqrt(150)
     = 2.89 x 5610 + 400 x 1.45 x 576 / 12.247449 = 16212.90 + 27277.52 = 43490.42 N
  R_CH = 567556.2 + 70209.34 + 43490.42 = 681256.0 N
Example 2 -- ice class IC (H_M = 0.6 m), both bounds active:
  L 100, B 30, T 5, L_PAR 40, L_BOW 25, A_wf 500, alpha 15, phi1 40, phi2 20
  H_F   = 0.26 + sqrt(18) = 0.26 + 4.242641 = 4.502641 m
  psi   = atan(tan 20 / sin 15) = atan(0.363970 / 0.258819) = atan(1.406273) = 54.58339 deg
  sin psi = 0.814960;  Cmu = 0.15 x 0.939693 + 0.814960 x 0.258819
          = 0.140954 + 0.210927 = 0.351881 < 0.45  ->  Cmu = 0.45
  Cpsi  = 0.047 x 54.58339 - 2.115 = 2.565419 - 2.115 = 0.450419
  term3 = 845 x 0.45 x (5.102641)^2 x (30 + 0.450419 x 4.502641)
        = 380.25 x 26.03694 x 32.02808 = 317095.5 N
  term4 = 42 x 40 x 4.502641^2 = 1680 x 20.27377 = 34059.94 N
  (L T / B^2)^3 = (500/900)^3 = 0.171468 < 5  ->  5
  term5 = 825 x 5 x 500 / 100 = 20625 N
  R_CH  = 317095.5 + 34059.94 + 20625 = 371780.4 N
Each example would fail if a constant, a bound, the psi definition or a term
were wrong (e.g. dropping the Cmu floor changes example 2 by 7.4 %).
Example 3 -- the command-line tool on an iceHull dictionary (the seed report's
dummy hull, lambda 100): checks it runs and writes R_CH / lambda^3.
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.join(HERE, "..", "..", "applications", "utilities", "brashIceChannel")
sys.path.insert(0, TOOLS)
from hedraIce.fsicr import r_ch  # noqa: E402


def main():
    fails = []

    def check(name, got, want, tol=2e-5):
        err = abs(got - want) / abs(want)
        print(f"{name:24s} tool {got:.7g}  hand {want:.7g}  rel. diff {err:.2e}")
        if err > tol:
            fails.append(f"{name}: {got} against {want}")

    e1 = dict(L=150, B=24, T=9, Lbow=40, Lpar=70, Awf=720, alpha=22, phi1=30, phi2=45)
    r = r_ch(**e1, ice_class="IA")
    check("ex1 H_F", r["HF"], 5.158979)
    check("ex1 psi", r["psi"], 69.46372)
    check("ex1 Cmu", r["Cmu"], 0.456866)
    check("ex1 Cpsi", r["Cpsi"], 1.149795)
    check("ex1 term3", r["term3"], 438324.5)
    check("ex1 term4", r["term4"], 78248.3)
    check("ex1 term5", r["term5"], 50983.4)
    check("ex1 R_CH IA", r["R"], 567556.2)
    check("ex1 model 1:100", r["R"] / 100 ** 3, 0.5675562)
    r = r_ch(**e1, ice_class="IASuper")
    check("ex1 C1 IA Super", r["C1"], 70209.34)
    check("ex1 C2 IA Super", r["C2"], 43490.42)
    check("ex1 R_CH IA Super", r["R"], 681256.0)
    r = r_ch(L=100, B=30, T=5, Lbow=25, Lpar=40, Awf=500, alpha=15, phi1=40, phi2=20,
             ice_class="IC")
    check("ex2 H_F", r["HF"], 4.502641)
    check("ex2 Cmu (floor)", r["Cmu"], 0.45)
    check("ex2 Cpsi", r["Cpsi"], 0.450419)
    check("ex2 (LT/B^2)^3 used", r["LTB3used"], 5.0)
    check("ex2 R_CH IC", r["R"], 371780.4)
    # the command-line tool
    case = tempfile.mkdtemp(prefix="fsicr", dir=os.environ.get("HEDRA_TEST_TMP"))
    os.makedirs(os.path.join(case, "system"))
    with open(os.path.join(case, "system", "iceHullDict"), "w") as f:
        f.write("hull { type dummy; }\nfsicr { scale 100; iceClass IA; }\n")
    subprocess.run([os.path.join(TOOLS, "fsicr"), "-case", case], check=True)
    vals = {}
    with open(os.path.join(case, "postProcessing", "fsicr", "fsicr.dat")) as f:
        for line in f:
            if not line.startswith("#"):
                k, v = line.split()
                vals[k] = float(v)
    check("ex3 Rmodel = R/100^3", vals["Rmodel"], vals["R"] / 1e6, 1e-9)
    check("ex3 H_F (B 20 m)", vals["HF"], 0.26 + 20 ** 0.5, 1e-9)
    for f_ in fails:
        print("FAIL:", f_)
    print("fsicrHandExample:", "FAILED" if fails else "passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
