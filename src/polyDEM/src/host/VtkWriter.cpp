// polyDEM: VTK XML PolyData writers and .pvd collections. See VtkWriter.hpp.

#include "polyDEM/VtkWriter.hpp"

#include "polyDEM/Error.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cstdio>
#include <locale>
#include <fstream>
#include <iterator>
#include <sstream>

namespace polydem
{

namespace
{

// Shortest text that reads back to the same double (full precision, compact)
void put(std::string& out, double v)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    out.append(buf, r.ptr);
}

void put(std::string& out, long long v)
{
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    out.append(buf, r.ptr);
}

std::string xmlEscape(const std::string& s)
{
    std::string r;
    for (char c : s)
    {
        switch (c)
        {
            case '&': r += "&amp;"; break;
            case '<': r += "&lt;"; break;
            case '>': r += "&gt;"; break;
            case '"': r += "&quot;"; break;
            case '\'': r += "&apos;"; break;
            default: r += c;
        }
    }
    return r;
}

std::string xmlUnescape(const std::string& s)
{
    static const std::pair<const char*, char> table[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string r;
    for (std::size_t i = 0; i < s.size();)
    {
        bool done = false;
        if (s[i] == '&')
        {
            for (const auto& e : table)
            {
                const std::size_t n = std::char_traits<char>::length(e.first);
                if (s.compare(i, n, e.first) == 0)
                {
                    r += e.second;
                    i += n;
                    done = true;
                    break;
                }
            }
        }
        if (!done)
        {
            r += s[i++];
        }
    }
    return r;
}

// Write via a temporary and rename, so a reader (ParaView, a restart) never
// sees a half-written file
void writeFileAtomically(const std::string& path, const std::string& text)
{
    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary);
        if (!os)
        {
            throw Error("cannot open file for writing", path);
        }
        os.write(text.data(), std::streamsize(text.size()));
        os.close();
        if (!os)
        {
            std::remove(tmp.c_str());
            throw Error("write error", path);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        std::remove(tmp.c_str());
        throw Error("cannot rename temporary file into place", path);
    }
}

const char* vtpHeader =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
    "header_type=\"UInt64\">\n"
    "  <PolyData>\n";

const char* vtpFooter =
    "    </Piece>\n"
    "  </PolyData>\n"
    "</VTKFile>\n";

void beginArray(std::string& out, const char* type, const std::string& name, int components)
{
    out += "        <DataArray type=\"";
    out += type;
    out += "\"";
    if (!name.empty())
    {
        out += " Name=\"" + xmlEscape(name) + "\"";
    }
    if (components > 1)
    {
        out += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    }
    out += " format=\"ascii\">\n";
}

void endArray(std::string& out)
{
    out += "\n        </DataArray>\n";
}

// Values separated by spaces, a line break every few values to keep lines short
template<class T, class Put>
void writeValues(std::string& out, const std::vector<T>& values, int perLine, Put putOne)
{
    out += "          ";
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (i > 0)
        {
            out += (i % perLine == 0) ? "\n          " : " ";
        }
        putOne(values[i]);
    }
}

void vec3Array(std::string& out, const std::string& name, const std::vector<Vec3>& v)
{
    beginArray(out, "Float64", name, 3);
    writeValues(out, v, 2, [&](const Vec3& a)
    {
        put(out, a.x); out += ' '; put(out, a.y); out += ' '; put(out, a.z);
    });
    endArray(out);
}

void doubleArray(std::string& out, const std::string& name, const std::vector<double>& v)
{
    beginArray(out, "Float64", name, 1);
    writeValues(out, v, 6, [&](double a) { put(out, a); });
    endArray(out);
}

template<class Int>
void intArray(std::string& out, const char* type, const std::string& name,
              const std::vector<Int>& v)
{
    beginArray(out, type, name, 1);
    writeValues(out, v, 10, [&](Int a) { put(out, static_cast<long long>(a)); });
    endArray(out);
}

