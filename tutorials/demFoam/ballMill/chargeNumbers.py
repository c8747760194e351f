#!/usr/bin/env python3
"""Ball numbers of the four size classes for a mill filling.

The filling J is the volume of the ball bed (balls and the voids between
them) over the shell's inside volume pi D^2/4 L; the bed's solid fraction is
taken as 0.6 (porosity 0.4, the usual value in mill filling definitions), so
the charge mass is M = J pi D^2/4 L 0.6 rho. Each class c (mass fraction f_c,
diameters uniform in [a, b]) gets N_c = f_c M / (rho pi/6 <d^3>), with
<d^3> = (b^4 - a^4) / (4 (b - a)).

Usage: chargeNumbers.py D L J scale
  prints 'class1 N1 class2 N2 class3 N3 class4 N4 M' (scale multiplies the
  seed's diameters: 1 the seed, 2 the reduced tutorial)
"""
import math
import sys

# The seed's classes (ballMill.md): diameter range [m], mass fraction
CLASSES = [((0.038, 0.040), 0.15), ((0.034, 0.038), 0.30),
           ((0.030, 0.034), 0.30), ((0.026, 0.030), 0.25)]
RHO = 7200.0
SOLID = 0.6

D, L, J, scale = map(float, sys.argv[1:5])
M = J * math.pi * D * D / 4 * L * SOLID * RHO
out = []
for k, ((a, b), f) in enumerate(CLASSES):
    a, b = a * scale, b * scale
    d3 = (b ** 4 - a ** 4) / (4 * (b - a))
    out.append("class%d %d" % (k + 1, round(f * M / (RHO * math.pi / 6 * d3))))
print(" ".join(out), "%.6g" % M)
