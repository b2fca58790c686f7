/*---------------------------------------------------------------------------*\
    SpoutLab: the particles' heat and water on the CFD side.
\*---------------------------------------------------------------------------*/
#include "ThermalCoupling.H"

#include "InputError.hpp"

#include <mpi.h>

#include <algorithm>

namespace spoutlab
{

std::unique_ptr<ThermalCoupling> ThermalCoupling::New
(
    const Foam::fvMesh& mesh,
    const FoamCellLocator& cells,
    const Foam::dictionary& couplingDict,
    const LiggghtsDem& dem,
    const std::string& liggghtsInput,
    const Foam::volScalarField& voidfraction,
    const Foam::surfaceScalarField& phi,
    double rho,
    double mu
)
{
    std::unique_ptr<HeatCoupling> heat = HeatCoupling::New
    (
        mesh, cells, couplingDict, dem, liggghtsInput, voidfraction, phi, rho, mu
    );
    const Foam::word model =
        couplingDict.getOrDefault<Foam::word>("dryingModel", "none");
    if (!heat)
    {
        if (model == "none") return nullptr;
        throw InputError
        (
            "constant/couplingProperties: drying (dryingModel " + model + ") "
            "expects gas-to-particle heat transfer, key 'heatTransferModel'"
        );
    }
    std::unique_ptr<MoistureCoupling> moisture = MoistureCoupling::New
    (
        mesh, cells, couplingDict, voidfraction, phi, rho, heat->gas().cp
    );
    // the particles' m c_p/A do not change during a run (deleting particles
    // can only raise the smallest), so it is taken once
    return std::unique_ptr<ThermalCoupling>
    (
        new ThermalCoupling
        (
            std::move(heat), std::move(moisture), dem.minHeatCapacityPerArea()
        )
    );
}


ThermalCoupling::ThermalCoupling
(
    std::unique_ptr<HeatCoupling> heat,
    std::unique_ptr<MoistureCoupling> moisture,
    double minHeatCapacityPerArea
)
:
    heat_(std::move(heat)),
    moisture_(std::move(moisture)),
    minHeatCapacityPerArea_(minHeatCapacityPerArea)
{}


void ThermalCoupling::start(LiggghtsDem& dem)
{
    if (!moisture_) return;
    moisture_->startParticles(dem, heat_->T());
    heat_->useHumidGas(moisture_->humidGas());
}


void ThermalCoupling::updateCoefficients
(
    const std::vector<Particle>& particles,
    const std::vector<double>& eps,
    const ParticleCellMap& map,
    const ExchangeResult& momentum
)
{
    heat_->updateCoefficients(particles, eps, map, momentum);
    heat_->checkTimeStep(minHeatCapacityPerArea_);
}


void ThermalCoupling::dry
(
    LiggghtsDem& dem,
    const std::vector<Particle>& particles,
    const ParticleCellMap& map,
    const Vec3& g,
    const RunGuards& guards
)
{
    if (!moisture_) return;
    moisture_->dryParticles(dem, particles, map, heat_->cells(), heat_->T(), g, guards);
}


void ThermalCoupling::solveGas(const RunGuards& guards)
{
    if (moisture_)
    {
        moisture_->solveVapour();
        guards.checkField(moisture_->Y());
    }
    heat_->solveGas();
    guards.checkField(heat_->T());
    if (moisture_) moisture_->updateRelativeHumidity(heat_->T());
}


void ThermalCoupling::transfer
(
    LiggghtsDem& dem,
    const std::vector<Particle>& particles,
    const ParticleCellMap& map,
    const RunGuards& guards,
    CouplingRow& row
)
{
    // this rank's share, like the forces
    heatFlux_ = heat_->particleHeatFlux(particles, map);
    guards.checkParticles("heat flux", heatFlux_, particles);
    // with drying, less the latent heat and for the wet kernel's capacity
    if (moisture_)
    {
        const std::vector<double> q = moisture_->liggghtsHeatFluxes(dem, heatFlux_);
        guards.checkParticles("heat flux less the latent heat", q, particles);
        dem.setHeatFluxes(q);
    }
    else
    {
        dem.setHeatFluxes(heatFlux_);
    }
    row.heat = heatRow(dem, particles);
    if (moisture_)
    {
        row.moisture = moisture_->balance(particles, row.heat->outletTemperature);
    }
}


HeatRow ThermalCoupling::heatRow
(
    const LiggghtsDem& dem,
    const std::vector<Particle>& particles
) const
{
    // m c_p T and m c_p: of the types' c_p, or with drying of the wet kernels
    double sums[3] = {0, 0, 0};
    for (const double q : heatFlux_) sums[0] += q;
    if (moisture_)
    {
        const std::pair<double, double> c = moisture_->particleHeatContent(particles);
        sums[1] = c.first;
        sums[2] = c.second;
    }
    MPI_Allreduce(MPI_IN_PLACE, sums, moisture_ ? 3 : 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    const GasHeatBalance b = heat_->balance();
    if (!moisture_)
    {
        const LiggghtsDem::HeatContent c = dem.heatContent();
        sums[1] = c.energy;
        sums[2] = c.capacity;
    }
    const double meanTp = sums[1]/std::max(sums[2], 1e-300);
    Foam::Info<< "Heat: " << sums[0] << " W to the particles, mean "
        << "particle temperature " << meanTp << " K, gas outlet "
        << b.outletTemperature << " K" << Foam::endl;
    return HeatRow
    {
        sums[0], b.gasGave, b.inflow, b.outflow, b.outletTemperature,
        b.gasEnergy, sums[1], meanTp
    };
}


void ThermalCoupling::addColumns
(
    const std::vector<Particle>& particles,
    const ParticleCellMap& map,
    ParticleColumns& columns
)
{
    T_.clear();
    for (const Particle& p : particles) T_.push_back(p.temperature);
    h_ = heat_->particleH(map);
    columns.scalars.insert
    (
        columns.scalars.end(),
        {{"temperature", &T_}, {"heatFlux", &heatFlux_}, {"h", &h_}}
    );
    if (!moisture_) return;
    rate_ = moisture_->dryingRate();
    columns.scalars.push_back({"moisture", &moisture_->moisture()});
    columns.scalars.push_back({"dryingRate", &rate_});
}

} // namespace spoutlab
