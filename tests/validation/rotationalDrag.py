#!/usr/bin/env python3
"""Rotational drag (forceModels (rotationalDrag), demPimpleFoam): the viscous
torque on a sphere turning relative to the fluid,
    T = rho/2 (d/2)^5 C_R |Omega| Omega,  Omega = curl(U)/2 - omega_p,
    Re_r = |Omega| d^2/nu,  C_R = 64 pi/Re_r (Re_r <= 32),
                            12.9/Re_r^0.5 + 128.4/Re_r (Re_r > 32)
(Dennis, Singh & Ingham 1980, J. Fluid Mech. 101:257; the first branch is
the Stokes torque 8 pi mu (d/2)^3 Omega).

No gravity; the particle does not translate (and touches nothing: its
material is soft only so that the DEM's contact-stability check allows the
step). Checked against references
that do not come from the code (tolerances stated):
  1. Stokes spin-down (d 2 mm, rho_p 2500, fluid 1000 kg/m3, nu 1e-5,
     omega0 5 rad/s, Re_r 2): omega = omega0 exp(-t/tau),
     tau = rho_p d^2/(60 mu) = 16.7 ms; coupling step 0.1 ms; every write
     within 1e-6 of omega0 (the torque's mean over a coupling interval
     is that of the exact decay for a sphere, so only round-off is left:
     measured 1e-15).
  2. The same with a coupling step of 20 ms = 1.2 tau: an explicit torque
     would reverse the spin in the first step (1 - 1.2 = -0.2); the model
     takes the interval's mean of the decay, so omega at the coupling times
     is still omega0 exp(-t/tau) (1e-6 of omega0; measured 1e-14) and
     never changes sign.
  3. Moderate Re_r (d 20 mm, rho_p 100, water nu 1e-6, omega0 2 rad/s,
     Re_r 800 -> 390): omega(t) against the ODE
     I domega/dt = -rho/2 (d/2)^5 C_R(Re_r) omega^2, I = m d^2/10,
     integrated here (RK4, 1e-4 s); every write within 2e-3 of omega0
     (measured 1.8e-4: C_R frozen over each 1 ms coupling step).
  4. Simple shear (plane Couette, gamma = 1/s, water; walls at y = +-10 mm
     moving at +-10 mm/s, cyclic in x and z): a free sphere of d 1 mm at
     the centre plane, neutrally buoyant, spins up to the fluid's rotation,
     omega_z = -gamma/2 (Jeffery 1922 for a sphere in Stokes flow), as
     -gamma/2 (1 - exp(-t/tau)); every write within 2e-3 of gamma/2
     (measured 9e-6: the particle's void fraction perturbs the Couette
     flow a little).
Without the model the spin stays at omega0 (1-3) or at zero (4): all fail.
"""
import math
import os

import hedracase as hc
import vofcase as vc  # noqa: F401 (puts tutorials/demInterFoam/common on the path)
import demState

NOG = (0.0, 0.0, 0.0)
COUPLING = """formulation setI;
momentumCoupling implicit;
voidFractionModel divided;
forceModels (rotationalDrag);
"""


def list_particle(position, omega):
    p = "({} {} {})".format(*position)
    w = "({} {} {})".format(*omega)
    return f"""    one
    {{
        type list; particleType beads;
        particles ( {{ position {p}; omega {w}; }} );
    }}"""


def spin_series(case, axis=2):
    out = []
    for t, d in demState.times(case):
        p = demState.read_state(os.path.join(case, d, "polyDEM", "state"))["particles"][0]
        out.append((t, p["w" + "xyz"[axis]]))
    return out


def quiescent_case(name, box, n, nu, rho, rhoP, d, omega0, end, dt, write, demDt):
    case = hc.workdir(f"rotationalDrag-{name}")
    hc.block_mesh(case, (0, 0, 0), (box, box, box), (n, n, n),
                  {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])})
    hc.control_dict(case, end, dt, write)
    hc.schemes_solution(case)
    hc.transport(case, nu, rho, g=NOG)
    hc.fields(case, {"walls": "type noSlip;"}, {"walls": "type fixedFluxPressure;"})
    c = (0.5 * box + 1.3e-4, 0.5 * box - 0.7e-4, 0.5 * box + 0.4e-4)
    hc.dem_properties(case, demDt, rhoP, d, {"floor": ((0, 0, 0), (0, 0, 1))},
                      list_particle(c, (0, 0, omega0)), E=5e4, gravity=NOG)
    hc.coupling(case, COUPLING)
    hc.run("blockMesh", case, "log.blockMesh")
    hc.run("demPimpleFoam", case, "log.demPimpleFoam")
    return spin_series(case)


def c_r(Re):
    return 64 * math.pi / Re if Re <= 32 else 12.9 / math.sqrt(Re) + 128.4 / Re


