// polyDEM: everything a simulation is set up with, as plain data.
// Front ends (demFoam reads constant/demProperties) fill it; System checks it.
#pragma once

#include "polyDEM/ConvexPolyhedron.hpp"
#include "polyDEM/TriangleMesh.hpp"
#include "polyDEM/Vec3.hpp"

#include <string>
#include <vector>

namespace polydem
{

enum class ContactLaw
{
    hertzMindlin,        //!< Hertz normal, Mindlin-Deresiewicz (no-slip) tangential
    linearSpringDashpot, //!< Cundall-Strack linear spring and dashpot
    overlapVolume        //!< volumetric (Blaze-DEM / Feng): Fn = Kn V n, for polyhedra
};

enum class RollingModel
{
    none,
    constantTorque,      //!< type A (Ai et al. 2011): M = -mu_r R* Fn w_rel/|w_rel|
    elasticPlastic       //!< type C (Ai et al. 2011): EPSD spring-dashpot, capped
};

enum class ShapeKind
{
    sphere,
    polyhedron
};

enum class MotionKind
{
    fixed,
    translation,  //!< constant velocity
    rotation      //!< constant angular velocity about an axis through a point
};

struct Material
{
    std::string name;
    double youngsModulus = 0;   //!< [Pa]
    double poissonsRatio = 0;   //!< [-]
    double density = 0;         //!< [kg/m3]
};

//- Interaction properties of a pair of materials
struct PairProperties
{
    double restitution = 0.5;     //!< normal coefficient of restitution
    double friction = 0.5;        //!< Coulomb sliding friction
    double rollingFriction = 0;   //!< rolling-resistance coefficient mu_r
    double rollingDamping = 0.3;  //!< EPSD viscous damping ratio eta_r
    double twistingFriction = 0;  //!< twisting (torsional) resistance coefficient mu_t
};

struct ContactModel
{
    ContactLaw law = ContactLaw::hertzMindlin;
    RollingModel rolling = RollingModel::none;
    //- Rolling-model option: twisting (torsional) resistance about the contact
    //  normal, M_t = -mu_t R* Fn w_n/|w_n| (with the pairs' twistingFriction)
    bool twisting = false;
    //- Linear law: normal stiffness [N/m]
    double normalStiffness = 0;
    //- Linear and overlapVolume laws: tangential / normal stiffness
    double tangentialStiffnessRatio = 2.0 / 7.0;
    //- overlapVolume law: normal force per overlap volume [N/m3]
    double volumetricStiffness = 0;
};

struct ParticleType
{
    std::string name;
    ShapeKind shape = ShapeKind::sphere;
    int material = 0;
    //- Default sphere radius (insertion may override per particle) [m]
    double radius = 0;
    //- Polyhedron: index into SimulationConfig::shapes
    int shapeIndex = -1;
};

struct WallMotion
{
    MotionKind kind = MotionKind::fixed;
    Vec3 velocity;           //!< translation [m/s]
    Vec3 origin;             //!< a point on the rotation axis [m]
    Vec3 axis{0, 0, 1};      //!< rotation axis (normalised by System)
    double omega = 0;        //!< angular speed [rad/s], right-handed about axis
};

struct PlaneWall
{
    std::string name;
    Vec3 point;              //!< a point on the plane at t = 0
    Vec3 normal{0, 0, 1};    //!< pointing into the particle side
    int material = 0;
    WallMotion motion;
    //- The point the wall load's torque is taken about, in the wall's
    //  frame at t = 0 (it moves with the wall; on a rotation axis it stays)
    Vec3 loadPoint;
};

struct MeshWall
{
    std::string name;
    TriangleMesh mesh;       //!< geometry at t = 0
    //- Per triangle, how deep its wall solid reaches for polyhedra; empty
    //  (the default): worked out by the engine and the insertion checks
    //  (WallDepths.hpp); given: used as it is
    std::vector<double> wallDepth;
    int material = 0;
    WallMotion motion;
    //- As PlaneWall::loadPoint
    Vec3 loadPoint;
};

//- A box whose particles are removed (an outlet region). The removal is the
//  domain's: both are applied where the neighbour lists are rebuilt, with
//  the particles' positions at that rebuild, and every removed particle is
//  reported with the region that removed it (Engine::takeRemoved)
struct OutletRegion
{
    std::string name;
    Vec3 min, max;
};

//- A box in which particles move kinematically (an inflow's approach
//  region, upstream of a fluid inlet, where the particles get no fluid force):
//  a particle whose centre lies in the box moves at velocity without
//  turning, whatever the forces on it (it still pushes the particles it
//  touches, and they do not push it); a particle that leaves the box is
//  free again. The test is made on the centre at the start of each step's
//  drift and again after it, so the state (positions) alone decides it and
//  a restart continues exactly.
struct ApproachRegion
{
    std::string name;
    Vec3 min, max;
    Vec3 velocity;
};

struct SimulationConfig
{
    double timeStep = 0;            //!< [s]
    Vec3 gravity{0, 0, -9.81};
    //- Particles leaving this box are removed (an outlet)
    Vec3 domainMin{-1e30, -1e30, -1e30}, domainMax{1e30, 1e30, 1e30};
    //- Particles inside one of these boxes are removed as well
    std::vector<OutletRegion> outlets;
    //- Kinematic boxes (ApproachRegion); where boxes overlap, the first wins
    std::vector<ApproachRegion> approaches;
    //- Verlet skin as a fraction of the largest particle diameter
    double skinFraction = 0.2;
    std::vector<Material> materials;
    //- materials.size()^2, row-major, symmetric
    std::vector<PairProperties> pairs;
    ContactModel contact;
    std::vector<ParticleType> types;
    //- Convex shapes of the polyhedral types (body frame, principal axes)
    std::vector<ConvexShape> shapes;
    std::vector<PlaneWall> planes;
    std::vector<MeshWall> meshes;
    //- Back end by name: "cpu" or "cuda"
    std::string device = "cpu";
    //- Where the config came from, for messages
    std::string source = "demProperties";

    const PairProperties& pair(int a, int b) const { return pairs[a * materials.size() + b]; }
};

} // namespace polydem
