/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ibLubrication.H"
#include "mathematicalConstants.H"


Foam::ibLubrication::ibLubrication(const dictionary& dict)
:
    model_(dict.getOrDefault<word>("model", "none")),
    cutoff_(dict.getOrDefault<scalar>("cutoff", 0.05)),
    minGap_(dict.getOrDefault<scalar>("minGap", 0.001)),
    walls_(dict.getOrDefault<bool>("walls", true)),
    implicit_(dict.getOrDefault<bool>("implicit", true))
{
    if (model_ != "none" && model_ != "Brenner")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown lubrication model " << model_
            << " (none | Brenner)" << exit(FatalIOError);
    }
    if (active() && (cutoff_ <= 0 || minGap_ <= 0 || minGap_ >= cutoff_))
    {
        FatalIOErrorInFunction(dict)
            << "lubrication needs 0 < minGap < cutoff (gaps over the smaller"
            << " radius), not minGap " << minGap_ << ", cutoff " << cutoff_
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::ibLubrication::equivalentRadius(const ibBody& b)
{
    if (b.polyhedron)
    {
        return cbrt(3*b.volume/(4*constant::mathematical::pi));
    }
    return b.radius;
}


Foam::scalar Foam::ibLubrication::coefficient
(
    scalar mu,
    scalar Reff,
    scalar Rmin,
    scalar h,
    scalar mEff,
    scalar dt
) const
{
    const scalar hc = cutoff_*Rmin;
    if (!active() || h >= hc)
    {
        return 0;
    }
    const scalar hEff = max(h, minGap_*Rmin);
    const scalar c =
        6*constant::mathematical::pi*mu*sqr(Reff)*(1/hEff - 1/hc);
    if (implicit_ && mEff > 0)
    {
        return c*mEff/(mEff + c*dt);
    }
    return c;
}


Foam::List<Foam::vector> Foam::ibLubrication::forces
(
    const UList<ibBody>& bodies,
    const demBackend* dem,
    scalar time,
    scalar mu,
    scalar dt
) const
{
    List<vector> F(bodies.size(), Zero);
    if (!active())
    {
        return F;
    }

    // Reduced mass (0: infinite)
    auto reduced = [](scalar a, scalar b)
    {
        if (a <= 0) return b;
        if (b <= 0) return a;
        return a*b/(a + b);
    };

    // Pairs
    forAll(bodies, i)
    {
        const ibBody& bi = bodies[i];
        const scalar Ri = equivalentRadius(bi);
        for (label j = i + 1; j < bodies.size(); ++j)
        {
            const ibBody& bj = bodies[j];
            const scalar Rj = equivalentRadius(bj);
            const vector d = bj.position - bi.position;
            const scalar dist = mag(d);
            const scalar Rmin = min(Ri, Rj);
            if (dist - Ri - Rj >= cutoff_*Rmin || dist < VSMALL)
            {
                continue;
            }
            const vector n = d/dist;
            const scalar h = dist - Ri - Rj;
            const scalar un = (bj.velocity - bi.velocity) & n;
            const scalar c = coefficient
            (
                mu, Ri*Rj/(Ri + Rj), Rmin, h, reduced(bi.mass, bj.mass), dt
            );
            const vector f = c*un*n;     // on i; -f on j
            F[i] += f;
            F[j] -= f;
        }
    }

    if (!walls_ || !dem)
    {
        return F;
    }

    forAll(bodies, i)
    {
        const ibBody& b = bodies[i];
        const scalar R = equivalentRadius(b);
        const scalar hc = cutoff_*R;

        // The DEM's walls at their position now, nearest points to the
        // centre (planes, then triangle meshes)
        for (const demWallPoint& w : dem->wallPoints(b.position, time))
        {
            const scalar h = w.distance - R;
            if (h >= hc)
            {
                continue;
            }
            const scalar un = (b.velocity - w.velocity) & w.normal;
            const scalar c = coefficient(mu, R, R, h, b.mass, dt);
            F[i] -= c*un*w.normal;
        }
    }

    return F;
}


// ************************************************************************* //
