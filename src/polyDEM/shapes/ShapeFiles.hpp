// polyDEM shapes: reading point sets (STL ascii/binary, OBJ) and writing
// shapes (STL ascii/binary, properties in OpenFOAM dictionary syntax).
#pragma once

#include "ConvexShapeBuilder.hpp"

#include "polyDEM/ConvexPolyhedron.hpp"

#include <string>
#include <vector>

namespace polydem
{

//- Vertices of an STL (ascii or binary, detected from the size) or OBJ ('v' lines)
//  file; duplicates are harmless for the hull. Throws polydem::Error.
std::vector<Vec3> readPointSet(const std::string& fileName);

//- Faces as triangle fans; binary or ascii STL. Throws polydem::Error.
void writeStl(const ConvexShape& shape, const std::string& fileName, bool binary = false);

//- Properties as an OpenFOAM-style dictionary (with the placement of the
//  input points when given)
void writeProperties(const ConvexShape& shape, const std::string& fileName,
                     const BodyPlacement* placement = nullptr);

} // namespace polydem
