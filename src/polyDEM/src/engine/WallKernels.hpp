// polyDEM engine: the per-particle force sum (gravity, external, the pairs
// it is body 1 and body 2 of) and the wall contacts: planes through per-particle
// candidate lists, triangle meshes in a kernel of their own.
// Part of ThrustEngine.inl: compiled once per back end inside
// namespace polydem::PD_BACKEND_NS (defined by the including back end).
#pragma once

#include "Integration.hpp"
#include "PairKernels.hpp"
#include "ShapePairs.hpp"

namespace polydem
{
namespace PD_BACKEND_NS
{

//- One particle's share of one wall's load: the force and the torque about
//  the particle's centre that the wall's contacts exert on the particle
//  (WallLoadReduce turns them into the load on the wall)
struct WallShare
{
    Vec3 force;
    Vec3 torque;
    //- The part of force along each contact's normal (the rest is friction)
    Vec3 normalForce;
    //- Contacts (a count, kept as a double so that sums over steps add up)
    double contacts = 0;

    PD_HD void add(const Vec3& f, const Vec3& t)
    {
        force += f;
        torque += t;
    }

    //- One contact: its force, torque and normal component
    PD_HD void addContact(const Vec3& f, const Vec3& t, const Vec3& fn)
    {
        force += f;
        torque += t;
        normalForce += fn;
        contacts += 1;
    }

    PD_HD void addShare(const WallShare& q)
    {
        force += q.force;
        torque += q.torque;
        normalForce += q.normalForce;
        contacts += q.contacts;
    }
};

//- One particle's energy flows in one step [J] (Engine::enableEnergyFlows):
//  what its contacts dissipated (the pairs it is body 1 of, its wall
//  contacts), the work the moving walls did on it through those contacts,
//  and the work of its external force and torque (the fluid's)
struct EnergyFlow
{
    double pairDissipation = 0;
    double wallDissipation = 0;
    double wallWork = 0;
    double externalWork = 0;

    PD_HD void add(const EnergyFlow& q)
    {
        pairDissipation += q.pairDissipation;
        wallDissipation += q.wallDissipation;
        wallWork += q.wallWork;
        externalWork += q.externalWork;
    }
};

//- Per particle nWalls shares (planes, then meshes), null when wall loads are
//  off; the plane pass clears a particle's shares before its walls add to them
struct WallShares
{
    WallShare* share = nullptr;
    int nWalls = 0;
    int nPlanes = 0;

    PD_HD WallShare* plane(int i, int p) const
    {
        return share ? share + size_t(i) * nWalls + p : nullptr;
    }
    PD_HD WallShare* mesh(int i, int m) const
    {
        return share ? share + size_t(i) * nWalls + nPlanes + m : nullptr;
    }
    PD_HD void clear(int i) const
    {
        if (!share) return;
        for (int w = 0; w < nWalls; ++w) share[size_t(i) * nWalls + w] = WallShare();
    }
};

//- Contact of particle i with a wall under law Law (shared by planes and meshes)
template<class Law, class Kind>
struct WallContact
{
    ParticleView p;
    LawView law;

    PD_HD const PairCoefficients& coefficients(int i, int material) const
    {
        return law.nMaterials == 1 ? law.pairs[0] : law.pair(law.typeMaterial[p.type[i]], material);
    }

    //- Point contact of a sphere (Hertz, linear law) at wallPoint.
    //  planeNormal (planes only; into the particle side): a centre on or
    //  behind the plane keeps the plane's normal and the overlap r - h of
    //  its signed distance h, instead of the direction to the foot point,
    //  which flips there (pulling the sphere through, and an overlap below
    //  zero once h < -r)
    PD_CONTACT void point
    (
        int i, int material, const Vec3& wallPoint, const Vec3& wallVel, const Vec3& wallOmega,
        Vec3& xi, Vec3& mr, Vec3& F, Vec3& T, WallShare* load, EnergyFlow* flow,
        const Vec3* planeNormal = nullptr, double signedDistance = 0
    ) const
    {
        const Vec3 x = p.pos[i];
        const double r = p.radius[i];
        const Vec3 d = wallPoint - x;
        const double dist = norm(d);
        ContactKinematics k;
        if (planeNormal && !(signedDistance > 0))
        {
            k.normal = -1.0 * (*planeNormal);
            k.overlap = r - signedDistance;
        }
        else
        {
            k.normal = (1.0 / dist) * d;
            k.overlap = r - dist;
        }
        k.rStar = r;
        k.mStar = p.mass[i];
        if (needsResistanceInertia(law.law))
        {
            k.rollingInertia = rollingInertiaOf(p.inertia[i].x, p.mass[i], r);
            k.spinInertia = p.inertia[i].x;
        }
        const Vec3 arm = (r - 0.5 * k.overlap) * k.normal;
        k.relVelocity = p.vel[i] + cross(p.omega[i], arm) - wallVel;
        k.relOmega = p.omega[i] - wallOmega;
        const ContactResult res = contactForce<Law>(law.law, coefficients(i, material), k, xi, mr);
        const Vec3 t = cross(arm, res.force) + res.rollingTorque;
        F += res.force;
        T += t;
        if (load) load->addContact(res.force, t, dot(res.force, k.normal) * k.normal);
        if (flow) account(res, wallVel, wallOmega, *flow);
    }

