// polyhedronGen: generate a convex particle shape (or the convex hull of an
// STL/OBJ), move it to its principal body frame, write it as STL and print
// its properties (optionally also as an OpenFOAM-style dictionary).

#include "ConvexShapeBuilder.hpp"
#include "ShapeFiles.hpp"
#include "ShapeGenerators.hpp"

#include "polyDEM/Error.hpp"

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace polydem;

namespace
{

const char* usage =
    "Usage: polyhedronGen -shape <kind> [options] -o <out.stl>\n"
    "\n"
    "  -shape cube|box|tetrahedron|octahedron|dodecahedron|icosahedron|rock|settling|hull\n"
    "  -d <diameter>          volume-equivalent sphere diameter (all but box; box: optional,\n"
    "                         rescales the box)\n"
    "  -size <a> <b> <c>      box edges (box); -size <a> sets the cube edge instead of -d\n"
    "  -AR <x>                settling: aspect ratio L / mean(W1, W2) >= 1\n"
    "  -C <n>                 settling: number of triangular facets, even, 4..64\n"
    "  -elongation <e>        rock: b/a in (0, 1]          (default 1)\n"
    "  -flatness <f>          rock: c/b in (0, 1]          (default 1)\n"
    "  -points <n>            rock: number of points, 4..34 (default 20)\n"
    "  -seed <s>              rock: random seed            (default 1)\n"
    "  -input <file.stl|obj>  hull (implied by -input): the convex hull of the file's\n"
    "                         vertices (-d optional: rescales)\n"
    "  -o <out.stl>           output STL (body frame: centroid at 0, principal axes)\n"
    "  -binary                write binary STL (default ascii)\n"
    "  -properties            also write <out>.properties (OpenFOAM dictionary)\n"
    "  -help                  this text\n";

[[noreturn]] void fail(const std::string& message)
{
    std::cerr << "polyhedronGen: error: " << message << "\n(polyhedronGen -help for usage)\n";
    std::exit(1);
}

double toNumber(const std::string& option, const std::string& text, const char* expected)
{
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0')
    {
        fail("option " + option + ": expected " + expected + ", got '" + text + "'");
    }
    return v;
}

long toInteger(const std::string& option, const std::string& text, const char* expected)
{
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0')
    {
        fail("option " + option + ": expected " + expected + ", got '" + text + "'");
    }
    return v;
}

void print(const ConvexShape& s)
{
    const Vec3& I = s.inertiaPerDensity;
    const Vec3& psi = s.crosswiseSphericity;
    std::cout << std::setprecision(10) << "shape                 " << s.name << '\n'
              << "volume                " << s.volume << '\n'
              << "surfaceArea           " << s.surfaceArea << '\n'
              << "equivalentDiameter    " << s.equivalentDiameter << '\n'
              << "sphericity            " << s.sphericity << '\n'
              << "crosswiseSphericity   " << psi.x << ' ' << psi.y << ' ' << psi.z
              << "   (along body x y z)\n"
              << "inertiaPerDensity     " << I.x << ' ' << I.y << ' ' << I.z << '\n'
              << "boundingRadius        " << s.boundingRadius << '\n'
              << "faces vertices edges  " << s.nFaces() << ' ' << s.nVertices() << ' '
              << s.nEdges() << '\n';
}

} // namespace


