#include "MoistureExchange.hpp"

#include "Psychrometrics.hpp"

#include <stdexcept>
#include <utility>

namespace spoutlab
{

MoistureExchange::MoistureExchange(std::unique_ptr<DryingModel> model, double pressure)
    : model_(std::move(model)), pressure_(pressure)
{
    if (!model_) throw std::invalid_argument("MoistureExchange: no drying model");
}

void MoistureExchange::initialise(KernelMoisture& kernels, std::size_t i) const
{
    model_->initialise(kernels.moisture[i],
                       kernels.stateOf(i, static_cast<std::size_t>(model_->stateSize())));
}

double MoistureExchange::dryInGas(const Particle& p, double dryMass, ParticleCellMap::Row cells,
                                  const MoistureCellFields& gas, double& moisture, double* state, double dt,
                                  double& latentHeat) const
{
    double Tg = 0.0, W = 0.0, km = 0.0;
    for (const CellWeight& cw : cells)
    {
        Tg += cw.weight * gas.temperature[cw.cell];
        W += cw.weight * gas.humidityRatio[cw.cell];
        km += cw.weight * gas.massTransfer[cw.cell];
    }
    const Kernel kernel{p.diameter(), dryMass, p.temperature};
    return model_->advanceWithLatentHeat(kernel, moisture, state, MoistAir{Tg, W, pressure_}, km, dt,
                                         latentHeat);
}

MoistureStep MoistureExchange::advance(const CellLocator& mesh, const std::vector<Particle>& particles,
                                       const ParticleCellMap& map, const MoistureCellFields& gas,
                                       KernelMoisture& kernels, double dt) const
{
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    const std::size_t n = particles.size();
    const std::size_t width = static_cast<std::size_t>(model_->stateSize());
    if (gas.temperature.size() != nCells || gas.humidityRatio.size() != nCells
        || gas.massTransfer.size() != nCells || map.nParticles() != n || kernels.dryMass.size() != n
        || kernels.moisture.size() != n
        || (kernels.stateRows.empty() ? kernels.state.size() != width * n : kernels.stateRows.size() != n)
        || !(dt > 0.0))
    {
        throw std::invalid_argument("MoistureExchange: field, particle or state sizes do not match");
    }
    MoistureStep out;
    out.waterLost.assign(n, 0.0);
    out.latentHeat.assign(n, 0.0);
    // per cell: water and water x T_p, with the halo's shares sent to their owners
    std::vector<double> sums(2 * nCells, 0.0);
    for (std::size_t i = 0; i < n; ++i)
    {
        if (map.cells(i).size() == 0) continue;
        // a parcel: one of its originals dries, the parcel loses cg^3 times its water
        const Particle& p = particles[i];
        const double originals = p.multiplicity();
        const double dryMass = kernels.dryMass[i] / originals;
        double* state = kernels.stateOf(i, width);
        // the gas is gathered only where the model uses it: inside a
        // kernelSteps block only the block's water is released
        const bool gasUsed = width == 0 || model_->needsGas(state);
        const double water =
            gasUsed
                ? dryInGas(p, dryMass, map.cells(i), gas, kernels.moisture[i], state, dt, out.latentHeat[i])
                : model_->release(dryMass, kernels.moisture[i], state, out.latentHeat[i]);
        const double dW = originals * water;
        out.waterLost[i] = dW;
        for (const CellWeight& cw : map.cells(i))
        {
            sums[2 * cw.cell] += cw.weight * dW;
            sums[2 * cw.cell + 1] += cw.weight * dW * p.temperature;
        }
    }
    mesh.complete(sums, 2);
    out.vapourSource.assign(nCells, 0.0);
    out.vapourEnthalpy.assign(nCells, 0.0);
    for (std::size_t c = 0; c < nCells; ++c)
    {
        const double perVolumeTime = 1.0 / (dt * mesh.cellVolume(static_cast<label>(c)));
        out.vapourSource[c] = sums[2 * c] * perVolumeTime;
        out.vapourEnthalpy[c] = psy::kCpVapour * sums[2 * c + 1] * perVolumeTime;
    }
    return out;
}

} // namespace spoutlab
