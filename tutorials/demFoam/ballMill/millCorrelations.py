#!/usr/bin/env python3
"""Morrell's empirical charge-shape correlations and his continuum ("C")
model of the net power drawn by the charge of a tumbling mill.

Source: S. Morrell, "Power draw of wet tumbling mills and its relationship to
charge dynamics - Part 1: a continuum approach to mathematical modelling of
mill power draw", Trans. Instn Min. Metall. (Sect. C: Mineral Process. Extr.
Metall.) 105 (1996) C43-C53 ("Morrell (1996a)"; the charge-shape
correlations come from his PhD thesis, S. Morrell, "The prediction of power
draw in wet tumbling mills", University of Queensland, 1993, and are restated
in T.J. Napier-Munn, S. Morrell, R.D. Morrison, T. Kojovic, "Mineral
Comminution Circuits: Their Operation and Optimisation", JKMRC, 1996).
Neither the paper, the thesis nor the book was at hand, and the journal
volume and pages above are from memory, not checked. The formulae below were
taken from two secondary restatements that agree with each other (the Met
Dynamics wiki page "Tumbling Mill (Power, Morrell Continuum)", which cites
Morrell (1996a), for the power equation; a public implementation of the
model for the charge-shape correlations and the auxiliary quantities) and
checked for consistency (units, limits; see README.md). Where they differed
(the wiki's power equation lacks r_i in the second term of the
potential-energy bracket and the cube of the kinetic-energy factor) the
dimensionally consistent form is used.

Angles (radians) are measured as in chargeShape (src/demFunctionObjects/
chargeShape/chargeShape.H): from the horizontal through the axis on the
rising side of the shell, positive in the sense of rotation, so that a point
at angle theta is R sin(theta) above the axis. Morrell's angles satisfy the
same relations: his potential-energy term is rho_c (sin theta_S - sin
theta_T) g r, i.e. the height of the shoulder over the toe, with theta_S in
(0, pi/2) (shoulder above the horizontal on the rising side) and theta_T in
(pi, 3 pi/2) (toe below the horizontal on the falling side); both tend to
pi/2 (the top) as the mill centrifuges. So theta_chargeShape [deg] =
theta_Morrell [rad] * 180/pi, no offset or reflection.

Symbols: phi fraction of the theoretical critical speed (N_c = 42.3/sqrt(D)
rpm, D in m); J fractional filling of the mill by the charge, voids included
(Morrell's J_t); r_m shell inside radius [m]; L length [m]; rho_c density of
the charge (balls and voids; dry: the balls' mass over the bed volume)
[kg/m^3]; N_m rotational rate [rev/s].

    theta_T = 2.5307 (1.2796 - J) (1 - exp(-19.42 (phi_c - phi))) + pi/2
    theta_S = pi/2 - (theta_T - pi/2) [(0.3386 + 0.1041 phi)
                                      + (1.54 - 2.5673 phi) J]
    phi_c   = phi                    for phi > 0.35 (3.364 - J)
            = 0.35 (3.364 - J)       otherwise
    (phi_c: the fraction of critical speed at which the charge centrifuges)

Net power of the charge in the cylindrical part (dry: no slurry pool, the
slurry term rho_p (sin theta_T - sin theta_TO) is zero; no cone ends):

    P = pi g L N_m r_m / (3 (r_m - z r_i))
        [2 r_m^3 - 3 z r_m^2 r_i + r_i^3 (3 z - 2)] rho_c (sin theta_S - sin theta_T)
      + L rho_c (N_m r_m pi / (r_m - z r_i))^3 [(r_m - z r_i)^4 - r_i^4 (z - 1)^4]
    z   = (1 - J)^0.4532
    r_i = r_m sqrt(1 - 2 pi beta J / (2 pi + theta_S - theta_T))   (inner surface of the charge)
    beta = t_c / (t_f + t_c)
    t_c = (2 pi - theta_T + theta_S) / (2 pi N_bar),  N_bar = N_m / 2
    t_f = sqrt(2 r_bar (sin theta_S - sin theta_T) / g)
    r_bar = r_m / 2 (1 + sqrt(1 - 2 pi J / (2 pi + theta_S - theta_T)))

P is the net power of the charge's motion; Morrell's gross (motor) power is
no-load power + k P with k = 1.26 for industrial mills: neither the no-load
power nor k applies to the torque on a simulated shell, which is compared
with P. The correlations were fitted to wet tumbling mills (the paper's
title); whether their data include smooth shells or dry ball charges was not
checked (the thesis was not at hand; see README.md).
"""
import math

G = 9.81


def criticalRpm(D):
    """Theoretical critical speed [rpm] of a shell of inside diameter D [m]."""
    return 42.3 / math.sqrt(D)


def phiC(J):
    """Fraction of critical speed at which centrifuging is fully established."""
    return 0.35 * (3.364 - J)


def toeAngle(phi, J):
    """Morrell's toe angle theta_T [rad] (chargeShape convention)."""
    pc = max(phi, phiC(J))
    return (2.5307 * (1.2796 - J) * (1.0 - math.exp(-19.42 * (pc - phi)))
            + math.pi / 2)


def shoulderAngle(phi, J):
    """Morrell's shoulder angle theta_S [rad] (chargeShape convention)."""
    tT = toeAngle(phi, J)
    return (math.pi / 2
            - (tT - math.pi / 2) * ((0.3386 + 0.1041 * phi) + (1.54 - 2.5673 * phi) * J))


def netPower(D, L, J, phi, rhoC, g=G, shoulder=None, toe=None):
    """Morrell's C-model net power of the charge [W] of a dry cylindrical
    mill (no slurry pool, no cone ends): D, L [m], rhoC [kg/m^3]. The
    shoulder and toe angles [rad] are Morrell's correlations unless given
    (e.g. measured ones)."""
    rm = D / 2
    Nm = phi * criticalRpm(D) / 60.0
    tT = toeAngle(phi, J) if toe is None else toe
    tS = shoulderAngle(phi, J) if shoulder is None else shoulder
    arc = 2 * math.pi + tS - tT
    dh = math.sin(tS) - math.sin(tT)
    rBar = rm / 2 * (1 + math.sqrt(1 - 2 * math.pi * J / arc))
    tc = (2 * math.pi - tT + tS) / (2 * math.pi * Nm / 2)
    tf = math.sqrt(2 * rBar * dh / g)
    beta = tc / (tf + tc)
    ri = rm * math.sqrt(1 - 2 * math.pi * beta * J / arc)
    z = (1 - J) ** 0.4532
    a = rm - z * ri
    potential = (math.pi * g * L * Nm * rm / (3 * a)
                 * (2 * rm ** 3 - 3 * z * rm ** 2 * ri + ri ** 3 * (3 * z - 2))
                 * rhoC * dh)
    kinetic = L * rhoC * (Nm * rm * math.pi / a) ** 3 * (a ** 4 - ri ** 4 * (z - 1) ** 4)
    return potential + kinetic


if __name__ == "__main__":
    import sys
    # millCorrelations.py D J rhoC [L]: a table over 0.5-0.95 of critical
    D, J, rhoC = map(float, sys.argv[1:4])
    L = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
    print("# phi  rpm  shoulder[deg]  toe[deg]  P[kW] (L = %g m)" % L)
    for k in range(10):
        phi = 0.5 + 0.05 * k
        print("%.2f %7.3f %7.2f %7.2f %9.3f"
              % (phi, phi * criticalRpm(D), math.degrees(shoulderAngle(phi, J)),
                 math.degrees(toeAngle(phi, J)), netPower(D, L, J, phi, rhoC) / 1e3))
