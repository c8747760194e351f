#!/usr/bin/env python3
"""One-way coupling (couplingDirection oneWay): the particles feel the fluid,
the fluid does not feel the particles.

Checked (tolerances):
  demPimpleFoam, a sphere (d 0.5 mm, 2500 kg/m3) settling in water at rest
  (the box of settlingVelocity.py):
    - the fluid is the fluid of the same run without the particle: U and p
      at the end equal to the last written digit (writePrecision 12);
    - the sphere reaches the Schiller-Naumann terminal velocity of a single
      sphere in unbounded fluid at rest within 0.5 % (two-way,
      settlingVelocity.py: 2 %, the wake's own velocity field around it);
  demInterFoam, unresolved mode, a tank whose water starts with a sloped
  surface and sloshes, with three floating blocks (700 kg/m3, edge 2 cells):
    - one-way: alpha.water, U and p_rgh after 0.4 s equal to those of the
      same run without particles (writePrecision 14);
    - two-way: they differ by more than 1e-3 in alpha (the comparison can
      tell a fluid that sees the blocks from one that does not);
  demInterFoam, one block (700 kg/m3, edge 2 cells) released 10 % of its edge
  above its draft in still water, one-way: its draft below the undisturbed
  level (which the block does not raise in one-way) is the Archimedes draft
  (rho_b - rho_a)/(rho_w - rho_a) H within 3 % (vofFloatingBlocks.py's
  tolerance), mean over the last 30 % of 3 s.
"""
import os
import hedracase as hc
import vofcase as vc
from dragLaws import cd_sn, terminal_velocity

results = []


def field_text(case, time, name):
    """The internalField of a written field, as written (ascii)."""
    txt = open(os.path.join(case, time, name)).read()
    i = txt.index("internalField")
    return txt[i:txt.index("boundaryField", i)]


def latest_time(case):
    times = [d for d in os.listdir(case) if d.replace(".", "", 1).isdigit() and d != "0"]
    return max(times, key=float)


def same_fields(label, a, b, names):
    ta, tb = latest_time(a), latest_time(b)
    same = ta == tb and all(field_text(a, ta, n) == field_text(b, tb, n) for n in names)
    print(f"{label}: {' '.join(names)} at t = {ta} {'identical' if same else 'DIFFER'}"
          f" to the written digits")
    results.append(same)
    if not same:
        print(f"FAILED: {label}")


# --- demPimpleFoam: a settling sphere -------------------------------------
rho, nu, rhoP, d = 1000.0, 1e-6, 2500.0, 5e-4


def settling_case(name, number, direction):
    case = hc.workdir(f"oneway-{name}")
    hc.block_mesh(case, (0, 0, 0), (0.03, 0.03, 0.1), (6, 6, 20),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, 0.3, 1e-3, 0.3)
    hc.schemes_solution(case)
    hc.transport(case, nu, rho)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    c, h = (0.0125, 0.0125, 0.085), d / 2 + 1e-8
    insertion = hc.random_fill("one", 1, tuple(x - h for x in c), tuple(x + h for x in c)) \
        if number else ""
    hc.dem_properties(case, 5e-6, rhoP, d, {"floor": ((0, 0, 0), (0, 0, 1))}, insertion)
    hc.coupling(case, f"""formulation setI;
momentumCoupling implicit;
couplingDirection {direction};
voidFractionModel divided;
forceModels (SchillerNaumann pressureGradient);
""")
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demPimpleFoam", case, "log.demPimpleFoam")
    return case


fluidOnly = settling_case("fluidOnly", 0, "twoWay")
sphere = settling_case("sphere", 1, "oneWay")
same_fields("demPimpleFoam one-way: the fluid of the run without the sphere",
            sphere, fluidOnly, ["U", "p"])
rows = hc.read_summary(sphere)
tEnd = rows[-1][0]
late = [r for r in rows if r[0] >= tEnd - 0.05 - 1e-9]
v = -sum(r[hc.COLS["Up"]][2] for r in late) / len(late)
vt = terminal_velocity(cd_sn, d, rhoP, rho, nu)
print(f"sphere: v_t = {vt:.6f} m/s, Re_t = {vt * d / nu:.2f}; simulated {v:.6f} m/s")
hc.check("demPimpleFoam one-way: Schiller-Naumann terminal velocity [m/s]", v, vt, 1e-4, results)


# --- demInterFoam: blocks in a sloshing tank --------------------------------
LO, HI, N = (0.0, 0.0, 0.0), (0.12, 0.12, 0.10), (12, 12, 10)
DX, H, RHO_B = 0.01, 0.02, 700.0
D = (RHO_B - vc.RHO_A) / (vc.RHO_W - vc.RHO_A) * H


