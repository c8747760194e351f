// Compile-only check: the polyhedron view and overlap routines are valid
// device code (nvcc -std=c++17 -arch=sm_90 -x cu -c).

#include "polyDEM/ConvexPolyhedron.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"

using namespace polydem;

__global__ void polyhedraOverlapKernel(PolyhedronTable table, const Vec3* pos, const Quaternion* q,
                                       const int* type, int n, OverlapResult* out)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i + 1 >= n)
    {
        return;
    }
    Vec3 axis;
    const ConvexPolyhedron a = table.shape(type[i]);
    const ConvexPolyhedron b = table.shape(type[i + 1]);
    OverlapResult r = polyhedronOverlap(a, pos[i], q[i], b, pos[i + 1], q[i + 1], &axis, true);
    const OverlapResult p = polyhedronPlaneOverlap(a, pos[i], q[i], Vec3(0, 0, 0), Vec3(0, 0, 1));
    const OverlapResult t = polyhedronTriangleOverlap(a, pos[i], q[i], Vec3(0, 0, 0),
                                                      Vec3(1, 0, 0), Vec3(0, 1, 0));
    const OverlapResult s = polyhedronSphereOverlap(a, pos[i], q[i], pos[i + 1], 0.1);
    r.volume += p.volume + t.volume + s.volume;
    out[i] = r;
}
