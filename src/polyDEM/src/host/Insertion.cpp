#include "polyDEM/Insertion.hpp"

#include "polyDEM/Error.hpp"
#include "polyDEM/InsertionChecks.hpp"
#include "polyDEM/PolyhedronOverlap.hpp"
#include "polyDEM/System.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace polydem
{

InsertedParticles insertRandomFill
(
    const System& system,
    const RandomFillInsertion& ins,
    const ParticleState& obstacles,
    std::int64_t firstId
)
{
    std::vector<SphereSeed> existing(obstacles.size());
    for (std::size_t i = 0; i < obstacles.size(); ++i)
    {
        existing[i].position = obstacles.position[i];
        existing[i].radius = obstacles.radius[i];
    }
    const std::vector<SphereSeed> seeds =
        randomFill(ins.region, ins.sizes, ins.number, ins.seed, ins.gap, existing,
                   ins.maxAttempts, ins.partial);

    const InsertionTypes& ut = ins.types;
    const SimulationConfig& config = system.config();
    std::vector<Vec3> positions(seeds.size());
    std::vector<double> radii(seeds.size());
    std::vector<int> types(seeds.size(), ut.firstType);
    for (std::size_t i = 0; i < seeds.size(); ++i)
    {
        positions[i] = seeds[i].position;
        radii[i] = seeds[i].radius;
    }

    // Polyhedra: the shape whose bounding sphere the seed is (a random one
    // among shapes of equal bounding radius) and a uniformly random
    // orientation (Shoemake 1992), from the insertion's seed
    std::vector<Quaternion> q(seeds.size());
    if (ut.polyhedron)
    {
        std::mt19937_64 rng(ins.seed * 0x9E3779B97F4A7C15ULL + 12345u);
        auto uniform = [&rng]() { return double(rng() >> 11) * 0x1.0p-53; };
        for (std::size_t i = 0; i < seeds.size(); ++i)
        {
            double best = 1e300;
            std::vector<int> ties;
            for (int k = 0; k < ut.nTypes; ++k)
            {
                const double dr = std::abs(config.types[ut.firstType + k].radius - radii[i]);
                if (dr < best - 1e-12 * radii[i])
                {
                    best = dr;
                    ties.assign(1, ut.firstType + k);
                }
                else if (dr <= best + 1e-12 * radii[i])
                {
                    ties.push_back(ut.firstType + k);
                }
            }
            types[i] = ties[std::min(ties.size() - 1, std::size_t(uniform() * ties.size()))];

            const double u1 = uniform(), u2 = uniform(), u3 = uniform();
            const double twoPi = 2 * M_PI;
            const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
            q[i] = normalised(Quaternion{b * std::cos(twoPi * u3), a * std::sin(twoPi * u2),
                                         a * std::cos(twoPi * u2), b * std::sin(twoPi * u3)});
            if (ins.fixedOrientation)
            {
                q[i] = ins.orientation;
            }
            if (ins.fixedOrientation && ins.randomYaw)
            {
                // A uniform heading about the axis, after the given orientation
                const Vec3 axis = ins.yawAxis / norm(ins.yawAxis);
                q[i] = normalised(fromRotationVector((twoPi * uniform()) * axis) * ins.orientation);
            }
        }
    }

    InsertedParticles result;
    ParticleState& p = result.particles;
    p = system.makeSpheres(ut.firstType, positions, radii, firstId);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        p.velocity[i] = ins.velocity;
        if (ut.polyhedron)
        {
            const auto& type = config.types[types[i]];
            const auto& shape = config.shapes[type.shapeIndex];
            const double rho = config.materials[type.material].density;
            p.type[i] = types[i];
            p.orientation[i] = q[i];
            p.mass[i] = rho * shape.volume;
            p.inertia[i] = rho * shape.inertiaPerDensity;
            p.radius[i] = shape.boundingRadius;
            result.volume += shape.volume;
        }
        else
        {
            result.volume += 4.0 / 3.0 * M_PI * std::pow(radii[i], 3);
        }
    }
    return result;
}


