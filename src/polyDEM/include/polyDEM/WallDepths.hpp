// polyDEM: how deep each triangle's wall solid reaches below it, for the
// overlap of polyhedra with triangle meshes (PolyhedronOverlap.hpp: the
// triangle's prism, down to this floor).
//
// The floor is the radius of the largest ball inside the body that touches
// the triangle (the largest over seven points of it: the centroid and points
// 5 % in from the vertices and the edge midpoints), so that the prisms of a
// thin closed body (a hull, a lifter) stop near its middle and do not come
// out through its far side, and those of two faces meeting at an edge
// overlap less. The balls start at half the distance along the inward normal
// to the body's far side (the least of the seven points' rays, through a
// uniform grid by a 3D-DDA walk) and shrink from there (the shrinking-ball
// method, Ma, Bae, Choi & Rusinkiewicz 2012), never larger than maxDepth: a
// floor deeper than any particle can reach is not needed, and without that
// bound a ball inside a large round body would search the whole surface.
// kUnboundedWallDepth where no ray meets the surface again (an open wall, the
// outside of a container). Hits closer than 1e-6 of the mesh's size
// (coincident triangles) are ignored.
//
// Building bins the triangles (O(n)); each triangle's depth is worked out on
// first use, so that a caller that needs a few (the insertion checks) pays
// for those only.
#pragma once

#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

#include <cstddef>
#include <vector>

namespace polydem
{

class WallDepths
{
public:
    explicit WallDepths(const TriangleMesh& mesh, double maxDepth = kUnboundedWallDepth);

    //- The floor depth of triangle t (worked out on first use)
    double operator()(std::size_t t);

    //- All triangles' depths
    std::vector<double> all();

private:
    //- Nearest hit t > tMin_ of the ray p + t d, other than triangle self; -1: none
    double cast(const Vec3& p, const Vec3& d, std::size_t self);

    //- Radius of the largest ball inside the body touching the surface at m
    //  (outward normal n), no larger than rho
    double shrinkBall(const Vec3& m, const Vec3& n, double rho);

    std::size_t cellIndex(int i, int j, int k) const
    {
        return (std::size_t(k) * n_[1] + j) * n_[0] + i;
    }

    const TriangleMesh& mesh_;
    double maxDepth_;
    Vec3 lo_, cell_;
    int n_[3] = {1, 1, 1};
    double tMin_ = 0;
    std::vector<std::vector<int>> bins_;
    std::vector<std::size_t> seen_;
    std::size_t stamp_ = 0;
    std::vector<double> depth_;   //!< < 0: not worked out yet
};

//- Every triangle's floor depth (WallDepths(mesh, maxDepth).all())
std::vector<double> wallDepths(const TriangleMesh& mesh, double maxDepth = kUnboundedWallDepth);

} // namespace polydem
