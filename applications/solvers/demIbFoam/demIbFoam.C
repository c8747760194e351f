/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Application
    demIbFoam

Description
    Resolved CFD-DEM: incompressible laminar PIMPLE fluid with the particles
    as immersed bodies (volume-fraction direct forcing, directForcingIB) and
    their motion from the polyDEM engine or held fixed (ibParticles,
    constant/ibProperties).

    Each time step:
      1. PIMPLE: ddt(U) + div(phi U) - div(nu grad U) = -grad(p) + fIB,
         (fIB: the IB's kept body force, zero unless integralForcing)
         div(U) = 0                                   (p kinematic)
         plus any fvOptions (system/fvOptions, e.g. a mean pressure gradient
         in a periodic box: vectorSemiImplicitSource or meanVelocityForce)
      2. IB: lambda, Us from the bodies' true shapes; U corrected to
         U_p + omega x r inside the bodies; projection (phiIB); fluid force
         and torque per body from the momentum of the correction
      3. DEM: setExternalForces(force, torque), sub-cycled over deltaT
    Writes lambda (solid fraction) and Us (rigid-body velocity field), and
    postProcessing/ibForces/<t0>/forces.dat.

    References: Uhlmann (2005) J. Comput. Phys. 209:448; Hager et al.
    (2014), CFDEM cfdemSolverIB; Kempe & Froehlich (2012) J. Comput. Phys.
    231:3663.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "pimpleControl.H"
#include "CorrectPhi.H"
#include "fvOptions.H"
#include "directForcingIB.H"
#include "ibParticles.H"
#include "ibRefinementIndicator.H"
#include "demBackend.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Resolved CFD-DEM: PIMPLE fluid with immersed-boundary particles"
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    demBackend::refuseAdjustTimeStep(runTime, "demIbFoam");
    #include "createDynamicFvMesh.H"
    #include "createDyMControls.H"
    #include "createFields.H"
    #include "createFvOptions.H"
    #include "createUfIfPresent.H"

    scalar cumulativeContErr = 0;

    ibParticles particles(mesh);
    directForcingIB ib
    (
        U,
        p,
        particles.dict().optionalSubDict("directForcing"),
        nu.value()
    );
    ib.update(particles.bodies());

    // Dynamic refinement around the bodies (constant/dynamicMeshDict with
    // dynamicRefineFvMesh and field ibRefinement); nothing when static
    autoPtr<ibRefinementIndicator> refinement;
    if (mesh.dynamic())
    {
        refinement.reset(new ibRefinementIndicator(mesh, particles.dict()));
    }

    Info<< "Resolved particles: " << particles.bodies().size()
        << ", solid volume on the mesh " << ib.solidVolume() << nl << endl;

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readDyMControls.H"
        #include "CourantNo.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        if (refinement)
        {
            // Refine where the bodies are now, unrefine where they were;
            // the fields are mapped, the flux made conservative again and
            // the solid mask rebuilt on the new cells
            refinement->update(particles.bodies());
            mesh.update();
            if (mesh.changing())
            {
                if (correctPhi)
                {
                    phi = mesh.Sf() & Uf();
                    CorrectPhi
                    (
                        U,
                        phi,
                        p,
                        dimensionedScalar("rAUf", dimTime, 1),
                        geometricZeroField(),
                        pimple
                    );
                    #include "continuityErrs.H"
                }
                ib.update(particles.bodies());
                Info<< "Mesh: " << returnReduce(mesh.nCells(), sumOp<label>())
                    << " cells" << endl;
            }
        }

        while (pimple.loop())
        {
            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }
        }

        // Immersed boundary: bodies at the start of the step
        ib.correct(U, p, phi, rhoFluid.value(), particles.bodies());
        fvc::correctUf(Uf, U, phi);

        // Fluid momentum inside the bodies at the end of the step
        // (internal-fluid inertia, ibParticles: internalFluid integrated)
        List<vector> Pin, Lin;
        ib.bodyMomentum(U, particles.bodies(), Pin, Lin);

        const List<vector> F(ib.force());
        const List<vector> T(ib.torque());
        if (F.size())
        {
            Info<< "IB: F[0] = " << F[0] << "  T[0] = " << T[0] << endl;
        }

        // DEM sub-cycled over the fluid step, then the new solid mask
        particles.evolve(F, T, rhoFluid.value(), Pin, Lin);
        ib.update(particles.bodies());

        particles.write();
        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}