InsertedParticles insertLayer
(
    const System& system,
    const LayerInsertion& ins,
    const ParticleState& present,
    std::int64_t firstId
)
{
    const SimulationConfig& config = system.config();
    if (ins.types.empty())
    {
        throw Error("a floating layer insertion needs at least one particle type");
    }
    // All polyhedra or all spheres (each sphere type of one diameter): the
    // particles are made by one path below
    const bool spheres =
        ins.types[0] >= 0 && ins.types[0] < int(config.types.size())
     && config.types[ins.types[0]].shape == ShapeKind::sphere;
    for (const int t : ins.types)
    {
        if (t < 0 || t >= int(config.types.size()))
        {
            throw Error("a floating layer insertion: particle type index out of range");
        }
        if ((config.types[t].shape == ShapeKind::sphere) != spheres)
        {
            throw Error("a floating layer insertion places either polyhedra or spheres, not both");
        }
        if (spheres && !(config.types[t].radius > 0))
        {
            throw Error("a floating layer insertion of spheres needs each type's diameter");
        }
    }

    // A body: centre, orientation, shape (polyhedra) or sphere radius
    struct Body
    {
        Vec3 x;
        Quaternion q;
        double r = 0;
        const ConvexShape* shape = nullptr;
    };
    auto bodyOf = [&](const ParticleState& p, std::size_t i)
    {
        Body b;
        b.x = p.position[i];
        b.q = p.orientation[i];
        b.r = p.radius[i];
        const ParticleType& t = config.types.at(p.type[i]);
        if (t.shape == ShapeKind::polyhedron)
        {
            b.shape = &config.shapes.at(t.shapeIndex);
            b.r = b.shape->boundingRadius;
        }
        return b;
    };
    auto touch = [](const Body& a, const Body& b)
    {
        if (norm(b.x - a.x) >= a.r + b.r) return false;
        if (a.shape && b.shape)
        {
            return polyhedronOverlap(a.shape->view(), a.x, a.q, b.shape->view(), b.x, b.q).touching;
        }
        if (a.shape) return polyhedronSphereOverlap(a.shape->view(), a.x, a.q, b.x, b.r).touching;
        if (b.shape) return polyhedronSphereOverlap(b.shape->view(), b.x, b.q, a.x, a.r).touching;
        return true;
    };

    // A new body of a type: the polyhedron's shape, or the sphere's radius
    auto newBody = [&](const int type)
    {
        Body b;
        const ParticleType& t = config.types[type];
        if (t.shape == ShapeKind::polyhedron)
        {
            b.shape = &config.shapes[t.shapeIndex];
            b.r = b.shape->boundingRadius;
        }
        else
        {
            b.r = t.radius;
        }
        return b;
    };

    // The particles that can touch the plan rectangle's blocks
    double rMax = 0;
    for (const int t : ins.types)
    {
        rMax = std::max(rMax, newBody(t).r);
    }
    std::vector<Body> near;
    for (std::size_t i = 0; i < present.size(); ++i)
    {
        const Vec3& x = present.position[i];
        const double reach = rMax + present.radius[i];
        if (x.x >= ins.min.x - reach && x.x <= ins.max.x + reach && x.y >= ins.min.y - reach
            && x.y <= ins.max.y + reach && std::abs(x.z - ins.height) <= reach)
        {
            near.push_back(bodyOf(present, i));
        }
    }

    std::mt19937_64 rng(ins.seed * 0x9E3779B97F4A7C15ULL + 777u);
    auto uniform = [&rng]() { return double(rng() >> 11) * 0x1.0p-53; };
    const Vec3 axis = ins.yawAxis / norm(ins.yawAxis);
    std::vector<ListedParticle> placed;
    std::vector<Body> placedBodies;
    for (std::size_t n = 0; n < ins.number; ++n)
    {
        const std::size_t pick = std::min(ins.types.size() - 1, std::size_t(uniform() * ins.types.size()));
        const int type = ins.types[pick];
        const Quaternion base =
            ins.typeOrientations.size() == ins.types.size() ? ins.typeOrientations[pick] : ins.orientation;
        Body b = newBody(type);
        bool found = false;
        for (std::size_t a = 0; a < ins.maxAttempts && !found; ++a)
        {
            b.x = Vec3(ins.min.x + uniform() * (ins.max.x - ins.min.x),
                       ins.min.y + uniform() * (ins.max.y - ins.min.y), ins.height);
            b.q = base;
            if (ins.randomYaw)
            {
                b.q = normalised(fromRotationVector((2 * M_PI * uniform()) * axis) * base);
            }
            found = true;
            for (const PlaneWall& w : config.planes)
            {
                const bool touching = b.shape
                    ? polyhedronPlaneOverlap(b.shape->view(), b.x, b.q, w.point, w.normal).touching
                    : dot(b.x - w.point, w.normal) < b.r;
                if (w.motion.kind == MotionKind::fixed && touching)
                {
                    found = false;
                    break;
                }
            }
            for (std::size_t k = 0; found && k < near.size(); ++k)
            {
                found = !touch(b, near[k]);
            }
            for (std::size_t k = 0; found && k < placedBodies.size(); ++k)
            {
                found = !touch(b, placedBodies[k]);
            }
        }
        if (!found)
        {
            break;
        }
        placedBodies.push_back(b);
        ListedParticle lp;
        lp.position = b.x;
        lp.orientation = b.q;
        lp.velocity = ins.velocity;
        lp.type = type;
        lp.radius = b.r;
        placed.push_back(lp);
    }

    // Mesh walls (and moving planes, at their t = 0 place) to the insertion
    // tolerance: a block that reaches into one is dropped
    InsertionTypes ut;
    ut.firstType = ins.types[0];
    ut.polyhedron = !spheres;
    auto make = [&](const std::vector<ListedParticle>& list)
    {
        ParticleState q = insertList(system, ut, list, firstId);
        if (spheres)
        {
            // insertList made them all of the first type: each its own type,
            // with the mass of its own material
            for (std::size_t i = 0; i < q.size(); ++i)
            {
                q.type[i] = list[i].type;
                q.mass[i] = 0;
            }
            system.completeMassProperties(q);
        }
        return q;
    };
    ParticleState p = make(placed);
    if (!config.meshes.empty() && p.size() > 0)
    {
        const std::vector<InsertionOverlap> bad = insertionOverlaps(config, p, ParticleState(), false);
        std::vector<char> drop(p.size(), 0);
        for (const InsertionOverlap& o : bad)
        {
            if (o.partner == InsertionOverlap::Partner::wall) drop[o.particle] = 1;
        }
        std::vector<ListedParticle> kept;
        for (std::size_t i = 0; i < placed.size(); ++i)
        {
            if (!drop[i]) kept.push_back(placed[i]);
        }
        if (kept.size() != placed.size())
        {
            p = make(kept);
        }
    }
    InsertedParticles result;
    result.particles = p;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        result.volume += spheres
            ? 4.0 / 3.0 * M_PI * std::pow(p.radius[i], 3)
            : config.shapes[config.types[p.type[i]].shapeIndex].volume;
    }
    return result;
}


