"""fsicr: the rule channel resistance R_CH of the Finnish-Swedish Ice Class Rules.

A RULE FORMULA, NOT A VALIDATION: R_CH is the resistance the rules assume for
a ship in a brash-ice channel of thickness H_M with a consolidated top layer
H_F, used to size the engine; it is drawn on the resistance plot as a
reference line only.

    R_CH = C1 + C2 + C3 Cmu (H_F + H_M)^2 (B + Cpsi H_F) + C4 L_PAR H_F^2
           + C5 (L T / B^2)^3 A_wf / L                                   [N]
    Cmu  = 0.15 cos(phi2) + sin(psi) sin(alpha),  Cmu >= 0.45
    psi  = arctan(tan(phi2) / sin(alpha))
    Cpsi = 0.047 psi - 2.115 (psi in degrees),  Cpsi = 0 for psi <= 45 deg
    H_F  = 0.26 + (H_M B)^0.5                    (metres in, metres out)
    H_M  = 1.0 m (IA Super, IA), 0.8 m (IB), 0.6 m (IC)
    (L T / B^2)^3 is taken as 5 when below 5 and as 20 when above 20
    C3 = 845 kg/(m^2 s^2), C4 = 42 kg/(m^2 s^2), C5 = 825 kg/s^2
    C1 = C2 = 0 for IA, IB, IC; for IA Super
    C1 = f1 B L_PAR / (2 T/B + 1) + (1 + 0.021 phi1)(f2 B + f3 L_BOW + f4 B L_BOW)
    C2 = (1 + 0.063 phi1)(g1 + g2 B) + g3 (1 + 1.2 T/B) B^2 / sqrt(L)
    f1 = 23 N/m^2, f2 = 45.8 N/m, f3 = 14.7 N/m, f4 = 29 N/m^2,
    g1 = 1530 N, g2 = 170 N/m, g3 = 400 N/m^1.5   (phi1 in degrees)
    L, B, T: length, breadth, draught at the upper ice waterline; L_BOW, L_PAR:
    bow and parallel mid-body lengths; A_wf: waterline area of the bow;
    alpha: waterline angle at B/4; phi1: stem rake at the centreline
    (90 deg for a bulbous bow); phi2: bow rake at B/4.

Source: Finnish-Swedish Ice Class Rules 2017 (Traficom/Trafi, TRAFI/494131/
03.04.01.00/2016), section 3.2.2 "Definition of R_CH"; Guidelines for the
application of the Finnish-Swedish Ice Class Rules, TRAFI/708629/03.04.01.01/
2018 (Helsinki, 8 January 2019).  The published text could NOT be retrieved
in this session (the search found those documents, not their formula pages):
the formula and constants above are checked against /work/shared/reference/
brashIce.md and the engineer's copy of the 2017 rules, and the IA Super
C1/C2 constants f1..f4, g1..g3 and the range-of-validity table below come
from that copy only.  Re-check them against the rule text before a design use.

Range of validity of the formula (rules, table in 3.2.2); outside it the tool
warns (the rules then ask for a model test or another method):
    alpha 15..55 deg, phi1 25..90 deg, phi2 10..90 deg, L 65..250 m,
    B 11..40 m, T 4..15 m, L_BOW/L 0.15..0.4, L_PAR/L 0.25..0.75,
    A_wf/(L B) 0.09..0.27
The rules round nothing inside the formula; report R_CH to 3 significant
figures at most (the rule formula is an engineering estimate).

Model scale (Froude similarity, the same densities): lengths / lambda, forces
/ lambda^3: R_model = R_CH(full-scale hull, H_M) / lambda^3.
"""
import math
import os

from .foamDict import Dict

H_M = {"IASuper": 1.0, "IA": 1.0, "IB": 0.8, "IC": 0.6}
C3, C4, C5 = 845.0, 42.0, 825.0
F1, F2, F3, F4 = 23.0, 45.8, 14.7, 29.0
G1, G2, G3 = 1530.0, 170.0, 400.0
VALIDITY = {"alpha": (15, 55), "phi1": (25, 90), "phi2": (10, 90), "L": (65, 250),
            "B": (11, 40), "T": (4, 15), "Lbow/L": (0.15, 0.4), "Lpar/L": (0.25, 0.75),
            "Awf/(L B)": (0.09, 0.27)}


