#include "virtualMassForce.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(virtualMassForce);
}


Foam::virtualMassForce::virtualMassForce
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context),
    Cvm_(coeffs_.getOrDefault<scalar>("Cvm", 0.5))
{
    // A negative added-mass coefficient makes the particle lighter than
    // it is when it accelerates: unphysical and unstable
    if (Cvm_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Cvm " << Cvm_ << " in " << modelType << "Coeffs of "
            << dict.name() << " must be >= 0 (0.5 for a sphere)"
            << exit(FatalIOError);
    }
}


void Foam::virtualMassForce::cacheFields(const bool store)
{
    if (store)
    {
        // Material derivative of the fluid velocity
        const volVectorField& U = context_.U();
        const volVectorField DUDt(fvc::ddt(U) + (fvc::grad(U) & U));
        DUDtP_ = context_.sample(DUDt);
    }
    else
    {
        DUDtP_.clear();
    }
}


void Foam::virtualMassForce::addForce(const particleSample& s, particleForce& f) const
{
    const vector dUpdt =
        s.deltaT > 0 ? (s.Up - context_.previousVelocity(s.index))/s.deltaT
                     : vector::zero;
    f.Fcoupled += Cvm_*s.rho*s.Vp*(DUDtP_[s.index] - dUpdt);
}
