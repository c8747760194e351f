// polyDEM: reading and writing STL surfaces (ASCII and binary).
//
// readStl detects the format from the file size (a binary STL is exactly
// 84 + 50 n bytes, whatever its header says: many exporters start binary
// headers with "solid"), merges duplicate vertices within a tolerance relative
// to the bounding-box diagonal, drops zero-area triangles and validates the
// rest. Every problem is reported as a polydem::Error naming the file.
// Triangle orientation is kept as in the file (nothing is re-oriented).
#pragma once

#include "polyDEM/TriangleMesh.hpp"

#include <cstddef>
#include <string>

namespace polydem
{

//- What readStl found, for logs ("dropped 3 degenerate triangles")
struct StlReadInfo
{
    bool binary = false;
    //- Facets in the file (over all solids of an ASCII file)
    std::size_t trianglesInFile = 0;
    //- Zero-area triangles (after vertex merging) that were dropped
    std::size_t degenerateDropped = 0;
    //- Vertices in the file (3 per facet) and after merging
    std::size_t verticesInFile = 0;
    std::size_t verticesMerged = 0;
};

//- Default merge tolerance, relative to the bounding-box diagonal
constexpr double stlMergeTolerance = 1e-9;

//- Read an ASCII or binary STL; coordinates are multiplied by scale (> 0).
//  info, when given, receives counts (degenerate triangles dropped, ...).
TriangleMesh readStl
(
    const std::string& path,
    double scale = 1.0,
    StlReadInfo* info = nullptr,
    double relativeMergeTolerance = stlMergeTolerance
);

//- Merge vertices closer than tol (absolute) in place and renumber the
//  triangles; returns the number of points removed. O(n) expected (hash grid).
std::size_t mergePoints(TriangleMesh& mesh, double tol);

//- Write an STL. Binary stores single precision (the format's limit);
//  ASCII writes round-trip double precision.
void writeStl
(
    const std::string& path,
    const TriangleMesh& mesh,
    bool binary = false,
    const std::string& solidName = "polyDEM"
);

} // namespace polydem