def r_ch(L, B, T, Lbow, Lpar, Awf, alpha, phi1, phi2, ice_class="IA", HM=None):
    """Full-scale R_CH [N] and its parts (dict).  Angles in degrees, SI units."""
    if ice_class not in H_M:
        raise ValueError(f"ice class '{ice_class}': valid {' '.join(H_M)}")
    HM = H_M[ice_class] if HM is None else HM
    a, p1, p2 = (math.radians(x) for x in (alpha, phi1, phi2))
    psi = math.degrees(math.atan(math.tan(p2) / math.sin(a))) if phi2 < 90 else 90.0
    Cmu = max(0.45, 0.15 * math.cos(p2) + math.sin(math.radians(psi)) * math.sin(a))
    Cpsi = 0.0 if psi <= 45 else 0.047 * psi - 2.115
    HF = 0.26 + math.sqrt(HM * B)
    lt = (L * T / B ** 2) ** 3
    lt_used = min(20.0, max(5.0, lt))
    if ice_class == "IASuper":
        c1 = (F1 * B * Lpar / (2 * T / B + 1)
              + (1 + 0.021 * phi1) * (F2 * B + F3 * Lbow + F4 * B * Lbow))
        c2 = (1 + 0.063 * phi1) * (G1 + G2 * B) + G3 * (1 + 1.2 * T / B) * B ** 2 / math.sqrt(L)
    else:
        c1 = c2 = 0.0
    t3 = C3 * Cmu * (HF + HM) ** 2 * (B + Cpsi * HF)
    t4 = C4 * Lpar * HF ** 2
    t5 = C5 * lt_used * Awf / L
    warn = []
    for key, val in (("alpha", alpha), ("phi1", phi1), ("phi2", phi2), ("L", L), ("B", B),
                     ("T", T), ("Lbow/L", Lbow / L), ("Lpar/L", Lpar / L),
                     ("Awf/(L B)", Awf / (L * B))):
        lo, hi = VALIDITY[key]
        if not lo <= val <= hi:
            warn.append(f"{key} = {val:.4g} outside the rule formula's range {lo}..{hi}")
    return dict(R=c1 + c2 + t3 + t4 + t5, C1=c1, C2=c2, term3=t3, term4=t4, term5=t5,
                psi=psi, Cmu=Cmu, Cpsi=Cpsi, HF=HF, HM=HM, LTB3=lt, LTB3used=lt_used,
                warnings=warn)


def main(argv=None):
    import argparse
    from .hull import hull_from_dict
    p = argparse.ArgumentParser(description="FSICR rule channel resistance R_CH (a rule "
                                "formula, not a validation): full scale and / lambda^3")
    p.add_argument("-case", default=".")
    p.add_argument("-dict", default="system/iceHullDict",
                   help="the hull (iceHull's dictionary, at model scale) and an `fsicr` "
                   "sub-dictionary: scale (lambda), iceClass, optional channelThickness "
                   "(full scale H_M [m])")
    a = p.parse_args(argv)
    dfile = a.dict if os.path.isabs(a.dict) else os.path.join(a.case, a.dict)
    d = Dict.read(dfile)
    d.check_keys(["hull", "placement", "resolution", "file", "fsicr"])
    hull = hull_from_dict(d.sub("hull"))
    f = d.sub("fsicr")
    f.check_keys(["scale", "iceClass", "channelThickness", "output"])
    lam = f.get("scale", float, min=0, strict_min=True)
    cls = f.get("iceClass", str, choices=list(H_M))
    HM = f.get("channelThickness", float, min=0, strict_min=True) \
        if "channelThickness" in f else None
    s = lam
    res = r_ch(L=hull.L * s, B=hull.B * s, T=hull.T * s, Lbow=hull.Lbow * s,
               Lpar=hull.Lpar * s, Awf=hull.bow_waterplane_area() * s * s,
               alpha=hull.alpha, phi1=hull.phi1, phi2=hull.phi2, ice_class=cls, HM=HM)
    Rm = res["R"] / lam ** 3
    out = os.path.join(a.case, f.get("output", str, default="postProcessing/fsicr/fsicr.dat"))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as fo:
        fo.write("# FSICR rule channel resistance (a rule formula, not a validation)\n"
                 f"# hull from {dfile}, scale lambda {lam}, ice class {cls}\n"
                 "# key value\n")
        for k in ("R", "C1", "C2", "term3", "term4", "term5", "psi", "Cmu", "Cpsi", "HF",
                  "HM", "LTB3", "LTB3used"):
            fo.write(f"{k} {res[k]:.10g}\n")
        fo.write(f"Rmodel {Rm:.10g}\nHMmodel {res['HM'] / lam:.10g}\n")
        for w in res["warnings"]:
            fo.write(f"# warning: {w}\n")
    print(f"fsicr: R_CH = {res['R'] / 1e3:.4g} kN at full scale (H_M {res['HM']} m, "
          f"H_F {res['HF']:.4g} m), model scale 1:{lam:g}: {Rm:.4g} N "
          f"(H_M {res['HM'] / lam:.4g} m); wrote {out}")
    for w in res["warnings"]:
        print("  warning:", w)
    return 0
