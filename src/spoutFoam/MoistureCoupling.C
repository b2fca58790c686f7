/*---------------------------------------------------------------------------*\
    SpoutLab: drying on the CFD side.
\*---------------------------------------------------------------------------*/
#include "MoistureCoupling.H"
#include "RangeWarnings.H"

#include "FoamParameters.H"
#include "InputError.hpp"
#include "MoistAir.hpp"
#include "Psychrometrics.hpp"
#include "RunGuards.H"
#include "ShortNumbers.H"

#include <mpi.h>

#include <cmath>

namespace spoutlab
{

namespace
{

// The energies of water, as the gas equation and the particles count them:
// liquid c_w T, vapour c_pv T + h_c, so that the difference is free water's
// heat of vaporisation h_fg0 + (c_pv - c_w)(T - 273.15) (Psychrometrics).
// The gas energy equation carries the vapour's c_pv T; h_c rides with the
// vapour mass fraction.
const double vapourEnthalpyOffset =
    psy::kHfg0 + (psy::kCpWater - psy::kCpVapour)*273.15;

const Foam::dimensionSet dimSpecificHeat(0, 2, -2, -1, 0);
const Foam::dimensionSet dimSource(1, -3, -1, 0, 0);          // kg/m3/s
const Foam::dimensionSet dimPowerDensity(1, -1, -3, 0, 0);    // W/m3


Foam::IOobject field
(
    const Foam::fvMesh& mesh, const Foam::word& name, bool written
)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh, Foam::IOobject::NO_READ,
        written ? Foam::IOobject::AUTO_WRITE : Foam::IOobject::NO_WRITE
    );
}


double readTransport(const Foam::fvMesh& mesh, const Foam::word& key, const std::string& what)
{
    const Foam::IOdictionary transport
    (
        Foam::IOobject
        (
            "transportProperties", mesh.time().constant(), mesh,
            Foam::IOobject::MUST_READ, Foam::IOobject::NO_WRITE, false
        )
    );
    return positiveEntry(transport, "constant/transportProperties", key, what, "drying");
}


