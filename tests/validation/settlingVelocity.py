#!/usr/bin/env python3
"""Single particles settling in a large domain reach the drag law's
terminal velocity.

Water (rho 1000, nu 1e-6) at rest in a 30 x 30 x 100 mm box (5 mm cells,
10 particle diameters: the particle's wake hardly changes the fluid velocity
it sees), one particle of d_v = 0.5 mm, rho_p = 2500, released at rest.
Force models: drag + pressureGradient (buoyancy), formulation setI,
divided void fraction, two-way coupling.
  sphere: SchillerNaumann;                     tolerance 2 %
  cube:   HaiderLevenspiel, sphericity 0.806;  tolerance 3 %
  cube as a sphere of the cube's volume with sphericity 0.806 given in
  couplingProperties particleShapes;
  polyhedralCube: a true cube in the engine (shape polyhedron, law
  overlapVolume), sphericity taken from the engine's shape (0.806);
  tolerance 3 %.
Reference: v_t solving (rho_p - rho) g Vp = 1/2 rho Cd(Re) pi d^2/4 v^2.
Measured: mean settling velocity over the last 0.05 s of 0.3 s.
"""
import math
import hedracase as hc
from dragLaws import cd_sn, cd_hl, terminal_velocity

rho, nu, rhoP, d, g = 1000.0, 1e-6, 2500.0, 5e-4, 9.81


def terminal(cd):
    return terminal_velocity(cd, d, rhoP, rho, nu, g)


cases = [
    ("sphere", "SchillerNaumann", "", lambda Re: cd_sn(Re), 0.02),
    ("cube", "HaiderLevenspiel", "particleShapes { beads { sphericity 0.806; } }",
     lambda Re: cd_hl(Re, 0.806), 0.03),
    # a real polyhedral cube in the engine; sphericity from its shape
    ("polyhedralCube", "HaiderLevenspiel", "", lambda Re: cd_hl(Re, math.pi**(1 / 3) * 6**(2 / 3) / 6), 0.03),
]
results = []
for name, drag, shapes, cd, tol in cases:
    case = hc.workdir(f"settling-{name}")
    hc.block_mesh(case, (0, 0, 0), (0.03, 0.03, 0.1), (6, 6, 20),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.3, 1e-3, 1)
    hc.schemes_solution(case)
    hc.transport(case, nu, rho)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    c = (0.0125, 0.0125, 0.085)
    a = d * (math.pi / 6)**(1 / 3)   # edge of the cube of volume pi d^3/6
    h = (a * math.sqrt(3) / 2 if name == "polyhedralCube" else d / 2) + 1e-8
    hc.dem_properties(case, 5e-6, rhoP, d, {"floor": ((0, 0, 0), (0, 0, 1))},
                      hc.random_fill("one", 1, tuple(x - h for x in c),
                                     tuple(x + h for x in c)))
    if name == "polyhedralCube":
        txt = open(f"{case}/constant/demProperties").read()
        txt = txt.replace("contactModel { law hertzMindlin; rolling none; }",
                          "contactModel { law overlapVolume; volumetricStiffness 1e9; rolling none; }")
        txt = txt.replace(f"beads {{ shape sphere; material mat; diameter {d}; }}",
                          f"beads {{ shape polyhedron; material mat; geometry {{ type cube; edge {a}; }} }}")
        open(f"{case}/constant/demProperties", "w").write(txt)
    hc.coupling(case, f"""formulation setI;
momentumCoupling implicit;
voidFractionModel divided;
forceModels ({drag} pressureGradient);
{shapes}
""")
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demPimpleFoam", case, "log.demPimpleFoam")
    rows = hc.read_summary(case)
    tEnd = rows[-1][0]
    late = [r for r in rows if r[0] >= tEnd - 0.05 - 1e-9]
    v = -sum(r[hc.COLS["Up"]][2] for r in late) / len(late)
    vt = terminal(cd)
    print(f"{name}: v_t = {vt:.6f} m/s, Re_t = {vt*d/nu:.2f}; simulated {v:.6f} m/s")
    hc.check(f"{name} ({drag}) terminal velocity [m/s]", v, vt, tol, results)

hc.finish(results)
