#include "polyDEM/Insertion.hpp"

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
