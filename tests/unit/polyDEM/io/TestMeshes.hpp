// Test helpers: small analytic triangle surfaces (cube, UV sphere, cylinder)
// with outward (counter-clockwise) triangles, and temporary file paths.
#pragma once

#include "polyDEM/TriangleMesh.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace polydem::test
{

// Flip triangles of a convex surface (star-shaped about centre) to face outward
inline void orientOutward(TriangleMesh& m, const Vec3& centre)
{
    for (auto& t : m.triangles)
    {
        const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
        const Vec3 n = cross(b - a, c - a);
        if (dot(n, (a + b + c) / 3.0 - centre) < 0)
        {
            std::swap(t[1], t[2]);
        }
    }
}

//- Unit cube [0,1]^3: 8 points, 12 triangles
inline TriangleMesh unitCube()
{
    TriangleMesh m;
    for (int i = 0; i < 8; ++i)
    {
        m.points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    }
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& q : quads)
    {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    orientOutward(m, {0.5, 0.5, 0.5});
    m.source = "unitCube";
    return m;
}

//- UV sphere of radius R about the origin
inline TriangleMesh uvSphere(double R, int nTheta, int nPhi)
{
    const double pi = 3.14159265358979323846;
    TriangleMesh m;
    m.points.push_back({0, 0, R});
    for (int i = 1; i < nTheta; ++i)
    {
        const double th = pi * i / nTheta;
        for (int j = 0; j < nPhi; ++j)
        {
            const double ph = 2 * pi * j / nPhi;
            m.points.push_back({R * std::sin(th) * std::cos(ph), R * std::sin(th) * std::sin(ph),
                                R * std::cos(th)});
        }
    }
    m.points.push_back({0, 0, -R});
    const int south = int(m.points.size()) - 1;
    auto ring = [&](int i, int j) { return 1 + (i - 1) * nPhi + (j % nPhi); };
    for (int j = 0; j < nPhi; ++j)
    {
        m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        m.triangles.push_back({south, ring(nTheta - 1, j), ring(nTheta - 1, j + 1)});
    }
    for (int i = 1; i < nTheta - 1; ++i)
    {
        for (int j = 0; j < nPhi; ++j)
        {
            m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    }
    orientOutward(m, {0, 0, 0});
    m.source = "uvSphere";
    return m;
}

//- Cylinder about the z axis, radius R, z in [0, H], n segments
inline TriangleMesh cylinder(double R, double H, int n)
{
    const double pi = 3.14159265358979323846;
    TriangleMesh m;
    for (int k = 0; k < 2; ++k)
    {
        for (int j = 0; j < n; ++j)
        {
            const double ph = 2 * pi * j / n;
            m.points.push_back({R * std::cos(ph), R * std::sin(ph), k * H});
        }
    }
    m.points.push_back({0, 0, 0});
    m.points.push_back({0, 0, H});
    const int c0 = 2 * n, c1 = 2 * n + 1;
    for (int j = 0; j < n; ++j)
    {
        const int a = j, b = (j + 1) % n;
        m.triangles.push_back({a, b, n + b});
        m.triangles.push_back({a, n + b, n + a});
        m.triangles.push_back({c0, a, b});
        m.triangles.push_back({c1, n + a, n + b});
    }
    orientOutward(m, {0, 0, 0.5 * H});
    m.source = "cylinder";
    return m;
}

//- A fresh path in the temporary folder
inline std::string tempPath(const std::string& name)
{
    return "/tmp/polyDEM_io_" + std::to_string(::getpid()) + "_" + name;
}

inline std::string slurp(const std::string& path)
{
    std::ifstream is(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
}

inline void spit(const std::string& path, const std::string& text)
{
    std::ofstream os(path, std::ios::binary);
    os << text;
}

} // namespace polydem::test
