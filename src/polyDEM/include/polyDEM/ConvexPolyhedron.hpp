// polyDEM: convex polyhedral particle shapes.
//
// ConvexPolyhedron is a flat, read-only view of one convex shape in its BODY
// frame (centroid at the origin, axes along the principal axes of inertia),
// usable on host and device: raw pointers into arrays owned elsewhere, no
// virtual functions, no std:: containers. Faces are convex polygons stored
// CSR-style (faceStart[f] .. faceStart[f+1]-1 index faceVertex[]), vertices in
// counter-clockwise order seen from outside; plane of face f:
// dot(faceNormal[f], x) = faceOffset[f], outward unit normal.
//
// ConvexShape is the host-side owner (std::vector storage plus the derived
// properties a user wants to see); PolyhedronTable packs many shapes into
// concatenated arrays + per-shape offsets so that a million particles of
// twenty shapes cost twenty shapes of memory on the device. Shapes are built
// and checked on the host by the polyDEMShapes library (src/polyDEM/shapes).
//
// Capacity: the contact routines (PolyhedronOverlap.hpp) use fixed stack
// buffers, hence the compile-time caps below; ConvexShape::check() and
// PolyhedronTable packing reject larger shapes with a polydem::Error.
#pragma once

#include "polyDEM/Error.hpp"
#include "polyDEM/Macros.hpp"
#include "polyDEM/Vec3.hpp"

#include <string>
#include <vector>

namespace polydem
{

//- Most vertices of one shape (a triangulated hull of V points has 2V-4 faces,
//  so with kMaxFaces = 64 a simplicial shape has at most 34 vertices)
constexpr int kMaxPolyhedronVertices = 64;
//- Most faces of one shape
constexpr int kMaxPolyhedronFaces = 64;
//- Most vertices of one face polygon
constexpr int kMaxFaceVertices = 32;
//- Most edges of one shape (E = V + F - 2 <= 126)
constexpr int kMaxPolyhedronEdges = 128;

//- An edge as two vertex indices (a < b)
struct PolyhedronEdge
{
    int a = 0, b = 0;
};

//- Flat, read-only view of one convex polyhedron in its body frame
struct ConvexPolyhedron
{
    int nVertices = 0;
    int nFaces = 0;
    int nEdges = 0;

    const Vec3* vertices = nullptr;        //!< [nVertices], body frame
    const Vec3* faceNormals = nullptr;     //!< [nFaces], outward unit normals
    const double* faceOffsets = nullptr;   //!< [nFaces], dot(n, x) = offset on the face
    const int* faceStart = nullptr;        //!< [nFaces + 1], into faceVertex, starts at 0
    const int* faceVertex = nullptr;       //!< [faceStart[nFaces]], CCW seen from outside
    const PolyhedronEdge* edges = nullptr; //!< [nEdges]

    double boundingRadius = 0;             //!< max |vertex| (centroid at origin)
    double volume = 0;
    Vec3 inertiaPerDensity;                //!< principal moments / density

    PD_INLINE int faceSize(int f) const { return faceStart[f + 1] - faceStart[f]; }

    //- Vertex i of face f (i in [0, faceSize(f)))
    PD_INLINE const Vec3& faceVertexPoint(int f, int i) const
    {
        return vertices[faceVertex[faceStart[f] + i]];
    }
};


//- Host-side owner of one convex shape and its derived properties
struct ConvexShape
{
    std::string name;

    // Geometry, body frame (see ConvexPolyhedron for the conventions)
    std::vector<Vec3> vertices;
    std::vector<Vec3> faceNormals;
    std::vector<double> faceOffsets;
    std::vector<int> faceStart{0};
    std::vector<int> faceVertex;
    std::vector<PolyhedronEdge> edges;

