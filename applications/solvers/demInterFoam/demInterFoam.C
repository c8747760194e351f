/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           | www.openfoam.com
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2011-2017 OpenFOAM Foundation
-------------------------------------------------------------------------------
License
    This file is part of OpenFOAM.

    OpenFOAM is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    OpenFOAM is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.

    Hedra (2026): demInterFoam, derived from OpenFOAM v1912's interFoam.

Application
    demInterFoam

Group
    grpMultiphaseSolvers

Description
    interFoam (two incompressible, isothermal immiscible fluids, VOF with
    MULES, p_rgh, surface tension, turbulence, optional mesh motion and
    refinement) with particles from the DEM back end (demCloud,
    constant/couplingProperties). Unresolved / semi-resolved mode: the
    volume-averaged equations with the fluid fraction eps,
        ddt(eps alpha1) + div(phi alpha1) + compression = Sp alpha1,
            Sp = ddt(eps) + div(phi)      (alphaSuSp.H)
        ddt(eps) + div(phi) = 0           (pEqn.H; phi superficial)
        ddt(eps rho U) + div(rhoPhi U) - div(eps rho nuEff ...) =
            eps (f_sigma - gh grad rho - grad p_rgh) - Ksl U + S  (UEqn.H)
    Before alpha1 is transported the flux is projected on the new void
    fraction (couplingEvolve.H). Particles feel the drag laws of
    demPimpleFoam with rho and mu averaged over their own volume, and the
    pressure force with the buoyancy of their submerged volume
    (freeSurfacePressure). MULES' correction flux is dropped on the
    boundary faces it would pass unlimited (backflow through an outlet
    whose alpha1 follows the cell; dropUnlimitedBoundaryCorrection.H), so
    alpha1 stays in [0, 1] there too; and bounded in the cells MULES'
    iterated limiter left outside [0, 1] (boundAlphaCorrection.H,
    MULESBoundTolerance in the alpha1 solver dictionary, default 1e-10).
    All coupling calls: createCoupling.H,
    couplingEvolve.H, couplingWrite.H. Without particles the operations
    are interFoam's.

    couplingMode resolved (constant/couplingProperties; the default is
    unresolved): the particles are immersed bodies with their true shapes
    (spheres, convex polyhedra), the immersed boundary of demIbFoam
    (directForcingIB, subdictionary directForcing; ibParticles with the DEM
    through demBackend, entries as in demIbFoam's ibProperties) on
    interFoam's equations (eps = 1):
        ddt(alpha1) + div(phi alpha1) + compression = 0
        ddt(rho U) + div(rhoPhi U) - div(rho nuEff ...) =
            f_sigma - gh grad rho - grad p_rgh
          + rho fIB + mu beta (Us - U)                         (UEqn.H)
    fIB the kept forcing that drives U to the rigid-body velocity Us in the
    cells whose centre is inside a body, beta the penalisation of the
    interface cells (a Shortley-Weller wall on the true surface) with the
    local mu = rho nuEff: the forcing of demIbFoam times the local mixture
    density. After the PIMPLE loop (resolvedStep.H): U corrected to Us in
    the forced cells (no projection: phi stays pEqn.H's divergence-free
    flux, which MULES needs), the force on each body from integrating the
    rho U equation over its cells,
        F = - sum_c f_c V_c + d/dt sum_c rho_c lambda_c U_c V_c - M g,
        M = sum_c rho_c lambda_c V_c,
    (f_c the force density of the forcing on the fluid, lambda the solid
    fraction), i.e. the stress of the outside fluid on the surface,
    hydrostatics included: -M g takes out the weight of the fluid inside
    that the fluid equations carried, so the buoyancy is that of the
    pressure on the surface whatever alpha1 is inside, and nothing else is
    added (no Archimedes term). The water (couplingProperties solidAlpha
    excluded, the default; resolvedWaterFlux.H): the bodies are excluded
    from the phase-fraction equation, which transports the water in the
    fluid part of each cell, eps = max(1 - lambda, minFluidFraction), with
    the flux phiWater, the fluid's share of phi projected so that
    ddt(eps) + div(phiWater) = 0: the water outside the bodies,
    sum eps alpha1 V, is conserved to the solvers' tolerance as they move
    and cross the surface. The momentum equation's density is the fluid's
    in the fluid part of a cell and the level outside continued through
    the bodies (alphaBody) in theirs, with the old density of its own mass
    balance. Then the DEM is sub-cycled and the new mask built.
    Lubrication is not available in this mode (it needs a constant nu).
    On a refining mesh (dynamicRefineFvMesh on the field ibRefinement of
    ibRefinementIndicator: around the bodies, and with refinement
    { freeSurface yes; } along the free surface) the mask is rebuilt on the
    new cells and the old fluid fraction takes the re-sampling of the
    bodies (resolvedTopoChange.H).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "dynamicRefineFvMesh.H"
#include "CMULES.H"
#include "dropUnlimitedBoundaryCorrection.H"
#include "boundAlphaCorrection.H"
#include "couplingCorrectPhi.H"
#include "EulerDdtScheme.H"
#include "localEulerDdtScheme.H"
#include "CrankNicolsonDdtScheme.H"
#include "subCycle.H"
#include "immiscibleIncompressibleTwoPhaseMixture.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "CorrectPhi.H"
#include "fvcSmooth.H"
#include "upwind.H"
#include "gaussReconstruct.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "demCloud.H"
#include "directForcingIB.H"
#include "ibParticles.H"
#include "ibRefinementIndicator.H"
#include "demBackend.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Solver for two incompressible, isothermal immiscible fluids"
        " using VOF phase-fraction based interface capturing.\n"
        "With optional mesh motion and mesh topology changes including"
        " adaptive re-meshing."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createDynamicFvMesh.H"
    #include "initContinuityErrs.H"
    #include "createDyMControls.H"
    #include "createFields.H"
    #include "createAlphaFluxes.H"
    #include "initCorrectPhi.H"
    #include "createUfIfPresent.H"

    turbulence->validate();

    if (LTS)
    {
        // Local time stepping has no physical time, and the DEM needs one
        FatalErrorInFunction
            << "ddtSchemes localEuler (local time stepping) in "
            << mesh.time().system()/"fvSchemes" << " is not available in"
            << " demInterFoam: the particles need one physical time step;"
            << " use Euler (or CrankNicolson) with adjustTimeStep"
            << exit(FatalError);
    }

    if (!LTS)
    {
        #include "CourantNo.H"
        #include "setInitialDeltaT.H"
        if (adjustTimeStep && demStepNow() > 0)
        {
            // A whole number of DEM steps (setDeltaT.H)
            runTime.setDeltaT
            (
                demBackend::compatibleDeltaT
                (
                    runTime, runTime.deltaTValue(), demStepNow()
                ),
                false
            );
        }
    }

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readDyMControls.H"

        if (LTS)
        {
            #include "setRDeltaT.H"
        }
        else
        {
            #include "CourantNo.H"
            #include "alphaCourantNo.H"
            #include "setDeltaT.H"
        }

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            if (pimple.firstIter() || moveMeshOuterCorrectors)
            {
                if (ibRefinement && pimple.firstIter())
                {
                    // Where the bodies are at the start of the step (and
                    // the free surface)
                    ibRefinement->update(ibBodies->bodies(), &alpha1);
                }

                mesh.update();

                if (mesh.changing())
                {
                    // Do not apply previous time-step mesh compression flux
                    // if the mesh topology changed
                    if (mesh.topoChanging())
                    {
                        talphaPhi1Corr0.clear();

                        if (resolvedMode)
                        {
                            #include "resolvedTopoChange.H"
                        }

                        // Refinement: the mesh maps only registered fields.
                        // eps rho of the momentum equation is not (it is
                        // named rho for interFoam's scheme names), so it is
                        // rebuilt on the new cells, old time included, from
                        // the mapped void fraction and density; the face
                        // void fraction from the mapped cell values (the
                        // mesh has no values for the new faces)
                        rhoEps = eps*rho;
                        rhoEps.oldTime() = eps.oldTime()*rho.oldTime();
                        epsf = fvc::interpolate(eps);
                    }

                    gh = (g & mesh.C()) - ghRef;
                    ghf = (g & mesh.Cf()) - ghRef;

                    MRF.update();

                    if (correctPhi)
                    {
                        // Calculate absolute flux
                        // from the mapped surface velocity
                        phi = mesh.Sf() & Uf();

                        if (couplingActive)
                        {
                            // Superficial and relative to the moved mesh
                            // (createCoupling.H); the projection with the
                            // new void fraction follows (couplingEvolve.H)
                            phi *= epsf;
                            makeFluxRelative(phi);
                        }
                        else
                        {
                            #include "correctPhi.H"

                            // Make the flux relative to the mesh motion
                            fvc::makeRelative(phi, U);
                        }

                        mixture.correct();
                    }

                    if (checkMeshCourantNo)
                    {
                        #include "meshCourantNo.H"
                    }
                }
            }

            if (pimple.firstIter())
            {
                #include "couplingEvolve.H"
                #include "resolvedWaterFlux.H"
            }

            #include "alphaControls.H"
            #include "alphaEqnSubCycle.H"

            mixture.correct();

            if (pimple.frozenFlow())
            {
                continue;
            }

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

        #include "resolvedStep.H"
        #include "couplingWrite.H"

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
