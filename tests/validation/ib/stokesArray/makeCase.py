#!/usr/bin/env python3
"""Write the Stokes-flow case: a fixed sphere (d = 1) at the centre of a
periodic cube (simple cubic array), fluid driven by a uniform body force G
along x (system/fvOptions, vectorSemiImplicitSource), nu = rho = 1.

Usage: makeCase.py [--c C] [--n N] [--dt DT] [--end T] [--G G]
  --c    solid volume fraction pi d^3 / (6 L^3)      (default 0.125)
  --n    cells per diameter (the cube gets round(N L / d) cells per side)
  --dt   time step (default: viscous number nu dt / dx^2 = 0.5)
  --end  end time (default 2.5 L^2 / nu, several viscous times of the cube)
  --G    body force per unit mass (default 0.1: Re = U d / nu ~ 0.01)
  --nSub, --threshold, --interface: directForcing entries (constant/ibProperties)
"""
import argparse
import math
import os

ap = argparse.ArgumentParser()
ap.add_argument("--c", type=float, default=0.125)
ap.add_argument("--n", type=float, default=8)
ap.add_argument("--dt", type=float, default=None)
ap.add_argument("--end", type=float, default=None)
ap.add_argument("--G", type=float, default=0.1)
ap.add_argument("--nSub", type=int, default=4)
ap.add_argument("--threshold", type=float, default=0.5)
ap.add_argument("--interface", default=None,
                help="explicit | penalised | none (default: the solver's)")
a = ap.parse_args()
for folder in ("system", "constant"):
    os.makedirs(folder, exist_ok=True)

d, nu = 1.0, 1.0
L = d * (math.pi / (6 * a.c)) ** (1.0 / 3.0)
n = max(4, round(a.n * L / d))
dx = L / n
dt = a.dt if a.dt else 0.5 * dx * dx / nu
end = a.end if a.end else 2.5 * L * L / nu
nSteps = round(end / dt)
end = nSteps * dt
h = 0.5 * L

with open("system/blockMeshDict", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
// makeCase.py: c = %g, L = %.10g, %d cells per side (d/dx = %.4g)
scale 1;
vertices
(
    (-%.12g -%.12g -%.12g) (%.12g -%.12g -%.12g) (%.12g %.12g -%.12g) (-%.12g %.12g -%.12g)
    (-%.12g -%.12g %.12g) (%.12g -%.12g %.12g) (%.12g %.12g %.12g) (-%.12g %.12g %.12g)
);
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
boundary
(
    xmin { type cyclic; neighbourPatch xmax; faces ((0 4 7 3)); }
    xmax { type cyclic; neighbourPatch xmin; faces ((1 2 6 5)); }
    ymin { type cyclic; neighbourPatch ymax; faces ((0 1 5 4)); }
    ymax { type cyclic; neighbourPatch ymin; faces ((3 7 6 2)); }
    zmin { type cyclic; neighbourPatch zmax; faces ((0 3 2 1)); }
    zmax { type cyclic; neighbourPatch zmin; faces ((4 5 6 7)); }
);
""" % ((a.c, L, n, d / dx) + (h,) * 24 + (n, n, n)))

with open("system/controlDict", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
// makeCase.py: viscous number nu dt / dx^2 = %.4g, %d steps
application     demIbFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %.12g;
deltaT          %.12g;
writeControl    runTime;
writeInterval   %.12g;
writeFormat     ascii;
writePrecision  12;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
""" % (nu * dt / dx**2, nSteps, end, dt, end))

with open("system/fvOptions", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }
// uniform driving force per unit mass along x: the mean pressure gradient
// of flow through the periodic array
drivingForce
{
    type            vectorSemiImplicitSource;
    selectionMode   all;
    volumeMode      specific;
    injectionRateSuSp
    {
        U           ((%.12g 0 0) 0);
    }
}
""" % a.G)

with open("constant/transportProperties", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
nu  %g;
rho 1;
""" % nu)

with open("constant/ibProperties", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object ibProperties; }
demBackend fixed;
directForcing
{%s
    nSubSamples        %d;
    pressureCorrection true;
    nCorrections       1;
    integralForcing    true;
    integralThreshold  %g;
}
bodies
(
    { shape sphere; radius %g; position (0 0 0); velocity (0 0 0); omega (0 0 0); }
);
""" % ("\n    interface          %s;" % a.interface if a.interface else "",
   a.nSub, a.threshold, 0.5 * d))

print("c %g: L %.6g, %d^3 cells, d/dx %.4g, dt %.4g (nu dt/dx^2 %.3g), %d steps"
      % (a.c, L, n, d / dx, dt, nu * dt / dx**2, nSteps))
