// polyDEM engine: device vectors and the plain views of the state passed into the kernels.
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "polyDEM/ContactLaws.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"

#include "DeviceGeometry.hpp"

#include <thrust/device_vector.h>
#include <thrust/host_vector.h>

#include <cstdint>
#include <vector>

namespace polydem
{
namespace PD_BACKEND_NS
{

using detail::RigidMotion;
using std::int64_t;

template<class T>
using dvec = thrust::device_vector<T>;

template<class T>
T* ptr(dvec<T>& v)
{
    return thrust::raw_pointer_cast(v.data());
}

template<class T>
const T* ptr(const dvec<T>& v)
{
    return thrust::raw_pointer_cast(v.data());
}

template<class T>
std::vector<T> toHost(const dvec<T>& d)
{
    thrust::host_vector<T> h(d);
    return std::vector<T>(h.begin(), h.end());
}

template<class T>
void toDevice(dvec<T>& d, const std::vector<T>& h)
{
    d.assign(h.begin(), h.end());
}

// ---------------------------------------------------------------------------
// Plain device views of the state, passed by value into the functors
// ---------------------------------------------------------------------------

struct ParticleView
{
    int n;
    const int64_t* id;
    const int* type;
    const double* radius;
    const double* mass;
    const Vec3* inertia;
    Vec3* pos;
    Quaternion* q;
    Vec3* vel;
    Vec3* omega;
    Vec3* force;
    Vec3* torque;
    const Vec3* extForce;  //!< null when none
    const Vec3* extTorque;
    //- Kinematic approach boxes (SimulationConfig::approaches)
    const Vec3* approachLo;
    const Vec3* approachHi;
    const Vec3* approachVel;
    int nApproach;
};

//- The approach box holding x (the first), or -1
PD_HD inline int approachOf(const ParticleView& p, const Vec3& x)
{
    for (int k = 0; k < p.nApproach; ++k)
    {
        const Vec3 a = p.approachLo[k], b = p.approachHi[k];
        if (x.x >= a.x && x.x <= b.x && x.y >= a.y && x.y <= b.y && x.z >= a.z && x.z <= b.z)
        {
            return k;
        }
    }
    return -1;
}

struct PlaneDevice
{
    Vec3 point;
    Vec3 normal;
    int material;
    RigidMotion motion;
};

//- One triangle-mesh wall, its triangles in the body (t = 0) frame, binned
//  once into a uniform grid: particles are moved into the body frame instead
//  of the triangles into the world frame, so a moving wall is never re-binned.
struct MeshDevice
{
    int material;
    RigidMotion motion;
    int firstTriangle;     //!< into the global triangle arrays
    Vec3 gridOrigin;
    double cellSize;
    int nx, ny, nz;
    int firstCell;         //!< into the global cell-start array (nx*ny*nz + 1 entries)
};

struct MeshSlot
{
    int mesh;              //!< -1 = empty
    int triangle;
    Vec3 normal;
    Vec3 xi;
    Vec3 mr;
};

constexpr int maxMeshSlots = 6;
constexpr int maxMeshCandidates = 24;

struct LawView
{
    LawParameters law;
    const PairCoefficients* pairs;
    int nMaterials;
    const int* typeMaterial;
    const int* typeShape;       //!< -1: sphere, else index into shapes
    PolyhedronTable shapes;     //!< device copies of the convex shapes

    PD_HD const PairCoefficients& pair(int ma, int mb) const
    {
        return pairs[ma * nMaterials + mb];
    }
};

//- Per-contact functions forced inline on the CPU (a call per pair costs more than
//  the distance test of a non-touching one); nvcc decides for itself
#if defined(__CUDACC__)
#define PD_CONTACT PD_HD
#else
#define PD_CONTACT __attribute__((always_inline))
#endif

//- Particle kinds a kernel is compiled for: a run whose types are all spheres
//  gets kernels with no polyhedral code in them (smaller, fewer registers)
struct SphereKind
{
    static constexpr bool polyhedra = false;
};

struct MixedKind
{
    static constexpr bool polyhedra = true;
};

PD_HD inline double rollingInertiaOf(double I, double m, double r)
{
    return I + m * r * r;
}

} // namespace PD_BACKEND_NS
} // namespace polydem
