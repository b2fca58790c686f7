#include "HeatExchange.hpp"

#include <stdexcept>
#include <utility>

namespace spoutlab
{

HeatExchange::HeatExchange(std::unique_ptr<HeatTransferModel> model) : model_(std::move(model))
{
    if (!model_) throw std::invalid_argument("HeatExchange: no heat-transfer model");
}

HeatCellCoefficients
HeatExchange::cellCoefficients(const CellLocator& mesh, const std::vector<Particle>& particles,
                               const ParticleCellMap& map, const ExchangeResult& momentum,
                               const GasHeatCellFields& f, const GasThermalProperties& gas,
                               double vapourDiffusivity) const
{
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    if (f.centre.size() != nCells || f.U.size() != nCells || f.voidFraction.size() != nCells
        || momentum.Us.size() != nCells || map.nParticles() != particles.size())
    {
        throw std::invalid_argument("HeatExchange: field or particle map sizes do not match");
    }
    // particle surface (A) and surface-weighted temperature (A T) per cell,
    // with the neighbouring ranks' particles in this rank's halo (complete())
    std::vector<double> sums(2 * nCells, 0.0);
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        const double a = particles[n].surface();
        for (const CellWeight& cw : map.cells(n))
        {
            sums[2 * cw.cell] += cw.weight * a;
            sums[2 * cw.cell + 1] += cw.weight * a * particles[n].temperature;
        }
    }
    mesh.complete(sums, 2);
    HeatCellCoefficients out;
    out.h.assign(nCells, 0.0);
    out.reynolds.assign(nCells, 0.0);
    out.region.assign(nCells, -1);
    out.correlation.assign(nCells, -1);
    out.K.assign(nCells, 0.0);
    out.S.assign(nCells, 0.0);
    if (vapourDiffusivity > 0.0) out.km.assign(nCells, 0.0);
    for (std::size_t c = 0; c < nCells; ++c)
    {
        const double area = sums[2 * c], areaT = sums[2 * c + 1];
        if (area <= 0.0) continue;
        const HeatTransferCell cell{f.centre[c], f.voidFraction[c], momentum.sauterDiameter[c],
                                    mag(momentum.Us[c] - f.U[c])};
        const double h = model_->h(cell, gas);
        const double volume = mesh.cellVolume(static_cast<label>(c));
        out.h[c] = h;
        out.reynolds[c] = heatTransferReynolds(cell, gas);
        out.region[c] = model_->region(cell);
        out.correlation[c] = model_->correlationIndex(cell);
        out.K[c] = h * area / volume;
        out.S[c] = h * areaT / volume;
        if (vapourDiffusivity > 0.0)
            out.km[c] = model_->massTransferCoefficient(cell, gas, vapourDiffusivity);
    }
    return out;
}

std::vector<double> HeatExchange::particleHeatFlux(const std::vector<Particle>& particles,
                                                   const ParticleCellMap& map,
                                                   const HeatCellCoefficients& cells,
                                                   const std::vector<double>& Tgas) const
{
    if (Tgas.size() != cells.h.size() || map.nParticles() != particles.size())
    {
        throw std::invalid_argument("HeatExchange: temperature field or particle map sizes do not match");
    }
    std::vector<double> q(particles.size(), 0.0);
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        double sum = 0.0;
        for (const CellWeight& cw : map.cells(n))
        {
            sum += cw.weight * cells.h[cw.cell] * (Tgas[cw.cell] - particles[n].temperature);
        }
        q[n] = particles[n].surface() * sum;
    }
    return q;
}

std::vector<double> HeatExchange::particleH(const ParticleCellMap& map, const HeatCellCoefficients& cells)
{
    std::vector<double> h(map.nParticles(), 0.0);
    for (std::size_t n = 0; n < h.size(); ++n)
    {
        for (const CellWeight& cw : map.cells(n)) h[n] += cw.weight * cells.h[cw.cell];
    }
    return h;
}

} // namespace spoutlab
