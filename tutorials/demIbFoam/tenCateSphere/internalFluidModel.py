#!/usr/bin/env python3
"""Lumped model of one demIbFoam step, to see which internal-fluid
treatment (ibParticles: internalFluid) keeps the coupling stable at low
density ratios rho_p/rho_f. Not a simulation: a linear caricature.

Masses per unit rho_f V_p: fluid inside the body m_f = 1, outer fluid that
moves with it (added mass) m_a = 0.5, particle m_p = rho_p/rho_f; linear drag
c W; gravity on the DEM side. One step, as in demIbFoam.C:
  fluid step (kept forcing G):  U* = W + (G - c W) dt/(m_f + m_a)
  IB correction to U_p:         G += m_f (U_p - U*)/dt
  projection (pressure impulse shared with the outer fluid):
                                W = (m_f U_p + m_a U*)/(m_f + m_a)
  DEM:  m_p dU_p/dt = -G + F_int + (m_p - m_f) g
with F_int:
  rigid      m_f (U_p^n - U_p^(n-1))/dt
  before     (P^n - P^(n-1))/dt,  P = m_f U*   (fluid before the correction)
  integrated (P^n - P^(n-1))/dt,  P = m_f W    (after correction+projection:
                                                what demIbFoam does)
Prints, per treatment, the density ratios at which it blows up (or ends
away from the terminal velocity (m_p - m_f) g/c) within 2000 steps.
"""


def run(ratio, mode, Ca=0.5, dt=0.004, n=2000, c=5.0, g=-9.81):
    mf, ma, mp = 1.0, Ca, ratio
    V = W = G = Vold = 0.0
    Pold = None
    for _ in range(n):
        Us = W + (G - c * W) * dt / (mf + ma)
        G += mf * (V - Us) / dt
        W = (mf * V + ma * Us) / (mf + ma)
        if mode == "rigid":
            Fint = mf * (V - Vold) / dt
        else:
            P = mf * (Us if mode == "before" else W)
            Fint = (P - (mf * V if Pold is None else Pold)) / dt
            Pold = P
        Vold = V
        V += dt / mp * (-G + Fint + (mp - mf) * g)
        if abs(V) > 1e6:
            return None
    return V


ratios = [round(0.2 + 0.05 * i, 2) for i in range(37)]
for mode in ("rigid", "before", "integrated"):
    bad = []
    for r in ratios:
        V = run(r, mode)
        if V is None or abs(V - (r - 1) * -9.81 / 5.0) > 1e-3 * (1 + abs(V)):
            bad.append(r)
    print("%-10s unstable or wrong at rho_p/rho_f = %s"
          % (mode, ", ".join("%g" % r for r in bad) if bad else "none of 0.2 .. 2"))
