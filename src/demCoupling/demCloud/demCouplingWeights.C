#include "demCouplingWeights.H"
#include "demParallel.H"
#include "locateModel.H"
#include "voidFractionModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCouplingWeights::demCouplingWeights()
:
    cell_(),
    start_(1, label(0)),
    cellIndex_(),
    weight_(),
    hint_(),
    nOutside_(0),
    maxCompletion_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demCouplingWeights::broadcast(demParticleArrays& particles)
{
    demParallel::broadcast(particles.id);
    demParallel::broadcast(particles.type);
    demParallel::broadcast(particles.radius);
    demParallel::broadcast(particles.mass);
    demParallel::broadcast(particles.position);
    demParallel::broadcast(particles.velocity);
    demParallel::broadcast(particles.omega);
    demParallel::broadcast(particles.orientation);
}


void Foam::demCouplingWeights::locate
(
    const demParticleArrays& particles,
    const locateModel& locate
)
{
    // The lowest processor holding the centre owns the particle
    const label n = particles.size();
    cell_.setSize(n);
    List<label> owner(n);
    owner = Pstream::nProcs();
    forAll(cell_, i)
    {
        cell_[i] =
            locate.findCell
            (
                particles.position[i],
                hint_.lookup(particles.id[i], -1)
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
            hint_.set(particles.id[i], cell_[i]);
        }
        if (owner[i] == Pstream::nProcs())
        {
            ++nOutside_;
        }
    }
}


void Foam::demCouplingWeights::distribute
(
    const demParticleArrays& particles,
    const List<demShape>& shapes,
    const voidFractionModel& voidFraction
)
{
    voidFraction.updateMesh();

    const label n = particles.size();
    start_.setSize(n + 1);
    cellIndex_.clear();
    weight_.clear();
    List<scalar> wSum(n, scalar(0));
    List<label> centreEntry(n);
    centreEntry = -1;
    forAll(cell_, i)
    {
        start_[i] = cellIndex_.size();
        const label t = particles.type[i];
        voidFraction.distributeShape
        (
            particles.position[i],
            particles.radius[i],
            particles.orientation[i],
            t < shapes.size() && shapes[t].polyhedron() ? &shapes[t] : nullptr,
            cell_[i],
            cellIndex_,
            weight_
        );
        for (label k = start_[i]; k < cellIndex_.size(); ++k)
        {
            wSum[i] += weight_[k];
            if (cellIndex_[k] == cell_[i])
            {
                centreEntry[i] = k;
            }
        }
        if (cell_[i] >= 0 && centreEntry[i] < 0)
        {
            centreEntry[i] = cellIndex_.size();
            cellIndex_.append(cell_[i]);
            weight_.append(0);
        }
    }
    start_[n] = cellIndex_.size();
    demParallel::allSum(wSum);
    maxCompletion_ = 0;
    forAll(wSum, i)
    {
        maxCompletion_ = max(maxCompletion_, mag(1 - wSum[i]));
    }
    forAll(cell_, i)
    {
        if (centreEntry[i] >= 0)
        {
            weight_[centreEntry[i]] += 1 - wSum[i];
        }
    }
}
