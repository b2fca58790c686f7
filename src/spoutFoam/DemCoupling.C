/*---------------------------------------------------------------------------*\
    SpoutLab: the CFD side of the CFD-DEM coupling.
\*---------------------------------------------------------------------------*/
#include "DemCoupling.H"

#include "DemTimeStep.hpp"
#include "FoamParameters.H"
#include "InputError.hpp"
#include "OStringStream.H"
#include "RankGather.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace spoutlab
{

namespace
{

std::string format(double value)
{
    std::ostringstream os;
    os << std::setprecision(4) << value;
    return os.str();
}


// Sums over the ranks of the coupled run (one rank when serial).
void sumOverRanks(double* data, std::size_t n)
{
    MPI_Allreduce(MPI_IN_PLACE, data, int(n), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}


bool finite(double x) { return std::isfinite(x); }
bool finite(const Foam::vector& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}
bool finite(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string format(const Vec3& v)
{
    return "(" + format(v.x) + " " + format(v.y) + " " + format(v.z) + ")";
}

// A cell field the coupling computes and writes with the gas fields.
Foam::IOobject outputField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh,
        Foam::IOobject::NO_READ, Foam::IOobject::AUTO_WRITE
    );
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
    couplingInterval_(dict_.get<Foam::label>("couplingInterval")),
    deleteLost_(false),
    maxCo_(dict_.getOrDefault<Foam::scalar>("maxCo", 1.0)),
    lastWritten_(mesh.time().timeName()),
    startIndex_(mesh.time().timeIndex()),
    locator_(mesh),
    vtk_(mesh.time().globalPath()/"particles", "particles"),
    Ksl_
    (
        outputField(mesh, "Ksl"), mesh,
        Foam::dimensionedScalar(Foam::dimDensity/Foam::dimTime, Foam::Zero)
    ),
    Us_
    (
        outputField(mesh, "Us"), mesh,
        Foam::dimensionedVector(Foam::dimVelocity, Foam::Zero)
    ),
    solidFraction_
    (
        outputField(mesh, "solidFraction"), mesh,
        Foam::dimensionedScalar(Foam::dimless, Foam::Zero)
    ),
    solidFlux_
    (
        outputField(mesh, "solidFlux"), mesh,
        Foam::dimensionedVector(Foam::dimVelocity, Foam::Zero)
    )
{
    if (couplingInterval_ < 1)
    {
        throw InputError
        (
            "constant/couplingProperties: key 'couplingInterval' expected a "
            "positive number of DEM steps per CFD step"
        );
    }
    const Foam::word lost = dict_.getOrDefault<Foam::word>("lostParticles", "stop");
    if (lost != "stop" && lost != "delete")
    {
        throw InputError
        (
            "constant/couplingProperties: key 'lostParticles' expected 'stop' "
            "or 'delete', got '" + lost + "'"
        );
    }
    deleteLost_ = (lost == "delete");

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

    startDem();
    checkTimeSteps();
    startHeat(phi, rho.value(), mu.value());

    if (Foam::Pstream::master())
    {
        const Foam::fileName dir = mesh.time().globalPath()/"postProcessing";
        Foam::mkDir(dir);
        const bool fresh = mesh.time().value() == 0;
        // a restart continues the log of the run it resumes: rows a killed
        // run wrote after its last write time go, and so does the row of the
        // restart time itself unless the step state keeps it exact
        if (!fresh)
        {
            trimLog(dir/"coupling.csv", resumed_ ? 0.5 : -0.5);
        }
        log_.reset
        (
            new std::ofstream
            (
                dir/"coupling.csv",
                fresh ? std::ios::trunc : std::ios::app
            )
        );
        if (fresh || log_->tellp() == 0)
        {
            *log_
                << "time [s],particles,particle mass [kg],solid volume [m3],"
                << "min voidfraction,"
                << "particle drag x [N],particle drag y [N],particle drag z [N],"
                << "gas exchange x [N],gas exchange y [N],gas exchange z [N],"
                << "gas received x [N],gas received y [N],gas received z [N]";
            if (heat_)
            {
                *log_
                    << ",heat to particles [W],heat from gas [W],"
                    << "gas enthalpy in [W],gas enthalpy out [W],"
                    << "gas outlet temperature [K],gas energy [J],"
                    << "particle energy [J],mean particle temperature [K]";
            }
            *log_ << '\n';
        }
        // ParaView opens OpenFOAM cases through an empty <case>.foam file
        const Foam::fileName stub =
            mesh.time().globalPath()/(mesh.time().globalCaseName() + ".foam");
        if (!Foam::isFile(stub)) std::ofstream touch(stub);
    }

    // particles at the start time: map them so the first gas step already
    // sees the bed.  A fresh run computes the fluid forces (and heat fluxes)
    // for the first DEM steps here; a restart has them from its step state
    // (the uninterrupted run computed them before that step's gas solve,
    // from gas fields the time directory no longer holds).
    vf_ = mapParticles();
    voidfraction_.oldTime() = voidfraction_;
    if (!resumed_)
    {
        exchange(vf_);
        logGasMomentum();
        transferHeat();
        writeParticles();
    }
    if (mesh.time().value() == 0)
    {
        // what the run starts from, beside the initial conditions: the
        // exchange of the settled bed (e.g. to compare decompositions)
        voidfraction_.write();
        Ksl_.write();
        Us_.write();
        solidFraction_.write();
        dem_->writeStepState(mesh.time().globalPath()/"DEM"/"start.state");
    }
}


void DemCoupling::trimLog(const std::string& file, double stepsPast) const
{
    std::ifstream in(file);
    if (!in) return;
    const double tMax =
        mesh_.time().value() + stepsPast*mesh_.time().deltaTValue();
    std::string kept, line;
    while (std::getline(in, line))
    {
        // the header and every row up to the restart time
        char* end = nullptr;
        const double t = std::strtod(line.c_str(), &end);
        if (end == line.c_str() || t <= tMax) kept += line + '\n';
    }
    in.close();
    const std::string tmp = file + ".tmp";
    std::ofstream(tmp, std::ios::trunc) << kept;
    std::rename(tmp.c_str(), file.c_str());
}


void DemCoupling::startDem()
{
    const Foam::Time& runTime = mesh_.time();
    const Foam::fileName caseDir = runTime.globalPath();
    const Foam::fileName demDir = caseDir/"DEM";
    if (Foam::Pstream::master()) Foam::mkDir(demDir);

    std::map<std::string, std::string> vars;
    vars["case"] = caseDir;
    vars["dem"] = demDir;
    if (const Foam::dictionary* user = dict_.findDict("liggghtsVariables"))
    {
        Parameters params = toParameters(dict_, "liggghtsVariables");
        for (const Foam::word& key : user->toc()) vars[key] = params.getWord(key);
    }
    if (runTime.value() > 0)
    {
        const Foam::fileName restart =
            demDir/("restart_" + runTime.timeName() + ".liggghts");
        if (!Foam::isFile(restart))
        {
            throw InputError
            (
                "restart at t = " + runTime.timeName()
              + " s needs the LIGGGHTS restart '" + restart + "' (missing)"
            );
        }
        vars["restart"] = restart;
    }

    Foam::fileName input = dict_.get<Foam::fileName>("liggghtsInput");
    input.expand();
    if (!input.isAbsolute()) input = caseDir/input;

    vars["inputDir"] = input.path();   // for includes beside the input
    liggghtsInput_ = input;
    dem_.reset
    (
        new LiggghtsDem(input, vars, caseDir/"log.liggghts", MPI_COMM_WORLD)
    );
    if (Foam::Pstream::parRun())
    {
        // each rank's atoms in its own cells; what they reach of the
        // neighbours' cells becomes its halo
        const std::vector<double> cuts = meshSlabs();
        const double reach = dem_->reach();
        for (std::size_t r = 0; r + 1 < cuts.size(); ++r)
        {
            if (cuts[r + 1] - cuts[r] < reach)
            {
                throw InputError
                (
                    "system/decomposeParDict: the x-slab of rank " + std::to_string(r)
                  + " is " + format(cuts[r + 1] - cuts[r]) + " m wide, less than "
                    "the particles' reach (largest radius + LIGGGHTS skin, "
                  + format(reach) + " m); run on fewer ranks"
                );
            }
        }
        dem_->setSlabs(cuts);
        locator_.addHalo(cuts, reach);
        std::vector<double> halo(Foam::Pstream::nProcs(), 0.0);
        halo[Foam::Pstream::myProcNo()] = double(locator_.nHaloCells());
        sumOverRanks(halo.data(), halo.size());
        Foam::Info<< "Parallel coupling: " << Foam::Pstream::nProcs()
            << " x-slabs cut at";
        for (std::size_t r = 1; r + 1 < cuts.size(); ++r) Foam::Info<< ' ' << cuts[r];
        Foam::Info<< " m; halo cells per rank (reach " << reach << " m):";
        for (const double h : halo) Foam::Info<< ' ' << label(h);
        Foam::Info<< Foam::endl;
    }
    if (runTime.value() > 0)
    {
        const Foam::fileName state =
            demDir/("restart_" + runTime.timeName() + ".state");
        if (Foam::isFile(state))
        {
            dem_->readStepState(state);
            resumed_ = true;
        }
        else
        {
            Foam::Info<< "spoutFoam: no DEM step state " << state << "; the "
                "fluid forces of the first steps are recomputed from the gas "
                "fields, so this restart is close to, not equal to, the "
                "uninterrupted run" << Foam::endl;
        }
    }
    Foam::Info<< "LIGGGHTS: " << dem_->nParticles() << " particles from "
        << input << ", DEM time step " << dem_->timeStep() << " s" << Foam::endl;
}


std::vector<double> DemCoupling::meshSlabs() const
{
    // each rank's x-extent, in rank order: the slabs must follow each other
    const Foam::label nProcs = Foam::Pstream::nProcs();
    std::vector<double> lo(nProcs, 0), hi(nProcs, 0);
    const Foam::boundBox local(mesh_.points(), false);   // not reduced
    lo[Foam::Pstream::myProcNo()] = local.min().x();
    hi[Foam::Pstream::myProcNo()] = local.max().x();
    sumOverRanks(lo.data(), lo.size());
    sumOverRanks(hi.data(), hi.size());
    const double tol = 1e-9*(hi.back() - lo.front());
    for (Foam::label r = 1; r < nProcs; ++r)
    {
        if (std::abs(lo[r] - hi[r-1]) > tol)
        {
            throw InputError
            (
                "system/decomposeParDict: the coupling expects the mesh in "
                "x-slabs in rank order (etc/caseFunctions decomposeSlabs); "
                "rank " + std::to_string(r - 1) + " spans x " + format(lo[r-1])
              + " to " + format(hi[r-1]) + " m, rank " + std::to_string(r)
              + " " + format(lo[r]) + " to " + format(hi[r]) + " m"
            );
        }
    }
    std::vector<double> cuts(lo);
    cuts.push_back(hi.back());
    return cuts;
}


void DemCoupling::startHeat
(
    const Foam::surfaceScalarField& phi, double rho, double mu
)
{
    const Foam::word model =
        dict_.getOrDefault<Foam::word>("heatTransferModel", "none");
    if (model == "none") return;
    // a bad name before what LIGGGHTS lacks for heat: the name is fixed first
    HeatTransferModel::registry().require(model, "constant/couplingProperties");
    if (!dem_->hasHeat())
    {
        throw InputError
        (
            "LIGGGHTS input '" + liggghtsInput_ + "': heat transfer "
            "(heatTransferModel " + model + " in constant/couplingProperties) "
            "expects the particle temperatures of 'fix ID all couple/cfd/"
            "convection T0 <K>' and 'fix ID all property/global "
            "thermalCapacity peratomtype ...'"
        );
    }
    heat_.reset
    (
        new HeatCoupling(mesh_, locator_, dict_, model, voidfraction_, phi, rho, mu)
    );
    // the particles' m c_p/A do not change during a run (deleting particles
    // can only raise the smallest), so it is taken once
    minHeatCapacityPerArea_ = dem_->minHeatCapacityPerArea();
    Foam::Info<< "Heat transfer: " << model.c_str() << ", gas c_p "
        << heat_->gas().cp << " J/kg/K, k_c " << heat_->gas().kappa
        << " W/m/K" << Foam::endl;
}


void DemCoupling::checkTimeSteps() const
{
    const double dtDem = dem_->timeStep();
    const double dtCfd = mesh_.time().deltaTValue();
    if (std::abs(dtCfd - couplingInterval_*dtDem) > 1e-9*dtCfd)
    {
        throw InputError
        (
            "system/controlDict: key 'deltaT' expected couplingInterval ("
          + std::to_string(couplingInterval_) + ") x LIGGGHTS time step ("
          + format(dtDem) + " s) = " + format(couplingInterval_*dtDem)
          + " s, got " + format(dtCfd) + " s"
        );
    }

    const double k = dem_->maxNormalStiffness();
    const double m = dem_->minParticleMass();
    if (k > 0 && dem_->nParticles() > 0)
    {
        const double limit = demTimeStepLimit(m, k);
        if (dtDem > limit*(1 + 1e-9))   // round-off: dt exactly at the limit is fine
        {
            throw InputError
            (
                "LIGGGHTS input '" + liggghtsInput_ + "': DEM time step "
              + format(dtDem)
              + " s exceeds the limit of eq 11, pi*sqrt(m/k)/5 = "
              + format(limit) + " s (lightest particle m = " + format(m)
              + " kg, largest k_n = " + format(k) + " N/m)"
            );
        }
    }
}


VoidFractionResult DemCoupling::mapParticles()
{
    dem_->localParticles(particles_);
    std::string found;
    for (const Particle& p : particles_)
    {
        if (finite(p.x) && finite(p.v)) continue;
        found = "non-finite position or velocity of particle " + std::to_string(p.id)
              + " (x " + format(p.x) + ", v " + format(p.v) + ")";
        break;
    }
    stopIfAnyRank(found);
    VoidFractionResult vf =
        voidFractionModel_->compute(locator_, particles_, vf_);   // the last step's

    // A rank's atoms lie in its cells or its halo; a centre in neither is
    // outside the mesh.
    std::vector<long> lost;
    for (const std::size_t i : vf.lostParticles) lost.push_back(particles_[i].id);
    lost = gathered(lost, MPI_COMM_WORLD, true);
    if (!lost.empty())
    {
        std::sort(lost.begin(), lost.end());   // the same line on any ranks
        std::string ids;
        for (std::size_t k = 0; k < lost.size() && k < 20; ++k)
        {
            ids += (k ? ", " : "") + std::to_string(lost[k]);
        }
        if (lost.size() > 20) ids += ", ...";
        const std::string what =
            std::to_string(lost.size()) + " particle(s) outside the CFD mesh at t = "
          + mesh_.time().timeName() + " s (ids " + ids + ")";
        if (!deleteLost_)
        {
            throw InputError
            (
                what + "; set 'lostParticles delete' in "
                "constant/couplingProperties to remove them instead"
            );
        }
        Foam::Info<< "spoutFoam: deleting " << what.c_str() << Foam::endl;
        dem_->deleteParticles(lost);
        dem_->localParticles(particles_);
        vf = voidFractionModel_->compute(locator_, particles_);
    }

    rowsKept_ += double(vf.rowsKept);
    rowsMapped_ += double(particles_.size());
    eps_ = voidFractionModel_->voidFraction(locator_, vf.solidVolume);
    Foam::scalarField& field = voidfraction_.primitiveFieldRef();
    forAll(field, celli) field[celli] = eps_[celli];
    voidfraction_.correctBoundaryConditions();
    checkField(voidfraction_);
    return vf;
}


void DemCoupling::exchange(const VoidFractionResult& vf)
{
    // the gas in this rank's cells and its halo
    const std::vector<Vec3> U = locator_.withHalo(U_.primitiveField());
    const std::vector<Vec3> gradP =
        locator_.withHalo(Foam::fvc::grad(p_)().primitiveField());
    const ExchangeResult ex = exchange_->compute
    (
        locator_, particles_, vf, GasCellFields{U, gradP, eps_}, gas_, g_
    );
    // before the forces reach LIGGGHTS or the log
    checkParticles("fluid force", ex.totalForce);

    forAll(Ksl_, celli)
    {
        Ksl_[celli] = ex.beta[celli];
        const Vec3& us = ex.Us[celli];
        Us_[celli] = Foam::vector(us.x, us.y, us.z);
        solidFraction_[celli] = ex.solidFraction[celli];
        solidFlux_[celli] = ex.solidFraction[celli]*Us_[celli];
    }
    Ksl_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();
    solidFraction_.correctBoundaryConditions();
    solidFlux_.correctBoundaryConditions();

    // this rank's share; summed over ranks only when written
    fluidForce_ = ex.totalForce;
    dragForce_ = ex.dragForce;
    dem_->setFluidForces(fluidForce_);
    if (heat_)
    {
        heat_->updateCoefficients(particles_, eps_, vf.map, ex);
        heat_->checkTimeStep(minHeatCapacityPerArea_);
    }
    logStep(vf, ex);
}


void DemCoupling::logStep(const VoidFractionResult& vf, const ExchangeResult& ex)
{
    double solid = 0;   // own cells: the halo's are the neighbours'
    for (label c = 0; c < locator_.nOwnedCells(); ++c) solid += vf.solidVolume[c];
    Vec3 drag, gas;
    for (const Vec3& f : ex.dragForce) drag += f;
    forAll(Ksl_, celli)
    {
        const Vec3& u = Vec3{U_[celli].x(), U_[celli].y(), U_[celli].z()};
        gas += ex.beta[celli]*mesh_.V()[celli]*(u - ex.Us[celli]);
    }
    double sums[8] =
        {solid, drag.x, drag.y, drag.z, gas.x, gas.y, gas.z, double(particles_.size())};
    const double mass = dem_->totalMass();
    sumOverRanks(sums, 8);
    const long nParticles = std::lround(sums[7]);
    const double epsMin = Foam::gMin(voidfraction_.primitiveField());

    Foam::Info<< "Coupling: " << nParticles << " particles, "
        << "min voidfraction " << epsMin
        << ", drag on particles (" << sums[1] << ' ' << sums[2] << ' '
        << sums[3] << ") N" << Foam::endl;
    std::ostringstream row;
    row << std::setprecision(10) << mesh_.time().value() << ','
        << nParticles << ',' << mass << ',' << sums[0] << ',' << epsMin;
    for (int k = 1; k < 7; ++k) row << ',' << sums[k];
    logRow_ = row.str();   // ends after the gas solve (logGasMomentum)
}


void DemCoupling::logGasMomentum()
{
    // What the discretised momentum equation took from the particles: its
    // exchange term Ksl (Us - U) is implicit in U, so with the U just
    // solved, not the U the particle drag was computed from.
    Vec3 received;
    forAll(Ksl_, celli)
    {
        const Foam::vector d = Ksl_[celli]*mesh_.V()[celli]*(U_[celli] - Us_[celli]);
        received += Vec3{d.x(), d.y(), d.z()};
    }
    double sums[3] = {received.x, received.y, received.z};
    sumOverRanks(sums, 3);
    std::ostringstream row;
    row << std::setprecision(10) << ',' << sums[0] << ',' << sums[1] << ',' << sums[2];
    logRow_ += row.str();
    if (!heat_) endLogRow();   // with heat, the row ends after the gas energy
}


void DemCoupling::logHeat()
{
    double toParticles = 0;
    for (double q : heatFlux_) toParticles += q;
    sumOverRanks(&toParticles, 1);
    const GasHeatBalance b = heat_->balance();
    const LiggghtsDem::HeatContent particles = dem_->heatContent();
    const double Ep = particles.energy;
    const double meanTp = Ep/std::max(particles.capacity, 1e-300);

    std::ostringstream row;
    // energies of order 1e6 J change by a few J per step: 15 digits keep
    // the step-by-step balance readable from the file
    row << std::setprecision(15) << ',' << toParticles << ',' << b.gasGave
        << ',' << b.inflow << ',' << b.outflow << ',' << b.outletTemperature
        << ',' << b.gasEnergy << ',' << Ep << ',' << meanTp;
    logRow_ += row.str();
    Foam::Info<< "Heat: " << toParticles << " W to the particles, mean "
        << "particle temperature " << meanTp << " K, gas outlet "
        << b.outletTemperature << " K" << Foam::endl;
    endLogRow();
}


void DemCoupling::endLogRow()
{
    if (log_)
    {
        *log_ << logRow_ << '\n';
        log_->flush();
    }
    logRow_.clear();
}


void DemCoupling::evolve()
{
    dem_->run(couplingInterval_);
    vf_ = mapParticles();
    exchange(vf_);
}


void DemCoupling::solveEnergy()
{
    if (!heat_) return;
    heat_->solveGas();
    checkField(heat_->T());
    transferHeat();
}


void DemCoupling::transferHeat()
{
    if (!heat_) return;
    // this rank's share, like the forces
    heatFlux_ = heat_->particleHeatFlux(particles_, vf_.map);
    checkParticles("heat flux", heatFlux_);
    dem_->setHeatFluxes(heatFlux_);
    logHeat();
}


// --- guards against NaN and Inf --------------------------------------------
// Each check is one pass over this rank's values and one integer reduction,
// so every rank reaches the same decision; the first offending rank's
// description goes to all.  Nothing of the failing step is written: the last
// good state is the latest time directory, where 'startFrom latestTime'
// restarts.

void DemCoupling::stopIfAnyRank(const std::string& found) const
{
    int rank = 0, nProcs = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nProcs);
    int first = found.empty() ? nProcs : rank;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == nProcs) return;

    int n = int(found.size());
    MPI_Bcast(&n, 1, MPI_INT, first, MPI_COMM_WORLD);
    std::string what(found);
    what.resize(std::size_t(n));
    MPI_Bcast(&what[0], n, MPI_CHAR, first, MPI_COMM_WORLD);
    throw InputError
    (
        what + " at t = " + mesh_.time().timeName() + " s; nothing of this "
        "step was written, the last good state is time " + lastWritten_
      + " (startFrom latestTime restarts from it)"
    );
}


template<class Type>
void DemCoupling::checkField
(
    const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& field
) const
{
    std::string found;
    const Foam::Field<Type>& values = field.primitiveField();
    forAll(values, celli)
    {
        if (finite(values[celli])) continue;
        const Foam::vector& c = mesh_.C()[celli];
        found = "non-finite " + field.name() + " in cell "
              + std::to_string(celli) + " " + format(Vec3{c.x(), c.y(), c.z()});
        if (Foam::Pstream::parRun())
        {
            found += " of processor " + std::to_string(Foam::Pstream::myProcNo());
        }
        break;
    }
    stopIfAnyRank(found);
}


template<class Value>
void DemCoupling::checkParticles
(
    const std::string& what, const std::vector<Value>& values
) const
{
    std::string found;
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (finite(values[i])) continue;
        found = "non-finite " + what + " on particle "
              + std::to_string(particles_[i].id) + " " + format(particles_[i].x);
        break;
    }
    stopIfAnyRank(found);
}