ParticleState insertList
(
    const System& system,
    const InsertionTypes& ut,
    const std::vector<ListedParticle>& list,
    std::int64_t firstId
)
{
    const SimulationConfig& config = system.config();
    const std::size_t n = list.size();
    std::vector<Vec3> positions(n);
    std::vector<double> radii(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        positions[i] = list[i].position;
        radii[i] = list[i].radius;
    }

    // The same path as the random fill: spheres of the type, then the shape,
    // mass properties and the given orientation for polyhedra
    ParticleState p = system.makeSpheres(ut.firstType, positions, radii, firstId);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const ListedParticle& lp = list[i];
        p.velocity[i] = lp.velocity;
        p.omega[i] = lp.omega;
        p.orientation[i] = lp.orientation;
        if (ut.polyhedron)
        {
            const auto& type = config.types[lp.type];
            const auto& shape = config.shapes[type.shapeIndex];
            const double rho = config.materials[type.material].density;
            p.type[i] = lp.type;
            p.mass[i] = rho * shape.volume;
            p.inertia[i] = rho * shape.inertiaPerDensity;
            p.radius[i] = shape.boundingRadius;
        }
    }
    return p;
}


std::int64_t nextParticleId(const ParticleState& p)
{
    std::int64_t next = 0;
    for (const std::int64_t id : p.id)
    {
        next = std::max(next, id + 1);
    }
    return next;
}


void appendParticles(ParticleState& a, const ParticleState& b)
{
    auto cat = [](auto& x, const auto& y) { x.insert(x.end(), y.begin(), y.end()); };
    cat(a.id, b.id);
    cat(a.type, b.type);
    cat(a.radius, b.radius);
    cat(a.mass, b.mass);
    cat(a.inertia, b.inertia);
    cat(a.position, b.position);
    cat(a.orientation, b.orientation);
    cat(a.velocity, b.velocity);
    cat(a.omega, b.omega);
    cat(a.force, b.force);
    cat(a.torque, b.torque);
}

} // namespace polydem
