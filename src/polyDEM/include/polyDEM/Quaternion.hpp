// polyDEM: unit quaternion for particle orientation (body -> world rotation).
#pragma once

#include "polyDEM/Vec3.hpp"

namespace polydem
{

struct Quaternion
{
    double w = 1, x = 0, y = 0, z = 0;
};

PD_INLINE Quaternion operator*(const Quaternion& a, const Quaternion& b)
{
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

PD_INLINE Quaternion conjugate(const Quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }

PD_INLINE Quaternion normalised(const Quaternion& q)
{
    const double n = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

//- Rotate a body-frame vector into the world frame
PD_INLINE Vec3 rotate(const Quaternion& q, const Vec3& v)
{
    // v' = v + 2 w (u x v) + 2 u x (u x v), u = vector part
    const Vec3 u{q.x, q.y, q.z};
    const Vec3 t = 2.0 * cross(u, v);
    return v + q.w * t + cross(u, t);
}

//- Rotate a world-frame vector into the body frame
PD_INLINE Vec3 rotateInverse(const Quaternion& q, const Vec3& v)
{
    return rotate(conjugate(q), v);
}

//- Quaternion of a rotation by |phi| about phi/|phi| (exact exponential map)
PD_INLINE Quaternion fromRotationVector(const Vec3& phi)
{
    const double angle = norm(phi);
    if (angle < 1e-300)
    {
        return {1, 0, 0, 0};
    }
    const double s = sin(0.5 * angle) / angle;
    return {cos(0.5 * angle), s * phi.x, s * phi.y, s * phi.z};
}

PD_INLINE Quaternion fromAxisAngle(const Vec3& axis, double angle)
{
    return fromRotationVector((angle / norm(axis)) * axis);
}

} // namespace polydem
