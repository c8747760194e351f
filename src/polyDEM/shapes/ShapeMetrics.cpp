// polyDEM shapes: surface and shape descriptors (see ShapeMetrics.hpp).

#include "ShapeMetrics.hpp"

#include "polyDEM/ConvexPolyhedron.hpp"

#include <algorithm>
#include <cmath>

namespace polydem
{

namespace
{
constexpr double pi = 3.14159265358979323846;

struct Point2
{
    double u, v;
};

double cross2(const Point2& o, const Point2& a, const Point2& b)
{
    return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
}
} // namespace


double surfaceArea(const std::vector<Vec3>& points, const std::vector<int>& faceStart,
                   const std::vector<int>& faceVertex)
{
    double area = 0;
    for (std::size_t f = 0; f + 1 < faceStart.size(); ++f)
    {
        const Vec3& a = points[faceVertex[faceStart[f]]];
        Vec3 twice;
        for (int i = faceStart[f] + 1; i + 1 < faceStart[f + 1]; ++i)
        {
            twice += cross(points[faceVertex[i]] - a, points[faceVertex[i + 1]] - a);
        }
        area += 0.5 * norm(twice);
    }
    return area;
}


double equivalentDiameter(double volume)
{
    return std::cbrt(6.0 * volume / pi);
}


double sphericity(double volume, double area)
{
    return std::cbrt(pi) * std::pow(6.0 * volume, 2.0 / 3.0) / area;
}


double projectedArea(const std::vector<Vec3>& points, const Vec3& direction)
{
    const Vec3 e = direction / norm(direction);
    const Vec3 a = std::fabs(e.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    Vec3 e1 = cross(a, e);
    e1 = e1 / norm(e1);
    const Vec3 e2 = cross(e, e1);

    std::vector<Point2> p;
    p.reserve(points.size());
    for (const Vec3& x : points)
    {
        p.push_back({dot(x, e1), dot(x, e2)});
    }
    std::sort(p.begin(), p.end(), [](const Point2& l, const Point2& r)
              { return l.u < r.u || (l.u == r.u && l.v < r.v); });
    // Andrew's monotone chain
    std::vector<Point2> hull(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        while (k >= 2 && cross2(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
        hull[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;)
    {
        while (k >= t && cross2(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
        hull[k++] = p[i];
    }
    double area2 = 0;
    for (std::size_t i = 0; i + 1 < k; ++i)
    {
        area2 += hull[i].u * hull[i + 1].v - hull[i + 1].u * hull[i].v;
    }
    return 0.5 * std::fabs(area2);
}


double crosswiseSphericity(const ConvexShape& shape, const Vec3& direction)
{
    const double d = equivalentDiameter(shape.volume);
    return 0.25 * pi * d * d / projectedArea(shape.vertices, direction);
}

} // namespace polydem
