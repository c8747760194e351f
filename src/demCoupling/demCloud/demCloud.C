#include "demCloud.H"
#include <cmath>
#include "demParallel.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "IOmanip.H"
#include "fvcDdt.H"

namespace Foam
{
    defineTypeNameAndDebug(demCloud, 0);
}

using Foam::demParallel::allSum;
using Foam::demParallel::broadcast;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCloud::demCloud
(
    const volVectorField& U,
    const volScalarField& p,
    scalar rho
)
:
    demCloud(U, p, rho, nullptr)
{}


Foam::demCloud::demCloud
(
    const volVectorField& U,
    const volScalarField& p,
    const demFreeSurface& fs
)
:
    demCloud(U, p, fs.rho1, &fs)
{}


Foam::demCloud::demCloud
(
    const volVectorField& U,
    const volScalarField& p,
    scalar rho,
    const demFreeSurface* fs
)
:
    mesh_(U.mesh()),
    dict_
    (
        IOobject
        (
            "couplingProperties",
            U.time().constant(),
            U.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    settings_(dict_),
    U_(U),
    p_(p),
    rho_(rho),
    backend_(),
    locate_(),
    voidFraction_(),
    smoothing_(),
    nSubSteps_(1),
    weights_(),
    exchange_(mesh_),
    oneWayFluidFraction_(),
    forceContext_(mesh_, settings_, rho_, U_, p_, weights_, previousUp_),
    forces_(),
    io_(mesh_.time())
{
    // The back end: on the master, or on every rank for a distributed DEM
    // (demBackend::onAllRanks: every call below then made on every rank;
    // the master's results are broadcast as for the others)
    if (Pstream::master() || demBackend::onAllRanks(dict_))
    {
        backend_ = demBackend::New(mesh_.time(), dict_);
        nSubSteps_ = backend_->stepsPerFluidStep();
        typeNames_ = backend_->typeNames();
        typeDensity_.setSize(typeNames_.size());
        sphericity_.setSize(typeNames_.size());
        crosswiseSphericity_.setSize(typeNames_.size());
        shapes_.setSize(typeNames_.size());
        forAll(typeDensity_, i)
        {
            typeDensity_[i] = backend_->typeDensity(i);
            backend_->typeShape(i, sphericity_[i], crosswiseSphericity_[i]);
            backend_->typePolyhedron(i, shapes_[i]);
        }
    }
    broadcast(sphericity_);
    broadcast(crosswiseSphericity_);
    broadcast(nSubSteps_);
    broadcast(typeNames_);
    broadcast(typeDensity_);
    {
        label nTypes = shapes_.size();
        broadcast(nTypes);
        shapes_.setSize(nTypes);
        for (demShape& sh : shapes_)
        {
            broadcast(sh.vertices);
            broadcast(sh.faces);
            broadcast(sh.normals);
            broadcast(sh.offsets);
            broadcast(sh.volume);
        }
    }

    settings_.checkSubSteps(nSubSteps_, mesh_.time().deltaTValue());

    locate_ = locateModel::New(dict_, mesh_);
    voidFraction_ = voidFractionModel::New(dict_, mesh_, locate_());
    smoothing_ = smoothingModel::New(dict_, mesh_);

    const wordList& forceNames = settings_.forceModelNames();
    forces_.setSize(forceNames.size());
    forAll(forceNames, i)
    {
        forces_.set(i, forceModel::New(forceNames[i], dict_, forceContext_));
    }

    settings_.readParticleShapes
    (
        typeNames_, sphericity_, crosswiseSphericity_, dnByDv_
    );

    if (!settings_.twoWay())
    {
        oneWayFluidFraction_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "oneWayFluidFraction",
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                mesh_,
                dimensionedScalar("one", dimless, 1)
            )
        );
    }

    io_.openSummary();

    updateParticles();

    if (fs)
    {
        settings_.checkFreeSurface();
        freeSurface_.reset(new demFreeSurface(*fs));
        submerged_.reset(new submergedVolume(mesh_, dict_));
        forceContext_.setFreeSurface(freeSurface_());
        Info<< "    free surface: phase densities " << fs->rho1 << ' '
            << fs->rho2
            << " kg/m3; rho and mu at a particle averaged over its volume"
            << endl;
    }

    checkInputEntries();
}


