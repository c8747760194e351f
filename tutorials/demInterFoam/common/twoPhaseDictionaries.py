"""The two-phase (water/air) dictionaries the demInterFoam tutorials share:
the dam breaks take all of them (write_two_phase_dictionaries), the
brash-ice channel its schemes (FV_SCHEMES) and write_laminar_gravity:
schemes, solvers (MULES with 20 limiter iterations, no
rest-state start of p_rgh), the phases, laminar flow, gravity. write is the
tutorial's own writer (its file header names the tutorial)."""


FV_SCHEMES = """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U)  Gauss linearUpwind grad(U);
    div(phi,alpha)  Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
"""


def write_laminar_gravity(case, write):
    """Laminar flow and gravity -z (every demInterFoam tutorial)."""
    write(f"{case}/constant/turbulenceProperties", "turbulenceProperties", "simulationType laminar;\n")
    write(f"{case}/constant/g", "g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n",
          cls="uniformDimensionedVectorField")


def write_two_phase_dictionaries(case, write, alpha_tolerance="1e-8", limiter_iter=20):
    """alpha_tolerance (text): of the implicit (MULESCorr) predictor, whose
    residual is what the water balance misses per step; limiter_iter: MULES
    limiter iterations"""
    write(f"{case}/system/fvSchemes", "fvSchemes", FV_SCHEMES)
    write(f"{case}/system/fvSolution", "fvSolution", """solvers
{
    "alpha.water.*"
    {
        nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1;
        // 20 limiter iterations: with 5 the water fraction left [0, 1] by
        // up to 1e-4 where the front runs through the rocks (measured in
        // damBreakRockPile; 4e-8 with 20, also with 1e-12 solver tolerances
        // it was 7e-5 with 5: the limiter, not the tolerances)
        MULESCorr yes; nLimiterIter LIMITER_ITER;
        solver smoothSolver; smoother symGaussSeidel; tolerance ALPHA_TOLERANCE; relTol 0;
    }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-9; relTol 0; }
    p_rgh { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 0.01; }
    p_rghFinal { $p_rgh; relTol 0; }
    "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0; }
}
PIMPLE
{
    momentumPredictor no;
    nOuterCorrectors 1;
    nCorrectors 2;
    nNonOrthogonalCorrectors 0;
    pRefCell 0;
    pRefValue 0;
    // No "discrete rest state" start of p_rgh: a released water column is
    // not at rest, and the rest-state p_rgh of a column with a vertical side
    // has a gradient in the air far from it that pushes the particles for
    // the first step (README, "Pressure at the start")
    hydrostaticInitialisation false;
}
""".replace("ALPHA_TOLERANCE", alpha_tolerance).replace("LIMITER_ITER", str(limiter_iter)))
    write(f"{case}/constant/transportProperties", "transportProperties", """phases (water air);
water { transportModel Newtonian; nu 1e-06; rho 1000; }
air { transportModel Newtonian; nu 1.48e-05; rho 1; }
sigma 0.07;
""")
    write_laminar_gravity(case, write)
