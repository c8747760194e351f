// polyDEM engine: particle-particle contact kernels.
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "ShapePairs.hpp"

namespace polydem
{
namespace PD_BACKEND_NS
{

//- The pairs of the half lists (CSR: pairs of particle i at start[i] .. start[i+1]-1)
struct PairLists
{
    const int* start;       //!< n + 1
    const int* partner;     //!< body 2 of each pair
    const int* owner;       //!< body 1 of each pair
    Vec3* xi;               //!< tangential springs
    Vec3* mr;               //!< rolling springs, null without a rolling model
    unsigned char* touching;
    Vec3* force;            //!< on body 1, where touching
    Vec3* torqueA;          //!< on body 1 (per-pair kernel only)
    Vec3* torqueB;          //!< on body 2, where touching
    //- Polyhedron pairs (null otherwise): the axis that separated the pair at
    //  its last evaluation, or its contact normal; tried first, so a pair that
    //  stays apart is rejected with one projection instead of the face tests,
    //  and a pair that touched (touching[k]) skips those tests and is clipped
    //  in a slab along it. The result depends on it at round-off, so a
    //  touching pair's normal is kept with its springs (rebuilds, snapshots:
    //  PairHistory::normal). Zero = none.
    Vec3* separatingAxis;
    //- Energy each touching pair dissipated in the step [J] (per-pair kernel
    //  with energy flows on; null otherwise)
    double* dissipation;
};

//- One contact of law Law between particles of kinds Kind: kinematics, law,
//  history. Returns false (and drops the springs) when the pair does not touch.
template<class Law, class Kind>
struct PairContact
{
    ParticleView p;
    LawView law;
    PairLists pl;

    //- A contact that ended: its springs go (written only once, not every step
    //  for every neighbour out of reach)
    PD_HD void release(int k) const
    {
        if (pl.touching[k])
        {
            pl.touching[k] = 0;
            pl.xi[k] = Vec3();
            if (pl.mr) pl.mr[k] = Vec3();
        }
    }

    //- D: the energy the contact dissipated in the step (0 unless law.accountEnergy)
    PD_CONTACT bool operator()(int a, int k, Vec3& F, Vec3& Ta, Vec3& Tb, double& D) const
    {
        const int b = pl.partner[k];
        const Vec3 d = p.pos[b] - p.pos[a];
        const double ra = p.radius[a], rb = p.radius[b];
        const double reach = ra + rb;
        const double distSqr = normSqr(d);
        // Bounding spheres first (for polyhedra the exact overlap is the costly part)
        if (distSqr >= reach * reach || distSqr <= 0)
        {
            release(k);
            return false;
        }
        ContactKinematics kin;
        Vec3 armA, armB;
        if constexpr (Law::volumetric)
        {
            const OverlapResult ov = pairOverlap<Kind>(p, law, a, b,
                                                       pl.separatingAxis ? pl.separatingAxis + k : nullptr,
                                                       pl.touching[k] != 0);
            if (!ov.touching)
            {
                release(k);
                return false;
            }
            kin.normal = ov.normal;
            kin.overlap = ov.volume;
            kin.contactArea = ov.contactArea;
            armA = ov.centroid - p.pos[a];
            armB = ov.centroid - p.pos[b];
        }
        else
        {
            const double dist = sqrt(distSqr);
            kin.overlap = reach - dist;
            kin.normal = (1.0 / dist) * d;
            armA = (ra - 0.5 * kin.overlap) * kin.normal;
            armB = -(rb - 0.5 * kin.overlap) * kin.normal;
        }
        kin.rStar = ra * rb / reach;
        const double ma = p.mass[a], mb = p.mass[b];
        kin.mStar = ma * mb / (ma + mb);
        if (needsResistanceInertia(law.law))
        {
            const double Ia = rollingInertiaOf(p.inertia[a].x, ma, ra);
            const double Ib = rollingInertiaOf(p.inertia[b].x, mb, rb);
            kin.rollingInertia = Ia * Ib / (Ia + Ib);
            kin.spinInertia = p.inertia[a].x * p.inertia[b].x / (p.inertia[a].x + p.inertia[b].x);
        }
        const Vec3 wa = p.omega[a], wb = p.omega[b];
        kin.relVelocity = (p.vel[a] + cross(wa, armA)) - (p.vel[b] + cross(wb, armB));
        kin.relOmega = wa - wb;
        const PairCoefficients& pc = law.nMaterials == 1 ? law.pairs[0]
                                   : law.pair(law.typeMaterial[p.type[a]], law.typeMaterial[p.type[b]]);
        Vec3 noRolling;
        const ContactResult res = contactForce<Law>(law.law, pc, kin, pl.xi[k], pl.mr ? pl.mr[k] : noRolling);
        pl.touching[k] = 1;
        F = res.force;
        Ta = cross(armA, res.force) + res.rollingTorque;
        Tb = cross(armB, -res.force) - res.rollingTorque;
        D = res.dissipated;
        return true;
    }
};

//- CPU: one thread per particle over the pairs it owns. Body 1's share is summed
//  here in list order (ownForce/ownTorque); body 2's share stays in the pair for
//  the gather. Same sums as the per-pair kernel followed by ParticleForces.
template<class Law, class Kind>
struct PairKernel
{
    PairContact<Law, Kind> contact;
    Vec3* ownForce;
    Vec3* ownTorque;
    double* ownDissipation;   //!< energy flows on: its pairs' dissipation; else null

    PD_HD void operator()(int i) const
    {
        Vec3 F, T;
        double D = 0;
        const PairLists& pl = contact.pl;
        const int end = pl.start[i + 1];
        for (int k = pl.start[i]; k < end; ++k)
        {
            Vec3 f, ta, tb;
            double d;
            if (contact(i, k, f, ta, tb, d))
            {
                F += f;
                T += ta;
                D += d;
                pl.force[k] = f;
                pl.torqueB[k] = tb;
            }
        }
        ownForce[i] = F;
        ownTorque[i] = T;
        if (ownDissipation) ownDissipation[i] = D;
    }
};

//- GPU: one thread per pair (a polyhedron pair is a long serial computation,
//  and one thread per particle leaves a small system with too few threads)
template<class Law, class Kind>
struct PairPerPairKernel
{
    PairContact<Law, Kind> contact;

    PD_HD void operator()(int k) const
    {
        const PairLists& pl = contact.pl;
        Vec3 f, ta, tb;
        double d;
        if (contact(pl.owner[k], k, f, ta, tb, d))
        {
            pl.force[k] = f;
            pl.torqueA[k] = ta;
            pl.torqueB[k] = tb;
            if (pl.dissipation) pl.dissipation[k] = d;
        }
    }
};

} // namespace PD_BACKEND_NS
} // namespace polydem
