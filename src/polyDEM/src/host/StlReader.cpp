// polyDEM: STL reading (ASCII/binary detection, vertex merging, validation)
// and writing. See StlReader.hpp.

#include "polyDEM/StlReader.hpp"

#include "polyDEM/Error.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unordered_map>

namespace polydem
{

namespace
{

std::string readWholeFile(const std::string& path)
{
    std::ifstream is(path, std::ios::binary);
    if (!is)
    {
        throw Error("cannot open STL file (missing or unreadable)", path);
    }
    std::string data((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
    if (is.bad())
    {
        throw Error("read error", path);
    }
    return data;
}

// Binary STL is little-endian whatever the host: decode byte by byte
std::uint32_t readU32(const unsigned char* p)
{
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16)
         | (std::uint32_t(p[3]) << 24);
}

float readF32(const unsigned char* p)
{
    const std::uint32_t u = readU32(p);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

void putU32(std::string& out, std::uint32_t u)
{
    for (int i = 0; i < 4; ++i)
    {
        out.push_back(char((u >> (8 * i)) & 0xffu));
    }
}

void putF32(std::string& out, float f)
{
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    putU32(out, u);
}

bool startsWithSolid(const std::string& data)
{
    std::size_t i = 0;
    while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i])))
    {
        ++i;
    }
    if (data.size() - i < 5)
    {
        return false;
    }
    std::string word = data.substr(i, 5);
    for (char& c : word)
    {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    return word == "solid";
}

// A text STL holds no NUL and (almost) no control bytes; binary data nearly always does
bool looksLikeText(const std::string& data)
{
    for (unsigned char c : data)
    {
        if (c == 0 || (c < 32 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v'))
        {
            return false;
        }
    }
    return true;
}

struct Token
{
    std::string text;
    std::size_t line;
};

std::vector<Token> tokenize(const std::string& data)
{
    std::vector<Token> tokens;
    std::size_t line = 1;
    std::size_t i = 0;
    const std::size_t n = data.size();
    while (i < n)
    {
        const char c = data[i];
        if (c == '\n')
        {
            ++line;
            ++i;
        }
        else if (std::isspace(static_cast<unsigned char>(c)))
        {
            ++i;
        }
        else
        {
            const std::size_t start = i;
            while (i < n && !std::isspace(static_cast<unsigned char>(data[i])))
            {
                ++i;
            }
            tokens.push_back({data.substr(start, i - start), line});
        }
    }
    return tokens;
}

bool keywordIs(const Token& t, const char* word)
{
    if (t.text.size() != std::strlen(word))
    {
        return false;
    }
    for (std::size_t i = 0; i < t.text.size(); ++i)
    {
        if (std::tolower(static_cast<unsigned char>(t.text[i])) != word[i])
        {
            return false;
        }
    }
    return true;
}

// Parses the ASCII grammar  solid [name] { facet [normal n n n] outer loop
// vertex x y z (x3) endloop endfacet } endsolid [name]  (several solids allowed)
class AsciiParser
{
public:
    AsciiParser(const std::string& path, const std::string& data)
        : path_(path), tokens_(tokenize(data))
    {
    }

    void parse(std::vector<Vec3>& vertices, std::size_t& facets)
    {
        while (pos_ < tokens_.size())
        {
            expectKeyword("solid", "'solid [name]'");
            // The name runs to the end of the line
            const std::size_t nameLine = tokens_[pos_ - 1].line;
            while (pos_ < tokens_.size() && tokens_[pos_].line == nameLine)
            {
                ++pos_;
            }
            for (;;)
            {
                if (pos_ >= tokens_.size())
                {
                    fail("expected 'facet normal nx ny nz' or 'endsolid'");
                }
                if (keywordIs(tokens_[pos_], "endsolid"))
                {
                    const std::size_t endLine = tokens_[pos_].line;
                    ++pos_;
                    while (pos_ < tokens_.size() && tokens_[pos_].line == endLine)
                    {
                        ++pos_;
                    }
                    break;
                }
                parseFacet(vertices);
                ++facets;
            }
        }
    }

private:
    [[noreturn]] void fail(const std::string& expected) const
    {
        std::ostringstream msg;
        if (pos_ < tokens_.size())
        {
            msg << "line " << tokens_[pos_].line << ": " << expected << ", found '"
                << tokens_[pos_].text << "' (malformed ASCII STL)";
        }
        else
        {
            const std::size_t line = tokens_.empty() ? 1 : tokens_.back().line;
            msg << "line " << line << ": " << expected
                << ", found end of file (malformed or truncated ASCII STL)";
        }
        throw Error(msg.str(), path_);
    }

    void expectKeyword(const char* word, const std::string& expected)
    {
        if (pos_ >= tokens_.size() || !keywordIs(tokens_[pos_], word))
        {
            fail("expected " + expected);
        }
        ++pos_;
    }

    double number(const std::string& expected)
    {
        if (pos_ >= tokens_.size())
        {
            fail("expected " + expected);
        }
        const std::string& s = tokens_[pos_].text;
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0')
        {
            fail("expected " + expected);
        }
        ++pos_;
        return v;
    }

    void parseFacet(std::vector<Vec3>& vertices)
    {
        const char* facetMsg = "'facet normal nx ny nz' or 'endsolid'";
        expectKeyword("facet", facetMsg);
        // The normal is ignored (recomputed from the vertices where needed);
        // exporters write nan normals for degenerate facets, so accept anything numeric
        if (pos_ < tokens_.size() && keywordIs(tokens_[pos_], "normal"))
        {
            ++pos_;
            for (int i = 0; i < 3; ++i)
            {
                number("'facet normal nx ny nz'");
            }
        }
        expectKeyword("outer", "'outer loop'");
        expectKeyword("loop", "'outer loop'");
        for (int k = 0; k < 3; ++k)
        {
            expectKeyword("vertex", "'vertex x y z'");
            const std::size_t line = tokens_[pos_ - 1].line;
            Vec3 v;
            v.x = number("'vertex x y z'");
            v.y = number("'vertex x y z'");
            v.z = number("'vertex x y z'");
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            {
                throw Error
                (
                    "line " + std::to_string(line) + ": non-finite vertex coordinate", path_
                );
            }
            vertices.push_back(v);
        }
        expectKeyword("endloop", "'endloop'");
        expectKeyword("endfacet", "'endfacet'");
    }

    const std::string& path_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

void readBinary
(
    const std::string& path,
    const std::string& data,
    std::vector<Vec3>& vertices,
    std::size_t& facets
)
{
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    const std::uint32_t n = readU32(bytes + 80);
    vertices.reserve(3 * std::size_t(n));
    for (std::uint32_t t = 0; t < n; ++t)
    {
        // 12 bytes normal (ignored), 3 x 12 bytes vertices, 2 bytes attribute
        const unsigned char* rec = bytes + 84 + 50 * std::size_t(t);
        for (int k = 0; k < 3; ++k)
        {
            const unsigned char* p = rec + 12 + 12 * k;
            const Vec3 v{readF32(p), readF32(p + 4), readF32(p + 8)};
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            {
                throw Error
                (
                    "binary STL triangle " + std::to_string(t) + ": non-finite vertex coordinate",
                    path
                );
            }
            vertices.push_back(v);
        }
    }
    facets = n;
}

struct CellKey
{
    std::int64_t i, j, k;
    bool operator==(const CellKey& o) const { return i == o.i && j == o.j && k == o.k; }
};

struct CellKeyHash
{
    std::size_t operator()(const CellKey& c) const
    {
        // Large odd multipliers (as in Teschner et al. 2003 spatial hashing)
        const std::uint64_t h = std::uint64_t(c.i) * 73856093ull
                              ^ std::uint64_t(c.j) * 19349663ull
                              ^ std::uint64_t(c.k) * 83492791ull;
        return std::size_t(h ^ (h >> 29));
    }
};

std::string formatDouble(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

} // namespace


std::size_t mergePoints(TriangleMesh& mesh, double tol)
{
    const std::size_t n = mesh.points.size();
    if (n == 0)
    {
        return 0;
    }
    double maxAbs = 0;
    for (const Vec3& p : mesh.points)
    {
        maxAbs = std::max({maxAbs, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    // Cell size at least tol; never so small that cell indices overflow
    const double h = std::max({tol, maxAbs * 1e-15, 1e-300});
    const double tolSqr = tol * tol;

    std::unordered_map<CellKey, std::vector<int>, CellKeyHash> grid;
    grid.reserve(n);
    std::vector<Vec3> merged;
    merged.reserve(n);
    std::vector<int> map(n);

    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3& p = mesh.points[i];
        const CellKey c{std::int64_t(std::floor(p.x / h)), std::int64_t(std::floor(p.y / h)),
                        std::int64_t(std::floor(p.z / h))};
        int found = -1;
        // Neighbouring cells too: two points within tol may straddle a cell face
        for (int di = -1; di <= 1 && found < 0; ++di)
        {
            for (int dj = -1; dj <= 1 && found < 0; ++dj)
            {
                for (int dk = -1; dk <= 1 && found < 0; ++dk)
                {
                    const auto it = grid.find({c.i + di, c.j + dj, c.k + dk});
                    if (it == grid.end())
                    {
                        continue;
                    }
                    for (int m : it->second)
                    {
                        if (normSqr(merged[m] - p) <= tolSqr)
                        {
                            found = m;
                            break;
                        }
                    }
                }
            }
        }
        if (found < 0)
        {
            found = int(merged.size());
            merged.push_back(p);
            grid[c].push_back(found);
        }
        map[i] = found;
    }

    for (auto& t : mesh.triangles)
    {
        for (int& v : t)
        {
            v = map[v];
        }
    }
    mesh.points.swap(merged);
    return n - mesh.points.size();
}


TriangleMesh readStl
(
    const std::string& path,
    double scale,
    StlReadInfo* info,
    double relativeMergeTolerance
)
{
    if (!(scale > 0) || !std::isfinite(scale))
    {
        throw Error("scale must be a finite positive number, got " + formatDouble(scale), path,
                    "scale");
    }
    const std::string data = readWholeFile(path);
    if (data.empty())
    {
        throw Error("empty STL file", path);
    }

    StlReadInfo local;
    std::vector<Vec3> vertices;
    std::size_t facets = 0;

    // Size check first: a binary header may legally start with "solid"
    bool binary = false;
    std::uint64_t expected = 0;
    if (data.size() >= 84)
    {
        const std::uint32_t n = readU32(reinterpret_cast<const unsigned char*>(data.data()) + 80);
        expected = 84 + 50 * std::uint64_t(n);
        binary = (expected == data.size());
    }

    if (binary)
    {
        readBinary(path, data, vertices, facets);
    }
    else if (startsWithSolid(data) && looksLikeText(data))
    {
        AsciiParser(path, data).parse(vertices, facets);
    }
    else if (data.size() < 84)
    {
        throw Error
        (
            "not an STL file: too short for binary STL (" + std::to_string(data.size())
          + " bytes < 84) and does not start with 'solid'",
            path
        );
    }
    else
    {
        const std::uint64_t n = (expected - 84) / 50;
        std::ostringstream msg;
        msg << (data.size() < expected ? "truncated binary STL" : "corrupt binary STL")
            << ": header declares " << n << " triangles (" << expected
            << " bytes) but the file has " << data.size() << " bytes";
        throw Error(msg.str(), path);
    }

    local.binary = binary;
    local.trianglesInFile = facets;
    local.verticesInFile = vertices.size();

    if (facets == 0)
    {
        throw Error("STL file holds no triangles", path);
    }

    TriangleMesh mesh;
    mesh.source = path;
    mesh.points = std::move(vertices);
    for (Vec3& p : mesh.points)
    {
        p *= scale;
    }
    mesh.triangles.resize(facets);
    for (std::size_t t = 0; t < facets; ++t)
    {
        mesh.triangles[t] = {int(3 * t), int(3 * t + 1), int(3 * t + 2)};
    }

    Vec3 lo = mesh.points[0], hi = mesh.points[0];
    for (const Vec3& p : mesh.points)
    {
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    }
    const double diag = norm(hi - lo);
    mergePoints(mesh, relativeMergeTolerance * diag);

    // Drop zero-area triangles: collapsed by merging or collinear
    const double areaTol = 1e-14 * diag * diag;
    std::vector<std::array<int, 3>> kept;
    kept.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
    {
        const bool collapsed = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
        if (!collapsed)
        {
            const Vec3& a = mesh.points[t[0]];
            const double area2 = norm(cross(mesh.points[t[1]] - a, mesh.points[t[2]] - a));
            if (area2 > areaTol)
            {
                kept.push_back(t);
                continue;
            }
        }
        ++local.degenerateDropped;
    }
    if (kept.empty())
    {
        throw Error("all " + std::to_string(facets) + " triangles are degenerate (zero area)",
                    path);
    }
    mesh.triangles.swap(kept);

    // Remove points only used by dropped triangles
    std::vector<int> newIndex(mesh.points.size(), -1);
    std::vector<Vec3> used;
    used.reserve(mesh.points.size());
    for (auto& t : mesh.triangles)
    {
        for (int& v : t)
        {
            if (newIndex[v] < 0)
            {
                newIndex[v] = int(used.size());
                used.push_back(mesh.points[v]);
            }
            v = newIndex[v];
        }
    }
    mesh.points.swap(used);
    local.verticesMerged = mesh.points.size();

    if (info)
    {
        *info = local;
    }
    return mesh;
}


void writeStl
(
    const std::string& path,
    const TriangleMesh& mesh,
    bool binary,
    const std::string& solidName
)
{
    auto normalOf = [&](const std::array<int, 3>& t)
    {
        const Vec3& a = mesh.points.at(t[0]);
        const Vec3 n = cross(mesh.points.at(t[1]) - a, mesh.points.at(t[2]) - a);
        const double l = norm(n);
        return l > 0 ? n / l : Vec3{0, 0, 0};
    };

    std::string out;
    if (binary)
    {
        // Header deliberately not starting with "solid" (helps naive readers)
        std::string header = "binary STL " + solidName + " written by polyDEM";
        header.resize(80, ' ');
        out.reserve(84 + 50 * mesh.triangles.size());
        out += header;
        putU32(out, std::uint32_t(mesh.triangles.size()));
        for (const auto& t : mesh.triangles)
        {
            const Vec3 n = normalOf(t);
            putF32(out, float(n.x)); putF32(out, float(n.y)); putF32(out, float(n.z));
            for (int k = 0; k < 3; ++k)
            {
                const Vec3& p = mesh.points.at(t[k]);
                putF32(out, float(p.x)); putF32(out, float(p.y)); putF32(out, float(p.z));
            }
            out.push_back('\0');
            out.push_back('\0');
        }
    }
    else
    {
        out += "solid " + solidName + "\n";
        for (const auto& t : mesh.triangles)
        {
            const Vec3 n = normalOf(t);
            out += "  facet normal " + formatDouble(n.x) + " " + formatDouble(n.y) + " "
                 + formatDouble(n.z) + "\n    outer loop\n";
            for (int k = 0; k < 3; ++k)
            {
                const Vec3& p = mesh.points.at(t[k]);
                out += "      vertex " + formatDouble(p.x) + " " + formatDouble(p.y) + " "
                     + formatDouble(p.z) + "\n";
            }
            out += "    endloop\n  endfacet\n";
        }
        out += "endsolid " + solidName + "\n";
    }

    std::ofstream os(path, std::ios::binary);
    if (!os)
    {
        throw Error("cannot open STL file for writing", path);
    }
    os.write(out.data(), std::streamsize(out.size()));
    if (!os)
    {
        throw Error("write error", path);
    }
}

} // namespace polydem
