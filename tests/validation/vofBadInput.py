#!/usr/bin/env python3
"""Bad input to demInterFoam is refused with a message that names the file,
the entry and what was expected (FatalIOError / FatalError, non-zero exit,
no crash, no hang):

  1. couplingMode misspelled (resolvd)    -> couplingProperties, the valid modes
                                             (unresolved resolved)
  2. submergedVolume misspelled (planar)  -> couplingProperties, the valid names
  3. formulation setII with a free surface -> couplingProperties, use setI
  4. nAlphaSubCycles 2 with particles      -> fvSolution, nAlphaSubCycles 1
  5. 0/alpha.water missing                 -> OpenFOAM's error naming the file
  6. resolved mode, interface misspelled   -> couplingProperties/directForcing,
     (penalized)                              the valid interfaces
  7. resolved mode, a misspelled entry     -> couplingProperties, the closest
     (solidAlpa; it used to be ignored)       valid name (solidAlpha)
  8. local time stepping (localEuler)      -> fvSchemes: the particles need a
                                              physical time step
  9. PIMPLE velocityCorrection misspelled  -> fvSolution, the valid values
     (gradients)                              (reconstruct gradient)
 10. resolved mode, solidAlpha misspelled  -> couplingProperties, the valid
     (exclude)                                values (excluded fill transported)
 11. resolved mode, minFluidFraction 1e-5 -> couplingProperties, the range
                                              [0.001, 0.1]
 12. resolved mode, refinement { band .. } -> couplingProperties: it needs
     on a static mesh                         dynamicRefineFvMesh (field
                                              ibRefinement) in dynamicMeshDict
 13. resolved mode on dynamicRefineFvMesh  -> dynamicMeshDict: field
     refining on alpha.water                  ibRefinement expected (a
                                              refinement that follows another
                                              field would merge cells a body
                                              cuts)
 14. resolved mode, directForcing          -> couplingProperties/directForcing:
     { closedSurface true; } with PIMPLE      it needs velocityCorrection
     velocityCorrection gradient              reconstruct (the closed surface
                                              is available since 2026-12-06;
                                              before, any closedSurface true
                                              was refused here)
 15. resolved mode, refining mesh,         -> couplingProperties/refinement:
     refinement { surfaceBand 0.01; }         surfaceBand needs freeSurface yes
     without freeSurface
 16. resolved mode, directForcing          -> couplingProperties/directForcing:
     { solidFraction exakt; }                 the valid values (subSampled
                                              exact)
Case: a tank of 4 x 4 x 4 cells (0.04 m), water 0.02 m deep, one floating
block; each run must fail and its log hold the strings listed. ~10 s.
"""
import os
import hedracase as hc
import vofcase as vc

LO, HI, N = (0.0, 0.0, 0.0), (0.04, 0.04, 0.04), (4, 4, 4)
LEVEL = 0.02
BASE = """couplingMode unresolved;
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
submergedVolume interfacePlane;
forceModels (Gidaspow freeSurfacePressure);
"""


def make(name, coupling):
    case = hc.workdir(f"vofBad-{name}")
    vc.closed_tank(case, LO, HI, N, open_top=True)
    H = 0.01
    box = ((0.015, 0.015, LEVEL - H / 2), (0.025, 0.025, LEVEL + H / 2))
    vc.water_field(case, LO, HI, N, LEVEL, [box])
    vc.vof_dicts(case, 0.004, 2e-3, 0.004)
    vc.dem_blocks(case, 1e-4, 500, [(0.02, 0.02, LEVEL)], (H, H, H), (LO, HI))
    hc.coupling(case, coupling)
    return case