template<class T>
bool present(const std::vector<T>& v, std::size_t n, const char* name, const std::string& path)
{
    if (v.empty() && n > 0)
    {
        return false;
    }
    if (v.size() != n)
    {
        throw Error(std::string("particle field '") + name + "' has " + std::to_string(v.size())
                        + " values for " + std::to_string(n) + " particles",
                    path, name);
    }
    return true;
}

// The particle fields of particles.vtp, one tuple per row; row k shows
// particle rows[k] (identity for particles.vtp, the owning particle of each
// face for polyhedra.vtp)
template<class T>
std::vector<T> gather(const std::vector<T>& v, const std::vector<std::size_t>& rows)
{
    std::vector<T> r;
    r.reserve(rows.size());
    for (std::size_t i : rows)
    {
        r.push_back(v[i]);
    }
    return r;
}

void particleFields
(
    std::string& out,
    const ParticleState& s,
    const std::vector<std::size_t>& rows,
    const std::vector<double>& volumeEquivalentDiameter,
    const std::string& path
)
{
    const std::size_t n = s.position.size();
    present(s.id, n, "id", path);
    intArray(out, "Int64", "id", gather(s.id, rows));
    if (present(s.type, n, "type", path))
    {
        intArray(out, "Int32", "type", gather(s.type, rows));
    }
    if (present(s.radius, n, "radius", path))
    {
        const std::vector<double> r = gather(s.radius, rows);
        doubleArray(out, "radius", r);
        std::vector<double> d(r.size());
        std::transform(r.begin(), r.end(), d.begin(), [](double a) { return 2 * a; });
        doubleArray(out, "diameter", d);
    }
    if (present(volumeEquivalentDiameter, n, "volumeEquivalentDiameter", path))
    {
        doubleArray(out, "volumeEquivalentDiameter", gather(volumeEquivalentDiameter, rows));
    }
    if (present(s.mass, n, "mass", path))
    {
        doubleArray(out, "mass", gather(s.mass, rows));
    }
    if (present(s.velocity, n, "velocity", path))
    {
        vec3Array(out, "velocity", gather(s.velocity, rows));
    }
    if (present(s.omega, n, "omega", path))
    {
        vec3Array(out, "omega", gather(s.omega, rows));
    }
    if (present(s.force, n, "force", path))
    {
        vec3Array(out, "force", gather(s.force, rows));
    }
    if (present(s.torque, n, "torque", path))
    {
        vec3Array(out, "torque", gather(s.torque, rows));
    }
    if (present(s.orientation, n, "orientation", path))
    {
        beginArray(out, "Float64", "orientation", 4);
        writeValues(out, gather(s.orientation, rows), 2, [&](const Quaternion& q)
        {
            put(out, q.w); out += ' '; put(out, q.x); out += ' ';
            put(out, q.y); out += ' '; put(out, q.z);
        });
        endArray(out);
    }
}

} // namespace


void writeParticlesVtp
(
    const std::string& path,
    const ParticleState& s,
    const std::vector<double>& volumeEquivalentDiameter
)
{
    const std::size_t n = s.position.size();
    present(s.id, n, "id", path);

    std::string out;
    out.reserve(400 * n + 2000);
    out += vtpHeader;
    out += "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfVerts=\""
         + std::to_string(n)
         + "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";

    out += "      <PointData Scalars=\"diameter\" Vectors=\"velocity\">\n";
    std::vector<std::size_t> rows(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        rows[i] = i;
    }
    particleFields(out, s, rows, volumeEquivalentDiameter, path);
    out += "      </PointData>\n";

    out += "      <Points>\n";
    vec3Array(out, "position", s.position);
    out += "      </Points>\n";

    // One vertex cell per point so that the points render without a filter
    std::vector<long long> conn(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        conn[i] = static_cast<long long>(i);
    }
    std::vector<long long> offsets(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        offsets[i] = static_cast<long long>(i + 1);
    }
    out += "      <Verts>\n";
    intArray(out, "Int64", "connectivity", conn);
    intArray(out, "Int64", "offsets", offsets);
    out += "      </Verts>\n";
    out += vtpFooter;

    writeFileAtomically(path, out);
}