    // Properties (per unit density where mass enters)
    double volume = 0;
    double surfaceArea = 0;
    double equivalentDiameter = 0;    //!< diameter of the sphere of equal volume
    double sphericity = 0;            //!< pi^(1/3) (6V)^(2/3) / A (Wadell 1933)
    Vec3 crosswiseSphericity;         //!< per principal axis: (pi d^2/4) / projected area
    double boundingRadius = 0;
    Vec3 inertiaPerDensity;           //!< principal moments of inertia / density

    int nVertices() const { return int(vertices.size()); }
    int nFaces() const { return int(faceNormals.size()); }
    int nEdges() const { return int(edges.size()); }

    //- The device-style view of this shape (valid while *this is unchanged)
    ConvexPolyhedron view() const
    {
        ConvexPolyhedron v;
        v.nVertices = nVertices();
        v.nFaces = nFaces();
        v.nEdges = nEdges();
        v.vertices = vertices.data();
        v.faceNormals = faceNormals.data();
        v.faceOffsets = faceOffsets.data();
        v.faceStart = faceStart.data();
        v.faceVertex = faceVertex.data();
        v.edges = edges.data();
        v.boundingRadius = boundingRadius;
        v.volume = volume;
        v.inertiaPerDensity = inertiaPerDensity;
        return v;
    }

    //- Throw polydem::Error if the shape breaks the caps or is inconsistent
    void check() const
    {
        const std::string what = "convex shape '" + name + "': ";
        if (nVertices() < 4 || nVertices() > kMaxPolyhedronVertices)
        {
            throw Error(what + std::to_string(nVertices()) + " vertices, expected 4.."
                        + std::to_string(kMaxPolyhedronVertices));
        }
        if (nFaces() < 4 || nFaces() > kMaxPolyhedronFaces)
        {
            throw Error(what + std::to_string(nFaces()) + " faces, expected 4.."
                        + std::to_string(kMaxPolyhedronFaces));
        }
        if (nEdges() > kMaxPolyhedronEdges || nVertices() - nEdges() + nFaces() != 2)
        {
            throw Error(what + "edge count " + std::to_string(nEdges())
                        + " breaks Euler's formula V - E + F = 2 or the cap "
                        + std::to_string(kMaxPolyhedronEdges));
        }
        if (int(faceOffsets.size()) != nFaces() || int(faceStart.size()) != nFaces() + 1
            || faceStart.back() != int(faceVertex.size()))
        {
            throw Error(what + "face arrays of inconsistent sizes");
        }
        for (int f = 0; f < nFaces(); ++f)
        {
            const int n = faceStart[f + 1] - faceStart[f];
            if (n < 3 || n > kMaxFaceVertices)
            {
                throw Error(what + "face " + std::to_string(f) + " has " + std::to_string(n)
                            + " vertices, expected 3.." + std::to_string(kMaxFaceVertices));
            }
        }
        for (int i : faceVertex)
        {
            if (i < 0 || i >= nVertices())
            {
                throw Error(what + "face vertex index " + std::to_string(i) + " out of range");
            }
        }
    }
};


//- Many shapes in concatenated arrays: a POD of raw pointers, so that the same
//  struct serves host arrays (PackedPolyhedra::table()) and device copies of
//  them (fill the pointers with the device addresses of the same arrays).
struct PolyhedronTable
{
    int nShapes = 0;

    // Per shape [nShapes + 1]: where shape k starts in each concatenated array
    const int* vertexBegin = nullptr;
    const int* faceBegin = nullptr;       //!< into faceNormals / faceOffsets
    const int* faceStartBegin = nullptr;  //!< into faceStart (nFaces + 1 entries per shape)
    const int* faceVertexBegin = nullptr;
    const int* edgeBegin = nullptr;

    // Per shape [nShapes]
    const double* boundingRadius = nullptr;
    const double* volume = nullptr;
    const Vec3* inertiaPerDensity = nullptr;

    // Concatenated geometry (indices inside are local to the shape)
    const Vec3* vertices = nullptr;
    const Vec3* faceNormals = nullptr;
    const double* faceOffsets = nullptr;
    const int* faceStart = nullptr;
    const int* faceVertex = nullptr;
    const PolyhedronEdge* edges = nullptr;