    //- A wall contact's energy flows: its dissipation, and the work of its
    //  force and moment at the wall's velocity there (the wall's drive)
    PD_HD void account(const ContactResult& res, const Vec3& wallVel, const Vec3& wallOmega, EnergyFlow& flow) const
    {
        flow.wallDissipation += res.dissipated;
        flow.wallWork += (dot(res.force, wallVel) + dot(res.rollingTorque, wallOmega)) * law.law.dt;
    }

    //- Volumetric contact. ov.normal points from the wall into the particle;
    //  ov.centroid is the contact point.
    PD_HD void volumetric
    (
        int i, int material, const OverlapResult& ov, const Vec3& wallVel, const Vec3& wallOmega,
        Vec3& xi, Vec3& mr, Vec3& F, Vec3& T, WallShare* load, EnergyFlow* flow
    ) const
    {
        const Vec3 x = p.pos[i];
        ContactKinematics k;
        k.normal = -ov.normal;
        k.overlap = ov.volume;
        k.contactArea = ov.contactArea;
        k.rStar = p.radius[i];
        k.mStar = p.mass[i];
        if (needsResistanceInertia(law.law))
        {
            k.rollingInertia = rollingInertiaOf(p.inertia[i].x, p.mass[i], p.radius[i]);
            k.spinInertia = p.inertia[i].x;
        }
        const Vec3 arm = ov.centroid - x;
        k.relVelocity = p.vel[i] + cross(p.omega[i], arm) - wallVel;
        k.relOmega = p.omega[i] - wallOmega;
        const ContactResult res = contactForce<Law>(law.law, coefficients(i, material), k, xi, mr);
        const Vec3 t = cross(arm, res.force) + res.rollingTorque;
        F += res.force;
        T += t;
        if (load) load->addContact(res.force, t, dot(res.force, k.normal) * k.normal);
        if (flow) account(res, wallVel, wallOmega, *flow);
    }
};

//- Reset a wall spring, writing only when there is something to reset
PD_HD inline void clearSpring(Vec3& xi)
{
    if (xi.x != 0 || xi.y != 0 || xi.z != 0) xi = Vec3();
}

//- Per particle: gravity + external + its pairs (body 1 first, in list order,
//  then body 2, in pair order: deterministic whatever the thread schedule) +
//  its plane candidates; with Kick also the second half kick of the step.
//  OwnFromPairs: body 1's sums are summed here from the pairs (per-pair kernel)
//  instead of taken from PairKernel's ownForce/ownTorque; the order is the same.
template<class Law, class Kind, bool Kick, bool OwnFromPairs>
struct ParticleForces
{
    WallContact<Law, Kind> wall;
    Vec3 gravity;
    double time;
    double dt;

    PairLists pairs;
    const Vec3* ownForce;
    const Vec3* ownTorque;
    const int* inStart;     //!< n + 1: pairs of which the particle is body 2
    const int* inPair;
    int* contactCount;

    const PlaneDevice* planes;
    const int* planeStart;  //!< n + 1: plane candidates of each particle
    const int* planePlane;
    Vec3* planeXi;
    Vec3* planeMr;          //!< null without a rolling model
    int* wallContactCount;
    WallShares shares;      //!< wall loads (share null: off)
    EnergyFlow* energy = nullptr;   //!< per particle, energy flows on; else null
    const double* ownDissipation = nullptr;   //!< PairKernel's sums (energy on, !OwnFromPairs)

