// polyDEM shapes: mass properties of a closed polygonal surface and its
// principal axes.
//
// Volume, centroid and the inertia tensor (per unit density) are exact sums
// over signed tetrahedra from a reference point to the fan triangles of each
// face (divergence theorem; Tonon, F. 2004, "Explicit exact formulas for the
// 3-D tetrahedron inertia tensor in terms of its vertex coordinates",
// J. Math. Stat. 1:8-11). Principal axes by cyclic Jacobi rotations
// (Golub & Van Loan, "Matrix Computations", 8.5).
#pragma once

#include "polyDEM/Quaternion.hpp"
#include "polyDEM/Vec3.hpp"

#include <vector>

namespace polydem
{

//- 3x3 matrix, row major
struct Matrix3
{
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

    Vec3 column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
    Vec3 operator*(const Vec3& v) const
    {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    //- R^T v
    Vec3 transposeTimes(const Vec3& v) const
    {
        return {dot(column(0), v), dot(column(1), v), dot(column(2), v)};
    }
};

struct MassProperties
{
    double volume = 0;
    Vec3 centroid;
    Matrix3 inertia; //!< about the centroid, per unit density
};

//- Mass properties of the closed surface with convex (or star-shaped from
//  their first vertex) faces faceVertex[faceStart[f] .. faceStart[f+1]),
//  counter-clockwise seen from outside
MassProperties polyhedronMassProperties(const std::vector<Vec3>& points,
                                        const std::vector<int>& faceStart,
                                        const std::vector<int>& faceVertex);

//- Principal moments (ascending, ties keep their order) and the rotation R
//  whose columns are the principal axes (right handed): I = R diag(moments) R^T
void principalAxes(const Matrix3& inertia, Vec3& moments, Matrix3& rotation);

//- Unit quaternion of a rotation matrix: rotate(q, v) == R v
Quaternion quaternionOfRotation(const Matrix3& rotation);

} // namespace polydem
