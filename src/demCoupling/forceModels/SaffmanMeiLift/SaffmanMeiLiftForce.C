#include "SaffmanMeiLiftForce.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(SaffmanMeiLiftForce);
}


Foam::SaffmanMeiLiftForce::SaffmanMeiLiftForce
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context)
{}


void Foam::SaffmanMeiLiftForce::cacheFields(const bool store)
{
    if (store)
    {
        // Vorticity of the fluid
        const volVectorField curlU(fvc::curl(context_.U()));
        curlUP_ = context_.sample(curlU);
    }
    else
    {
        curlUP_.clear();
    }
}


void Foam::SaffmanMeiLiftForce::addForce(const particleSample& s, particleForce& f) const
{
    const scalar nu = max(s.nu, VSMALL);
    const scalar Re = mag(s.Ur())*s.d/nu;
    const scalar Rew = mag(curlUP_[s.index])*sqr(s.d)/nu;
    const scalar b = 0.5*Rew/(Re + ROOTVSMALL);
    const scalar a = 0.3314*sqrt(b);
    const scalar fa = (1 - a)*exp(-0.1*Re) + a;
    const scalar Cld = Re < 40 ? 6.46*fa : 6.46*0.0524*sqrt(b*Re);
    const scalar Cl =
        3.0/(constant::mathematical::twoPi*sqrt(Rew + ROOTVSMALL))*Cld;
    f.Fcoupled += s.rho*s.Vp*Cl*(s.Ur() ^ curlUP_[s.index]);
}
