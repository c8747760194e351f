// polyDEM: 3-vector in double precision, usable on host and device.
#pragma once

#include "polyDEM/Macros.hpp"

#include <cmath>

namespace polydem
{

struct Vec3
{
    double x = 0, y = 0, z = 0;

    Vec3() = default;
    PD_INLINE Vec3(double a, double b, double c) : x(a), y(b), z(c) {}

    PD_INLINE double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    PD_INLINE double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

    PD_INLINE Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    PD_INLINE Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    PD_INLINE Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
};

PD_INLINE Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
PD_INLINE Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PD_INLINE Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
PD_INLINE Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
PD_INLINE Vec3 operator*(const Vec3& a, double s) { return {s * a.x, s * a.y, s * a.z}; }
PD_INLINE Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }

PD_INLINE double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PD_INLINE Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
PD_INLINE double normSqr(const Vec3& a) { return dot(a, a); }
PD_INLINE double norm(const Vec3& a) { return sqrt(dot(a, a)); }
PD_INLINE Vec3 cmul(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

} // namespace polydem
