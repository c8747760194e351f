#include "demCloudIO.H"
#include "demExchangeFields.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "Map.H"
#include <fstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCloudIO::demCloudIO(const Time& runTime)
:
    time_(runTime),
    summary_(),
    clock_(),
    timeDem_(0),
    timeParticles_(0),
    timeForces_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demCloudIO::openSummary()
{
    if (!Pstream::master())
    {
        return;
    }
    const fileName dir
    (
        time_.globalPath()/"postProcessing"/"demCloud"/time_.timeName()
    );
    mkDir(dir);
    summary_.reset(new OFstream(dir/"summary.dat"));
    summary_()
        << "# time nParticles nOutside Fx Fy Fz (total fluid force on"
        << " particles [N]) Pcx Pcy Pcz (coupled force on particles)"
        << " Sfx Sfy Sfz (exchange source in the fluid) relErr"
        << " Upx Upy Upz (mean particle velocity) xpx xpy xpz"
        << " (mean position) alphaMin weightCompletion (max |1 - sum w|"
        << " put in the centre cells)" << nl;
    summary_().precision(12);
}


void Foam::demCloudIO::writeSummary
(
    const demParticleArrays& particles,
    const List<vector>& force,
    const label nOutside,
    const demExchangeFields& exchange,
    const scalar weightCompletion
)
{
    if (!Pstream::master())
    {
        return;
    }
    const label n = particles.size();
    vector Ftot(Zero), Up(Zero), xp(Zero);
    forAll(force, i)
    {
        Ftot += force[i];
        Up += particles.velocity[i];
        xp += particles.position[i];
    }
    if (n)
    {
        Up /= n;
        xp /= n;
    }
    const vector& Pp = exchange.particleMomentum();
    const vector& Pf = exchange.fluidMomentum();

    OFstream& os = summary_();
    os  << time_.value() << ' ' << n << ' ' << nOutside << ' '
        << Ftot.x() << ' ' << Ftot.y() << ' ' << Ftot.z() << ' '
        << Pp.x() << ' ' << Pp.y() << ' ' << Pp.z() << ' '
        << Pf.x() << ' ' << Pf.y() << ' ' << Pf.z() << ' '
        << exchange.balanceError() << ' '
        << Up.x() << ' ' << Up.y() << ' ' << Up.z() << ' '
        << xp.x() << ' ' << xp.y() << ' ' << xp.z() << ' '
        << min(exchange.voidfraction().primitiveField()) << ' '
        << weightCompletion << nl;
    os.flush();
}


void Foam::demCloudIO::addTimes
(
    const scalar dem,
    const scalar particles,
    const scalar forces
)
{
    timeDem_ += dem;
    timeParticles_ += particles;
    timeForces_ += forces;
}
