/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "directForcingIB.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"

Foam::directForcingIB::directForcingIB
(
    const volVectorField& U,
    const volScalarField& p,
    const dictionary& dict
)
:
    mesh_(U.mesh()),
    nSub_(dict.getOrDefault<label>("nSubSamples", 4)),
    pressureCorrection_(dict.getOrDefault<bool>("pressureCorrection", true)),
    nCorrections_(dict.getOrDefault<label>("nCorrections", 1)),
    integral_(dict.getOrDefault<bool>("integralForcing", true)),
    integralThreshold_
    (
        dict.getOrDefault<scalar>("integralThreshold", 0.5)
    ),
    fIB_
    (
        IOobject
        (
            "fIB",
            mesh_.time().timeName(),
            mesh_,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedVector(dimAcceleration, Zero),
        "zeroGradient"
    ),
    cellMin_(mesh_.nCells()),
    cellMax_(mesh_.nCells()),
    cellHalfDiag_(mesh_.nCells()),
    lambda_
    (
        IOobject
        (
            "lambda",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    ),
    Us_
    (
        IOobject
        (
            "Us",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedVector(dimVelocity, Zero),
        "zeroGradient"
    ),
    cellBody_(mesh_.nCells(), -1),
    phiIB_
    (
        IOobject
        (
            "phiIB",
            mesh_.time().timeName(),
            mesh_,
            IOobject::READ_IF_PRESENT,  // the solver's initial guess: a
            IOobject::AUTO_WRITE        // restart continues bit for bit
        ),
        mesh_,
        dimensionedScalar(dimArea/dimTime, Zero),
        p.boundaryField().types()
    ),
    solidVolume_(0)
{
    if (nSub_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "nSubSamples must be >= 1, not " << nSub_ << exit(FatalIOError);
    }
    mesh_.setFluxRequired(phiIB_.name());
    updateCellBoxes();
}


void Foam::directForcingIB::updateCellBoxes()
{
    const pointField& pts = mesh_.points();
    const labelListList& cp = mesh_.cellPoints();
    cellMin_.setSize(mesh_.nCells());
    cellMax_.setSize(mesh_.nCells());
    cellHalfDiag_.setSize(mesh_.nCells());
    cellBody_.setSize(mesh_.nCells());
    forAll(cp, celli)
    {
        point lo(GREAT, GREAT, GREAT), hi(-GREAT, -GREAT, -GREAT);
        for (const label pi : cp[celli])
        {
            lo = min(lo, pts[pi]);
            hi = max(hi, pts[pi]);
        }
        cellMin_[celli] = lo;
        cellMax_[celli] = hi;
        cellHalfDiag_[celli] = 0.5*mag(hi - lo);
    }
}


Foam::scalar Foam::directForcingIB::cellFraction
(
    label celli,
    const ibBody& b
) const
{
    const point& lo = cellMin_[celli];
    const point& hi = cellMax_[celli];

    // All corners inside a convex body: the whole box is inside
    bool allIn = true;
    for (label k = 0; k < 8 && allIn; ++k)
    {
        const point c
        (
            (k & 1) ? hi.x() : lo.x(),
            (k & 2) ? hi.y() : lo.y(),
            (k & 4) ? hi.z() : lo.z()
        );
        allIn = b.inside(c);
    }
    if (allIn)
    {
        return 1;
    }

    const vector h = (hi - lo)/scalar(nSub_);
    label nIn = 0;
    for (label i = 0; i < nSub_; ++i)
    {
        for (label j = 0; j < nSub_; ++j)
        {
            for (label k = 0; k < nSub_; ++k)
            {
                const point x
                (
                    lo.x() + (i + 0.5)*h.x(),
                    lo.y() + (j + 0.5)*h.y(),
                    lo.z() + (k + 0.5)*h.z()
                );
                if (b.inside(x))
                {
                    ++nIn;
                }
            }
        }
    }
    return scalar(nIn)/scalar(nSub_*nSub_*nSub_);
}


void Foam::directForcingIB::update(const UList<ibBody>& bodies)
{
    // Refined or moved mesh (dynamicFvMesh): new cells, new boxes
    if (cellMin_.size() != mesh_.nCells() || mesh_.changing())
    {
        updateCellBoxes();
    }

    scalarField& lam = lambda_.primitiveFieldRef();
    vectorField& us = Us_.primitiveFieldRef();
    lam = 0;
    us = Zero;
    cellBody_ = -1;

    const vectorField& C = mesh_.C();

    forAll(bodies, bi)
    {
        const ibBody& b = bodies[bi];
        forAll(C, celli)
        {
            const scalar reach = b.radius + cellHalfDiag_[celli];
            if (magSqr(C[celli] - b.position) > reach*reach)
            {
                continue;
            }
            const scalar f = cellFraction(celli, b);
            // Overlapping bodies (contact): the larger share owns the cell
            if (f > lam[celli])
            {
                lam[celli] = f;
                cellBody_[celli] = bi;
                us[celli] = b.rigidVelocity(C[celli]);
            }
        }
    }

    lambda_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();

    // Cells a body has left (or now covers less than the threshold) carry
    // no kept forcing
    vectorField& fib = fIB_.primitiveFieldRef();
    forAll(fib, celli)
    {
        if (cellBody_[celli] < 0 || lam[celli] < integralThreshold_)
        {
            fib[celli] = Zero;
        }
    }
    fIB_.correctBoundaryConditions();

    solidVolume_ = gSum(lam*mesh_.V().field());
}


void Foam::directForcingIB::correctVelocity
(
    volVectorField& U,
    scalar rhoFluid,
    const UList<ibBody>& bodies
)
{
    force_.setSize(bodies.size());
    torque_.setSize(bodies.size());
    force_ = Zero;
    torque_ = Zero;

    const scalar dt = mesh_.time().deltaTValue();
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& lam = lambda_.primitiveField();
    const vectorField& us = Us_.primitiveField();
    vectorField& u = U.primitiveFieldRef();
    vectorField& fib = fIB_.primitiveFieldRef();

    forAll(u, celli)
    {
        const label bi = cellBody_[celli];
        if (bi < 0)
        {
            continue;
        }
        vector du = lam[celli]*(us[celli] - u[celli]);
        vector f = rhoFluid*du*V[celli]/dt;   // on the fluid
        if (integral_ && lam[celli] >= integralThreshold_)
        {
            // Kept forcing drives U to Us exactly: only in cells at least
            // integralThreshold inside, so that the blocked volume matches
            // the body's (with all cells lambda > 0 the body grows by
            // about one cell)
            du = us[celli] - u[celli];
            fib[celli] += du/dt;
            f = rhoFluid*fib[celli]*V[celli];
        }
        force_[bi] -= f;
        torque_[bi] -= (C[celli] - bodies[bi].position) ^ f;
        u[celli] += du;
    }
    U.correctBoundaryConditions();
    fIB_.correctBoundaryConditions();

    // Bodies spanning processors: sum the parts
    Pstream::listCombineGather(force_, plusEqOp<vector>());
    Pstream::listCombineScatter(force_);
    Pstream::listCombineGather(torque_, plusEqOp<vector>());
    Pstream::listCombineScatter(torque_);
}


void Foam::directForcingIB::bodyMomentum
(
    const volVectorField& U,
    const UList<ibBody>& bodies,
    List<vector>& P,
    List<vector>& L
) const
{
    P.setSize(bodies.size());
    L.setSize(bodies.size());
    P = Zero;
    L = Zero;

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& lam = lambda_.primitiveField();
    const vectorField& u = U.primitiveField();

    forAll(u, celli)
    {
        const label bi = cellBody_[celli];
        if (bi < 0)
        {
            continue;
        }
        const vector m = lam[celli]*V[celli]*u[celli];
        P[bi] += m;
        L[bi] += (C[celli] - bodies[bi].position) ^ m;
    }

    Pstream::listCombineGather(P, plusEqOp<vector>());
    Pstream::listCombineScatter(P);
    Pstream::listCombineGather(L, plusEqOp<vector>());
    Pstream::listCombineScatter(L);
}


void Foam::directForcingIB::correctPressure
(
    volVectorField& U,
    volScalarField& p,
    surfaceScalarField& phi
)
{
    if (!pressureCorrection_)
    {
        phi = fvc::flux(U);
        return;
    }

    const surfaceScalarField phiU(fvc::flux(U));

    fvScalarMatrix phiIBEqn
    (
        fvm::laplacian(phiIB_) == fvc::div(phiU)
    );
    if (phiIB_.needReference())
    {
        phiIBEqn.setReference(0, 0);
    }
    phiIBEqn.solve();

    phi = phiU - phiIBEqn.flux();
    U -= fvc::grad(phiIB_);
    U.correctBoundaryConditions();
    p += phiIB_/mesh_.time().deltaT();
    p.correctBoundaryConditions();
}


void Foam::directForcingIB::correct
(
    volVectorField& U,
    volScalarField& p,
    surfaceScalarField& phi,
    scalar rhoFluid,
    const UList<ibBody>& bodies
)
{
    List<vector> F(bodies.size(), Zero);
    List<vector> T(bodies.size(), Zero);
    for (label k = 0; k < max(nCorrections_, label(1)); ++k)
    {
        correctVelocity(U, rhoFluid, bodies);
        correctPressure(U, p, phi);
        forAll(F, i)
        {
            // integral forcing: force_ already holds the whole of fIB
            F[i] = integral_ ? force_[i] : F[i] + force_[i];
            T[i] = integral_ ? torque_[i] : T[i] + torque_[i];
        }
    }
    force_ = F;
    torque_ = T;
}


// ************************************************************************* //