namespace
{

// Polygons over points with the cell data section cellData (may be empty)
void writePolygonsVtp
(
    const std::string& path,
    const std::vector<Vec3>& points,
    const std::vector<std::vector<int>>& polygons,
    const std::string& cellData
)
{
    std::vector<long long> conn, offsets;
    offsets.reserve(polygons.size());
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
        if (polygons[p].size() < 3)
        {
            throw Error("polygon " + std::to_string(p) + " has fewer than 3 vertices", path);
        }
        for (int v : polygons[p])
        {
            if (v < 0 || std::size_t(v) >= points.size())
            {
                throw Error("polygon " + std::to_string(p) + " refers to point "
                                + std::to_string(v) + " of " + std::to_string(points.size()),
                            path);
            }
            conn.push_back(v);
        }
        offsets.push_back(static_cast<long long>(conn.size()));
    }

    std::string out;
    out.reserve(60 * points.size() + 20 * conn.size() + 2000);
    out += vtpHeader;
    out += "    <Piece NumberOfPoints=\"" + std::to_string(points.size())
         + "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
         + std::to_string(polygons.size()) + "\">\n";
    out += cellData;
    out += "      <Points>\n";
    vec3Array(out, "points", points);
    out += "      </Points>\n";
    out += "      <Polys>\n";
    intArray(out, "Int64", "connectivity", conn);
    intArray(out, "Int64", "offsets", offsets);
    out += "      </Polys>\n";
    out += vtpFooter;

    writeFileAtomically(path, out);
}

} // namespace


void writeSurfaceVtp
(
    const std::string& path,
    const std::vector<Vec3>& points,
    const std::vector<std::vector<int>>& polygons,
    const std::vector<int>& polygonIds,
    const std::string& idName
)
{
    if (!polygonIds.empty() && polygonIds.size() != polygons.size())
    {
        throw Error("polygon ids: " + std::to_string(polygonIds.size()) + " values for "
                        + std::to_string(polygons.size()) + " polygons",
                    path, idName);
    }
    std::string cellData;
    if (!polygonIds.empty())
    {
        cellData += "      <CellData Scalars=\"" + xmlEscape(idName) + "\">\n";
        intArray(cellData, "Int32", idName, polygonIds);
        cellData += "      </CellData>\n";
    }
    writePolygonsVtp(path, points, polygons, cellData);
}


void writeParticleFacesVtp
(
    const std::string& path,
    const std::vector<Vec3>& points,
    const std::vector<std::vector<int>>& polygons,
    const std::vector<std::size_t>& polygonParticle,
    const ParticleState& state,
    const std::vector<double>& volumeEquivalentDiameter
)
{
    if (polygonParticle.size() != polygons.size())
    {
        throw Error("polygon particles: " + std::to_string(polygonParticle.size())
                        + " values for " + std::to_string(polygons.size()) + " polygons",
                    path, "particleId");
    }
    for (std::size_t i : polygonParticle)
    {
        if (i >= state.position.size())
        {
            throw Error("a polygon refers to particle " + std::to_string(i) + " of "
                            + std::to_string(state.position.size()),
                        path, "particleId");
        }
    }
    std::string cellData = "      <CellData Scalars=\"particleId\" Vectors=\"velocity\">\n";
    particleFields(cellData, state, polygonParticle, volumeEquivalentDiameter, path);
    if (!state.id.empty())
    {
        // The name polyhedra.vtp had before it carried every field
        intArray(cellData, "Int64", "particleId", gather(state.id, polygonParticle));
    }
    cellData += "      </CellData>\n";
    writePolygonsVtp(path, points, polygons, cellData);
}