    //- Gravity and the external force and torque of particle i
    PD_HD void base(int i, Vec3& F, Vec3& T) const
    {
        const ParticleView& p = wall.p;
        F = p.mass[i] * gravity;
        T = Vec3();
        if (p.extForce) F += p.extForce[i];
        if (p.extTorque) T += p.extTorque[i];
    }

    //- Plane contacts of particle i (its candidates); returns how many touch
    PD_HD int planeContacts(int i, Vec3& F, Vec3& T) const
    {
        const ParticleView& p = wall.p;
        int walls = 0;
        const Vec3 x = p.pos[i];
        const double r = p.radius[i];
        const int cEnd = planeStart[i + 1];
        for (int c = planeStart[i]; c < cEnd; ++c)
        {
            const PlaneDevice& pl = planes[planePlane[c]];
            Vec3 n = pl.normal, p0 = pl.point;
            if (pl.motion.kind != int(MotionKind::fixed))
            {
                const Quaternion R = pl.motion.rotationAt(time);
                n = pl.motion.directionToWorld(pl.normal, R);
                p0 = pl.motion.toWorld(pl.point, time, R);
            }
            const double h = dot(x - p0, n);
            Vec3 noRolling;
            Vec3& mr = planeMr ? planeMr[c] : noRolling;
            if (h >= r)
            {
                clearSpring(planeXi[c]);
                if (planeMr) clearSpring(mr);
                continue;
            }
            const Vec3 foot = x - h * n;
            if constexpr (Law::volumetric)
            {
                const OverlapResult ov = planeOverlap<Kind>(p, wall.law, i, p0, n, foot);
                if (!ov.touching)
                {
                    clearSpring(planeXi[c]);
                    if (planeMr) clearSpring(mr);
                    continue;
                }
                ++walls;
                wall.volumetric(i, pl.material, ov, pl.motion.velocityAt(ov.centroid),
                                pl.motion.angularVelocity(), planeXi[c], mr, F, T,
                                shares.plane(i, planePlane[c]), energy ? energy + i : nullptr);
                continue;
            }
            ++walls;
            wall.point(i, pl.material, foot, pl.motion.velocityAt(foot), pl.motion.angularVelocity(),
                       planeXi[c], mr, F, T, shares.plane(i, planePlane[c]), energy ? energy + i : nullptr,
                       &n, h);
        }
        return walls;
    }

    //- Walls, store, kick: the end of particle i's step once its pair sums are
    //  in (pairDissipation: of the pairs it is body 1 of, energy flows on)
    PD_HD void finish(int i, Vec3 F, Vec3 T, double pairDissipation) const
    {
        const ParticleView& p = wall.p;
        shares.clear(i);
        if (energy)
        {
            energy[i] = EnergyFlow();
            energy[i].pairDissipation = pairDissipation;
            // The external force is constant over the step and the particle
            // moved by v(n+1/2) dt in it (velocity Verlet's drift): its work,
            // exactly the kinetic energy it adds; the torque's at w(n+1/2)
            if (p.extForce) energy[i].externalWork += dot(p.extForce[i], p.vel[i]) * dt;
            if (p.extTorque) energy[i].externalWork += dot(p.extTorque[i], p.omega[i]) * dt;
        }
        wallContactCount[i] = planeContacts(i, F, T);
        p.force[i] = F;
        p.torque[i] = T;
        if (Kick) finalKick<Kind>(p, wall.law.typeShape, dt, i, F, T);
    }

    //- Sum order: base, pairs as body 2 (pair order), pairs as body 1 (their
    //  sum, list order), planes. SerialStep produces the same operations.
    PD_HD void operator()(int i) const
    {
        Vec3 F, T;
        base(i, F, T);
        int touching = 0;
        const int inEnd = inStart[i + 1];
        for (int l = inStart[i]; l < inEnd; ++l)
        {
            const int k = inPair[l];
            if (!pairs.touching[k]) continue;
            ++touching;
            F -= pairs.force[k];
            T += pairs.torqueB[k];
        }
        Vec3 Fo, To;
        double Do = 0;
        const int end = pairs.start[i + 1];
        for (int k = pairs.start[i]; k < end; ++k)
        {
            if (!pairs.touching[k]) continue;
            ++touching;
            if (OwnFromPairs)
            {
                Fo += pairs.force[k];
                To += pairs.torqueA[k];
                if (energy) Do += pairs.dissipation[k];
            }
        }
        if (!OwnFromPairs)
        {
            Fo = ownForce[i];
            To = ownTorque[i];
            if (energy) Do = ownDissipation[i];
        }
        F += Fo;
        T += To;
        contactCount[i] = touching;
        finish(i, F, T, Do);
    }
};

//- Body 2's running sums in the one-thread force pass, in one cache line: a
//  touching pair adds to one line of its partner instead of to three arrays
struct alignas(64) ForceSum
{
    Vec3 force;
    Vec3 torque;
    int contacts;
};

//- CPU, one thread: the whole force pass in one loop over particles in order,
//  each pair's share for body 2 added straight into its accumulator (body 2
//  comes later in the order, so it is complete when its turn comes). The
//  operations and their order are those of PairKernel + ParticleForces, so
//  the result is bit-identical to the multi-threaded path.
template<class Law, class Kind, bool Kick>
struct SerialStep
{
    PairContact<Law, Kind> contact;
    ParticleForces<Law, Kind, Kick, false> forces;
    ForceSum* sums;
    static constexpr int prefetchDistance = 8;

