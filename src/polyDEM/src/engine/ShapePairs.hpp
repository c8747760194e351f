// polyDEM engine: the shape-pair dispatch (sphere-sphere, polyhedron-sphere,
// polyhedron-polyhedron, and each against a plane) for the volumetric law.
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "DeviceViews.hpp"

namespace polydem
{
namespace PD_BACKEND_NS
{

//- Overlap of two spheres as the volumetric law sees it: lens volume, area of
//  the intersection disc, lens centroid (on the line of centres); n from a to b
PD_HD inline OverlapResult sphereSphereOverlap
(
    const Vec3& xa, double ra, const Vec3& xb, double rb
)
{
    OverlapResult res;
    const Vec3 d = xb - xa;
    const double dist = norm(d);
    const double h = ra + rb - dist;
    if (h <= 0 || dist <= 0) return res;
    const double pi = 3.14159265358979323846;
    res.touching = true;
    res.normal = d / dist;
    // Distance from a's centre to the plane of the intersection circle
    const double xPlane = (dist * dist - rb * rb + ra * ra) / (2 * dist);
    const double ha = ra - xPlane, hb = rb - (dist - xPlane);  // cap heights
    const double va = pi * ha * ha * (3 * ra - ha) / 3, vb = pi * hb * hb * (3 * rb - hb) / 3;
    res.volume = va + vb;
    const double a2 = ra * ra - xPlane * xPlane;
    res.contactArea = pi * (a2 > 0 ? a2 : 0);
    // Cap centroids measured from their sphere centres
    const double za = 3 * (2 * ra - ha) * (2 * ra - ha) / (4 * (3 * ra - ha));
    const double zb = 3 * (2 * rb - hb) * (2 * rb - hb) / (4 * (3 * rb - hb));
    const double s = res.volume > 0 ? (va * za + vb * (dist - zb)) / res.volume : xPlane;
    res.centroid = xa + s * res.normal;
    res.areaVector = res.contactArea * res.normal;
    return res;
}

//- A sphere against the half-space behind a plane (normal n out of the wall):
//  cap volume, section area, cap centroid; result normal from the wall to the sphere
PD_HD inline OverlapResult sphereHalfSpaceOverlap(const Vec3& x, double r, const Vec3& foot, const Vec3& n)
{
    OverlapResult res;
    const double h = r - dot(x - foot, n);
    if (h <= 0) return res;
    const double hh = h < 2 * r ? h : 2 * r;
    const double pi = 3.14159265358979323846;
    res.touching = true;
    res.normal = n;
    res.volume = pi * hh * hh * (3 * r - hh) / 3;
    res.contactArea = pi * hh * (2 * r - hh);
    const double z = 3 * (2 * r - hh) * (2 * r - hh) / (4 * (3 * r - hh));
    res.centroid = x - z * n;
    res.areaVector = res.contactArea * n;
    return res;
}

//- Evaluates every contact once, in the list of its particle of smaller id,

//- Volumetric overlap of particles a and b, normal from a to b: the one
//  shape-pair dispatch (for Kind = SphereKind it is the sphere lens only).
//  separatingAxis (may be null): the pair's cached axis for two polyhedra;
//  touchedBefore: the pair touched at its last evaluation (the axis is its
//  contact normal)
template<class Kind>
PD_HD inline OverlapResult pairOverlap(const ParticleView& p, const LawView& law, int a, int b,
                                       Vec3* separatingAxis = nullptr, bool touchedBefore = false)
{
    if constexpr (Kind::polyhedra)
    {
        const int sa = law.typeShape[p.type[a]];
        const int sb = law.typeShape[p.type[b]];
        if (sa >= 0 && sb >= 0)
        {
            return polyhedronOverlap(law.shapes.shape(sa), p.pos[a], p.q[a],
                                     law.shapes.shape(sb), p.pos[b], p.q[b], separatingAxis,
                                     false, touchedBefore);
        }
        if (sa >= 0)
        {
            return polyhedronSphereOverlap(law.shapes.shape(sa), p.pos[a], p.q[a], p.pos[b], p.radius[b]);
        }
        if (sb >= 0)
        {
            OverlapResult r = polyhedronSphereOverlap(law.shapes.shape(sb), p.pos[b], p.q[b], p.pos[a], p.radius[a]);
            r.normal = -r.normal;
            r.areaVector = -r.areaVector;
            return r;
        }
    }
    (void)separatingAxis;
    (void)touchedBefore;
    return sphereSphereOverlap(p.pos[a], p.radius[a], p.pos[b], p.radius[b]);
}

//- Volumetric overlap of particle i with the half-space behind a plane
//  (point p0, normal n out of the wall); foot: i's centre projected on the plane
template<class Kind>
PD_HD inline OverlapResult planeOverlap
(
    const ParticleView& p, const LawView& law, int i, const Vec3& p0, const Vec3& n, const Vec3& foot
)
{
    if constexpr (Kind::polyhedra)
    {
        const int sh = law.typeShape[p.type[i]];
        if (sh >= 0) return polyhedronPlaneOverlap(law.shapes.shape(sh), p.pos[i], p.q[i], p0, n);
    }
    return sphereHalfSpaceOverlap(p.pos[i], p.radius[i], foot, n);
}

} // namespace PD_BACKEND_NS
} // namespace polydem