void sumOverRanks(double* data, int n)
{
    MPI_Allreduce(MPI_IN_PLACE, data, n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

} // namespace


int MoistureCoupling::stateSize(const Foam::dictionary& couplingDict)
{
    const Foam::word model =
        couplingDict.getOrDefault<Foam::word>("dryingModel", "none");
    if (model == "none") return -1;
    return DryingModel::New(model, toParameters(couplingDict, model + "Props"))->stateSize();
}


std::unique_ptr<MoistureCoupling> MoistureCoupling::New
(
    const Foam::fvMesh& mesh,
    const FoamCellLocator& cells,
    const Foam::dictionary& couplingDict,
    const Foam::volScalarField& voidfraction,
    const Foam::surfaceScalarField& phi,
    double rho,
    double cpAir
)
{
    const Foam::word model =
        couplingDict.getOrDefault<Foam::word>("dryingModel", "none");
    if (model == "none") return nullptr;
    std::unique_ptr<MoistureCoupling> moisture
    (
        new MoistureCoupling(mesh, cells, couplingDict, model, voidfraction, phi, rho, cpAir)
    );
    Foam::Info<< "Drying: " << model.c_str() << ", vapour diffusivity "
        << moisture->Dv_ << " m2/s, gas pressure " << moisture->exchange_.pressure()
        << " Pa, dry solid c_p " << moisture->dryHeatCapacity_ << " J/kg/K" << Foam::endl;
    return moisture;
}


MoistureCoupling::MoistureCoupling
(
    const Foam::fvMesh& mesh,
    const FoamCellLocator& cells,
    const Foam::dictionary& couplingDict,
    const Foam::word& modelName,
    const Foam::volScalarField& voidfraction,
    const Foam::surfaceScalarField& phi,
    double rho,
    double cpAir
)
:
    mesh_(mesh),
    locator_(cells),
    voidfraction_(voidfraction),
    phi_(phi),
    rho_(rho),
    cpAir_(cpAir),
    Dv_(readTransport(mesh, "Dv", "the vapour's diffusivity in the gas D_v [m2/s], a positive number")),
    dryHeatCapacity_
    (
        positiveEntry
        (
            couplingDict, "constant/couplingProperties", "kernelHeatCapacity",
            "the dry solid's specific heat c_d [J/kg/K], a positive number", "drying"
        )
    ),
    exchange_
    (
        DryingModel::New(modelName, toParameters(couplingDict, modelName + "Props")),
        readTransport(mesh, "pressure", "the gas's total pressure [Pa], a positive number")
    ),
    Y_
    (
        Foam::IOobject
        (
            "H2O", mesh.time().timeName(), mesh,
            Foam::IOobject::MUST_READ, Foam::IOobject::AUTO_WRITE
        ),
        mesh
    ),
    W_(field(mesh, "humidity", true), mesh, Foam::dimensionedScalar(Foam::dimless, Foam::Zero)),
    RH_(field(mesh, "RH", true), mesh, Foam::dimensionedScalar(Foam::dimless, Foam::Zero)),
    Sv_(field(mesh, "Sv", true), mesh, Foam::dimensionedScalar(dimSource, Foam::Zero)),
    Hv_(field(mesh, "vapourEnthalpy", false), mesh, Foam::dimensionedScalar(dimPowerDensity, Foam::Zero)),
    cp_(field(mesh, "cpGas", false), mesh, Foam::dimensionedScalar("cpAir", dimSpecificHeat, cpAir))
{
    checkCase();
    if (const SorptionIsotherm* isotherm = exchange_.model().sorptionIsotherm())
    {
        ranges_.add(isotherm->name(), isotherm->statedRanges());
        temperatureSlot_ = ranges_.slot(isotherm->name(), "temperature");
        humiditySlot_ = ranges_.slot(isotherm->name(), "relative humidity");
    }
}


void MoistureCoupling::checkCase() const
{
    checkStartField(Y_);
    const std::string file = mesh_.time().timeName() + "/H2O";
    double lo = Foam::gMin(Y_.primitiveField()), hi = Foam::gMax(Y_.primitiveField());
    forAll(Y_.boundaryField(), patchi)
    {
        const Foam::scalarField& Yb = Y_.boundaryField()[patchi];
        if (Yb.size()) lo = std::min(lo, Foam::min(Yb)), hi = std::max(hi, Foam::max(Yb));
    }
    Foam::reduce(lo, Foam::minOp<double>());
    Foam::reduce(hi, Foam::maxOp<double>());
    if (!(lo >= 0 && hi < 1))
    {
        throw InputError
        (
            file + ": expected vapour mass fractions from 0 to below 1, got "
            + format(lo) + " to " + format(hi)
        );
    }
    if (!mesh_.solutionDict().subDict("solvers").found("H2O"))
    {
        throw InputError
        (
            "system/fvSolution: key 'solvers/H2O' is missing (drying solves "
            "the vapour mass fraction H2O)"
        );
    }
    const Foam::dictionary& div = mesh_.schemesDict().subDict("divSchemes");
    if (!div.found("div(phi,H2O)") && !div.found("default"))
    {
        throw InputError
        (
            "system/fvSchemes: key 'divSchemes/div(phi,H2O)' is missing "
            "(drying convects the vapour mass fraction H2O)"
        );
    }
}


void MoistureCoupling::checkSaturation(const Foam::volScalarField& T) const
{
    // the humidity the case starts from, in every cell and on every
    // boundary, at or below saturation at the gas temperature there
    const double p = exchange_.pressure();
    double worst = 0;
    auto check = [&](double Y, double Tg)
    {
        worst = std::max(worst, relativeHumidity(MoistAir{Tg, Y/(1 - Y), p}));
    };
    forAll(Y_, i) check(Y_[i], T[i]);
    forAll(Y_.boundaryField(), patchi)
    {
        const Foam::scalarField& Yb = Y_.boundaryField()[patchi];
        const Foam::scalarField& Tb = T.boundaryField()[patchi];
        forAll(Yb, f) check(Yb[f], Tb[f]);
    }
    double all = worst;
    Foam::reduce(all, Foam::maxOp<double>());
    if (all > 1 + 1e-9)
    {
        throw InputError
        (
            mesh_.time().timeName() + "/H2O: expected humidities at or below "
            "saturation at the gas temperature (" + mesh_.time().timeName()
          + "/T), got a relative humidity of " + format(all)
        );
    }
}


void MoistureCoupling::updateHumidity(const Foam::volScalarField& T)
{
    updateHumidityRatio();
    updateRelativeHumidity(T);
}


void MoistureCoupling::updateHumidityRatio()
{
    W_ = Y_/(1 - Y_);
    cp_ = (1 - Y_)*Foam::dimensionedScalar("cpAir", dimSpecificHeat, cpAir_)
        + Y_*Foam::dimensionedScalar("cpVapour", dimSpecificHeat, psy::kCpVapour);
}


void MoistureCoupling::updateRelativeHumidity(const Foam::volScalarField& T)
{
    const double p = exchange_.pressure();
    forAll(RH_, i) RH_[i] = relativeHumidity(MoistAir{T[i], W_[i], p});
    RH_.correctBoundaryConditions();
}


void MoistureCoupling::startParticles(LiggghtsDem& dem, const Foam::volScalarField& T)
{
    checkSaturation(T);
    updateHumidity(T);
    const std::vector<std::size_t> fresh = dem.localMoisture(kernels_);
    long bad[2] = {0, 0};   // negative, not finite
    for (const std::size_t i : fresh)
    {
        const double X = kernels_.moisture[i];
        if (!std::isfinite(X)) ++bad[1];
        else if (X < 0) ++bad[0];
        else exchange_.initialise(kernels_, i);
    }
    MPI_Allreduce(MPI_IN_PLACE, bad, 2, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    if (bad[0] + bad[1] > 0)
    {
        throw InputError
        (
            std::to_string(bad[0] + bad[1]) + " particle(s) with a "
          + (bad[1] ? (bad[0] ? "negative or non-finite" : "non-finite") : "negative")
          + " moisture "
            "X (LIGGGHTS 'fix property/atom moisture'): expected kg water per "
            "kg dry solid, 0 or more"
        );
    }
    if (!fresh.empty()) dem.setMoisture(kernels_, Vec3{0, 0, 0});
    kernels_.stateRows.clear();   // LIGGGHTS' rows: valid only until it runs
}


void MoistureCoupling::dryParticles
(
    LiggghtsDem& dem,
    const std::vector<Particle>& particles,
    const ParticleCellMap& map,
    const HeatCellCoefficients& cells,
    const Foam::volScalarField& Tgas,
    const Vec3& g,
    const RunGuards& guards
)
{
    const std::vector<std::size_t> fresh = dem.localMoisture(kernels_);
    for (const std::size_t i : fresh) exchange_.initialise(kernels_, i);
    const std::vector<double> T = locator_.withHalo(Tgas.primitiveField());
    const std::vector<double> W = locator_.withHalo(W_.primitiveField());
    step_ = exchange_.advance
    (
        locator_, particles, map, MoistureCellFields{T, W, cells.km}, kernels_,
        mesh_.time().deltaTValue()
    );
    guards.checkParticles("moisture", kernels_.moisture, particles);
    dem.setMoisture(kernels_, g);
    kernels_.stateRows.clear();   // LIGGGHTS' rows: valid only until it runs
    forAll(Sv_, i)
    {
        Sv_[i] = step_.vapourSource[i];
        Hv_[i] = step_.vapourEnthalpy[i];
    }
    Sv_.correctBoundaryConditions();
    Hv_.correctBoundaryConditions();
    watchRanges(particles, cells);
}


void MoistureCoupling::watchRanges
(
    const std::vector<Particle>& particles,
    const HeatCellCoefficients& cells
)
{
    // the isotherm is evaluated at the kernel's temperature in the air of
    // its cells: the kernels' temperatures, the humidity where there is solid
    if (ranges_.empty()) return;
    for (const Particle& p : particles) ranges_.see(temperatureSlot_, p.temperature);
    forAll(RH_, i)
    {
        if (cells.h[i] > 0) ranges_.see(humiditySlot_, RH_[i]);
    }
    reportRanges(ranges_);
}


void MoistureCoupling::solveVapour()
{
    const Foam::dimensionedScalar Dv("Dv", Foam::dimViscosity, Dv_);
    const Foam::dimensionedScalar rho("rho", Foam::dimDensity, rho_);
    // conservative in eps Y: the vapour the gas holds changes exactly by what
    // crosses the boundaries and what the particles give (the log's balance)
    Foam::fvScalarMatrix YEqn
    (
        Foam::fvm::ddt(voidfraction_, Y_) + Foam::fvm::div(phi_, Y_)
      - Foam::fvm::laplacian(Foam::fvc::interpolate(voidfraction_)*Dv, Y_)
     ==
        Sv_/rho
    );
    YEqn.solve();
    updateHumidityRatio();
}


std::vector<double> MoistureCoupling::liggghtsHeatFluxes
(
    const LiggghtsDem& dem,
    const std::vector<double>& q
) const
{
    const std::vector<double> liggghts = dem.liggghtsHeatCapacities();
    const double dt = mesh_.time().deltaTValue();
    const bool drying = step_.waterLost.size() == q.size();
    std::vector<double> out(q.size());
    for (std::size_t i = 0; i < q.size(); ++i)
    {
        const double latent = drying ? step_.waterLost[i]/dt*step_.latentHeat[i] : 0.0;
        const double wet =
            kernels_.dryMass[i]*(dryHeatCapacity_ + kernels_.moisture[i]*psy::kCpWater);
        out[i] = (q[i] - latent)*liggghts[i]/wet;
    }
    return out;
}


std::pair<double, double> MoistureCoupling::particleHeatContent
(
    const std::vector<Particle>& particles
) const
{
    double energy = 0, capacity = 0;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const double C =
            kernels_.dryMass[i]*(dryHeatCapacity_ + kernels_.moisture[i]*psy::kCpWater);
        energy += C*particles[i].temperature;
        capacity += C;
    }
    return {energy, capacity};
}


std::vector<double> MoistureCoupling::dryingRate() const
{
    std::vector<double> rate(kernels_.moisture.size(), 0.0);
    if (step_.waterLost.size() != rate.size()) return rate;
    const double dt = mesh_.time().deltaTValue();
    for (std::size_t i = 0; i < rate.size(); ++i) rate[i] = step_.waterLost[i]/dt;
    return rate;
}


void MoistureCoupling::boundaryFlows(double sums[4]) const
{
    // what the discretised vapour equation lets through each boundary face,
    // into the gas: convection -rho phi Y and diffusion rho eps D_v dY/dn
    forAll(Y_.boundaryField(), patchi)
    {
        const Foam::fvPatchScalarField& Yb = Y_.boundaryField()[patchi];
        if (Yb.coupled()) continue;
        const Foam::scalarField& phib = phi_.boundaryField()[patchi];
        const Foam::scalarField& epsb = voidfraction_.boundaryField()[patchi];
        const Foam::scalarField& Wb = W_.boundaryField()[patchi];
        const Foam::scalarField snGrad(Yb.snGrad());
        const Foam::scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
        forAll(Yb, f)
        {
            const double into =
                rho_*(-phib[f]*Yb[f] + epsb[f]*Dv_*snGrad[f]*magSf[f]);
            if (phib[f] < 0) sums[0] += into;
            else sums[1] -= into;
            if (phib[f] > 0)
            {
                sums[2] += phib[f];
                sums[3] += phib[f]*Wb[f];
            }
        }
    }
}


MoistureRow MoistureCoupling::balance
(
    const std::vector<Particle>& particles,
    double outletTemperature
) const
{
    double s[11] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    // vapour in, out, outflow, outflow x W; then the particles and cells
    boundaryFlows(s);
    const double dt = mesh_.time().deltaTValue();
    const bool drying = step_.waterLost.size() == particles.size();
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        s[4] += kernels_.dryMass[i]*kernels_.moisture[i];
        if (!drying) continue;
        const double mdot = step_.waterLost[i]/dt;
        const double free = psy::latentHeat(particles[i].temperature - 273.15);
        s[5] += mdot;
        s[6] += mdot*step_.latentHeat[i];
        s[7] += mdot*(step_.latentHeat[i] - free);
    }
    const Foam::scalarField& V = mesh_.V().field();
    forAll(V, c)
    {
        s[8] += V[c]*Sv_[c];
        s[9] += V[c]*Hv_[c];
        s[10] += V[c]*rho_*voidfraction_[c]*Y_[c];
    }
    sumOverRanks(s, 11);
    const double Wout = s[2] > 0 ? s[3]/s[2] : 0.0;
    const double RHout = s[2] > 0
      ? relativeHumidity(MoistAir{outletTemperature, Wout, exchange_.pressure()})
      : 0.0;
    const double h = vapourEnthalpyOffset;
    return MoistureRow
    {
        s[4], s[5], s[8], s[0], s[1], s[10], Wout, RHout,
        s[6], s[7], s[9], h*s[10], h*s[0], h*s[1]
    };
}

} // namespace spoutlab