void writeSurfaceVtp
(
    const std::string& path,
    const TriangleMesh& mesh,
    const std::vector<int>& triangleIds,
    const std::string& idName
)
{
    std::vector<std::vector<int>> polys(mesh.triangles.size());
    for (std::size_t t = 0; t < polys.size(); ++t)
    {
        polys[t].assign(mesh.triangles[t].begin(), mesh.triangles[t].end());
    }
    writeSurfaceVtp(path, mesh.points, polys, triangleIds, idName);
}


void PvdCollection::add(double time, const std::string& relativeFile, int part)
{
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e)
                                  { return e.time > time || (e.time == time && e.part == part); }),
                   entries_.end());
    entries_.push_back({time, relativeFile, part});
}


bool PvdCollection::read(const std::string& path, double restartTime)
{
    std::ifstream is(path, std::ios::binary);
    if (!is)
    {
        return false;
    }
    const std::string text((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
    if (text.find("<VTKFile") == std::string::npos
        || text.find("Collection") == std::string::npos)
    {
        throw Error("not a ParaView .pvd collection (no <VTKFile type=\"Collection\">)", path);
    }

    // Attribute value of name="..." (or '...') inside one tag
    auto attribute = [&](const std::string& tag, const std::string& name, std::string& value)
    {
        std::size_t pos = 0;
        while ((pos = tag.find(name, pos)) != std::string::npos)
        {
            const bool wordStart = pos == 0 || std::isspace(static_cast<unsigned char>(tag[pos - 1]));
            std::size_t q = pos + name.size();
            while (q < tag.size() && std::isspace(static_cast<unsigned char>(tag[q]))) ++q;
            if (wordStart && q < tag.size() && tag[q] == '=')
            {
                ++q;
                while (q < tag.size() && std::isspace(static_cast<unsigned char>(tag[q]))) ++q;
                if (q < tag.size() && (tag[q] == '"' || tag[q] == '\''))
                {
                    const std::size_t close = tag.find(tag[q], q + 1);
                    if (close == std::string::npos)
                    {
                        return false;
                    }
                    value = xmlUnescape(tag.substr(q + 1, close - q - 1));
                    return true;
                }
            }
            pos += name.size();
        }
        return false;
    };

    std::vector<Entry> loaded;
    std::size_t pos = 0;
    while ((pos = text.find("<DataSet", pos)) != std::string::npos)
    {
        const std::size_t end = text.find('>', pos);
        if (end == std::string::npos)
        {
            throw Error("unterminated <DataSet> tag", path);
        }
        const std::string tag = text.substr(pos, end - pos);
        pos = end;

        std::string timeText, file, partText;
        if (!attribute(tag, "timestep", timeText))
        {
            throw Error("<DataSet> without timestep", path, "timestep");
        }
        if (!attribute(tag, "file", file))
        {
            throw Error("<DataSet> without file", path, "file");
        }
        Entry e{0, file, 0};
        std::istringstream ts(timeText);
        ts.imbue(std::locale::classic());
        if (!(ts >> e.time))
        {
            throw Error("timestep '" + timeText + "' is not a number", path, "timestep");
        }
        if (attribute(tag, "part", partText))
        {
            std::istringstream ps(partText);
            if (!(ps >> e.part))
            {
                throw Error("part '" + partText + "' is not an integer", path, "part");
            }
        }
        if (e.time < restartTime)
        {
            loaded.push_back(std::move(e));
        }
    }
    entries_ = std::move(loaded);
    return true;
}


void PvdCollection::write(const std::string& path) const
{
    std::string out =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <Collection>\n";
    for (const Entry& e : entries_)
    {
        out += "    <DataSet timestep=\"";
        put(out, e.time);
        out += "\" group=\"\" part=\"" + std::to_string(e.part) + "\" file=\""
             + xmlEscape(e.file) + "\"/>\n";
    }
    out += "  </Collection>\n</VTKFile>\n";
    writeFileAtomically(path, out);
}

} // namespace polydem
