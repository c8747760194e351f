#include "forceModelContext.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::forceModelContext::forceModelContext
(
    const fvMesh& mesh,
    const demCloudSettings& settings,
    const scalar rho,
    const volVectorField& U,
    const volScalarField& p,
    const demCouplingWeights& weights,
    const List<vector>& previousUp
)
:
    mesh_(mesh),
    settings_(settings),
    rho_(rho),
    U_(U),
    p_(p),
    weights_(weights),
    previousUp_(previousUp),
    nuPtr_(nullptr),
    nuEffPtr_(nullptr),
    freeSurfacePtr_(nullptr)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::forceModelContext::setViscosity
(
    const volScalarField& nu,
    const volScalarField& nuEff
)
{
    nuPtr_ = &nu;
    nuEffPtr_ = &nuEff;
}


void Foam::forceModelContext::clearViscosity()
{
    nuPtr_ = nullptr;
    nuEffPtr_ = nullptr;
}


const Foam::volScalarField& Foam::forceModelContext::nu() const
{
    if (!nuPtr_)
    {
        FatalErrorInFunction
            << "No viscosity given to the force models yet"
            << " (setViscosity before cacheFields)" << exit(FatalError);
    }
    return *nuPtr_;
}


const Foam::volScalarField& Foam::forceModelContext::nuEff() const
{
    if (!nuEffPtr_)
    {
        FatalErrorInFunction
            << "No effective viscosity given to the force models yet"
            << " (setViscosity before cacheFields)" << exit(FatalError);
    }
    return *nuEffPtr_;
}