Foam::demCloud::~demCloud()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demCloud::checkInputEntries() const
{
    if (!backend_)
    {
        // The ranks without the back end read the same file
        return;
    }

    HashTable<wordList> coeffKeys;
    coeffKeys.set(locate_->type() + "Coeffs", locate_->coeffKeys());
    coeffKeys.set(voidFraction_->type() + "Coeffs", voidFraction_->coeffKeys());
    coeffKeys.set(smoothing_->type() + "Coeffs", smoothing_->coeffKeys());
    for (const forceModel& f : forces_)
    {
        coeffKeys.set(f.type() + "Coeffs", f.coeffKeys());
    }

    wordHashSet modelNames;
    modelNames.insert(locateModel::dictionaryConstructorTablePtr_->toc());
    modelNames.insert(voidFractionModel::dictionaryConstructorTablePtr_->toc());
    modelNames.insert(smoothingModel::dictionaryConstructorTablePtr_->toc());
    modelNames.insert(forceModel::dictionaryConstructorTablePtr_->toc());
    modelNames.insert(demBackend::dictionaryConstructorTablePtr_->toc());

    settings_.checkEntries
    (
        coeffKeys, backend_->dictKeys(), modelNames, freeSurface_.valid()
    );
}


void Foam::demCloud::updateParticles()
{
    // 1. Copy from the back end, broadcast
    if (backend_.valid())
    {
        backend_->particles(particles_);
    }
    demCouplingWeights::broadcast(particles_);

    const label n = particles_.size();
    const scalar pi = constant::mathematical::pi;

    volume_.setSize(n);
    previousUp_.setSize(n);
    forAll(volume_, i)
    {
        const scalar rhoT = typeDensity_[particles_.type[i]];
        volume_[i] =
            rhoT > 0 && particles_.mass[i] > 0
          ? particles_.mass[i]/rhoT
          : 4.0/3.0*pi*pow3(particles_.radius[i]);
        previousUp_[i] =
            velocityById_.lookup(particles_.id[i], particles_.velocity[i]);
    }

    // 2. Locate; the lowest processor holding the centre owns the particle
    weights_.locate(particles_, locate_());

    // 3. Weights (CSR), completed to 1 in the centre's cell
    weights_.distribute(particles_, shapes_, voidFraction_());

    // 4. Void fraction
    exchange_.updateVoidFraction
    (
        weights_, volume_, smoothing_(), voidFraction_->alphaMin()
    );
}


