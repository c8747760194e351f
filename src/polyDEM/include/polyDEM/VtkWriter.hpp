// polyDEM: VTK XML PolyData (.vtp) writers for ParaView, and a .pvd
// collection (time series index) that survives restarts.
//
// Files are ASCII with shortest round-trip double formatting (full
// precision). Particles are written as points with vertex cells and point
// data, so ParaView's Glyph filter can draw spheres scaled by "diameter"
// (the bounding diameter; Scale Factor = 1) or, where given, by
// "volumeEquivalentDiameter" (spheres of the particle's volume), oriented by
// "orientation". Surfaces are generic polygons: wall triangles, and
// polyhedral particles' faces with their particle's fields.
#pragma once

#include "polyDEM/ParticleState.hpp"
#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

#include <limits>
#include <string>
#include <vector>

namespace polydem
{

//- Particles as a point cloud. Point data: id (Int64), type (Int32),
//  radius, diameter, mass (Float64), velocity, omega, force, torque (3 x
//  Float64), orientation (4 x Float64, quaternion w x y z).
//  Arrays of ParticleState that are empty are skipped (e.g. no torque kept);
//  any other size mismatch throws polydem::Error.
//  volumeEquivalentDiameter, when not empty, is one value per particle,
//  (6 V/pi)^(1/3), written under that name: the glyph scale that shows a
//  polyhedron's volume ("diameter" is twice the bounding radius).
void writeParticlesVtp
(
    const std::string& path,
    const ParticleState& state,
    const std::vector<double>& volumeEquivalentDiameter = {}
);

//- Polygon surface. polygonIds, when not empty, is one int per polygon
//  written as cell data named idName (wall patch id, particle id, ...).
void writeSurfaceVtp
(
    const std::string& path,
    const std::vector<Vec3>& points,
    const std::vector<std::vector<int>>& polygons,
    const std::vector<int>& polygonIds = {},
    const std::string& idName = "id"
);

//- Particle faces (polyhedra.vtp): polygons over points, face p belonging to
//  the particle of index polygonParticle[p] in state. Cell data: the point
//  data of writeParticlesVtp for that particle, and particleId (= id).
void writeParticleFacesVtp
(
    const std::string& path,
    const std::vector<Vec3>& points,
    const std::vector<std::vector<int>>& polygons,
    const std::vector<std::size_t>& polygonParticle,
    const ParticleState& state,
    const std::vector<double>& volumeEquivalentDiameter = {}
);

//- Convenience: a triangle surface (walls)
void writeSurfaceVtp
(
    const std::string& path,
    const TriangleMesh& mesh,
    const std::vector<int>& triangleIds = {},
    const std::string& idName = "id"
);


//- ParaView .pvd index of a time series of files.
//  On restart read() the existing index first: earlier entries are kept,
//  those at or after the restart time are dropped (they are rewritten).
class PvdCollection
{
public:
    struct Entry
    {
        double time;
        std::string file; //!< relative to the .pvd file's folder
        int part;         //!< several files per time (particles, walls)
    };

    //- Add a data set. An entry at the same time and part is replaced, and
    //  entries at later times are dropped (a run that went back in time).
    void add(double time, const std::string& relativeFile, int part = 0);

    //- Load an existing .pvd, keeping entries with time < restartTime.
    //  A missing file is not an error (fresh start); returns whether one was read.
    //  A malformed file throws polydem::Error.
    bool read(const std::string& path,
              double restartTime = std::numeric_limits<double>::infinity());

    //- Write the index (to a temporary file, then renamed: never half-written)
    void write(const std::string& path) const;

    const std::vector<Entry>& entries() const { return entries_; }
    void clear() { entries_.clear(); }

private:
    std::vector<Entry> entries_;
};

} // namespace polydem
