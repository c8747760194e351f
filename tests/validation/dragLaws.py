"""Reference drag correlations of the tests, written independently of the
force models under test (src/demCoupling/forceModels), so that a test
compares the solver's drag against the published formula.

  cd_sn: Schiller & Naumann (1933), C_d = 24/Re (1 + 0.15 Re^0.687) up to
         Re 1000, 0.44 above (Newton regime).
  cd_hl: Haider & Levenspiel (1989), non-spherical particles of sphericity
         phi, C_d = 24/Re (1 + A Re^B) + C / (1 + D/Re).
  terminal_velocity: the speed v at which a drag law balances the buoyant
         weight of a sphere-equivalent particle in fluid at rest,
         (rho_p - rho) g pi d^3/6 = 1/2 rho C_d(v d/nu) pi d^2/4 v^2
         (bisection on 1e-6..10 m/s).
"""
import math


def cd_sn(Re):
    return 24 / Re * (1 + 0.15 * Re**0.687) if Re < 1000 else 0.44


def cd_hl(Re, phi):
    A = math.exp(2.3288 - 6.4581 * phi + 2.4486 * phi**2)
    B = 0.0964 + 0.5565 * phi
    C = math.exp(4.905 - 13.8944 * phi + 18.4222 * phi**2 - 10.2599 * phi**3)
    D = math.exp(1.4681 + 12.2584 * phi - 20.7322 * phi**2 + 15.8855 * phi**3)
    return 24 / Re * (1 + A * Re**B) + C / (1 + D / Re)


def terminal_velocity(cd, d, rhoP, rho, nu, g=9.81):
    W = (rhoP - rho) * g * math.pi / 6 * d**3
    lo, hi = 1e-6, 10.0
    for _ in range(200):
        v = 0.5 * (lo + hi)
        F = 0.5 * rho * cd(v * d / nu) * math.pi / 4 * d**2 * v**2
        lo, hi = (v, hi) if F < W else (lo, v)
    return 0.5 * (lo + hi)