void Foam::demCloud::computeForces
(
    const volScalarField& nu,
    const volScalarField& nuEff,
    const surfaceScalarField& alphaPhi
)
{
    const label n = particles_.size();
    const List<label>& cell = weights_.cells();

    // No particles anywhere (n counts all ranks' particles, so every rank
    // takes the same branch): the fluid fields the force models sample are
    // not built, so that a solver without particles costs what its parent
    // solver costs (bench/damBreak); the exchange fields below are zero
    beta_.setSize(n);
    Fcoupled_.setSize(n);
    Fparticle_.setSize(n);
    torque_.setSize(n);

    // solidVelocity rigidBody: each particle's mean arm sum_c w_pc (x_c - x_p)
    // and the shift of its cells' velocities to Uf (below)
    List<vector> meanArm, shift;
    if (n == 0)
    {
        Uf_.clear();
        submergedFraction_.clear();
        usedPlane_.clear();
        buoyancyArm_.clear();
    }
    else
    {
        // The fluid velocity the particles see: the cell velocity, or the
        // superficial velocity reconstructed from the face fluxes divided by the
        // void fraction (continuity-consistent where alpha jumps, e.g. at the
        // edges of a packed bed, where the cell-centred U is poor)
        tmp<volVectorField> tUseen;
        if (settings_.fluxVelocity())
        {
            tUseen = fvc::reconstruct(alphaPhi)/fluidFraction();
        }
        else
        {
            tUseen = tmp<volVectorField>(U_);
        }
        const volVectorField& Useen = tUseen();

        // Weighted averages at the particles (partial sums, then summed)
        Uf_ = weights_.average(Useen.primitiveField());
        const List<scalar> alphaP
        (
            weights_.average(exchange_.voidfraction().primitiveField())
        );
        const List<scalar> nuP(weights_.average(nu.primitiveField()));

        // Free surface: mixture rho and mu = rho nu averaged over the particle's
        // own volume, and the submerged part of the particle
        List<scalar> rhoP, muP;
        if (freeSurface_)
        {
            const demFreeSurface& fs = freeSurface_();
            rhoP = weights_.average(fs.rho.primitiveField());
            muP = weights_.average
            (
                scalarField(fs.rho.primitiveField()*nu.primitiveField())
            );
            submerged_->fractions
            (
                particles_, volume_, shapes_, weights_,
                fluidFraction(), settings_.twoWay(), fs.alpha1, fs.g,
                submergedFraction_, usedPlane_, buoyancyArm_
            );
        }

        // Fields the force models need, built and sampled by each model
        forceContext_.setViscosity(nu, nuEff);
        for (forceModel& m : forces_)
        {
            m.cacheFields(true);
        }

        // Forces, by the owner of each particle
        beta_ = 0;
        Fcoupled_ = Zero;
        Fparticle_ = Zero;
        torque_ = Zero;

        const scalar pi = constant::mathematical::pi;
        forAll(cell, i)
        {
            if (cell[i] < 0)
            {
                continue;
            }
            particleSample ps;
            ps.index = i;
            ps.type = particles_.type[i];
            ps.Up = particles_.velocity[i];
            ps.omega = particles_.omega[i];
            ps.Vp = volume_[i];
            ps.d = cbrt(6*volume_[i]/pi);
            ps.rhoP = particles_.mass[i]/max(volume_[i], VSMALL);
            ps.sphericity = sphericity_[ps.type];
            ps.crosswiseSphericity = crosswiseSphericity_[ps.type];
            ps.dnByDv = dnByDv_[ps.type];
            ps.U = Uf_[i];
            ps.alpha = alphaP[i];
            ps.rho = rho_;
            ps.nu = nuP[i];
            ps.deltaT = mesh_.time().deltaTValue();
            if (freeSurface_)
            {
                const scalar rhoMix = max(rhoP[i], VSMALL);
                ps.rho = rhoMix;
                ps.nu = muP[i]/rhoMix;
                ps.submergedFraction = submergedFraction_[i];
                ps.buoyancyArm = buoyancyArm_[i];
            }

            particleForce pf;
            for (const forceModel& m : forces_)
            {
                m.addForce(ps, pf);
            }
            beta_[i] = pf.beta;
            Fcoupled_[i] = pf.Fcoupled;
            Fparticle_[i] = pf.Fparticle;
            torque_[i] = pf.Tparticle;
        }

        for (forceModel& m : forces_)
        {
            m.cacheFields(false);
        }
        forceContext_.clearViscosity();
    }

    allSum(beta_);
    allSum(Fcoupled_);
    allSum(Fparticle_);
    allSum(torque_);

    // solidVelocity rigidBody: the drag of each cell acts on the solid's
    // velocity there, Up + omega x r (r = x_c - x_p), with the cell's own
    // fluid velocity U_c shifted by dU = Uf - sum_c w U_c (so that its mean
    // is the Uf the force models saw); summed over the cells this is the
    // drag at the centre less beta omega x rbar, and the torque about the
    // centre
    //     T = beta (sum_c w r x U_c + rbar x (dU - Up) - J omega),
    //     rbar = sum_c w r,  J = sum_c w (|r|^2 I - r r)
    // (a block turning in still water drives the water of its cells round
    // with it, and pays for it)
    const bool rigid = settings_.rigidBodySolid() && n > 0;
    if (rigid)
    {
        const vectorField& C = mesh_.C().primitiveField();
        const vectorField& Ucell = U_.primitiveField();
        const List<label>& start = weights_.start();
        const List<label>& cellIndex = weights_.cellIndex();
        const List<scalar>& weight = weights_.weight();
        meanArm.setSize(n, Zero);
        shift = Uf_;
        List<vector> meanU(n, Zero);
        List<vector> armCrossU(n, Zero);
        List<symmTensor> J(n, Zero);
        forAll(meanArm, i)
        {
            for (label k = start[i]; k < start[i + 1]; ++k)
            {
                const label c = cellIndex[k];
                const scalar w = weight[k];
                const vector r = C[c] - particles_.position[i];
                meanArm[i] += w*r;
                meanU[i] += w*Ucell[c];
                armCrossU[i] += w*(r ^ Ucell[c]);
                J[i] += w*(magSqr(r)*symmTensor::I - sqr(r));
            }
        }
        allSum(meanArm);
        allSum(meanU);
        allSum(armCrossU);
        allSum(J);
        forAll(torque_, i)
        {
            shift[i] -= meanU[i];
            torque_[i] += beta_[i]*
            (
                armCrossU[i]
              + (meanArm[i] ^ (shift[i] - particles_.velocity[i]))
              - (J[i] & particles_.omega[i])
            );
        }
    }

    force_.setSize(n);
    forAll(force_, i)
    {
        vector Fdrag = beta_[i]*(Uf_[i] - particles_.velocity[i]);
        if (rigid)
        {
            Fdrag -= beta_[i]*(particles_.omega[i] ^ meanArm[i]);
        }
        force_[i] = Fdrag + Fcoupled_[i] + Fparticle_[i];
    }
    checkForcesFinite();

    // Exchange fields with the same weights, and the momentum balance
    autoPtr<demSolidRotation> rotation;
    if (rigid)
    {
        rotation.reset
        (
            new demSolidRotation
            {
                shift, particles_.position, particles_.omega, meanArm
            }
        );
    }
    exchange_.update
    (
        weights_,
        particles_.velocity,
        volume_,
        beta_,
        Fcoupled_,
        Uf_,
        U_,
        settings_.implicitCoupling(),
        smoothing_(),
        settings_.twoWay(),  // one-way: the fluid does not take them
        rotation.get()
    );

    // Hand the forces to the back end (engine order) for the next advance;
    // the torques only when a model gave one (every rank holds the same
    // sums), so that a LIGGGHTS script without torque transfer still runs
    // spheres, which get none
    if (backend_.valid())
    {
        backend_->setForces(force_, torquesToHand());
    }

    // Velocities of this step, for dUp/dt at the next
    velocityById_.clear();
    forAll(particles_.id, i)
    {
        velocityById_.set(particles_.id[i], particles_.velocity[i]);
    }

    io_.writeSummary
    (
        particles_, force_, weights_.nOutside(), exchange_,
        weights_.maxCompletion()
    );
}


