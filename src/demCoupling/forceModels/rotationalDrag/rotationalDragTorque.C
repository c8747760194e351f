#include "rotationalDragTorque.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "mathematicalConstants.H"

namespace Foam
{
    makeForceModel(rotationalDragTorque);
}


Foam::rotationalDragTorque::rotationalDragTorque
(
    const word& modelType,
    const dictionary& dict,
    const forceModelContext& context
)
:
    forceModel(modelType, dict, context)
{}


Foam::scalar Foam::rotationalDragTorque::coefficient(const scalar Rer)
{
    const scalar Re = max(Rer, VSMALL);
    if (Re <= 32)
    {
        return 64*constant::mathematical::pi/Re;
    }
    return 12.9/sqrt(Re) + 128.4/Re;
}


void Foam::rotationalDragTorque::cacheFields(const bool store)
{
    if (store)
    {
        const volVectorField curlU(fvc::curl(context_.U()));
        curlUP_ = context_.sample(curlU);
    }
    else
    {
        curlUP_.clear();
    }
}


void Foam::rotationalDragTorque::addForce
(
    const particleSample& s,
    particleForce& f
) const
{
    const vector Omega = 0.5*curlUP_[s.index] - s.omega;
    const scalar magOmega = mag(Omega);
    if (magOmega < VSMALL || s.d <= 0)
    {
        return;
    }

    const scalar nu = max(s.nu, VSMALL);
    const scalar Rer = magOmega*sqr(s.d)/nu;

    // T = c Omega, c [N m s]: rho/2 (d/2)^5 C_R |Omega|; in the Stokes
    // branch this is 8 pi mu (d/2)^3 whatever |Omega|
    const scalar c = 0.5*s.rho*pow5(0.5*s.d)*coefficient(Rer)*magOmega;

    // Mean over the coupling interval of the decay the torque drives in a
    // sphere of the particle's mass and d (see the header)
    scalar factor = 1;
    const scalar inertia = 0.1*s.rhoP*s.Vp*sqr(s.d);
    if (s.deltaT > 0 && inertia > 0)
    {
        const scalar x = c*s.deltaT/inertia;
        factor = x < 1e-6 ? 1 - 0.5*x : (1 - exp(-x))/x;
    }

    f.Tparticle += factor*c*Omega;
}
