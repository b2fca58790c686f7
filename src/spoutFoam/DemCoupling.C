/*---------------------------------------------------------------------------*\
    SpoutLab: the CFD side of the CFD-DEM coupling.
\*---------------------------------------------------------------------------*/
#include "DemCoupling.H"

#include "FoamParameters.H"
#include "InputError.hpp"
#include "LiggghtsStart.H"
#include "BoxDecomposition.H"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spoutlab
{

namespace
{

// Sums over the ranks of the coupled run (one rank when serial).
void sumOverRanks(double* data, std::size_t n)
{
    MPI_Allreduce(MPI_IN_PLACE, data, int(n), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}


Vec3 sumOverRanks(const Vec3& v)
{
    double sums[3] = {v.x, v.y, v.z};
    sumOverRanks(sums, 3);
    return Vec3{sums[0], sums[1], sums[2]};
}


// couplingProperties' word `key` (`first` when absent), one of first, second
bool isSecond
(
    const Foam::dictionary& dict,
    const std::string& key,
    const std::string& first,
    const std::string& second
)
{
    const Foam::word value = dict.getOrDefault<Foam::word>(key, first);
    if (value != first && value != second)
    {
        throw InputError
        (
            "constant/couplingProperties: key '" + key + "' expected '" + first
          + "' or '" + second + "', got '" + value + "'"
        );
    }
    return value == second;
}


} // namespace


DemCoupling::DemCoupling
(
    const Foam::fvMesh& mesh,
    const Foam::volVectorField& U,
    const Foam::volScalarField& p,
    Foam::volScalarField& voidfraction,
    const Foam::surfaceScalarField& phi,
    const Foam::dimensionedScalar& rho,
    const Foam::dimensionedScalar& mu,
    const Foam::uniformDimensionedVectorField& g
)
:
    mesh_(mesh),
    U_(U),
    p_(p),
    voidfraction_(voidfraction),
    gas_{rho.value(), mu.value()},
    g_{g.value().x(), g.value().y(), g.value().z()},
    dict_
    (
        Foam::IOobject
        (
            "couplingProperties", mesh.time().constant(), mesh,
            Foam::IOobject::MUST_READ, Foam::IOobject::NO_WRITE
        )
    ),
    startIndex_(mesh.time().timeIndex()),
    locator_(mesh),
    guards_(mesh),
    particleOutput_(mesh.time().globalPath()/"particles"),
    fields_(mesh)
{
    checkStartField(U_);   // before anything runs: NaN or Inf read
    checkStartField(p_);
    readControls();
    selectModels();
    startDem();
    guards_.checkTimeSteps(*dem_, couplingInterval_, liggghtsInput_);
    thermal_ = ThermalCoupling::New
    (
        mesh_, locator_, dict_, *dem_, liggghtsInput_, voidfraction_, phi,
        rho.value(), mu.value()
    );
    log_.reset
    (
        new CouplingLog
        (
            mesh.time(), bool(thermal_), thermal_ && thermal_->drying(), resumed_
        )
    );
    circulation_ = CirculationCoupling::New(mesh_, dict_, phi, rho.value());
    writeFoamStub();
    startFromBed();
}


// --- set-up ------------------------------------------------------------------

void DemCoupling::readControls()
{
    couplingInterval_ = dict_.get<Foam::label>("couplingInterval");
    maxCo_ = dict_.getOrDefault<Foam::scalar>("maxCo", 1.0);
    if (couplingInterval_ < 1)
    {
        throw InputError
        (
            "constant/couplingProperties: key 'couplingInterval' expected a "
            "positive number of DEM steps per CFD step"
        );
    }
    deleteLost_ = isSecond(dict_, "lostParticles", "stop", "delete");
    faceBalance_ = !isSecond(dict_, "dragVelocity", "flux", "cellCentre");
    if (faceBalance_)
    {
        // the pressure gradient's face shares (gradP), written with the
        // fields so that a restart continues with them; 1/2 at the start
        ownerShare_.reset
        (
            new Foam::surfaceScalarField
            (
                Foam::IOobject
                (
                    "ownerShare", mesh_.time().timeName(), mesh_,
                    Foam::IOobject::READ_IF_PRESENT, Foam::IOobject::AUTO_WRITE
                ),
                mesh_, Foam::dimensionedScalar("half", Foam::dimless, 0.5)
            )
        );
    }
}


void DemCoupling::selectModels()
{
    const Foam::word dragName = dict_.get<Foam::word>("dragModel");
    exchange_.reset
    (
        new MomentumExchange
        (
            DragModel::New(dragName, toParameters(dict_, dragName + "Props"))
        )
    );
    const Foam::word vfName = dict_.get<Foam::word>("voidFractionModel");
    voidFractionModel_ =
        VoidFractionModel::New(vfName, toParameters(dict_, vfName + "Props"));
}


void DemCoupling::startDem()
{
    dem_ = startLiggghts
    (
        mesh_.time(), dict_, liggghtsInput_, MoistureCoupling::stateSize(dict_),
        CirculationCoupling::trackWidth(dict_)
    );
    if (Foam::Pstream::parRun()) matchDecomposition(mesh_, *dem_, locator_);
    resumeStepState();
    nParticles_ = dem_->nParticles();
    Foam::Info<< "LIGGGHTS: " << dem_->nParticles() << " particles from "
        << liggghtsInput_.c_str() << ", DEM time step " << dem_->timeStep()
        << " s" << Foam::endl;
}


void DemCoupling::resumeStepState()
{
    const Foam::Time& runTime = mesh_.time();
    if (runTime.value() <= 0) return;
    const Foam::fileName state =
        runTime.globalPath()/"DEM"/("restart_" + runTime.timeName() + ".state");
    if (Foam::isFile(state))
    {
        dem_->readStepState(state);
        resumed_ = true;
        return;
    }
    Foam::Info<< "spoutFoam: no DEM step state " << state << "; the "
        "fluid forces of the first steps are recomputed from the gas "
        "fields, so this restart is close to, not equal to, the "
        "uninterrupted run" << Foam::endl;
}


void DemCoupling::writeFoamStub() const
{
    // ParaView opens OpenFOAM cases through an empty <case>.foam file
    if (!Foam::Pstream::master()) return;
    const Foam::Time& runTime = mesh_.time();
    const Foam::fileName stub =
        runTime.globalPath()/(runTime.globalCaseName() + ".foam");
    if (!Foam::isFile(stub)) std::ofstream touch(stub);
}


void DemCoupling::startFromBed()
{
    // particles at the start time: map them so the first gas step already
    // sees the bed.  A fresh run computes the fluid forces (and heat fluxes)
    // for the first DEM steps here; a restart has them from its step state
    // (the uninterrupted run computed them before that step's gas solve,
    // from gas fields the time directory no longer holds).
    vf_ = mapParticles();
    voidfraction_.oldTime() = voidfraction_;
    if (thermal_) thermal_->start(*dem_);
    if (!resumed_)
    {
        exchange(vf_);
        row_.gasReceived = sumOverRanks(fields_.gasMomentum(U_));
        transferHeat();
        log_->write(row_);
        writeParticles();
    }
    if (mesh_.time().value() == 0)
    {
        // what the run starts from, beside the initial conditions: the
        // exchange of the settled bed (e.g. to compare decompositions)
        voidfraction_.write();
        fields_.write();
        dem_->writeStepState(mesh_.time().globalPath()/"DEM"/"start.state");
    }
}


// --- the step ----------------------------------------------------------------

void DemCoupling::evolve()
{
    dem_->run(couplingInterval_);
    checkAtomsKept();
    vf_ = mapParticles();
    exchange(vf_);
    if (thermal_) thermal_->dry(*dem_, particles_, vf_.map, g_, guards_);
}


void DemCoupling::checkAtomsKept()
{
    // LIGGGHTS drops an atom whose centre leaves its box (boundary f f f,
    // 'thermo_modify lost warn' only warns): a particle striking a soft
    // wall on the box's face faster than r sqrt(k/m) passes it by more than
    // its radius and is gone before spoutFoam can see it outside the mesh
    const long n = dem_->nParticles();
    const long gone = nParticles_ - n;
    nParticles_ = n;
    if (gone <= 0) return; // none lost (more: a fix insert in the input)
    const std::string what =
        std::to_string(gone) + " particle(s) lost by LIGGGHTS (centre out of its box, "
        "e.g. through a wall on the box's face) at t = " + mesh_.time().timeName() + " s";
    if (!deleteLost_) throw std::runtime_error(what);
    Foam::Info<< "spoutFoam: " << what.c_str() << "; the run goes on without them "
        "(lostParticles delete)" << Foam::endl;
}


VoidFractionResult DemCoupling::mapParticles()
{
    dem_->localParticles(particles_);
    guards_.checkParticles(particles_);
    VoidFractionResult vf =
        voidFractionModel_->compute(locator_, particles_, vf_);   // the last step's
    deleteLost(vf);

    rowsKept_ += double(vf.rowsKept);
    rowsMapped_ += double(particles_.size());
    eps_ = voidFractionModel_->voidFraction(locator_, vf.solidVolume);
    Foam::scalarField& field = voidfraction_.primitiveFieldRef();
    forAll(field, celli) field[celli] = eps_[celli];
    voidfraction_.correctBoundaryConditions();
    guards_.checkField(voidfraction_);
    return vf;
}


void DemCoupling::deleteLost(VoidFractionResult& vf)
{
    const std::vector<long> lost =
        guards_.lostParticles(vf.lostParticles, particles_, deleteLost_);
    if (lost.empty()) return;
    dem_->deleteParticles(lost);
    dem_->localParticles(particles_);
    nParticles_ = dem_->nParticles();
    vf = voidFractionModel_->compute(locator_, particles_);
}


void DemCoupling::exchange(const VoidFractionResult& vf)
{
    // the gas in this rank's cells and its halo
    const std::vector<Vec3> U = locator_.withHalo(U_.primitiveField());
    const std::vector<Vec3> gradP = locator_.withHalo(this->gradP()().primitiveField());
    const ExchangeResult ex = exchange_->compute
    (
        locator_, particles_, vf, GasCellFields{U, gradP, eps_}, gas_, g_
    );
    // before the forces reach LIGGGHTS or the log
    guards_.checkParticles("fluid force", ex.totalForce, particles_);

    fields_.update(ex);

    // this rank's share; summed over ranks only when written
    fluidForce_ = ex.totalForce;
    dragForce_ = ex.dragForce;
    dem_->setFluidForces(fluidForce_);
    if (thermal_) thermal_->updateCoefficients(particles_, eps_, vf.map, ex);
    fillMomentumRow(vf, ex);
}


Foam::tmp<Foam::volVectorField> DemCoupling::gradP() const
{
    if (!ownerShare_) return Foam::fvc::grad(p_);
    // face pressures where the series balance puts them: the owner's half
    // takes the share R_o/(R_o + R_n) of the drop to the neighbour
    Foam::surfaceScalarField pf(Foam::fvc::interpolate(p_));
    const Foam::labelUList& owner = mesh_.owner();
    const Foam::labelUList& neighbour = mesh_.neighbour();
    const Foam::surfaceScalarField& share = *ownerShare_;
    forAll(owner, facei)
    {
        const Foam::scalar po = p_[owner[facei]];
        pf[facei] = po + share[facei]*(p_[neighbour[facei]] - po);
    }
    forAll(pf.boundaryField(), patchi)
    {
        const Foam::fvPatchScalarField& pp = p_.boundaryField()[patchi];
        if (!pp.coupled()) continue;
        const Foam::scalarField po(pp.patchInternalField());
        pf.boundaryFieldRef()[patchi] =
            po + share.boundaryField()[patchi]*(pp.patchNeighbourField() - po);
    }
    return Foam::fvc::surfaceIntegrate(mesh_.Sf()*pf);
}


void DemCoupling::setResistance(const Foam::volScalarField& resistance)
{
    // the owner's half is 1 - w of the way between the centres (w the
    // linear weight), so its drop is R_o (1 - w) of R_o (1 - w) + R_n w
    const Foam::labelUList& owner = mesh_.owner();
    const Foam::labelUList& neighbour = mesh_.neighbour();
    const Foam::surfaceScalarField& w = mesh_.weights();
    Foam::surfaceScalarField& share = *ownerShare_;
    forAll(owner, facei)
    {
        const Foam::scalar ro = resistance[owner[facei]]*(1 - w[facei]);
        share[facei] = ro/(ro + resistance[neighbour[facei]]*w[facei]);
    }
    forAll(share.boundaryField(), patchi)
    {
        const Foam::fvPatchScalarField& rp = resistance.boundaryField()[patchi];
        if (!rp.coupled()) continue;
        const Foam::scalarField& wp = w.boundaryField()[patchi];
        const Foam::scalarField ro(rp.patchInternalField()*(1 - wp));
        share.boundaryFieldRef()[patchi] = ro/(ro + rp.patchNeighbourField()*wp);
    }
}


void DemCoupling::solveEnergy()
{
    if (!thermal_) return;
    thermal_->solveGas(guards_);
    transferHeat();
}


void DemCoupling::transferHeat()
{
    if (thermal_) thermal_->transfer(*dem_, particles_, vf_.map, guards_, row_);
}


void DemCoupling::endStep(const Foam::surfaceScalarField& phiU)
{
    row_.gasReceived = sumOverRanks(fields_.gasMomentum(U_));
    guards_.checkCourant(phiU, maxCo_);
    log_->write(row_);
    if (circulation_)
    {
        circulation_->sample(*dem_, particles_, vf_.map, eps_, locator_, thermal_.get());
    }
}


void DemCoupling::checkGas() const
{
    guards_.checkField(U_);
    guards_.checkField(p_);
}


// --- coupling.csv ------------------------------------------------------------

void DemCoupling::fillMomentumRow
(
    const VoidFractionResult& vf, const ExchangeResult& ex
)
{
    double solid = 0;   // own cells: the halo's are the neighbours'
    for (label c = 0; c < locator_.nOwnedCells(); ++c) solid += vf.solidVolume[c];
    Vec3 drag, gas;
    for (const Vec3& f : ex.dragForce) drag += f;
    forAll(U_, celli)
    {
        const Vec3& u = Vec3{U_[celli].x(), U_[celli].y(), U_[celli].z()};
        gas += ex.beta[celli]*mesh_.V()[celli]*(u - ex.Us[celli]);
    }
    double sums[8] =
        {solid, drag.x, drag.y, drag.z, gas.x, gas.y, gas.z, double(particles_.size())};
    row_.particleMass = dem_->totalMass();
    sumOverRanks(sums, 8);
    row_.time = mesh_.time().value();
    row_.particles = std::lround(sums[7]);
    row_.solidVolume = sums[0];
    row_.minVoidFraction = Foam::gMin(voidfraction_.primitiveField());
    row_.particleDrag = Vec3{sums[1], sums[2], sums[3]};
    row_.gasExchange = Vec3{sums[4], sums[5], sums[6]};

    Foam::Info<< "Coupling: " << row_.particles << " particles, "
        << "min voidfraction " << row_.minVoidFraction
        << ", drag on particles (" << sums[1] << ' ' << sums[2] << ' '
        << sums[3] << ") N" << Foam::endl;
}


// --- output ------------------------------------------------------------------

void DemCoupling::write()
{
    const Foam::Time& runTime = mesh_.time();
    if (!runTime.writeTime()) return;

    guards_.written(runTime.timeName());
    writeParticles();
    if (circulation_) circulation_->write(*dem_, particles_, thermal_.get(), true);
    // LIGGGHTS 3.8 cannot write a system without atoms (its set-up stops
    // with "Atom types must start from 1"): once lostParticles delete has
    // removed the last particle there is no DEM restart, and a restart from
    // these times stops naming the missing file
    if (dem_->nParticles() == 0)   // all ranks: write_restart is collective
    {
        Foam::Info<< "spoutFoam: no particles left, no LIGGGHTS restart at t = "
            << runTime.timeName() << " s" << Foam::endl;
        return;
    }
    const Foam::fileName stem =
        runTime.globalPath()/"DEM"/("restart_" + runTime.timeName());
    dem_->writeRestart(stem + ".liggghts", stem + ".state");
}


void DemCoupling::writeParticles()
{
    ParticleColumns columns;
    columns.vectors = {{"fluidForce", &fluidForce_}, {"dragForce", &dragForce_}};
    if (thermal_) thermal_->addColumns(particles_, vf_.map, columns);
    const Foam::Time& runTime = mesh_.time();
    particleOutput_.write(runTime.value(), runTime.timeName(), particles_, columns);
}


void DemCoupling::finish()
{
    log_->flush();
    if (circulation_) circulation_->report();
    // how often LIGGGHTS rebuilt its neighbour lists (bench/neighbourSettings):
    // a rebuild costs several plain DEM steps
    Foam::Info<< "LIGGGHTS: " << dem_->neighbourBuilds() << " neighbour list builds in "
        << dem_->step() << " DEM steps (skin " << dem_->skin() << " m)" << Foam::endl;
    double rows[2] = {rowsKept_, rowsMapped_};
    sumOverRanks(rows, 2);
    Foam::Info<< "Void fraction: " << 100*rows[0]/std::max(rows[1], 1.0)
        << " % of the particles kept the last step's cells" << Foam::endl;
    // what the neighbour exchange cost, per rank and step (benchmarks)
    const double steps = std::max(1.0, double(mesh_.time().timeIndex() - startIndex_));
    if (Foam::Pstream::parRun()) reportHaloTraffic(locator_, steps);
}

} // namespace spoutlab