    void run(int n) const
    {
        const PairLists& pl = contact.pl;
        const ParticleView& p = contact.p;
        for (int i = 0; i < n; ++i)
        {
            forces.base(i, sums[i].force, sums[i].torque);
            sums[i].contacts = 0;
        }
        const int nPairs = pl.start[n];
        for (int i = 0; i < n; ++i)
        {
            Vec3 Fo, To;
            double Do = 0;
            int touching = sums[i].contacts;
            const int end = pl.start[i + 1];
            for (int k = pl.start[i]; k < end; ++k)
            {
                // The partners lie anywhere in memory (cell-hash order): ask for
                // the lines of a pair a few pairs ahead while this one computes
                if (k + prefetchDistance < nPairs)
                {
                    const int ahead = pl.partner[k + prefetchDistance];
                    __builtin_prefetch(p.pos + ahead);
                    __builtin_prefetch(p.radius + ahead);
                    __builtin_prefetch(p.vel + ahead);
                    __builtin_prefetch(p.omega + ahead);
                    __builtin_prefetch(p.mass + ahead);
                    __builtin_prefetch(sums + ahead);
                }
                Vec3 f, ta, tb;
                double d;
                if (!contact(i, k, f, ta, tb, d)) continue;
                ++touching;
                Fo += f;
                To += ta;
                Do += d;
                ForceSum& partner = sums[pl.partner[k]];
                partner.force -= f;
                partner.torque += tb;
                ++partner.contacts;
            }
            forces.contactCount[i] = touching;
            forces.finish(i, sums[i].force + Fo, sums[i].torque + To, Do);
        }
    }
};

//- Triangle-mesh walls, after ParticleForces: adds to force/torque and the
//  wall-contact count; with Kick also the second half kick of the step
template<class Law, class Kind, bool Kick>
struct MeshWallKernel
{
    WallContact<Law, Kind> wall;
    double time;
    double dt;
    const MeshDevice* meshes;
    int nMeshes;
    const Vec3* triA;
    const Vec3* triB;
    const Vec3* triC;
    const double* triDepth;  //!< per triangle, the floor of its solid (polyhedra)
    const int* triSideStart; //!< per triangle, its side planes (CSR; polyhedra)
    const Vec3* triSideNormal;
    const double* triSideOffset;
    const int* cellStart;
    const int* cellTriangles;
    MeshSlot* meshSlots;     //!< per particle maxMeshSlots slots
    int* wallContactCount;
    WallShares shares;       //!< wall loads (share null: off); cleared by ParticleForces
    EnergyFlow* energy = nullptr;   //!< energy flows (null: off); set by ParticleForces

