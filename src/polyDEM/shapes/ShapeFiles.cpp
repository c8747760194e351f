// polyDEM shapes: shape files (see ShapeFiles.hpp).

#include "ShapeFiles.hpp"

#include "polyDEM/Error.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace polydem
{

namespace
{
std::string lowerExtension(const std::string& fileName)
{
    const std::size_t dot = fileName.rfind('.');
    std::string ext = dot == std::string::npos ? "" : fileName.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string readAll(const std::string& fileName)
{
    std::ifstream in(fileName, std::ios::binary);
    if (!in)
    {
        throw Error("cannot open for reading", fileName);
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
} // namespace


std::vector<Vec3> readPointSet(const std::string& fileName)
{
    const std::string data = readAll(fileName);
    std::vector<Vec3> points;
    const std::string ext = lowerExtension(fileName);
    if (ext == "obj")
    {
        std::istringstream in(data);
        std::string line;
        while (std::getline(in, line))
        {
            std::istringstream ls(line);
            std::string key;
            Vec3 p;
            if (ls >> key && key == "v" && (ls >> p.x >> p.y >> p.z))
            {
                points.push_back(p);
            }
        }
    }
    else if (ext == "stl")
    {
        std::uint32_t nTri = 0;
        if (data.size() >= 84)
        {
            std::memcpy(&nTri, data.data() + 80, 4);
        }
        if (data.size() >= 84 && data.size() == 84 + 50 * std::size_t(nTri))
        {
            // Binary: 80-byte header, count, 50 bytes per triangle (normal, 3 vertices, attribute)
            for (std::uint32_t t = 0; t < nTri; ++t)
            {
                const char* tri = data.data() + 84 + 50 * std::size_t(t) + 12;
                for (int k = 0; k < 3; ++k)
                {
                    float xyz[3];
                    std::memcpy(xyz, tri + 12 * k, 12);
                    points.emplace_back(xyz[0], xyz[1], xyz[2]);
                }
            }
        }
        else
        {
            std::istringstream in(data);
            std::string word;
            while (in >> word)
            {
                if (word == "vertex")
                {
                    Vec3 p;
                    if (!(in >> p.x >> p.y >> p.z))
                    {
                        throw Error("bad 'vertex' line in ascii STL", fileName);
                    }
                    points.push_back(p);
                }
            }
        }
    }
    else
    {
        throw Error("unknown point-set format '." + ext + "', expected .stl or .obj", fileName);
    }
    if (points.empty())
    {
        throw Error("no vertices found", fileName);
    }
    return points;
}


void writeStl(const ConvexShape& s, const std::string& fileName, bool binary)
{
    std::ofstream out(fileName, binary ? std::ios::binary : std::ios::out);
    if (!out)
    {
        throw Error("cannot open for writing", fileName);
    }
    std::uint32_t nTri = 0;
    for (int f = 0; f < s.nFaces(); ++f)
    {
        nTri += std::uint32_t(s.faceStart[f + 1] - s.faceStart[f] - 2);
    }
    if (binary)
    {
        char header[80] = {};
        std::snprintf(header, sizeof(header), "polyDEM convex shape %s", s.name.c_str());
        out.write(header, 80);
        out.write(reinterpret_cast<const char*>(&nTri), 4);
    }
    else
    {
        out << "solid " << s.name << '\n' << std::setprecision(17);
    }
    for (int f = 0; f < s.nFaces(); ++f)
    {
        const int b = s.faceStart[f], e = s.faceStart[f + 1];
        const Vec3& n = s.faceNormals[f];
        for (int i = b + 1; i + 1 < e; ++i)
        {
            const Vec3 tri[3] = {s.vertices[s.faceVertex[b]], s.vertices[s.faceVertex[i]],
                                 s.vertices[s.faceVertex[i + 1]]};
            if (binary)
            {
                float buf[12] = {float(n.x), float(n.y), float(n.z)};
                for (int k = 0; k < 3; ++k)
                {
                    buf[3 + 3 * k] = float(tri[k].x);
                    buf[4 + 3 * k] = float(tri[k].y);
                    buf[5 + 3 * k] = float(tri[k].z);
                }
                const std::uint16_t attribute = 0;
                out.write(reinterpret_cast<const char*>(buf), 48);
                out.write(reinterpret_cast<const char*>(&attribute), 2);
            }
            else
            {
                out << "  facet normal " << n.x << ' ' << n.y << ' ' << n.z << "\n    outer loop\n";
                for (const Vec3& p : tri)
                {
                    out << "      vertex " << p.x << ' ' << p.y << ' ' << p.z << '\n';
                }
                out << "    endloop\n  endfacet\n";
            }
        }
    }
    if (!binary)
    {
        out << "endsolid " << s.name << '\n';
    }
    if (!out)
    {
        throw Error("write failed", fileName);
    }
}


void writeProperties(const ConvexShape& s, const std::string& fileName,
                     const BodyPlacement* placement)
{
    std::ofstream out(fileName);
    if (!out)
    {
        throw Error("cannot open for writing", fileName);
    }
    const auto vec = [](const Vec3& v)
    {
        std::ostringstream o;
        o << std::setprecision(15) << '(' << v.x << ' ' << v.y << ' ' << v.z << ')';
        return o.str();
    };
    std::string object = fileName;
    const std::size_t slash = object.rfind('/');
    if (slash != std::string::npos) object = object.substr(slash + 1);
    out << std::setprecision(15);
    out << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        << "  Hedra polyhedronGen: convex particle shape, body frame = principal axes\n"
        << "\\*---------------------------------------------------------------------------*/\n"
        << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
        << "    class       dictionary;\n    object      " << object << ";\n}\n\n";
    out << "name                " << s.name << ";\n"
        << "volume              " << s.volume << ";\n"
        << "surfaceArea         " << s.surfaceArea << ";\n"
        << "equivalentDiameter  " << s.equivalentDiameter << ";\n"
        << "sphericity          " << s.sphericity << ";\n"
        << "crosswiseSphericity " << vec(s.crosswiseSphericity) << "; // along body x y z\n"
        << "inertiaPerDensity   " << vec(s.inertiaPerDensity) << "; // principal, [m5]\n"
        << "boundingRadius      " << s.boundingRadius << ";\n"
        << "nVertices           " << s.nVertices() << ";\n"
        << "nFaces              " << s.nFaces() << ";\n"
        << "nEdges              " << s.nEdges() << ";\n";
    if (placement)
    {
        const Quaternion& q = placement->orientation;
        out << "\n// Where the body frame lies in the input's frame: x = centroid + R x_body\n"
            << "placement\n{\n    centroid     " << vec(placement->centroid) << ";\n"
            << "    orientation  (" << q.w << ' ' << q.x << ' ' << q.y << ' ' << q.z
            << "); // quaternion (w x y z)\n}\n";
    }
}

} // namespace polydem
