// polyDEM shapes: mass properties and principal axes (see MassProperties.hpp).

#include "MassProperties.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace polydem
{

MassProperties polyhedronMassProperties(const std::vector<Vec3>& points,
                                        const std::vector<int>& faceStart,
                                        const std::vector<int>& faceVertex)
{
    // Reference point: the vertex mean, so that the sums stay well conditioned
    Vec3 o;
    for (const Vec3& p : points)
    {
        o += p;
    }
    o = o / double(points.size());

    double sixV = 0;
    Vec3 moment;           // sum 6V_t (a + b + c)
    double second[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // int x x^T dV about o
    for (std::size_t f = 0; f + 1 < faceStart.size(); ++f)
    {
        const int begin = faceStart[f], end = faceStart[f + 1];
        const Vec3 a = points[faceVertex[begin]] - o;
        for (int i = begin + 1; i + 1 < end; ++i)
        {
            const Vec3 b = points[faceVertex[i]] - o;
            const Vec3 c = points[faceVertex[i + 1]] - o;
            const double d = dot(a, cross(b, c)); // 6 V_t
            sixV += d;
            const Vec3 s = a + b + c;
            moment += d * s;
            // Tetra (0, a, b, c): int x_i x_j dV = (6V_t / 120) (sum_k v_ki v_kj + s_i s_j)
            for (int r = 0; r < 3; ++r)
            {
                for (int k = 0; k < 3; ++k)
                {
                    second[r][k] += d / 120.0
                                    * (a[r] * a[k] + b[r] * b[k] + c[r] * c[k] + s[r] * s[k]);
                }
            }
        }
    }
    MassProperties mp;
    mp.volume = sixV / 6.0;
    const Vec3 cRel = moment / (4.0 * sixV);
    mp.centroid = o + cRel;
    // Shift the second moment to the centroid, then I = tr(C) 1 - C
    double C[3][3];
    for (int r = 0; r < 3; ++r)
    {
        for (int k = 0; k < 3; ++k)
        {
            C[r][k] = second[r][k] - mp.volume * cRel[r] * cRel[k];
        }
    }
    const double trace = C[0][0] + C[1][1] + C[2][2];
    for (int r = 0; r < 3; ++r)
    {
        for (int k = 0; k < 3; ++k)
        {
            mp.inertia.m[r][k] = (r == k ? trace : 0.0) - C[r][k];
        }
    }
    return mp;
}


void principalAxes(const Matrix3& inertia, Vec3& moments, Matrix3& rotation)
{
    double a[3][3];
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double scale =
        std::fabs(inertia.m[0][0]) + std::fabs(inertia.m[1][1]) + std::fabs(inertia.m[2][2]);
    for (int r = 0; r < 3; ++r)
    {
        for (int k = 0; k < 3; ++k)
        {
            // Round-off off the diagonal would turn symmetric shapes (cube) by
            // 45 degrees: a tensor that is diagonal to 1e-13 is taken as is
            a[r][k] = (r != k && std::fabs(inertia.m[r][k]) < 1e-13 * scale) ? 0.0
                                                                              : inertia.m[r][k];
        }
    }
    for (int sweep = 0; sweep < 50; ++sweep)
    {
        const double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
        if (off <= 1e-17 * scale)
        {
            break;
        }
        for (int p = 0; p < 2; ++p)
        {
            for (int q = p + 1; q < 3; ++q)
            {
                if (a[p][q] == 0)
                {
                    continue;
                }
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0)
                                 / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0);
                const double s = t * c;
                for (int k = 0; k < 3; ++k)
                {
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k)
                {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k)
                {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
        }
    }
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(),
                     [&](int i, int j) { return a[i][i] < a[j][j] * (1 - 1e-12); });
    for (int j = 0; j < 3; ++j)
    {
        moments[j] = a[order[j]][order[j]];
        for (int r = 0; r < 3; ++r)
        {
            rotation.m[r][j] = v[r][order[j]];
        }
    }
    // Right handed: det R = +1
    if (dot(rotation.column(0), cross(rotation.column(1), rotation.column(2))) < 0)
    {
        for (int r = 0; r < 3; ++r)
        {
            rotation.m[r][2] = -rotation.m[r][2];
        }
    }
}


Quaternion quaternionOfRotation(const Matrix3& R)
{
    const auto& m = R.m;
    const double trace = m[0][0] + m[1][1] + m[2][2];
    Quaternion q;
    if (trace > 0)
    {
        const double s = 2.0 * std::sqrt(trace + 1.0);
        q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
    }
    else if (m[0][0] > m[1][1] && m[0][0] > m[2][2])
    {
        const double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
    }
    else if (m[1][1] > m[2][2])
    {
        const double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
    }
    else
    {
        const double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
        q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
    }
    return normalised(q);
}

} // namespace polydem