def sloped_water(case, level, slope, sub=20):
    """alpha.water of the surface z = level + slope (x - x_mid), the cell
    fractions by sub x sub strips in x and exactly in z."""
    dx = [(HI[k] - LO[k]) / N[k] for k in range(3)]
    xm = 0.5 * (LO[0] + HI[0])
    vals = []
    for k in range(N[2]):
        z0 = LO[2] + k * dx[2]
        for j in range(N[1]):
            for i in range(N[0]):
                x0 = LO[0] + i * dx[0]
                f = 0.0
                for s in range(sub):
                    x = x0 + (s + 0.5) * dx[0] / sub
                    zs = level + slope * (x - xm)
                    f += min(max((zs - z0) / dx[2], 0.0), 1.0) / sub
                vals.append(f)
    body = ("dimensions [0 0 0 0 0 0 0];\ninternalField nonuniform List<scalar>\n"
            f"{len(vals)}\n(\n" + "\n".join(f"{v:.17g}" for v in vals) + "\n);\n"
            "boundaryField\n{\n    walls { type zeroGradient; }\n}\n")
    hc.foamfile(os.path.join(case, "0/alpha.water"), "alpha.water", body, cls="volScalarField")


def coupling_blocks(case, direction):
    hc.coupling(case, f"""couplingMode unresolved;
couplingDirection {direction};
formulation setI;
momentumCoupling implicit;
locateModel hinted;
voidFractionModel exactOverlap;
smoothingModel none;
forceModels (Gidaspow freeSurfacePressure);
""")


def slosh_case(name, direction):
    case = hc.workdir(f"oneway-slosh-{name}")
    vc.closed_tank(case, LO, HI, N)
    sloped_water(case, 0.06, 0.25)
    vc.vof_dicts(case, 0.4, 2e-3, 0.4)
    if direction is None:
        vc.coupling_without_particles(case, (0, 0, 1))
    else:
        blocks = [(0.0312, 0.0617, 0.06 - 0.25 * 0.0288 - D + H / 2),
                  (0.0634, 0.0327, 0.06 - 0.25 * 0.0034 - D + H / 2),
                  (0.0905, 0.0873, 0.06 + 0.25 * 0.0305 - D + H / 2)]
        vc.dem_blocks(case, 1e-4, RHO_B, blocks, (H, H, H), (LO, HI))
        coupling_blocks(case, direction)
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)
    return case


fluidOnly = slosh_case("fluidOnly", None)
oneWay = slosh_case("oneWay", "oneWay")
twoWay = slosh_case("twoWay", "twoWay")
same_fields("demInterFoam one-way: the fluid of the run without the blocks",
            oneWay, fluidOnly, ["alpha.water", "U", "p_rgh"])


def alpha_values(case):
    txt = field_text(case, latest_time(case), "alpha.water")
    return [float(x) for x in txt[txt.index("(") + 1:txt.rindex(")")].split()]


diff = max(abs(a - b) for a, b in zip(alpha_values(twoWay), alpha_values(fluidOnly)))
ok = diff > 1e-3
print(f"demInterFoam two-way: max |alpha - alpha without blocks| = {diff:.3e} (expected > 1e-3)"
      f" {'ok' if ok else 'FAILED'}")
results.append(ok)

# --- demInterFoam: a floating block's draft in one-way ---------------------
case = hc.workdir("oneway-float")
vc.closed_tank(case, LO, HI, N, open_top=True)
xc = (0.0634, 0.0627)
zb0 = 0.06 - D + 0.1 * H
vc.water_field(case, LO, HI, N, 0.06)     # the water does not see the block
vc.vof_dicts(case, 3.0, 2e-3, 3.0)
vc.dem_blocks(case, 1e-4, RHO_B, [(xc[0], xc[1], zb0 + H / 2)], (H, H, H), (LO, HI))
coupling_blocks(case, "oneWay")
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demInterFoam", case, "log.demInterFoam", timeout=1800)
z = [r[hc.COLS["xp"]][2] for r in hc.read_summary(case)]
zEnd = vc.late_mean(z)
draft = 0.06 - (zEnd - H / 2)
print(f"one-way floating block: draft {draft * 1e3:.4f} mm, Archimedes {D * 1e3:.4f} mm")
hc.check("demInterFoam one-way: floating block's draft [m]", draft, D, 0.03, results)

hc.finish(results)
