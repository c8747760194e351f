/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Application
    demPimpleFoam

Description
    Unresolved (volume-averaged) CFD-DEM: PIMPLE solver of the
    volume-averaged incompressible Navier-Stokes equations coupled to a DEM
    back end (polyDEM) through demCloud (constant/couplingProperties).

    Fluid (alpha = voidfraction, U interstitial, p kinematic incl. the
    hydrostatic part, Ksl exchange coefficient):
        ddt(alpha) + div(alpha U) = 0
        ddt(alpha U) + div(alpha U U) - div(alpha nuEff dev(grad U ...))
          = - a grad(p) + alpha g - Ksl/rho (U - Us) + fExchange/rho
        a = alpha  formulation setI  (pressure shared by both phases)
        a = 1      formulation setII (fluid pressure only; pressure-gradient
                   and viscous forces on the particles fed back)
    (Zhou et al. 2010, J. Fluid Mech. 661:482; CFDEM cfdemSolverPiso models
    A/B). Laminar or any incompressible turbulence model, phase-weighted as
    in DPMFoam. Writes voidfraction, Us, Ksl, fExchange.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pimpleControl.H"
#include "demCloud.H"
#include "demBackend.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Unresolved CFD-DEM: volume-averaged PIMPLE fluid coupled to polyDEM"
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    demBackend::refuseAdjustTimeStep(runTime, "demPimpleFoam");
    #include "createMesh.H"
    #include "createControl.H"
    #include "createFields.H"

    scalar cumulativeContErr = 0;

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "CourantNo.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        laminarTransport.correct();

        // DEM sub-steps, particles, void fraction, forces, exchange fields
        particleCloud.evolve(laminarTransport.nu(), turbulence->nuEff(), alphaPhi);

        voidfractionf = fvc::interpolate(voidfraction);
        alphaPhi = voidfractionf*phi;

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            #include "UEqn.H"

            // --- Pressure corrector loop
            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            if (pimple.turbCorr())
            {
                turbulence->correct();
            }
        }

        particleCloud.write();
        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