void Foam::demCloud::checkForcesFinite() const
{
    // Every rank holds every force after the sums: all stop together
    auto finite = [](const vector& v)
    {
        return std::isfinite(v.x()) && std::isfinite(v.y())
            && std::isfinite(v.z());
    };
    forAll(force_, i)
    {
        if
        (
            finite(force_[i]) && finite(torque_[i])
         && std::isfinite(beta_[i])
        )
        {
            continue;
        }
        wordList models;
        for (const forceModel& m : forces_)
        {
            models.append(m.type());
        }
        FatalErrorInFunction
            << "Non-finite fluid force on particle " << particles_.id[i]
            << " (type " << particles_.type[i] << ") at t = "
            << mesh_.time().value() << " s" << nl
            << "    position " << particles_.position[i]
            << ", velocity " << particles_.velocity[i]
            << ", fluid velocity there " << Uf_[i] << nl
            << "    drag coefficient beta " << beta_[i]
            << " kg/s, coupled force " << Fcoupled_[i]
            << " N, particle-only force " << Fparticle_[i] << " N"
            << ", torque " << torque_[i] << " N m" << nl
            << "    force models " << models
            << " (constant/couplingProperties); usual causes: a fluid"
            << " that has blown up (Courant number), a particle outside"
            << " the mesh, or a void fraction of 0"
            << exit(FatalError);
    }
}