void DemCoupling::checkGas() const
{
    checkField(U_);
    checkField(p_);
}


void DemCoupling::checkCourant(const Foam::surfaceScalarField& phiU) const
{
    const Foam::scalarField sumPhi
    (
        Foam::fvc::surfaceSum(Foam::mag(phiU))().primitiveField()
    );
    const Foam::scalar Co =
        0.5*Foam::gMax(sumPhi/mesh_.V().field())*mesh_.time().deltaTValue();
    Foam::Info<< "Courant number (interstitial) max: " << Co << Foam::endl;
    if (Co > maxCo_)
    {
        throw InputError
        (
            "gas Courant number " + format(Co) + " at t = "
          + mesh_.time().timeName() + " s exceeds maxCo " + format(maxCo_)
          + " (constant/couplingProperties); reduce deltaT and couplingInterval"
        );
    }
}


void DemCoupling::write()
{
    const Foam::Time& runTime = mesh_.time();
    if (!runTime.writeTime()) return;

    lastWritten_ = runTime.timeName();
    writeParticles();
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
    // one row per particle, gathered on the master: id, x (3), v (3),
    // radius, T, fluid force (3), drag (3)[, heat flux, h]
    const int width = heat_ ? 17 : 15;
    std::vector<double> h;
    if (heat_) h = heat_->particleH(vf_.map);
    std::vector<double> rows;
    rows.reserve(particles_.size()*width);
    for (std::size_t i = 0; i < particles_.size(); ++i)
    {
        const Particle& p = particles_[i];
        rows.insert
        (
            rows.end(),
            {
                double(p.id), p.x.x, p.x.y, p.x.z, p.v.x, p.v.y, p.v.z, p.radius,
                p.temperature, fluidForce_[i].x, fluidForce_[i].y, fluidForce_[i].z,
                dragForce_[i].x, dragForce_[i].y, dragForce_[i].z
            }
        );
        if (heat_) rows.insert(rows.end(), {heatFlux_[i], h[i]});
    }
    rows = gathered(rows, MPI_COMM_WORLD, false);
    if (!Foam::Pstream::master()) return;

    const std::size_t n = rows.size()/width;
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = k;
    std::sort
    (
        order.begin(), order.end(),
        [&](std::size_t a, std::size_t b) { return rows[a*width] < rows[b*width]; }
    );
    std::vector<Particle> all(n);
    std::vector<Vec3> fluid(n), drag(n);
    std::vector<double> T(n), q(n), hp(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        const double* r = &rows[order[k]*width];
        all[k].id = long(r[0]);
        all[k].x = Vec3{r[1], r[2], r[3]};
        all[k].v = Vec3{r[4], r[5], r[6]};
        all[k].radius = r[7];
        T[k] = all[k].temperature = r[8];
        fluid[k] = Vec3{r[9], r[10], r[11]};
        drag[k] = Vec3{r[12], r[13], r[14]};
        if (heat_) { q[k] = r[15]; hp[k] = r[16]; }
    }
    std::vector<std::pair<std::string, std::vector<double>>> scalars;
    if (heat_) scalars = {{"temperature", T}, {"heatFlux", q}, {"h", hp}};
    const Foam::Time& runTime = mesh_.time();
    vtk_.write
    (
        runTime.value(), runTime.timeName(), all,
        {{"fluidForce", fluid}, {"dragForce", drag}}, scalars
    );
}


