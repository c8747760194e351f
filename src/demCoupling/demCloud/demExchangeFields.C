#include "demExchangeFields.H"
#include "smoothingModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demExchangeFields::demExchangeFields(const fvMesh& mesh)
:
    mesh_(mesh),
    voidfraction_
    (
        IOobject
        (
            "voidfraction",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedScalar("one", dimless, 1),
        "zeroGradient"
    ),
    Us_
    (
        IOobject("Us", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedVector(dimVelocity, Zero),
        "zeroGradient"
    ),
    Ksl_
    (
        IOobject("Ksl", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedScalar(dimDensity/dimTime, Zero),
        "zeroGradient"
    ),
    KslUs_
    (
        IOobject("KslUs", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE),
        mesh_,
        dimensionedVector(dimDensity*dimVelocity/dimTime, Zero),
        "zeroGradient"
    ),
    fExchange_
    (
        IOobject("fExchange", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedVector(dimForce/dimVolume, Zero),
        "zeroGradient"
    ),
    rotationSource_
    (
        IOobject("rotationSource", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE),
        mesh_,
        dimensionedVector(dimForce/dimVolume, Zero),
        "zeroGradient"
    ),
    particleMomentum_(Zero),
    fluidMomentum_(Zero)
{
    voidfraction_.oldTime();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demExchangeFields::updateVoidFraction
(
    const demCouplingWeights& weights,
    const List<scalar>& volume,
    const smoothingModel& smoothing,
    const scalar alphaMin
)
{
    computeVoidFraction(weights, volume, smoothing, alphaMin, voidfraction_);
}


void Foam::demExchangeFields::computeVoidFraction
(
    const demCouplingWeights& weights,
    const List<scalar>& volume,
    const smoothingModel& smoothing,
    const scalar alphaMin,
    volScalarField& result
) const
{
    const List<label>& start = weights.start();
    const List<label>& cellIndex = weights.cellIndex();
    const List<scalar>& weight = weights.weight();

    const scalarField& V = mesh_.V();
    volScalarField solid
    (
        IOobject("solidFraction", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    );
    scalarField& s = solid.primitiveFieldRef();
    forAll(volume, i)
    {
        for (label k = start[i]; k < start[i + 1]; ++k)
        {
            s[cellIndex[k]] += weight[k]*volume[i];
        }
    }
    s /= V;
    solid.correctBoundaryConditions();
    smoothing.smooth(solid);

    scalarField& a = result.primitiveFieldRef();
    a = max(1 - s, alphaMin);
    result.correctBoundaryConditions();
}


void Foam::demExchangeFields::update
(
    const demCouplingWeights& weights,
    const List<vector>& Up,
    const List<scalar>& volume,
    const List<scalar>& beta,
    const List<vector>& Fcoupled,
    const List<vector>& Uf,
    const volVectorField& U,
    const bool implicit,
    const smoothingModel& smoothing,
    const bool smoothFields,
    const demSolidRotation* rotation
)
{
    const List<label>& start = weights.start();
    const List<label>& cellIndex = weights.cellIndex();
    const List<scalar>& weight = weights.weight();
    const scalarField& V = mesh_.V();

    // What the particles get (drag and coupled forces; the particle-only
    // forces have no reaction in the fluid)
    vector particleSide(Zero);
    forAll(Up, i)
    {
        vector Fdrag = beta[i]*(Uf[i] - Up[i]);
        if (rotation)
        {
            Fdrag -= beta[i]*(rotation->omega[i] ^ rotation->meanArm[i]);
        }
        particleSide += Fdrag + Fcoupled[i];
    }
    const vectorField& C = mesh_.C().primitiveField();

    scalarField& K = Ksl_.primitiveFieldRef();
    vectorField& KU = KslUs_.primitiveFieldRef();
    vectorField& fE = fExchange_.primitiveFieldRef();
    vectorField& Us = Us_.primitiveFieldRef();
    vectorField& rot = rotationSource_.primitiveFieldRef();
    K = 0;
    KU = Zero;
    fE = Zero;
    Us = Zero;
    rot = Zero;
    scalarField solidV(mesh_.nCells(), scalar(0));
    forAll(Up, i)
    {
        const vector& Upi = Up[i];
        for (label k = start[i]; k < start[i + 1]; ++k)
        {
            const label c = cellIndex[k];
            const scalar w = weight[k];

            // The solid's velocity in this cell and the fluid velocity the
            // drag acts on (rigidBody: the cell's own; centre: the
            // particle's mean)
            vector Useenk = Uf[i];
            vector turning = Zero;
            if (rotation)
            {
                turning =
                    rotation->omega[i] ^ (C[c] - rotation->position[i]);
                Useenk = U[c] + rotation->shift[i];
                rot[c] += w*beta[i]*turning;
            }
            const vector Usk = Upi + turning;
            const vector Fexp =
                implicit
              ? Fcoupled[i]
              : Fcoupled[i] + beta[i]*(Useenk - Upi);
            K[c] += w*beta[i];
            KU[c] += w*beta[i]*Upi;
            fE[c] -= w*Fexp;
            if (implicit)
            {
                // Deferred correction: with the implicit -Ksl U the fluid
                // gets exactly -beta (Useen - Us) at the coupling time
                fE[c] += w*beta[i]*(U[c] - Useenk);
            }
            Us[c] += w*volume[i]*Usk;
            solidV[c] += w*volume[i];
        }
    }
    forAll(Us, c)
    {
        if (solidV[c] > 0)
        {
            Us[c] /= solidV[c];
        }
    }

    // Momentum balance of the exchange (before smoothing, which keeps the
    // integrals only to its solver tolerance)
    vector fluidSide(Zero);
    forAll(K, c)
    {
        vector s = fE[c] + rot[c];
        if (implicit)
        {
            s += KU[c] - K[c]*U[c];
        }
        fluidSide += s;
    }
    reduce(fluidSide, sumOp<vector>());
    particleMomentum_ = particleSide;
    fluidMomentum_ = fluidSide;

    K /= V;
    KU /= V;
    fE /= V;
    rot /= V;
    rotationSource_.correctBoundaryConditions();
    Ksl_.correctBoundaryConditions();
    KslUs_.correctBoundaryConditions();
    fExchange_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();

    if (smoothing.active() && smoothFields)
    {
        smoothing.smooth(Ksl_);
        smoothing.smooth(KslUs_);
        smoothing.smooth(fExchange_);
        if (rotation)
        {
            smoothing.smooth(rotationSource_);
        }
    }
}


Foam::scalar Foam::demExchangeFields::balanceError() const
{
    const scalar scale = max(mag(particleMomentum_), mag(fluidMomentum_));
    return
        scale > 0 ? mag(particleMomentum_ + fluidMomentum_)/scale : 0;
}


Foam::tmp<Foam::volScalarField> Foam::demExchangeFields::KslByRho
(
    const scalar rho,
    const bool implicit
) const
{
    if (implicit)
    {
        return Ksl_/dimensionedScalar("rho", dimDensity, rho);
    }
    return tmp<volScalarField>::New
    (
        IOobject("KslByRho", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(Ksl_.dimensions()/dimDensity, Zero)
    );
}


Foam::tmp<Foam::volVectorField> Foam::demExchangeFields::explicitSourceByRho
(
    const scalar rho,
    const bool implicit
) const
{
    const dimensionedScalar rhoD("rho", dimDensity, rho);
    if (implicit)
    {
        return (KslUs_ + fExchange_)/rhoD;
    }
    return fExchange_/rhoD;
}


Foam::tmp<Foam::volScalarField> Foam::demExchangeFields::implicitCoefficient
(
    const bool implicit
) const
{
    if (implicit)
    {
        return tmp<volScalarField>::New("implicitCoefficient", Ksl_);
    }
    return tmp<volScalarField>::New
    (
        IOobject("implicitCoefficient", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(Ksl_.dimensions(), Zero)
    );
}


Foam::tmp<Foam::volVectorField> Foam::demExchangeFields::explicitSource
(
    const bool implicit
) const
{
    if (implicit)
    {
        return KslUs_ + fExchange_;
    }
    return tmp<volVectorField>::New("explicitSource", fExchange_);
}
