#!/usr/bin/python3
"""CTest iceChannel.badInput: every tool stops on a bad entry with
"FOAM FATAL IO ERROR", exit status 1, the dictionary's path and the entry
(and, for a misspelled name, the closest valid one)."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.join(HERE, "..", "..", "applications", "utilities", "brashIceChannel")

GOOD = """channel { origin (0 -1); length 3; width 2; waterLevel 2.5; }
thickness { type uniform; value 0.1; }
blockThickness 0.1;
sizeDistribution { type uniform; min 0.08; max 0.12; }
shape { type cuboid; }
porosity 0.5;
iceDensity 920;
waterDensity 1010;
"""
# (tool, dictionary file, text, expected words in the message)
CASES = [
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("porosity", "porosty"),
     ["porosty", "did you mean 'porosity'"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("length 3", "length -3"),
     ["channel/length", "must be >"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("type uniform; min", "type gaussian; min"),
     ["sizeDistribution/type", "valid: uniform normal logNormal table"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("iceDensity 920", "iceDensity 1020"),
     ["iceDensity", "lighter than water"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("porosity 0.5", "porosity 0.99"),
     ["porosity", "<= 0.95"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("blockThickness 0.1", "blockThickness 0.3"),
     ["blockThickness", "more than the largest ice thickness"]),
    ("brashIceChannel", "brashIceChannelDict",
     GOOD.replace("thickness { type uniform; value 0.1; }",
                  "thickness { type profile; points ((0.2 0.1) (1 0.2)); }"),
     ["thickness/points", "from eta"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD + "packing lattice;\nshape2 1;\n",
     ["shape2"]),
    ("brashIceChannel", "brashIceChannelDict", GOOD.replace("porosity 0.5;", "porosity 0.5"),
     ["porosity", "is a ';' missing after entry 'porosity'"]),
    ("iceHull", "iceHullDict", "hull { type parametric; length 150; beam 24; draft 9; depth 14; "
     "parallelMidbodyLength 70; bowLength 40; stemAngle 30; bowAngle 45; waterlineAngle 40; }\n",
     ["hull/waterlineAngle", "needs"]),
    ("iceHull", "iceHullDict", "hull { type dummy; lenght 1.2; }\n",
     ["hull/lenght", "did you mean 'length'"]),
    ("iceChannelMesh", "iceChannelMeshDict",
     "domain { min (0 -1 0); max (10 1 5); }\ncellSize 0.1;\nwaterLevel 7;\n",
     ["waterLevel", "not inside the domain"]),
    ("fsicr", "iceHullDict", "hull { type dummy; }\nfsicr { scale 100; iceClass IAS; }\n",
     ["fsicr/iceClass", "valid: IASuper IA IB IC"]),
]


def main():
    fails = []
    for k, (tool, dname, text, words) in enumerate(CASES):
        case = tempfile.mkdtemp(prefix=f"badInput{k}", dir=os.environ.get("HEDRA_TEST_TMP"))
        os.makedirs(os.path.join(case, "system"))
        path = os.path.join(case, "system", dname)
        with open(path, "w") as f:
            f.write(text)
        r = subprocess.run([os.path.join(TOOLS, tool), "-case", case],
                           capture_output=True, text=True)
        msg = r.stderr
        ok = (r.returncode == 1 and "FOAM FATAL IO ERROR" in msg and path in msg
              and all(w in msg for w in words) and "Traceback" not in msg)
        first = [l.strip() for l in msg.splitlines() if l.strip()][1:2]
        print(f"{'ok  ' if ok else 'FAIL'} {tool:15s} {words[0]:24s} {first}")
        if not ok:
            fails.append(f"{tool} case {k}: rc {r.returncode}, message:\n{msg}")
    for f_ in fails:
        print("FAIL:", f_)
    print("badInput:", "FAILED" if fails else "passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