Foam::List<Foam::vector> Foam::demCloud::torquesToHand() const
{
    for (const vector& T : torque_)
    {
        if (T != vector::zero)
        {
            return torque_;
        }
    }
    return List<vector>();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace
{
    //- couplingDirection oneWay: an exchange term the fluid does not get
    template<class FieldType>
    Foam::tmp<FieldType> withoutFeedback(Foam::tmp<FieldType> tf, bool twoWay)
    {
        if (!twoWay)
        {
            tf.ref() == Foam::dimensioned<typename FieldType::value_type>
            (
                "zero", tf().dimensions(), Foam::Zero
            );
        }
        return tf;
    }
}


Foam::tmp<Foam::volScalarField> Foam::demCloud::KslByRho() const
{
    return withoutFeedback
    (
        exchange_.KslByRho(rho_, settings_.implicitCoupling()),
        settings_.twoWay()
    );
}


Foam::tmp<Foam::volVectorField> Foam::demCloud::explicitSourceByRho() const
{
    return withoutFeedback
    (
        exchange_.explicitSourceByRho(rho_, settings_.implicitCoupling()),
        settings_.twoWay()
    );
}


Foam::tmp<Foam::volScalarField> Foam::demCloud::implicitCoefficient() const
{
    return withoutFeedback
    (
        exchange_.implicitCoefficient(settings_.implicitCoupling()),
        settings_.twoWay()
    );
}


Foam::tmp<Foam::volVectorField> Foam::demCloud::rotationSource() const
{
    return withoutFeedback
    (
        tmp<volVectorField>::New("rotationSource", exchange_.rotationSource()),
        settings_.twoWay()
    );
}


Foam::tmp<Foam::volVectorField> Foam::demCloud::rotationSourceByRho() const
{
    return withoutFeedback
    (
        tmp<volVectorField>
        (
            exchange_.rotationSource()/dimensionedScalar("rho", dimDensity, rho_)
        ),
        settings_.twoWay()
    );
}


Foam::tmp<Foam::volVectorField> Foam::demCloud::explicitSource() const
{
    return withoutFeedback
    (
        exchange_.explicitSource(settings_.implicitCoupling()),
        settings_.twoWay()
    );
}


Foam::tmp<Foam::volScalarField> Foam::demCloud::voidfractionRate() const
{
    const volScalarField& eps = fluidFraction();
    if (!voidfractionBeforeStep_ || !settings_.twoWay())
    {
        return fvc::ddt(eps);
    }
    return tmp<volScalarField>::New
    (
        "voidfractionRate",
        (eps - voidfractionBeforeStep_())/mesh_.time().deltaT()
    );
}


void Foam::demCloud::evolve
(
    const volScalarField& nu,
    const volScalarField& nuEff,
    const surfaceScalarField& alphaPhi
)
{
    const scalar tMoving = io_.elapsedTime();

    // A moving mesh: the particles as they are (the previous step's) on the
    // moved cells, for the rate at fixed points in space (voidfractionRate,
    // when the solver asked for it)
    if (mesh_.moving() && voidfractionRateRequested_ && settings_.twoWay())
    {
        if (!voidfractionBeforeStep_)
        {
            voidfractionBeforeStep_.reset
            (
                new volScalarField
                (
                    IOobject
                    (
                        "voidfractionBeforeStep",
                        mesh_.time().timeName(),
                        mesh_,
                        IOobject::NO_READ,
                        IOobject::NO_WRITE,
                        false
                    ),
                    exchange_.voidfraction()
                )
            );
        }
        weights_.locate(particles_, locate_());
        weights_.distribute(particles_, shapes_, voidFraction_());
        exchange_.computeVoidFraction
        (
            weights_, volume_, smoothing_(), voidFraction_->alphaMin(),
            voidfractionBeforeStep_()
        );
    }
    else
    {
        voidfractionBeforeStep_.clear();
    }

    // One-way: the fluid fraction stays 1 on a mesh that refines (mapping
    // interpolates it)
    if (oneWayFluidFraction_.valid() && mesh_.changing())
    {
        oneWayFluidFraction_() == dimensionedScalar("one", dimless, 1.0);
    }

    const scalar t0 = io_.elapsedTime();
    if (backend_.valid())
    {
        backend_->evolve();
    }
    const scalar t1 = io_.elapsedTime();
    updateParticles();
    const scalar t2 = io_.elapsedTime();
    computeForces(nu, nuEff, alphaPhi);
    const scalar t3 = io_.elapsedTime();
    io_.addTimes(t1 - t0, t2 - t1 + t0 - tMoving, t3 - t2);

    // One line of "name value" pairs per step (foamLog, grep; cumulative
    // CPU seconds of the three parts); the momentum exchange, its
    // balance and the weight completion per step are in
    // postProcessing/demCloud/<t0>/summary.dat
    Info<< "demCloud: particles " << particles_.size()
        << " outsideMesh " << weights_.nOutside()
        << " voidfractionMin "
        << gMin(exchange_.voidfraction().primitiveField())
        << " exchangeBalance " << exchange_.balanceError()
        << " cpuDEM " << io_.timeDem()
        << " cpuLocateVoidfraction " << io_.timeParticles()
        << " cpuForcesExchange " << io_.timeForces() << endl;
}


void Foam::demCloud::write()
{
    // The back end writes its state and the forces it holds for the next
    // advance (<time>/polyDEM/fluidForces, handed over again by start())
    if (backend_.valid())
    {
        backend_->write();
    }
}


bool Foam::demCloud::restartFilesPresent() const
{
    bool found = Pstream::master() && backend_->restartForcesFound();
    reduce(found, orOp<bool>());
    return found;
}


void Foam::demCloud::start
(
    const volScalarField& nu,
    const volScalarField& nuEff,
    const surfaceScalarField& alphaPhi
)
{
    computeForces(nu, nuEff, alphaPhi);
    // The first handover: at a restart the back end replaces the forces by
    // those written with its state
    if (backend_.valid())
    {
        List<vector> torque(torquesToHand());
        backend_->start(force_, torque);
        if (torque.size())
        {
            torque_ = torque;
        }
    }
    broadcast(force_);
    broadcast(torque_);
}


