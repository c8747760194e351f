// polyDEM: small geometric kernels shared by the back ends (host+device).
#pragma once

#include "polyDEM/Quaternion.hpp"
#include "polyDEM/Vec3.hpp"

namespace polydem
{
namespace detail
{

enum TriangleFeature
{
    featureFace = 0,
    featureEdge = 1,
    featureVertex = 2
};

//- Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5)
PD_HD inline Vec3 closestPointOnTriangle
(
    const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int& feature
)
{
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) { feature = featureVertex; return a; }
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) { feature = featureVertex; return b; }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        feature = featureEdge;
        return a + (d1 / (d1 - d3)) * ab;
    }
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) { feature = featureVertex; return c; }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        feature = featureEdge;
        return a + (d2 / (d2 - d6)) * ac;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        feature = featureEdge;
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    }
    const double denom = 1.0 / (va + vb + vc);
    feature = featureFace;
    return a + (vb * denom) * ab + (vc * denom) * ac;
}

//- Rigid prescribed motion of a wall at time t
struct RigidMotion
{
    int kind = 0;       //!< 0 fixed, 1 translation, 2 rotation (MotionKind)
    Vec3 velocity;
    Vec3 origin;
    Vec3 axis{0, 0, 1};
    double omega = 0;

    PD_HD Quaternion rotationAt(double t) const
    {
        return kind == 2 ? fromRotationVector((omega * t) * axis) : Quaternion{};
    }

    //- Body (t = 0) frame point -> world point at time t
    PD_HD Vec3 toWorld(const Vec3& y, double t, const Quaternion& R) const
    {
        if (kind == 1) return y + t * velocity;
        if (kind == 2) return origin + rotate(R, y - origin);
        return y;
    }

    //- World point at time t -> body (t = 0) frame point
    PD_HD Vec3 toBody(const Vec3& x, double t, const Quaternion& R) const
    {
        if (kind == 1) return x - t * velocity;
        if (kind == 2) return origin + rotateInverse(R, x - origin);
        return x;
    }

    PD_HD Vec3 directionToWorld(const Vec3& d, const Quaternion& R) const
    {
        return kind == 2 ? rotate(R, d) : d;
    }

    //- Velocity of the wall material at world point x
    PD_HD Vec3 velocityAt(const Vec3& x) const
    {
        if (kind == 1) return velocity;
        if (kind == 2) return cross(omega * axis, x - origin);
        return Vec3();
    }

    PD_HD Vec3 angularVelocity() const
    {
        return kind == 2 ? omega * axis : Vec3();
    }
};

} // namespace detail
} // namespace polydem