    PD_HD void operator()(int i) const
    {
        const ParticleView& p = wall.p;
        const LawView& law = wall.law;
        Vec3 F = p.force[i];
        Vec3 T = p.torque[i];
        int walls = wallContactCount[i];
        const Vec3 xi_ = p.pos[i];
        const double ri = p.radius[i];
    MeshSlot* slots = meshSlots + size_t(i) * maxMeshSlots;
        MeshSlot next[maxMeshSlots];
        int nNext = 0;

        for (int w = 0; w < nMeshes; ++w)
        {
            const MeshDevice& mesh = meshes[w];
            const Quaternion R = mesh.motion.rotationAt(time);
            const Vec3 y = mesh.motion.toBody(xi_, time, R);
            const Vec3 g = (y - mesh.gridOrigin) / mesh.cellSize;
            const int cx = int(floor(g.x)), cy = int(floor(g.y)), cz = int(floor(g.z));
            if (cx < 0 || cy < 0 || cz < 0 || cx >= mesh.nx || cy >= mesh.ny || cz >= mesh.nz) continue;
            const int cell = mesh.firstCell + (cz * mesh.ny + cy) * mesh.nx + cx;

            const int shapeI = law.typeShape[p.type[i]];
            if (Kind::polyhedra && Law::volumetric && shapeI >= 0)
            {
                // Polyhedron: every triangle's solid adds its own overlap
                // (neighbours meet on bisector planes and partition the
                // body, WallSidePlanes.hpp: nothing is counted twice, at
                // edges and corners too). The triangles a particle touches
                // form one contact per group of normals within 30 degrees (a face lying
                // across triangle edges, a curved wall; a corner has several):
                // its volume, first moment and area vector are the sums over
                // the group's triangles, so one spring, one dashpot (of the
                // whole area: the dashpot goes with the root of Kn A, which
                // would not add over triangles) and one friction history, and
                // however finely the wall is tessellated no triangle is left out
                const ConvexPolyhedron P = law.shapes.shape(shapeI);
                const Quaternion qBody = conjugate(R) * p.q[i];
                const double sameContact = 0.8660254037844387;   // cos 30 degrees
                OverlapResult group[maxMeshSlots];   // the first triangle's, then the sums
                Vec3 groupMoment[maxMeshSlots], groupFirstNormal[maxMeshSlots];
                int groupTriangle[maxMeshSlots], groupSize[maxMeshSlots];
                int nGroups = 0;
                for (int t = cellStart[cell]; t < cellStart[cell + 1]; ++t)
                {
                    const int tri = cellTriangles[t];
                    const int g0 = mesh.firstTriangle + tri;
                    const int s0 = triSideStart[g0];
                    const OverlapResult ov = polyhedronTriangleOverlap(P, y, qBody, triA[g0], triB[g0], triC[g0],
                                                                       triDepth[g0], triSideNormal + s0,
                                                                       triSideOffset + s0, triSideStart[g0 + 1] - s0);
                    if (!ov.touching) continue;
                    // The group whose first normal is nearest; a new one when
                    // none is within 30 degrees and there is room (with no room,
                    // the nearest: a particle touching more than maxMeshSlots
                    // walls at once keeps all their volume, under fewer normals)
                    int best = -1;
                    double bestDot = -2;
                    for (int k = 0; k < nGroups; ++k)
                    {
                        const double d = dot(groupFirstNormal[k], ov.normal);
                        if (d > bestDot)
                        {
                            bestDot = d;
                            best = k;
                        }
                    }
                    if ((best < 0 || bestDot <= sameContact) && nNext + nGroups < maxMeshSlots)
                    {
                        best = nGroups++;
                        group[best] = ov;
                        groupMoment[best] = ov.volume * ov.centroid;
                        groupFirstNormal[best] = ov.normal;
                        groupTriangle[best] = tri;
                        groupSize[best] = 1;
                        continue;
                    }
                    if (best < 0) continue;
                    group[best].volume += ov.volume;
                    groupMoment[best] += ov.volume * ov.centroid;
                    group[best].areaVector += ov.areaVector;
                    ++groupSize[best];
                }
                for (int k = 0; k < nGroups; ++k)
                {
                    OverlapResult& body = group[k];
                    if (groupSize[k] > 1)
                    {
                        body.centroid = (1.0 / body.volume) * groupMoment[k];
                        body.contactArea = norm(body.areaVector);
                        // A particle wholly inside the wall solid has no area
                        // vector: keep the first triangle's normal
                        body.normal = body.contactArea > 1e-9 * P.boundingRadius * P.boundingRadius
                                          ? body.areaVector / body.contactArea
                                          : groupFirstNormal[k];
                    }
                    OverlapResult ov = body;
                    ov.normal = mesh.motion.directionToWorld(body.normal, R);
                    ov.centroid = mesh.motion.toWorld(body.centroid, time, R);
                    // The friction history of last step's contact of this mesh
                    // along the same normal (slots keep -normal, world frame)
                    Vec3 sxi, smr;
                    double slotDot = sameContact;
                    for (int s2 = 0; s2 < maxMeshSlots; ++s2)
                    {
                        if (slots[s2].mesh != w) continue;
                        const double d = -dot(slots[s2].normal, ov.normal);
                        if (d > slotDot)
                        {
                            slotDot = d;
                            sxi = slots[s2].xi;
                            smr = slots[s2].mr;
                        }
                    }
                    ++walls;
                    wall.volumetric(i, mesh.material, ov, mesh.motion.velocityAt(ov.centroid),
                                    mesh.motion.angularVelocity(), sxi, smr, F, T, shares.mesh(i, w),
                                    energy ? energy + i : nullptr);
                    MeshSlot& ns = next[nNext++];
                    ns.mesh = w;
                    ns.triangle = groupTriangle[k];
                    ns.normal = -ov.normal;
                    ns.xi = sxi;
                    ns.mr = smr;
                }
                continue;
            }

            // Candidates: every triangle within reach
            Vec3 cPoint[maxMeshCandidates];
            double cDist[maxMeshCandidates];
            int cTri[maxMeshCandidates], cFeature[maxMeshCandidates];
            int nc = 0;
            for (int t = cellStart[cell]; t < cellStart[cell + 1]; ++t)
            {
                const int tri = cellTriangles[t];
                const int g0 = mesh.firstTriangle + tri;
                int feature;
                const Vec3 cp = detail::closestPointOnTriangle(y, triA[g0], triB[g0], triC[g0], feature);
                const double dd = norm(cp - y);
                if (dd >= ri || dd <= 0) continue;
                // Keep the nearest ones, sorted by feature (faces first) then distance
                int pos = nc < maxMeshCandidates ? nc : maxMeshCandidates - 1;
                if (nc == maxMeshCandidates)
                {
                    const bool better = feature < cFeature[pos] || (feature == cFeature[pos] && dd < cDist[pos]);
                    if (!better) continue;
                }
                else
                {
                    ++nc;
                }
                while (pos > 0 && (feature < cFeature[pos - 1] || (feature == cFeature[pos - 1] && dd < cDist[pos - 1])))
                {
                    cPoint[pos] = cPoint[pos - 1]; cDist[pos] = cDist[pos - 1];
                    cTri[pos] = cTri[pos - 1]; cFeature[pos] = cFeature[pos - 1];
                    --pos;
                }
                cPoint[pos] = cp; cDist[pos] = dd; cTri[pos] = tri; cFeature[pos] = feature;
            }

            // Accept face contacts; an edge or vertex contact is an artefact of the
            // tessellation when it lies on an accepted face's plane or on an
            // accepted contact point (the same touch seen by a neighbour triangle).
            int accepted[maxMeshCandidates];
            int na = 0;
            const double tol = 1e-9 * ri + 1e-6 * ri;
            for (int c = 0; c < nc; ++c)
            {
                bool duplicate = false;
                for (int a = 0; a < na && !duplicate; ++a)
                {
                    const int q = accepted[a];
                    if (norm(cPoint[c] - cPoint[q]) < tol) duplicate = true;
                    else if (cFeature[c] != detail::featureFace && cFeature[q] == detail::featureFace)
                    {
                        const Vec3 nq = (y - cPoint[q]) / cDist[q];
                        if (fabs(dot(cPoint[c] - cPoint[q], nq)) < tol) duplicate = true;
                    }
                }
                if (!duplicate) accepted[na++] = c;
            }

            for (int a = 0; a < na && nNext < maxMeshSlots; ++a)
            {
                const int c = accepted[a];
                const Vec3 nBody = (cPoint[c] - y) / cDist[c];
                const Vec3 nWorld = mesh.motion.directionToWorld(nBody, R);
                // The spring of this touch: same triangle, else a neighbour
                // triangle touched last step with nearly the same normal
                Vec3 sxi, smr;
                int found = -1;
                for (int s = 0; s < maxMeshSlots; ++s)
                {
                    if (slots[s].mesh == w && slots[s].triangle == cTri[c]) { found = s; break; }
                }
                if (found < 0)
                {
                    for (int s = 0; s < maxMeshSlots; ++s)
                    {
                        if (slots[s].mesh == w && dot(slots[s].normal, nWorld) > 0.99) { found = s; break; }
                    }
                }
                if (found >= 0)
                {
                    sxi = slots[found].xi;
                    smr = slots[found].mr;
                }
                const Vec3 wallPoint = mesh.motion.toWorld(cPoint[c], time, R);
                ++walls;
                if constexpr (Law::volumetric)
                {
                    // A sphere under the volumetric law: the cap cut by the
                    // tangent plane at the closest point
                    const OverlapResult ov = sphereHalfSpaceOverlap(xi_, ri, wallPoint, -nWorld);
                    wall.volumetric(i, mesh.material, ov, mesh.motion.velocityAt(ov.centroid),
                                    mesh.motion.angularVelocity(), sxi, smr, F, T, shares.mesh(i, w),
                                    energy ? energy + i : nullptr);
                }
                else
                {
                    wall.point(i, mesh.material, wallPoint, mesh.motion.velocityAt(wallPoint),
                               mesh.motion.angularVelocity(), sxi, smr, F, T, shares.mesh(i, w),
                               energy ? energy + i : nullptr);
                }
                MeshSlot& ns = next[nNext++];
                ns.mesh = w;
                ns.triangle = cTri[c];
                ns.normal = nWorld;
                ns.xi = sxi;
                ns.mr = smr;
            }
        }
        for (int s = 0; s < maxMeshSlots; ++s)
        {
            if (s < nNext) slots[s] = next[s];
            else slots[s].mesh = -1;
        }
        wallContactCount[i] = walls;
        p.force[i] = F;
        p.torque[i] = T;
        if (Kick) finalKick<Kind>(p, law.typeShape, dt, i, F, T);
    }
};

//- Particles per block of the wall-load sum: fixed, so that the order of the
//  additions depends on the particle order only (not on threads or device)
constexpr int wallLoadBlock = 256;

//- Where a wall's torque is taken: its load point carried with its motion
struct WallLoadPoint
{
    RigidMotion motion;
    Vec3 point;     //!< in the wall's frame at t = 0