void DemCoupling::finish()
{
    if (log_) log_->flush();
    // how often LIGGGHTS rebuilt its neighbour lists (bench/neighbourSettings):
    // a rebuild costs several plain DEM steps
    Foam::Info<< "LIGGGHTS: " << dem_->neighbourBuilds() << " neighbour list builds in "
        << dem_->step() << " DEM steps (skin " << dem_->skin() << " m)" << Foam::endl;
    double rows[2] = {rowsKept_, rowsMapped_};
    sumOverRanks(rows, 2);
    Foam::Info<< "Void fraction: " << 100*rows[0]/std::max(rows[1], 1.0)
        << " % of the particles kept the last step's cells" << Foam::endl;
    if (!Foam::Pstream::parRun()) return;
    // what the neighbour exchange cost, per rank and step (benchmarks)
    const Foam::label nProcs = Foam::Pstream::nProcs();
    const double steps = std::max(1.0, double(mesh_.time().timeIndex() - startIndex_));
    std::vector<double> messages(nProcs, 0.0), bytes(nProcs, 0.0);
    messages[Foam::Pstream::myProcNo()] = locator_.traffic().messages/steps;
    bytes[Foam::Pstream::myProcNo()] = locator_.traffic().bytes/steps;
    sumOverRanks(messages.data(), messages.size());
    sumOverRanks(bytes.data(), bytes.size());
    Foam::Info<< "Halo exchange per step, by rank (messages, kB):";
    for (Foam::label r = 0; r < nProcs; ++r)
    {
        Foam::Info<< " (" << messages[r] << ", " << bytes[r]/1024 << ")";
    }
    Foam::Info<< Foam::endl;
}

} // namespace spoutlab
