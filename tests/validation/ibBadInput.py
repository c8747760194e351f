#!/usr/bin/env python3
"""Bad input of the resolved coupling (demIbFoam, constant/ibProperties) is
refused with a message that names the file and the entry, and a body that
leaves the fluid mesh stops the run naming it:

  1. a misspelled top-level entry (internalFluids) -> refused, with the
     closest valid name (it would otherwise be ignored, default in force)
  2. a misspelled entry of directForcing (nSubSample) -> refused
  3. nSubSamples 1000 (used to hang: 1e9 samples per cell) -> refused with
     the range
  4. integralThreshold 2, nCorrections 0 (used to be accepted) -> refused
  5. adjustTimeStep yes in controlDict (used to be ignored without a word)
     -> refused, naming adjustTimeStep
  6. a body whose centre leaves the mesh (used to get zero force silently)
     -> stopped, naming the body
  7. closedSurface true with integralForcing false (explicit interface) ->
     refused, naming both
  8. the unchanged case runs (the checks refuse nothing valid), and so does
     it with closedSurface true
Each bad run must fail (non-zero exit, no signal) with the strings listed.
"""
import os
import shutil
import hedracase as hc

IB = """demBackend polyDEM;
internalFluid integrated;
directForcing
{
    nSubSamples 4; pressureCorrection true; nCorrections 1;
    interface penalised; integralForcing true; integralThreshold 0.5;
}
lubrication { model none; }
"""

INSIDE = "(0.015 0.015 0.015)"
# Above the floor, inside the DEM, but outside the 3 cm fluid box
OUTSIDE = "(0.015 0.015 0.045)"

tests = [
    ("misspelledTopKey", IB.replace("internalFluid", "internalFluids"), INSIDE, "",
     ["Unknown entry 'internalFluids'", "did you mean 'internalFluid'", "ibProperties"]),
    ("misspelledForcingKey", IB.replace("nSubSamples", "nSubSample"), INSIDE, "",
     ["Unknown entry 'directForcing/nSubSample'", "did you mean 'nSubSamples'", "ibProperties"]),
    ("nSubSamplesHuge", IB.replace("nSubSamples 4", "nSubSamples 1000"), INSIDE, "",
     ["nSubSamples", "[1, 16]", "ibProperties"]),
    ("integralThreshold", IB.replace("integralThreshold 0.5", "integralThreshold 2"), INSIDE, "",
     ["integralThreshold", "(0, 1]", "ibProperties"]),
    ("nCorrectionsZero", IB.replace("nCorrections 1", "nCorrections 0"), INSIDE, "",
     ["nCorrections", ">= 1", "ibProperties"]),
    ("adjustTimeStep", IB, INSIDE, "adjustTimeStep yes;\nmaxCo 0.5;\n",
     ["adjustTimeStep", "controlDict", "demIbFoam"]),
    ("closedSurfaceNoIntegral",
     IB.replace("interface penalised; integralForcing true;",
                "interface explicit; integralForcing false; closedSurface true;"), INSIDE, "",
     ["closedSurface true needs integralForcing true", "ibProperties"]),
    ("bodyOutsideMesh", IB, OUTSIDE, "",
     ["Body 0 has left the fluid mesh", "centre (0.015 0.015 0.045)"]),
]
good = [("valid", IB, INSIDE, "", []),
        ("validClosed", IB.replace("integralThreshold 0.5;", "integralThreshold 0.5; closedSurface true;"),
         INSIDE, "", [])]

results = []
for name, ib, position, control, expect in tests + good:
    mustFail = not name.startswith("valid")
    case = hc.workdir(f"ibbad-{name}")
    hc.block_mesh(case, (0, 0, 0), (0.03, 0.03, 0.03), (6, 6, 6),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.003, 1e-3, 1, control)
    ibSrc = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ib", "settlingSphere", "system")
    for f in ("fvSchemes", "fvSolution"):
        shutil.copy(os.path.join(ibSrc, f), os.path.join(case, "system", f))
    hc.foamfile(os.path.join(case, "constant/transportProperties"), "transportProperties",
                "nu 1e-5;\nrho 1000;\n")
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type zeroGradient;"})
    hc.dem_properties(case, 1e-4, 2500, 0.012, {"floor": ((0, 0, 0), (0, 0, 1))},
                      f"""    one
    {{
        type list; particleType beads;
        particles ( {{ position {position}; }} );
    }}""")
    hc.foamfile(os.path.join(case, "constant/ibProperties"), "ibProperties", ib)
    hc.run("blockMesh", case, "log.blockMesh")
    rc = hc.run("demIbFoam", case, "log.demIbFoam", check=False, timeout=120)
    log = open(os.path.join(case, "log.demIbFoam")).read()
    missing = [s for s in expect if s not in log]
    clean = 0 <= rc < 128 and "printStack" not in log
    ok = clean and (rc != 0 and "FOAM FATAL" in log if mustFail else rc == 0) and not missing
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {name}: exit {rc}"
          + (f", missing in the message: {missing}" if missing else ""))
    if not ok:
        i = log.find("FOAM FATAL")
        print(log[i:i + 1500] if i >= 0 else log[-1500:])
hc.finish(results)
