#!/usr/bin/env python3
"""Ball mill tutorial: a markdown table of the steady shoulder, toe and power
of the cases given (chargeShape means, postProcessing/charge/*/chargeMean.dat)
next to the seed's dry values (ballMill.md; its angle convention is not
defined in the paper). Energy balance: (power - dissipation - dE/dt) / power
over the steady window (chargeShape's energyBalance: the power drawn against
what the contacts dissipate)."""
import glob
import sys

SEED = {"noLifters": ("2.00", "0.72", "19.36", "214.16"),
        "lifters8": ("2.62", "0.38", "51.84", "244.18")}


def means(case):
    m = {}
    for f in glob.glob(case + "/postProcessing/charge/*/chargeMean.dat"):
        for line in open(f):
            if line.startswith("#") or not line.strip():
                continue
            q, v, e, n = line.split()
            m[q.split("[")[0]] = (float(v), float(e), int(n))
    return m


def fmt(m, k, scale=1.0, digits=2):
    if k not in m:
        return "-"
    v, e = m[k][:2]
    return "%.*f +- %.*f" % (digits, v * scale, digits, e * scale)


if __name__ == "__main__":
    print("| case | shoulder deg | toe deg | shoulder height m | toe height m "
          "| power kW | M g xc omega kW | dissipation kW | energy balance % "
          "| seed: shoulder h, toe h m | seed: angles as printed deg |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for case in sys.argv[1:]:
        m = means(case)
        s = SEED.get(case, ("-",) * 4)
        balance = ("%.2f" % (100 * m["energyBalance"][0])) if "energyBalance" in m else "-"
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s, %s | %s, %s |"
              % (case, fmt(m, "shoulder", digits=1), fmt(m, "toe", digits=1),
                 fmt(m, "shoulderHeight"), fmt(m, "toeHeight"),
                 fmt(m, "power", 1e-3), fmt(m, "powerGravity", 1e-3),
                 fmt(m, "dissipation", 1e-3), balance,
                 s[0], s[1], s[2], s[3]))
