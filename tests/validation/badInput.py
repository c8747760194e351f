#!/usr/bin/env python3
"""Bad input in couplingProperties / time steps is refused with a message
that names what is wrong.

  1. unknown force model        -> lists the valid force models
  2. unknown void-fraction model -> lists the valid ones
  3. missing coefficient         -> names the dictionary and the key
  4. DEM step not dividing the fluid step -> refused (FatalIOError)
  5. demStepsPerFluidStep not matching deltaT/timeStep -> refused
  6. a misspelled top-level entry (momentumCoupeling) -> refused, with the
     closest valid name (it would otherwise be ignored and its default used)
  7. a misspelled coefficient of a selected model (dividedCoeffs nShell) ->
     refused, with the model's valid coefficients
  8. a misspelled coefficient dictionary (GidaspowCoefs) -> refused
  9. out-of-range coefficients: dividedCoeffs alphaMin 2 (void fraction 2
     everywhere), GidaspowCoeffs alphaMax -1 (reversed exchange force),
     virtualMassCoeffs Cvm -0.5 -> refused with the range
 10. adjustTimeStep yes in controlDict (demPimpleFoam keeps deltaT fixed:
     it used to be ignored) -> refused, naming adjustTimeStep
 11. an unused coefficient dictionary of a registered model (dividedCoeffs
     with voidFractionModel centre) is accepted, as in OpenFOAM (the run
     must succeed and say it is unused)
 12. couplingDirection sideways -> refused, with the valid values
 13. solidVelocity rigid -> refused, with the valid values (centre, rigidBody)
Each run must fail (non-zero exit) and its log contain the strings listed.
"""
import os
import sys
import hedracase as hc

BASE = """formulation setI;
voidFractionModel centre;
forceModels (SchillerNaumann pressureGradient);
"""

tests = [
    ("unknownForce", BASE.replace("SchillerNaumann", "Stokesian"), 1e-5,
     ["Unknown forceModel type Stokesian", "Valid forceModel types",
      "SchillerNaumann", "DiFelice", "Gidaspow", "HaiderLevenspiel", "couplingProperties"]),
    ("unknownVoidFraction", BASE.replace("centre", "nearest"), 1e-5,
     ["Unknown voidFractionModel type nearest", "centre", "divided"]),
    ("missingCoefficient",
     BASE + "smoothingModel implicitDiffusion;\nimplicitDiffusionCoeffs { }\n", 1e-5,
     ["lengthScale", "implicitDiffusionCoeffs", "couplingProperties"]),
    ("demStepNotDividing", BASE, 3e-5,
     ["does not divide", "timeStep", "demProperties"]),
    ("subStepsMismatch", BASE + "demStepsPerFluidStep 7;\n", 1e-5,
     ["demStepsPerFluidStep 7", "does not match", "couplingProperties"]),
    ("misspelledEntry", BASE + "momentumCoupeling explicit;\n", 1e-5,
     ["Unknown entry 'momentumCoupeling'", "did you mean 'momentumCoupling'",
      "couplingProperties"]),
    ("misspelledCoefficient",
     BASE.replace("centre", "divided") + "dividedCoeffs { nShell 3; }\n", 1e-5,
     ["Unknown entry 'dividedCoeffs/nShell'", "did you mean 'nShells'",
      "alphaMin", "couplingProperties"]),
    ("misspelledCoeffsDict",
     BASE.replace("SchillerNaumann", "Gidaspow") + "GidaspowCoefs { alphaMax 0.99; }\n",
     1e-5, ["Unknown entry 'GidaspowCoefs'", "did you mean 'GidaspowCoeffs'"]),
    ("alphaMinOutOfRange",
     BASE.replace("centre", "divided") + "dividedCoeffs { alphaMin 2; }\n", 1e-5,
     ["alphaMin 2", "dividedCoeffs", "must be in (0, 1)", "couplingProperties"]),
    ("alphaMaxNegative",
     BASE.replace("SchillerNaumann", "Gidaspow") + "GidaspowCoeffs { alphaMax -1; }\n",
     1e-5, ["alphaMax -1", "GidaspowCoeffs", "must be in (0, 1]"]),
    ("adjustTimeStep", BASE, 1e-5,
     ["adjustTimeStep", "controlDict", "demPimpleFoam"]),
    ("couplingDirection", BASE + "couplingDirection sideways;\n", 1e-5,
     ["Unknown couplingDirection 'sideways'", "twoWay", "oneWay", "couplingProperties"]),
    ("solidVelocity", BASE + "solidVelocity rigid;\n", 1e-5,
     ["Unknown solidVelocity 'rigid'", "centre", "rigidBody", "couplingProperties"]),
    ("CvmNegative",
     BASE.replace("pressureGradient", "pressureGradient virtualMass")
     + "virtualMassCoeffs { Cvm -0.5; }\n", 1e-5,
     ["Cvm -0.5", "virtualMassCoeffs", "must be >= 0"]),
]

# Runs that must succeed
good = [
    ("unusedCoeffsDict", BASE + "dividedCoeffs { nShells 2; alphaMin 0.3; }\n", 1e-5,
     ["dividedCoeffs in", "not used (the model is not selected)"]),
]

results = []
for name, coupling, demDt, expect in tests + good:
    mustFail = (name, coupling, demDt, expect) in tests
    case = hc.workdir(f"bad-{name}")
    hc.block_mesh(case, (0, 0, 0), (0.02, 0.02, 0.02), (2, 2, 2),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.002, 1e-3, 1,
                    "adjustTimeStep yes;\nmaxCo 0.5;\n" if name == "adjustTimeStep" else "")
    hc.schemes_solution(case)
    hc.transport(case, 1e-6, 1000)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    hc.dem_properties(case, demDt, 2500, 2e-3, {"floor": ((0, 0, 0), (0, 0, 1))},
                      hc.random_fill("one", 1, (0.005, 0.005, 0.005), (0.015, 0.015, 0.015)))
    hc.coupling(case, coupling)
    hc.run("blockMesh", case, "log.blockMesh")
    rc = hc.run("demPimpleFoam", case, "log.demPimpleFoam", check=False)
    log = open(os.path.join(case, "log.demPimpleFoam")).read()
    missing = [s for s in expect if s not in log]
    ok = (rc != 0 if mustFail else rc == 0) and not missing
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {name}: exit {rc}"
          + (f", missing in the message: {missing}" if missing else ""))
    if not ok:
        i = log.find("FOAM FATAL")
        print(log[i:i + 1500] if i >= 0 else log[-1500:])
hc.finish(results)
