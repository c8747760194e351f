// rockShapes.hpp: read the plain-text shape file that makeShapes writes
// (rocks.shapes), for the drivers of bench/polyhedraCpu. Host code, polyDEM
// API only (no CGAL), so it compiles against older engine trees as well.
#pragma once

#include "polyDEM/ConvexPolyhedron.hpp"
#include "polyDEM/Error.hpp"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace polydem
{
namespace bench
{

inline std::vector<ConvexShape> readShapes(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw Error("cannot open the shape file", path, "");
    std::vector<ConvexShape> shapes;
    std::string line, key;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream is(line);
        is >> key;
        if (key == "shape")
        {
            shapes.emplace_back();
            int nv, nf, ne;
            is >> shapes.back().name >> nv >> nf >> ne;
        }
        else if (key == "properties")
        {
            ConvexShape& s = shapes.back();
            is >> s.volume >> s.surfaceArea >> s.equivalentDiameter >> s.sphericity >> s.boundingRadius
               >> s.inertiaPerDensity.x >> s.inertiaPerDensity.y >> s.inertiaPerDensity.z;
        }
        else if (key == "v")
        {
            Vec3 v;
            is >> v.x >> v.y >> v.z;
            shapes.back().vertices.push_back(v);
        }
        else if (key == "f")
        {
            ConvexShape& s = shapes.back();
            Vec3 n;
            double off;
            int m;
            is >> n.x >> n.y >> n.z >> off >> m;
            s.faceNormals.push_back(n);
            s.faceOffsets.push_back(off);
            for (int j = 0; j < m; ++j)
            {
                int i;
                is >> i;
                s.faceVertex.push_back(i);
            }
            s.faceStart.push_back(int(s.faceVertex.size()));
        }
        else if (key == "e")
        {
            PolyhedronEdge e;
            is >> e.a >> e.b;
            shapes.back().edges.push_back(e);
        }
        if (!is && key != "shapes") throw Error("malformed line: " + line, path, "");
    }
    for (const auto& s : shapes) s.check();
    if (shapes.empty()) throw Error("no shapes", path, "");
    return shapes;
}

} // namespace bench
} // namespace polydem