    PD_HD Vec3 at(double t) const { return motion.toWorld(point, t, motion.rotationAt(t)); }
};

//- One (block, wall): the load on the wall from the block's particles, in
//  particle order: F_w = -sum f_i, T_w = -sum [(x_i - O_w) x f_i + t_i]
struct WallLoadBlocks
{
    const WallShare* share;
    const Vec3* pos;
    const WallLoadPoint* points;
    int n;
    int nWalls;
    double time;
    WallShare* blockSum;    //!< nBlocks x nWalls

    PD_HD void operator()(int k) const
    {
        const int b = k / nWalls;
        const int w = k % nWalls;
        const Vec3 O = points[w].at(time);
        WallShare s;
        const int end = (b + 1) * wallLoadBlock < n ? (b + 1) * wallLoadBlock : n;
        for (int i = b * wallLoadBlock; i < end; ++i)
        {
            const WallShare& q = share[size_t(i) * nWalls + w];
            s.force -= q.force;
            s.torque -= cross(pos[i] - O, q.force) + q.torque;
            s.normalForce -= q.normalForce;
            s.contacts += q.contacts;
        }
        blockSum[k] = s;
    }
};

//- One wall: its block sums in block order; the step's load, and its running sum
struct WallLoadTotal
{
    const WallShare* blockSum;
    int nBlocks;
    int nWalls;
    bool accumulate;
    WallShare* current;
    WallShare* sum;

