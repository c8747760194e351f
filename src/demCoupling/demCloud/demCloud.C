#include "demCloud.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "IOmanip.H"

namespace Foam
{
    defineTypeNameAndDebug(demCloud, 0);
}


// * * * * * * * * * * * * * * * Local helpers * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Sum a list over the processors, result on every processor
template<class T>
void allSum(List<T>& l)
{
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(l, plusEqOp<T>());
        Pstream::listCombineScatter(l);
    }
}

template<class T>
void broadcast(T& value)
{
    if (Pstream::parRun())
    {
        Pstream::scatter(value);
    }
}

word readChoice
(
    const dictionary& dict,
    const word& key,
    const wordList& valid,
    const word& def
)
{
    const word value(dict.getOrDefault<word>(key, def));
    if (!valid.found(value))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown " << key << " '" << value << "' in " << dict.name()
            << nl << "Valid " << key << " values: " << valid
            << exit(FatalIOError);
    }
    return value;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCloud::demCloud
(
    const volVectorField& U,
    const volScalarField& p,
    scalar rho
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
    U_(U),
    p_(p),
    rho_(rho),
    formulation_(couplingFormulation::setI),
    implicit_(true),
    fluxVelocity_(true),
    backend_(),
    locate_(),
    voidFraction_(),
    smoothing_(),
    forces_(),
    needDivTau_(false),
    needDUDt_(false),
    needCurlU_(false),
    nSubSteps_(1),
    voidfraction_
    (
        IOobject
        (
            "voidfraction",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedScalar("one", dimless, 1),
        "zeroGradient"
    ),
    Us_
    (
        IOobject("Us", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedVector(dimVelocity, Zero),
        "zeroGradient"
    ),
    Ksl_
    (
        IOobject("Ksl", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedScalar(dimDensity/dimTime, Zero),
        "zeroGradient"
    ),
    KslUs_
    (
        IOobject("KslUs", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE),
        mesh_,
        dimensionedVector(dimDensity*dimVelocity/dimTime, Zero),
        "zeroGradient"
    ),
    fExchange_
    (
        IOobject("fExchange", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedVector(dimForce/dimVolume, Zero),
        "zeroGradient"
    ),
    summary_(),
    lastParticleMomentum_(Zero),
    lastFluidMomentum_(Zero),
    nOutside_(0),
    maxCompletion_(0),
    clock_(),
    timeDem_(0),
    timeParticles_(0),
    timeForces_(0)
{
    Info<< "Reading couplingProperties (demCloud)" << endl;

    formulation_ =
        readChoice(dict_, "formulation", {"setI", "setII"}, "setI") == "setI"
      ? couplingFormulation::setI
      : couplingFormulation::setII;

    implicit_ =
        readChoice
        (
            dict_, "momentumCoupling", {"implicit", "explicit"}, "implicit"
        ) == "implicit";

    if (Pstream::master())
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

    // Sub-cycling: the DEM steps per fluid step given in couplingProperties
    // must be those of the time steps (demSimulation checks the division)
    if (dict_.found("demStepsPerFluidStep"))
    {
        const label n = dict_.get<label>("demStepsPerFluidStep");
        if (n != nSubSteps_)
        {
            FatalIOErrorInFunction(dict_)
                << "demStepsPerFluidStep " << n << " in " << dict_.name()
                << " does not match deltaT/timeStep = " << nSubSteps_
                << " (controlDict deltaT " << mesh_.time().deltaTValue()
                << " s, DEM time step "
                << mesh_.time().deltaTValue()/max(nSubSteps_, 1) << " s)"
                << nl << "    deltaT must be demStepsPerFluidStep DEM steps"
                << exit(FatalIOError);
        }
    }
    Info<< "    " << nSubSteps_ << " DEM steps per fluid step" << endl;

    locate_ = locateModel::New(dict_, mesh_);
    voidFraction_ = voidFractionModel::New(dict_, mesh_, locate_());
    smoothing_ = smoothingModel::New(dict_, mesh_);

    const wordList forceNames(dict_.get<wordList>("forceModels"));
    forces_.setSize(forceNames.size());
    forAll(forceNames, i)
    {
        forces_.set(i, forceModel::New(forceNames[i], dict_, *this));
        needDivTau_ = needDivTau_ || forceNames[i] == "viscousStress";
        needDUDt_ = needDUDt_ || forceNames[i] == "virtualMass";
        needCurlU_ = needCurlU_ || forceNames[i] == "SaffmanMeiLift";
    }

    fluxVelocity_ =
        readChoice(dict_, "fluidVelocity", {"flux", "cell"}, "flux") == "flux";
    Info<< "    fluid velocity at the particles: "
        << (fluxVelocity_ ? "reconstruct(alphaPhi)/voidfraction" : "cell U")
        << endl;

    readShapes();

    voidfraction_.oldTime();

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh_.time().globalPath()/"postProcessing"/"demCloud"
           /mesh_.time().timeName()
        );
        mkDir(dir);
        summary_.reset(new OFstream(dir/"summary.dat"));
        summary_()
            << "# time nParticles nOutside Fx Fy Fz (total fluid force on"
            << " particles [N]) Pcx Pcy Pcz (coupled force on particles)"
            << " Sfx Sfy Sfz (exchange source in the fluid) relErr"
            << " Upx Upy Upz (mean particle velocity) xpx xpy xpz"
            << " (mean position) alphaMin" << nl;
        summary_().precision(12);
    }

    updateParticles();
}


Foam::demCloud::~demCloud()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demCloud::readShapes()
{
    // Defaults from the back end (1 for spheres, the shape's for polyhedra)
    const label nTypes = typeNames_.size();
    dnByDv_.setSize(nTypes, scalar(1));
    forAll(sphericity_, t)
    {
        if (sphericity_[t] != 1 || crosswiseSphericity_[t] != 1)
        {
            Info<< "    particle type " << typeNames_[t]
                << " (polyhedron): sphericity " << sphericity_[t]
                << ", crosswise " << crosswiseSphericity_[t] << endl;
        }
    }

    const dictionary shapes(dict_.subOrEmptyDict("particleShapes"));
    for (const entry& e : shapes)
    {
        const label t = typeNames_.find(e.keyword());
        if (t < 0 || !e.isDict())
        {
            FatalIOErrorInFunction(shapes)
                << "Unknown particle type '" << e.keyword() << "' in "
                << shapes.name() << nl << "Valid particle types: "
                << typeNames_ << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        sphericity_[t] = d.get<scalar>("sphericity");
        crosswiseSphericity_[t] =
            d.getOrDefault<scalar>("crosswiseSphericity", sphericity_[t]);
        dnByDv_[t] = d.getOrDefault<scalar>("dnByDv", 1);
        if (sphericity_[t] <= 0 || sphericity_[t] > 1)
        {
            FatalIOErrorInFunction(d)
                << "sphericity must be in (0, 1] in " << d.name()
                << exit(FatalIOError);
        }
        Info<< "    particle type " << e.keyword() << ": sphericity "
            << sphericity_[t] << ", crosswise " << crosswiseSphericity_[t]
            << endl;
    }
}


void Foam::demCloud::updateParticles()
{
    // 1. Copy from the back end, broadcast
    if (Pstream::master())
    {
        backend_->particles(particles_);
    }
    broadcast(particles_.id);
    broadcast(particles_.type);
    broadcast(particles_.radius);
    broadcast(particles_.mass);
    broadcast(particles_.position);
    broadcast(particles_.velocity);
    broadcast(particles_.omega);
    broadcast(particles_.orientation);

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
    cell_.setSize(n);
    List<label> owner(n);
    owner = Pstream::nProcs();
    forAll(cell_, i)
    {
        cell_[i] =
            locate_->findCell
            (
                particles_.position[i],
                hint_.lookup(particles_.id[i], -1)
            );
        if (cell_[i] >= 0)
        {
            owner[i] = Pstream::myProcNo();
        }
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(owner, minEqOp<label>());
        Pstream::listCombineScatter(owner);
    }
    hint_.clear();
    nOutside_ = 0;
    forAll(cell_, i)
    {
        if (owner[i] != Pstream::myProcNo())
        {
            cell_[i] = -1;
        }
        else
        {
            hint_.set(particles_.id[i], cell_[i]);
        }
        if (owner[i] == Pstream::nProcs())
        {
            ++nOutside_;
        }
    }

    // 3. Weights (CSR), completed to 1 in the centre's cell
    wStart_.setSize(n + 1);
    wCell_.clear();
    wWeight_.clear();
    List<scalar> wSum(n, scalar(0));
    List<label> centreEntry(n);
    centreEntry = -1;
    forAll(cell_, i)
    {
        wStart_[i] = wCell_.size();
        const label t = particles_.type[i];
        voidFraction_->distributeShape
        (
            particles_.position[i],
            particles_.radius[i],
            particles_.orientation[i],
            t < shapes_.size() && shapes_[t].polyhedron() ? &shapes_[t] : nullptr,
            cell_[i],
            wCell_,
            wWeight_
        );
        for (label k = wStart_[i]; k < wCell_.size(); ++k)
        {
            wSum[i] += wWeight_[k];
            if (wCell_[k] == cell_[i])
            {
                centreEntry[i] = k;
            }
        }
        if (cell_[i] >= 0 && centreEntry[i] < 0)
        {
            centreEntry[i] = wCell_.size();
            wCell_.append(cell_[i]);
            wWeight_.append(0);
        }
    }
    wStart_[n] = wCell_.size();
    allSum(wSum);
    maxCompletion_ = 0;
    forAll(wSum, i)
    {
        maxCompletion_ = max(maxCompletion_, mag(1 - wSum[i]));
    }
    forAll(cell_, i)
    {
        if (centreEntry[i] >= 0)
        {
            wWeight_[centreEntry[i]] += 1 - wSum[i];
        }
    }

    // 4. Void fraction
    const scalarField& V = mesh_.V();
    volScalarField solid
    (
        IOobject("solidFraction", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    );
    scalarField& s = solid.primitiveFieldRef();
    forAll(cell_, i)
    {
        for (label k = wStart_[i]; k < wStart_[i + 1]; ++k)
        {
            s[wCell_[k]] += wWeight_[k]*volume_[i];
        }
    }
    s /= V;
    solid.correctBoundaryConditions();
    smoothing_->smooth(solid);

    scalarField& a = voidfraction_.primitiveFieldRef();
    a = max(1 - s, voidFraction_->alphaMin());
    voidfraction_.correctBoundaryConditions();
}


void Foam::demCloud::computeForces
(
    const volScalarField& nu,
    const volScalarField& nuEff,
    const surfaceScalarField& alphaPhi
)
{
    const label n = particles_.size();
    const scalarField& V = mesh_.V();

    // The fluid velocity the particles see: the cell velocity, or the
    // superficial velocity reconstructed from the face fluxes divided by the
    // void fraction (continuity-consistent where alpha jumps, e.g. at the
    // edges of a packed bed, where the cell-centred U is poor)
    tmp<volVectorField> tUseen;
    if (fluxVelocity_)
    {
        tUseen = fvc::reconstruct(alphaPhi)/voidfraction_;
    }
    else
    {
        tUseen = tmp<volVectorField>(U_);
    }
    const volVectorField& Useen = tUseen();

    // Fluid fields the force models may need
    const volVectorField gradP(fvc::grad(p_));
    tmp<volVectorField> tdivTau, tDUDt, tcurlU;
    if (needDivTau_)
    {
        tdivTau =
            fvc::laplacian(nuEff, U_)
          + fvc::div(nuEff*dev2(T(fvc::grad(U_))));
    }
    if (needDUDt_)
    {
        tDUDt = fvc::ddt(U_) + (fvc::grad(U_) & U_);
    }
    if (needCurlU_)
    {
        tcurlU = fvc::curl(U_);
    }

    // Weighted averages at the particles (partial sums, then summed)
    Uf_.setSize(n);
    Uf_ = Zero;
    List<scalar> alphaP(n, scalar(0)), nuP(n, scalar(0));
    List<vector> gradPP(n, Zero), divTauP(n, Zero), DUDtP(n, Zero),
        curlUP(n, Zero);
    forAll(cell_, i)
    {
        for (label k = wStart_[i]; k < wStart_[i + 1]; ++k)
        {
            const label c = wCell_[k];
            const scalar w = wWeight_[k];
            Uf_[i] += w*Useen[c];
            alphaP[i] += w*voidfraction_[c];
            nuP[i] += w*nu[c];
            gradPP[i] += w*gradP[c];
            if (needDivTau_) divTauP[i] += w*tdivTau()[c];
            if (needDUDt_) DUDtP[i] += w*tDUDt()[c];
            if (needCurlU_) curlUP[i] += w*tcurlU()[c];
        }
    }
    allSum(Uf_);
    allSum(alphaP);
    allSum(nuP);
    allSum(gradPP);
    if (needDivTau_) allSum(divTauP);
    if (needDUDt_) allSum(DUDtP);
    if (needCurlU_) allSum(curlUP);

    // Forces, by the owner of each particle
    beta_.setSize(n);
    beta_ = 0;
    Fcoupled_.setSize(n);
    Fcoupled_ = Zero;
    Fparticle_.setSize(n);
    Fparticle_ = Zero;

    for (forceModel& m : forces_)
    {
        m.update();
    }

    const scalar pi = constant::mathematical::pi;
    forAll(cell_, i)
    {
        if (cell_[i] < 0)
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
        ps.gradP = gradPP[i];
        ps.divTau = divTauP[i];
        ps.DUDt = DUDtP[i];
        ps.curlU = curlUP[i];
        ps.deltaT = mesh_.time().deltaTValue();

        particleForce pf;
        for (const forceModel& m : forces_)
        {
            m.addForce(ps, pf);
        }
        beta_[i] = pf.beta;
        Fcoupled_[i] = pf.Fcoupled;
        Fparticle_[i] = pf.Fparticle;
    }
    allSum(beta_);
    allSum(Fcoupled_);
    allSum(Fparticle_);

    force_.setSize(n);
    vector particleSide(Zero);
    forAll(force_, i)
    {
        const vector Fdrag = beta_[i]*(Uf_[i] - particles_.velocity[i]);
        force_[i] = Fdrag + Fcoupled_[i] + Fparticle_[i];
        particleSide += Fdrag + Fcoupled_[i];
    }

    // Exchange fields, same weights
    scalarField& K = Ksl_.primitiveFieldRef();
    vectorField& KU = KslUs_.primitiveFieldRef();
    vectorField& fE = fExchange_.primitiveFieldRef();
    vectorField& Us = Us_.primitiveFieldRef();
    K = 0;
    KU = Zero;
    fE = Zero;
    Us = Zero;
    scalarField solidV(mesh_.nCells(), scalar(0));
    forAll(cell_, i)
    {
        const vector& Up = particles_.velocity[i];
        const vector Fexp =
            implicit_
          ? Fcoupled_[i]
          : Fcoupled_[i] + beta_[i]*(Uf_[i] - Up);
        for (label k = wStart_[i]; k < wStart_[i + 1]; ++k)
        {
            const label c = wCell_[k];
            const scalar w = wWeight_[k];
            K[c] += w*beta_[i];
            KU[c] += w*beta_[i]*Up;
            fE[c] -= w*Fexp;
            if (implicit_)
            {
                // Deferred correction: with the implicit -Ksl U the fluid
                // gets exactly -beta (Uf - Up) at the coupling time
                fE[c] += w*beta_[i]*(U_[c] - Uf_[i]);
            }
            Us[c] += w*volume_[i]*Up;
            solidV[c] += w*volume_[i];
        }
    }
    forAll(Us, c)
    {
        if (solidV[c] > 0)
        {
            Us[c] /= solidV[c];
        }
    }

    // Momentum balance of the exchange (before smoothing, which keeps the
    // integrals only to its solver tolerance)
    vector fluidSide(Zero);
    forAll(K, c)
    {
        vector s = fE[c];
        if (implicit_)
        {
            s += KU[c] - K[c]*U_[c];
        }
        fluidSide += s;
    }
    reduce(fluidSide, sumOp<vector>());
    lastParticleMomentum_ = particleSide;
    lastFluidMomentum_ = fluidSide;

    K /= V;
    KU /= V;
    fE /= V;
    Ksl_.correctBoundaryConditions();
    KslUs_.correctBoundaryConditions();
    fExchange_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();

    if (smoothing_->active())
    {
        smoothing_->smooth(Ksl_);
        smoothing_->smooth(KslUs_);
        smoothing_->smooth(fExchange_);
    }

    // Hand the forces to the back end (engine order) for the next advance
    if (Pstream::master())
    {
        backend_->setForces(force_, List<vector>());
    }

    // Velocities of this step, for dUp/dt at the next
    velocityById_.clear();
    forAll(particles_.id, i)
    {
        velocityById_.set(particles_.id[i], particles_.velocity[i]);
    }

    writeSummary();
}


void Foam::demCloud::writeSummary()
{
    if (!Pstream::master())
    {
        return;
    }
    const label n = particles_.size();
    vector Ftot(Zero), Up(Zero), xp(Zero);
    forAll(force_, i)
    {
        Ftot += force_[i];
        Up += particles_.velocity[i];
        xp += particles_.position[i];
    }
    if (n)
    {
        Up /= n;
        xp /= n;
    }
    const scalar scale =
        max(mag(lastParticleMomentum_), mag(lastFluidMomentum_));
    const scalar relErr =
        scale > 0 ? mag(lastParticleMomentum_ + lastFluidMomentum_)/scale : 0;

    OFstream& os = summary_();
    os  << mesh_.time().value() << ' ' << n << ' ' << nOutside_ << ' '
        << Ftot.x() << ' ' << Ftot.y() << ' ' << Ftot.z() << ' '
        << lastParticleMomentum_.x() << ' ' << lastParticleMomentum_.y()
        << ' ' << lastParticleMomentum_.z() << ' '
        << lastFluidMomentum_.x() << ' ' << lastFluidMomentum_.y() << ' '
        << lastFluidMomentum_.z() << ' ' << relErr << ' '
        << Up.x() << ' ' << Up.y() << ' ' << Up.z() << ' '
        << xp.x() << ' ' << xp.y() << ' ' << xp.z() << ' '
        << min(voidfraction_.primitiveField()) << nl;
    os.flush();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField> Foam::demCloud::KslByRho() const
{
    if (implicit_)
    {
        return Ksl_/dimensionedScalar("rho", dimDensity, rho_);
    }
    return tmp<volScalarField>::New
    (
        IOobject("KslByRho", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(Ksl_.dimensions()/dimDensity, Zero)
    );
}


Foam::tmp<Foam::volVectorField> Foam::demCloud::explicitSourceByRho() const
{
    const dimensionedScalar rho("rho", dimDensity, rho_);
    if (implicit_)
    {
        return (KslUs_ + fExchange_)/rho;
    }
    return fExchange_/rho;
}


void Foam::demCloud::evolve
(
    const volScalarField& nu,
    const volScalarField& nuEff,
    const surfaceScalarField& alphaPhi
)
{
    const scalar t0 = clock_.elapsedTime();
    if (Pstream::master())
    {
        backend_->evolve();
    }
    const scalar t1 = clock_.elapsedTime();
    updateParticles();
    const scalar t2 = clock_.elapsedTime();
    computeForces(nu, nuEff, alphaPhi);
    const scalar t3 = clock_.elapsedTime();
    timeDem_ += t1 - t0;
    timeParticles_ += t2 - t1;
    timeForces_ += t3 - t2;

    Info<< "demCloud: " << particles_.size() << " particles";
    if (nOutside_)
    {
        Info<< " (" << nOutside_ << " outside the mesh)";
    }
    Info<< ", voidfraction min " << gMin(voidfraction_.primitiveField())
        << ", momentum exchange: particles " << lastParticleMomentum_
        << " fluid " << lastFluidMomentum_ << nl
        << "demCloud: void-fraction weights completed in the centre cells by"
        << " at most " << maxCompletion_ << " (max |1 - sum w|)" << nl
        << "demCloud: cumulative CPU s: DEM " << timeDem_
        << ", locate+voidfraction " << timeParticles_
        << ", forces+exchange " << timeForces_ << endl;
}


void Foam::demCloud::write()
{
    // The back end writes its state and the forces it holds for the next
    // advance (<time>/polyDEM/fluidForces, handed over again by start())
    if (Pstream::master())
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
    if (Pstream::master())
    {
        List<vector> torque;
        backend_->start(force_, torque);
    }
    broadcast(force_);
}