int main(int argc, char** argv)
{
    // Options and how many values each takes
    const std::map<std::string, int> arity = {
        {"-shape", 1}, {"-d", 1},         {"-size", -1},   {"-AR", 1},     {"-C", 1},
        {"-elongation", 1}, {"-flatness", 1}, {"-points", 1}, {"-seed", 1}, {"-input", 1},
        {"-o", 1},     {"-binary", 0},    {"-properties", 0}, {"-help", 0}};
    std::map<std::string, std::vector<std::string>> opt;
    for (int i = 1; i < argc; ++i)
    {
        const std::string key = argv[i];
        const auto it = arity.find(key);
        if (it == arity.end())
        {
            fail("unknown option '" + key + "'");
        }
        std::vector<std::string>& values = opt[key];
        if (it->second < 0)
        {
            // -size: one or three numbers
            while (i + 1 < argc && argv[i + 1][0] != '-' ) values.push_back(argv[++i]);
            if (values.size() != 1 && values.size() != 3)
            {
                fail("option -size: expected 1 (cube edge) or 3 (box edges a b c) numbers");
            }
        }
        for (int k = 0; k < it->second; ++k)
        {
            if (i + 1 >= argc)
            {
                fail("option " + key + ": missing value");
            }
            values.push_back(argv[++i]);
        }
    }
    if (opt.count("-help"))
    {
        std::cout << usage;
        return 0;
    }
    const auto has = [&](const char* k) { return opt.count(k) > 0; };
    const auto number = [&](const char* k, const char* expected)
    { return toNumber(k, opt.at(k)[0], expected); };
    const auto positive = [&](const char* k)
    {
        const double v = number(k, "a positive number");
        if (!(v > 0)) fail(std::string("option ") + k + ": expected a positive number");
        return v;
    };

    if (!has("-shape") && has("-input")) opt["-shape"] = {"hull"};
    if (argc == 1)
    {
        std::cout << usage;
        return 1;
    }
    if (!has("-shape")) fail("option -shape is required");
    if (!has("-o")) fail("option -o <out.stl> is required");
    const std::string kind = opt["-shape"][0];
    const std::string outFile = opt["-o"][0];

    try
    {
        ConvexShape shape;
        BodyPlacement placement;
        bool havePlacement = false;
        const auto needD = [&]()
        {
            if (!has("-d")) fail("shape " + kind + ": option -d <equivalent diameter> is required");
            return positive("-d");
        };
        if (kind == "cube")
        {
            if (has("-size"))
            {
                if (opt["-size"].size() != 1) fail("option -size: a cube takes one edge length");
                const double a = toNumber("-size", opt["-size"][0], "a positive number");
                if (!(a > 0)) fail("option -size: expected a positive edge length");
                shape = makeCube(a);
            }
            else
            {
                shape = makeCube(1.0);
                scaleToEquivalentDiameter(shape, needD());
            }
        }
        else if (kind == "box")
        {
            if (!has("-size") || opt["-size"].size() != 3)
            {
                fail("shape box: option -size <a> <b> <c> (three positive edges) is required");
            }
            double e[3];
            for (int k = 0; k < 3; ++k)
            {
                e[k] = toNumber("-size", opt["-size"][k], "a positive number");
                if (!(e[k] > 0)) fail("option -size: expected positive edges");
            }
            shape = makeBox(e[0], e[1], e[2]);
            if (has("-d")) scaleToEquivalentDiameter(shape, positive("-d"));
        }
        else if (kind == "tetrahedron") shape = makeTetrahedron(needD());
        else if (kind == "octahedron") shape = makeOctahedron(needD());
        else if (kind == "dodecahedron") shape = makeDodecahedron(needD());
        else if (kind == "icosahedron") shape = makeIcosahedron(needD());
        else if (kind == "rock")
        {
            const double d = needD();
            const double e = has("-elongation") ? number("-elongation", "a number in (0, 1]") : 1.0;
            const double f = has("-flatness") ? number("-flatness", "a number in (0, 1]") : 1.0;
            const long n = has("-points") ? toInteger("-points", opt["-points"][0], "an integer") : 20;
            const long seed = has("-seed") ? toInteger("-seed", opt["-seed"][0], "an integer") : 1;
            shape = makeRock(d, e, f, int(n), std::uint64_t(seed));
        }
        else if (kind == "settling")
        {
            const double d = needD();
            if (!has("-AR")) fail("shape settling: option -AR <aspect ratio >= 1> is required");
            if (!has("-C")) fail("shape settling: option -C <even facet count 4..64> is required");
            const double ar = number("-AR", "a number >= 1");
            const long c = toInteger("-C", opt["-C"][0], "an even integer");
            shape = makeSettlingParticle(d, ar, int(c));
        }
        else if (kind == "hull")
        {
            if (!has("-input")) fail("shape hull: option -input <file.stl|file.obj> is required");
            const std::string input = opt["-input"][0];
            const std::size_t slash = input.find_last_of('/');
            const std::string base = input.substr(slash == std::string::npos ? 0 : slash + 1);
            shape = buildConvexShape(readPointSet(input), base.substr(0, base.rfind('.')),
                                     &placement);
            havePlacement = true;
            if (has("-d")) scaleToEquivalentDiameter(shape, positive("-d"));
        }
        else
        {
            fail("option -shape: expected cube, box, tetrahedron, octahedron, dodecahedron, "
                 "icosahedron, rock, settling or hull, got '" + kind + "'");
        }
        if (has("-input") && kind != "hull")
        {
            fail("option -input: only with -shape hull");
        }

        shape.check();
        writeStl(shape, outFile, has("-binary"));
        print(shape);
        std::cout << "written               " << outFile << '\n';
        if (has("-properties"))
        {
            std::string base = outFile;
            if (base.size() > 4 && base.substr(base.size() - 4) == ".stl")
            {
                base = base.substr(0, base.size() - 4);
            }
            writeProperties(shape, base + ".properties", havePlacement ? &placement : nullptr);
            std::cout << "written               " << base << ".properties\n";
        }
    }
    catch (const Error& e)
    {
        std::cerr << "polyhedronGen: error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