    //- View of shape k
    PD_INLINE ConvexPolyhedron shape(int k) const
    {
        ConvexPolyhedron v;
        v.nVertices = vertexBegin[k + 1] - vertexBegin[k];
        v.nFaces = faceBegin[k + 1] - faceBegin[k];
        v.nEdges = edgeBegin[k + 1] - edgeBegin[k];
        v.vertices = vertices + vertexBegin[k];
        v.faceNormals = faceNormals + faceBegin[k];
        v.faceOffsets = faceOffsets + faceBegin[k];
        v.faceStart = faceStart + faceStartBegin[k];
        v.faceVertex = faceVertex + faceVertexBegin[k];
        v.edges = edges + edgeBegin[k];
        v.boundingRadius = boundingRadius[k];
        v.volume = volume[k];
        v.inertiaPerDensity = inertiaPerDensity[k];
        return v;
    }
};


//- Host storage behind a PolyhedronTable. Copy each vector to the device and
//  point a PolyhedronTable at the copies to use the shapes in kernels.
struct PackedPolyhedra
{
    std::vector<int> vertexBegin{0}, faceBegin{0}, faceStartBegin{0}, faceVertexBegin{0},
        edgeBegin{0};
    std::vector<double> boundingRadius, volume;
    std::vector<Vec3> inertiaPerDensity;
    std::vector<Vec3> vertices, faceNormals;
    std::vector<double> faceOffsets;
    std::vector<int> faceStart, faceVertex;
    std::vector<PolyhedronEdge> edges;

    int nShapes() const { return int(volume.size()); }

    //- Append one shape (checked against the caps); returns its index
    int add(const ConvexShape& s)
    {
        s.check();
        vertices.insert(vertices.end(), s.vertices.begin(), s.vertices.end());
        faceNormals.insert(faceNormals.end(), s.faceNormals.begin(), s.faceNormals.end());
        faceOffsets.insert(faceOffsets.end(), s.faceOffsets.begin(), s.faceOffsets.end());
        faceStart.insert(faceStart.end(), s.faceStart.begin(), s.faceStart.end());
        faceVertex.insert(faceVertex.end(), s.faceVertex.begin(), s.faceVertex.end());
        edges.insert(edges.end(), s.edges.begin(), s.edges.end());
        vertexBegin.push_back(int(vertices.size()));
        faceBegin.push_back(int(faceNormals.size()));
        faceStartBegin.push_back(int(faceStart.size()));
        faceVertexBegin.push_back(int(faceVertex.size()));
        edgeBegin.push_back(int(edges.size()));
        boundingRadius.push_back(s.boundingRadius);
        volume.push_back(s.volume);
        inertiaPerDensity.push_back(s.inertiaPerDensity);
        return nShapes() - 1;
    }

    //- A table over the host arrays (valid while *this is unchanged)
    PolyhedronTable table() const
    {
        PolyhedronTable t;
        t.nShapes = nShapes();
        t.vertexBegin = vertexBegin.data();
        t.faceBegin = faceBegin.data();
        t.faceStartBegin = faceStartBegin.data();
        t.faceVertexBegin = faceVertexBegin.data();
        t.edgeBegin = edgeBegin.data();
        t.boundingRadius = boundingRadius.data();
        t.volume = volume.data();
        t.inertiaPerDensity = inertiaPerDensity.data();
        t.vertices = vertices.data();
        t.faceNormals = faceNormals.data();
        t.faceOffsets = faceOffsets.data();
        t.faceStart = faceStart.data();
        t.faceVertex = faceVertex.data();
        t.edges = edges.data();
        return t;
    }
};

inline PackedPolyhedra packPolyhedra(const std::vector<ConvexShape>& shapes)
{
    PackedPolyhedra packed;
    for (const ConvexShape& s : shapes)
    {
        packed.add(s);
    }
    return packed;
}

} // namespace polydem