def ode_spin(omega0, d, rhoP, rho, nu, times, h=1e-4):
    """omega(t) of I domega/dt = -rho/2 (d/2)^5 C_R omega|omega| (RK4)."""
    I = 0.1 * rhoP * math.pi * d ** 3 / 6 * d * d

    def f(w):
        if w == 0:
            return 0.0
        return -0.5 * rho * (0.5 * d) ** 5 * c_r(abs(w) * d * d / nu) * w * abs(w) / I

    out, w, t = [], omega0, 0.0
    for tt in times:
        while t < tt - 1e-12:
            s = min(h, tt - t)
            k1 = f(w)
            k2 = f(w + 0.5 * s * k1)
            k3 = f(w + 0.5 * s * k2)
            k4 = f(w + s * k3)
            w += s / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            t += s
        out.append(w)
    return out


def check_series(label, series, ref, scale, tol, results):
    worst, at = 0.0, 0.0
    for (t, w), r in zip(series, ref):
        e = abs(w - r) / scale
        if e > worst:
            worst, at = e, t
    ok = worst <= tol and len(series) >= 3
    results.append(ok)
    print(f"{'PASS' if ok else 'FAIL'}: {label}: largest |omega - ref| {worst:.3g} of"
          f" {scale:g} rad/s at t = {at:g} s over {len(series)} writes (tolerance {tol:g});"
          f" at the end {series[-1][1]:.6g} vs {ref[-1]:.6g} rad/s")


results = []

# 1., 2. Stokes spin-down, small and large coupling step
d, rhoP, rho, nu, w0 = 2e-3, 2500.0, 1000.0, 1e-5, 5.0
tau = rhoP * d * d / (60 * rho * nu)
print(f"Stokes: tau = {tau:.6g} s, Re_r = {w0*d*d/nu:g}")
for name, dt, write in (("stokes", 1e-4, 5e-3), ("stokesLargeStep", 0.02, 0.02)):
    series = [(0.0, w0)] + quiescent_case(name, 0.02, 4, nu, rho, rhoP, d, w0, 0.1, dt, write, 1e-4)
    ref = [w0 * math.exp(-t / tau) for t, _ in series]
    check_series(f"{name}: omega = omega0 exp(-t/tau), coupling step {dt:g} s"
                 f" = {dt/tau:.3g} tau", series, ref, w0, 1e-6, results)
    if name == "stokesLargeStep":
        ok = all(w > 0 for _, w in series)
        results.append(ok)
        print(f"{'PASS' if ok else 'FAIL'}: {name}: the spin never reverses"
              f" (smallest {min(w for _, w in series):.4g} rad/s)")

# 3. Moderate rotational Reynolds number (second branch of C_R)
d, rhoP, rho, nu, w0 = 0.02, 100.0, 1000.0, 1e-6, 2.0
series = [(0.0, w0)] + quiescent_case("dennis", 0.1, 5, nu, rho, rhoP, d, w0, 1.0, 1e-3, 0.1, 1e-4)
ref = ode_spin(w0, d, rhoP, rho, nu, [t for t, _ in series])
print(f"Dennis: Re_r from {w0*d*d/nu:g} to {series[-1][1]*d*d/nu:.4g}")
check_series("Re_r 800: omega(t) against the C_R(Re_r) ODE", series, ref, w0, 2e-3, results)

# 4. Simple shear: a free sphere spins at half the fluid's vorticity
h, Uw, nu, rho, d = 0.01, 0.01, 1e-6, 1000.0, 1e-3
gamma = Uw / h
tau = rho * d * d / (60 * rho * nu)
case = hc.workdir("rotationalDrag-shear")
L, n = 0.02, (4, 8, 4)
hc.couette_case(case, h, L, n, gamma, nu, rho)
hc.control_dict(case, 0.1, 1e-3, 0.01)
c = (0.5 * L + 1.3e-4, 0.0, 0.5 * L - 0.6e-4)
hc.dem_properties(case, 1e-4, rho, d, {"floor": ((0, -h, 0), (0, 1, 0))},
                  list_particle(c, (0, 0, 0)), E=5e3, gravity=NOG)
hc.coupling(case, COUPLING)
hc.run("blockMesh", case, "log.blockMesh")
hc.run("demPimpleFoam", case, "log.demPimpleFoam")
series = [(0.0, 0.0)] + spin_series(case)
ref = [-0.5 * gamma * (1 - math.exp(-t / tau)) for t, _ in series]
print(f"shear: gamma = {gamma:g} 1/s, tau = {tau:.4g} s, Re_r = {0.5*gamma*d*d/nu:g}")
check_series("simple shear: omega_z -> -gamma/2 as -gamma/2 (1 - exp(-t/tau))",
             series, ref, 0.5 * gamma, 2e-3, results)

hc.finish(results)