    PD_HD void operator()(int w) const
    {
        WallShare s;
        for (int b = 0; b < nBlocks; ++b)
        {
            s.addShare(blockSum[size_t(b) * nWalls + w]);
        }
        current[w] = s;
        if (accumulate) sum[w].addShare(s);
    }
};

//- Particles per block of the energy-flow sum: fixed, as for the wall loads
constexpr int energyFlowBlock = 256;

//- One block: its particles' energy flows in particle order
struct EnergyFlowBlocks
{
    const EnergyFlow* flow;
    int n;
    EnergyFlow* blockSum;

    PD_HD void operator()(int b) const
    {
        EnergyFlow s;
        const int end = (b + 1) * energyFlowBlock < n ? (b + 1) * energyFlowBlock : n;
        for (int i = b * energyFlowBlock; i < end; ++i) s.add(flow[i]);
        blockSum[b] = s;
    }
};

//- The blocks in order, added to the running sum (one thread)
struct EnergyFlowTotal
{
    const EnergyFlow* blockSum;
    int nBlocks;
    EnergyFlow* sum;

    PD_HD void operator()(int) const
    {
        EnergyFlow s;
        for (int b = 0; b < nBlocks; ++b) s.add(blockSum[b]);
        sum->add(s);
    }
};

} // namespace PD_BACKEND_NS
} // namespace polydem