tests = [
    ("couplingMode", BASE.replace("couplingMode unresolved;", "couplingMode resolvd;"),
     None, ["couplingMode 'resolvd'", "couplingProperties", "Valid couplingMode values",
            "unresolved", "(unresolved resolved)"]),
    ("submergedVolume", BASE.replace("interfacePlane;", "planar;"),
     None, ["Unknown submergedVolume 'planar'", "couplingProperties",
            "cellWeights interfacePlane auto"]),
    ("formulation", BASE.replace("setI;", "setII;"),
     None, ["formulation setII", "couplingProperties", "use setI"]),
    ("nAlphaSubCycles", BASE, "subCycles",
     ["nAlphaSubCycles 2", "fvSolution", "use nAlphaSubCycles 1"]),
    ("alphaMissing", BASE, "noAlpha",
     ["alpha.water", "cannot find file"]),
    ("resolvedInterface",
     "couplingMode resolved;\ndemBackend polyDEM;\ndirectForcing { interface penalized; }\n",
     None, ["interface penalized", "couplingProperties", "explicit", "penalised", "none"]),
    ("resolvedMisspelled",
     "couplingMode resolved;\ndemBackend polyDEM;\nsolidAlpa transported;\n",
     None, ["Unknown entry 'solidAlpa'", "did you mean 'solidAlpha'", "couplingProperties"]),
    ("localEuler", BASE, "LTS", ["localEuler", "fvSchemes", "physical time step"]),
    ("velocityCorrection", BASE, "velocityCorrection",
     ["velocityCorrection 'gradients'", "fvSolution", "(reconstruct gradient gaussBalance)"]),
    ("solidAlphaValue",
     "couplingMode resolved;\ndemBackend polyDEM;\nsolidAlpha exclude;\n",
     None, ["solidAlpha 'exclude'", "couplingProperties", "(excluded fill transported)"]),
    ("minFluidFraction",
     "couplingMode resolved;\ndemBackend polyDEM;\nminFluidFraction 1e-5;\n",
     None, ["minFluidFraction 1e-05", "couplingProperties", "[0.001, 0.1]"]),
    ("resolvedRefinementEntry",
     "couplingMode resolved;\ndemBackend polyDEM;\nrefinement { band 5e-3; }\n",
     None, ["Entry 'refinement'", "couplingProperties", "dynamicRefineFvMesh",
            "ibRefinement"]),
    ("resolvedClosedSurface",
     "couplingMode resolved;\ndemBackend polyDEM;\ndirectForcing { closedSurface true; }\n",
     "velocityCorrectionGradient",
     ["closedSurface true", "couplingProperties", "directForcing",
      "needs PIMPLE velocityCorrection reconstruct", "it is 'gradient'"]),
    ("resolvedSurfaceBand",
     "couplingMode resolved;\ndemBackend polyDEM;\nrefinement { band 5e-3; surfaceBand 0.01; }\n",
     "refineAroundBodies", ["surfaceBand", "couplingProperties", "refinement",
                            "needs freeSurface yes"]),
    ("resolvedRefiningMesh",
     "couplingMode resolved;\ndemBackend polyDEM;\n", "refiningMesh",
     ["field alpha.water", "dynamicMeshDict", "expected field ibRefinement"]),
    ("resolvedSolidFraction",
     "couplingMode resolved;\ndemBackend polyDEM;\ndirectForcing { solidFraction exakt; }\n",
     None, ["solidFraction", "couplingProperties", "directForcing", "exakt",
            "not one of subSampled, exact"]),
]

results = []
for name, coupling, change, expect in tests:
    case = make(name, coupling)
    if change == "subCycles":
        p = os.path.join(case, "system/fvSolution")
        txt = open(p).read().replace("nAlphaSubCycles 1;", "nAlphaSubCycles 2;")
        open(p, "w").write(txt)
    elif change == "noAlpha":
        os.remove(os.path.join(case, "0/alpha.water"))
    elif change == "LTS":
        p = os.path.join(case, "system/fvSchemes")
        txt = open(p).read().replace("default Euler;", "default localEuler;")
        open(p, "w").write(txt)
    elif change == "refiningMesh":
        vc.refine_at_surface(case)
    elif change == "refineAroundBodies":
        vc.refine_around_bodies(case)
    elif change == "velocityCorrectionGradient":
        p = os.path.join(case, "system/fvSolution")
        txt = open(p).read().replace("PIMPLE\n{", "PIMPLE\n{\n    velocityCorrection gradient;")
        open(p, "w").write(txt)
    elif change == "velocityCorrection":
        p = os.path.join(case, "system/fvSolution")
        txt = open(p).read().replace("PIMPLE\n{", "PIMPLE\n{\n    velocityCorrection gradients;")
        open(p, "w").write(txt)
    hc.run("blockMesh", case, "log.blockMesh")
    rc = hc.run("demInterFoam", case, "log.demInterFoam", check=False, timeout=120)
    log = open(os.path.join(case, "log.demInterFoam")).read()
    missing = [s for s in expect if s not in log]
    ok = rc != 0 and not missing and "FOAM FATAL" in log
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {name}: exit {rc}"
          + (f", missing in the message: {missing}" if missing else ""))
    if not ok or os.environ.get("HEDRA_SHOW"):
        i = log.find("FOAM FATAL")
        print(log[i:i + 1200] if i >= 0 else log[-1500:])
hc.finish(results)
