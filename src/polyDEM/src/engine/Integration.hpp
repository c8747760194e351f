// polyDEM engine: velocity-Verlet integration (half kicks and drift).
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "DeviceViews.hpp"

#include <cmath>

namespace polydem
{
namespace PD_BACKEND_NS
{

//- Angular momentum <-> angular velocity through the rotated inertia tensor
PD_HD inline Vec3 worldInertiaTimes(const Quaternion& q, const Vec3& I, const Vec3& w)
{
    return rotate(q, cmul(I, rotateInverse(q, w)));
}

PD_HD inline Vec3 worldInverseInertiaTimes(const Quaternion& q, const Vec3& I, const Vec3& L)
{
    const Vec3 b = rotateInverse(q, L);
    return rotate(q, Vec3(b.x / I.x, b.y / I.y, b.z / I.z));
}

//- Largest absolute component: compared where a square could overflow
PD_HD inline double maxAbs(const Vec3& a)
{
    const double x = a.x < 0 ? -a.x : a.x;
    const double y = a.y < 0 ? -a.y : a.y;
    const double z = a.z < 0 ? -a.z : a.z;
    return x > y ? (x > z ? x : z) : (y > z ? y : z);
}

//- The squared displacement d since the last neighbour-list build, or
//  +infinity for a particle that has blown up (the blow-up guard of the step
//  loop, folded into the rebuild check's reduction): a position or an
//  angular velocity that is not finite, a displacement beyond 1e100 m
//  (tested without squaring, which could overflow and trip a floating-point
//  trap before the guard speaks), or a turn of more than 1 rad in one step.
//  A NaN fails every comparison and so lands in the infinity branch.
PD_HD inline double guardedDisplacementSqr(const Vec3& d, const Vec3& omega, double dt)
{
    const double big = 1e100;
    if (!(maxAbs(d) < big) || !(maxAbs(omega) * dt <= 1.0))
    {
        return HUGE_VAL;
    }
    return normSqr(d);
}

//- First half kick and drift; returns the squared displacement since the last
//  neighbour-list build (guardedDisplacementSqr), so that the rebuild check
//  and the blow-up guard need no pass of their own
template<class Kind>
struct KickDrift
{
    ParticleView p;
    const int* typeShape;   //!< -1 for spheres
    const Vec3* ref;
    double dt;

    PD_HD double operator()(int i) const
    {
        const int a = p.nApproach > 0 ? approachOf(p, p.pos[i]) : -1;
        if (a >= 0)
        {
            // Kinematic (an approach region): the prescribed velocity, no turning
            const Vec3 v = p.approachVel[a];
            const Vec3 x = p.pos[i] + dt * v;
            p.pos[i] = x;
            p.vel[i] = v;
            p.omega[i] = Vec3();
            return guardedDisplacementSqr(x - ref[i], p.omega[i], dt);
        }
        const double m = p.mass[i];
        const Vec3 v = p.vel[i] + (0.5 * dt / m) * p.force[i];
        const Vec3 x = p.pos[i] + dt * v;
        p.pos[i] = x;
        p.vel[i] = v;

        const Vec3 I = p.inertia[i];
        if (!Kind::polyhedra || typeShape[p.type[i]] < 0)
        {
            // A sphere: its orientation changes nothing, so it is not integrated
            p.omega[i] += (0.5 * dt / I.x) * p.torque[i];
            return guardedDisplacementSqr(x - ref[i], p.omega[i], dt);
        }

        const Quaternion q0 = p.q[i];
        const Vec3 L = worldInertiaTimes(q0, I, p.omega[i]) + (0.5 * dt) * p.torque[i];
        Quaternion q1;
        Vec3 w;
        if (I.x == I.y && I.y == I.z)
        {
            // Isotropic inertia (a cube, a regular solid): omega is constant over the drift
            w = L / I.x;
            q1 = normalised(fromRotationVector(dt * w) * q0);
        }
        else
        {
            // Implicit midpoint for the free rotation at constant L: the angular
            // velocity of the mid orientation rotates the start one by dt.
            Vec3 wMid = worldInverseInertiaTimes(q0, I, L);
            for (int it = 0; it < 4; ++it)
            {
                const Quaternion qMid = normalised(fromRotationVector((0.5 * dt) * wMid) * q0);
                wMid = worldInverseInertiaTimes(qMid, I, L);
            }
            q1 = normalised(fromRotationVector(dt * wMid) * q0);
            w = worldInverseInertiaTimes(q1, I, L);
        }
        p.q[i] = q1;
        p.omega[i] = w;
        return guardedDisplacementSqr(x - ref[i], w, dt);
    }
};

//- Second half kick of particle i (fused into the last force kernel of a step)
template<class Kind>
PD_HD inline void finalKick(const ParticleView& p, const int* typeShape, double dt, int i, const Vec3& F, const Vec3& T)
{
    if (p.nApproach > 0)
    {
        // Still (or now) in an approach region after the drift: kinematic
        const int a = approachOf(p, p.pos[i]);
        if (a >= 0)
        {
            p.vel[i] = p.approachVel[a];
            p.omega[i] = Vec3();
            return;
        }
    }
    p.vel[i] += (0.5 * dt / p.mass[i]) * F;
    const Vec3 I = p.inertia[i];
    if (!Kind::polyhedra || typeShape[p.type[i]] < 0)
    {
        p.omega[i] += (0.5 * dt / I.x) * T;
    }
    else
    {
        const Vec3 L = worldInertiaTimes(p.q[i], I, p.omega[i]) + (0.5 * dt) * T;
        p.omega[i] = worldInverseInertiaTimes(p.q[i], I, L);
    }
}

} // namespace PD_BACKEND_NS
} // namespace polydem
