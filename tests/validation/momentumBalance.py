#!/usr/bin/env python3
"""Momentum conservation of the coupling: every coupling step, the fluid's
exchange source (sum over cells of V (KslUs - Ksl U + fExchange)) and the
sum of the coupled fluid forces on the particles cancel to round-off.

200 spheres settle in water (closed box), with every model family in use
(all drag laws but SchillerNaumann/HaiderLevenspiel, which settlingVelocity
uses; the three locate models; laminar, RAS kEpsilon and kOmegaSST).
Variants: setI/implicit/divided, setII/explicit/centre (all forces fed
back), setI/implicit/divided + implicitDiffusion smoothing (the balance is
taken before smoothing). Drag laws cycled through the variants. Two more
with `solidVelocity rigidBody` (each cell's drag on the solid's velocity
there, Up + omega x r; the spheres turn from their contacts), implicit and
explicit.
Tolerance: |sum_particles + sum_fluid| / max(|.|) < 1e-12 at every step
(written by demCloud as relErr in postProcessing/demCloud/0/summary.dat).
"""
import sys
import hedracase as hc

# formulation, coupling, void fraction, smoothing, forces, locate, turbulence
variants = [
    ("setI", "implicit", "divided", "none", "DiFelice pressureGradient viscousStress virtualMass SaffmanMeiLift", "hinted", "laminar"),
    ("setII", "explicit", "centre", "none", "KochHill pressureGradient viscousStress virtualMass SaffmanMeiLift", "standard", "laminar"),
    ("setI", "implicit", "divided", "implicitDiffusion", "Beetstra pressureGradient", "meshSearch", "laminar"),
    ("setII", "implicit", "divided", "none", "Tenneti pressureGradient", "hinted", "kEpsilon"),
    ("setI", "explicit", "divided", "none", "Ganser pressureGradient", "meshSearch", "laminar"),
    ("setI", "implicit", "centre", "none", "HoelzerSommerfeld pressureGradient", "hinted", "laminar"),
    ("setI", "implicit", "divided", "none", "Gidaspow pressureGradient viscousStress", "hinted", "kOmegaSST"),
    ("setI", "implicit", "divided", "none", "Gidaspow pressureGradient", "hinted", "laminar", "rigidBody"),
    ("setII", "explicit", "divided", "none", "DiFelice pressureGradient", "hinted", "laminar", "rigidBody"),
]
results = []
for k, (form, mc, vf, sm, forces, loc, turb, *solid) in enumerate(variants):
    solid = solid[0] if solid else "centre"
    case = hc.workdir(f"momentum{k}")
    hc.block_mesh(case, (0, 0, 0), (0.02, 0.02, 0.04), (8, 8, 16),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.05, 1e-3, 1)
    hc.schemes_solution(case)
    hc.transport(case, 1e-6, 1000)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    hc.dem_properties(case, 1e-5, 2500, 1e-3, {"floor": ((0, 0, 0), (0, 0, 1))},
                      hc.random_fill("cloud", 200, (0.001, 0.001, 0.015), (0.019, 0.019, 0.035)))
    if turb != "laminar":
        hc.foamfile(f"{case}/constant/turbulenceProperties", "turbulenceProperties",
                    f"simulationType RAS;\nRAS {{ RASModel {turb}; turbulence on; printCoeffs off; }}\n")
        for fname, dims, val, wall in (
                ("k", "[0 2 -2 0 0 0 0]", 1e-6, "kqRWallFunction; value uniform 1e-6"),
                ("epsilon", "[0 2 -3 0 0 0 0]", 1e-6, "epsilonWallFunction; value uniform 1e-6"),
                ("omega", "[0 0 -1 0 0 0 0]", 1.0, "omegaWallFunction; value uniform 1"),
                ("nut", "[0 2 -1 0 0 0 0]", 0, "nutkWallFunction; value uniform 0")):
            hc.foamfile(f"{case}/0/{fname}", fname,
                        f"dimensions {dims};\ninternalField uniform {val};\n"
                        f"boundaryField {{ walls {{ type {wall}; }} }}\n", cls="volScalarField")
    hc.coupling(case, f"""formulation {form};
locateModel {loc};
momentumCoupling {mc};
voidFractionModel {vf};
smoothingModel {sm};
solidVelocity {solid};
implicitDiffusionCoeffs {{ lengthScale 0.003; }}
forceModels ({forces});
particleShapes {{ beads {{ sphericity 0.9; crosswiseSphericity 0.85; }} }}
""")
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demPimpleFoam", case, "log.demPimpleFoam")
    rows = hc.read_summary(case)[1:]
    worst = max(r[hc.COLS["relErr"]] for r in rows)
    scale = max(max(abs(x) for x in r[hc.COLS["Pc"]]) for r in rows)
    ok = worst < 1e-12 and scale > 0 and len(rows) >= 50
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {form}/{mc}/{vf}/{sm}/{loc}/{turb}/{solid}/({forces}): "
          f"{len(rows)} steps, largest exchanged force {scale:.3g} N, worst relErr {worst:.3g} (< 1e-12)")
hc.finish(results)
