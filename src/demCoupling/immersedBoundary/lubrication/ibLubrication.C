/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ibLubrication.H"
#include "mathematicalConstants.H"
#include "polyDEM/Config.hpp"
#include "polyDEM/MeshQueries.hpp"
#include "polyDEM/Quaternion.hpp"

namespace
{
Foam::vector toV(const polydem::Vec3& v)
{
    return Foam::vector(v.x, v.y, v.z);
}
polydem::Vec3 toP(const Foam::vector& v)
{
    return polydem::Vec3{v.x(), v.y(), v.z()};
}

//- Rigid motion of a wall at time t: x(t) = place(x(0)), and back
struct WallFrame
{
    const polydem::WallMotion& m;
    double t;

    polydem::Quaternion R() const
    {
        const polydem::Vec3 a = m.axis/norm(m.axis);
        return polydem::fromRotationVector((m.omega*t)*a);
    }

    Foam::vector forward(const Foam::vector& y) const
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return y + t*toV(m.velocity);
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            return toV(m.origin + polydem::rotate(R(), toP(y) - m.origin));
        }
        return y;
    }

    Foam::vector backward(const Foam::vector& x) const
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return x - t*toV(m.velocity);
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            return toV
            (
                m.origin + polydem::rotateInverse(R(), toP(x) - m.origin)
            );
        }
        return x;
    }

    Foam::vector rotateNormal(const Foam::vector& n) const
    {
        if (m.kind == polydem::MotionKind::rotation)
        {
            return toV(polydem::rotate(R(), toP(n)));
        }
        return n;
    }

    //- Velocity of the wall's material point now at x
    Foam::vector velocity(const Foam::vector& x) const
    {
        if (m.kind == polydem::MotionKind::translation)
        {
            return toV(m.velocity);
        }
        if (m.kind == polydem::MotionKind::rotation)
        {
            const Foam::vector a = toV(m.axis/norm(m.axis));
            return (m.omega*a) ^ (x - toV(m.origin));
        }
        return Foam::Zero;
    }
};
}


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
    const polydem::SimulationConfig* walls,
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

    if (!walls_ || !walls)
    {
        return F;
    }

    forAll(bodies, i)
    {
        const ibBody& b = bodies[i];
        const scalar R = equivalentRadius(b);
        const scalar hc = cutoff_*R;

        auto add = [&](const vector& n, scalar h, const vector& Uw)
        {
            const scalar un = (b.velocity - Uw) & n;
            const scalar c = coefficient(mu, R, R, h, b.mass, dt);
            F[i] -= c*un*n;
        };

        for (const polydem::PlaneWall& pl : walls->planes)
        {
            const WallFrame frame{pl.motion, time};
            const vector p = frame.forward(toV(pl.point));
            vector n = frame.rotateNormal(toV(pl.normal));
            n /= mag(n);
            const scalar dist = (b.position - p) & n;
            const scalar h = dist - R;
            if (h >= hc)
            {
                continue;
            }
            add(n, h, frame.velocity(b.position - dist*n));
        }

        for (const polydem::MeshWall& mw : walls->meshes)
        {
            const WallFrame frame{mw.motion, time};
            const vector y = frame.backward(b.position);
            scalar best = GREAT;
            vector closest(Zero);
            for (const auto& tri : mw.mesh.triangles)
            {
                const vector c = toV
                (
                    polydem::closestPointOnTriangle
                    (
                        toP(y),
                        mw.mesh.points[tri[0]],
                        mw.mesh.points[tri[1]],
                        mw.mesh.points[tri[2]]
                    )
                );
                const scalar dd = magSqr(y - c);
                if (dd < best)
                {
                    best = dd;
                    closest = c;
                }
            }
            const scalar dist = Foam::sqrt(best);
            if (best >= GREAT || dist - R >= hc || dist < VSMALL)
            {
                continue;
            }
            const vector c = frame.forward(closest);
            const vector n = (b.position - c)/mag(b.position - c);
            add(n, dist - R, frame.velocity(c));
        }
    }

    return F;
}


// ************************************************************************* //
