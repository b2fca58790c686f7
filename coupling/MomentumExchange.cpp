#include "MomentumExchange.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace spoutlab
{

namespace
{

void checkSizes(const CellLocator& mesh, const std::vector<Particle>& particles, const VoidFractionResult& vf,
                const GasCellFields& f)
{
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    const bool ok = f.U.size() == nCells && f.gradP.size() == nCells && f.voidFraction.size() == nCells
                    && vf.map.nParticles() == particles.size() && vf.centreCell.size() == particles.size();
    if (!ok) throw std::invalid_argument("MomentumExchange: field or particle map sizes do not match");
}

} // namespace

MomentumExchange::MomentumExchange(std::unique_ptr<DragModel> drag) : drag_(std::move(drag))
{
    if (!drag_) throw std::invalid_argument("MomentumExchange: no drag model");
}

ExchangeResult MomentumExchange::compute(const CellLocator& mesh, const std::vector<Particle>& particles,
                                         const VoidFractionResult& voidFraction,
                                         const GasCellFields& gasFields, const GasProperties& gas,
                                         const Vec3& g) const
{
    checkSizes(mesh, particles, voidFraction, gasFields);
    ExchangeResult out;
    cellAverages(mesh, particles, voidFraction.map, out);
    cellBeta(gasFields, gas, out);
    particleForces(particles, voidFraction, gasFields, gas, g, out);
    return out;
}

// Solid fraction, Us and Sauter diameter from the map itself (not from a
// separately summed solidVolume), so phi_c and Us_c are built from exactly the
// same sums the particle forces use.
void MomentumExchange::cellAverages(const CellLocator& mesh, const std::vector<Particle>& particles,
                                    const ParticleCellMap& map, ExchangeResult& out) const
{
    // per cell: solid volume, momentum (3) and surface of the particles in it;
    // complete() adds the neighbouring ranks' particles in this rank's halo
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    std::vector<double> sums(5 * nCells, 0.0);
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        const Particle& p = particles[n];
        const double volume = p.volume();
        // a parcel's originals' surface: d_c is the originals' diameter
        const double surface = p.surface();
        for (const CellWeight& cw : map.cells(n))
        {
            double* cell = &sums[5 * static_cast<std::size_t>(cw.cell)];
            cell[0] += cw.weight * volume;
            cell[1] += p.v.x * (cw.weight * volume);
            cell[2] += p.v.y * (cw.weight * volume);
            cell[3] += p.v.z * (cw.weight * volume);
            cell[4] += cw.weight * surface;
        }
    }
    mesh.complete(sums, 5);
    out.solidFraction.assign(nCells, 0.0);
    out.Us.assign(nCells, Vec3{});
    out.sauterDiameter.assign(nCells, 0.0);
    for (std::size_t c = 0; c < nCells; ++c)
    {
        const double* cell = &sums[5 * c];
        if (cell[0] <= 0.0) continue;
        out.solidFraction[c] = cell[0] / mesh.cellVolume(static_cast<label>(c));
        out.Us[c] = Vec3{cell[1], cell[2], cell[3]} / cell[0];
        out.sauterDiameter[c] = 6.0 * cell[0] / cell[4];
    }
}

void MomentumExchange::cellBeta(const GasCellFields& f, const GasProperties& gas, ExchangeResult& out) const
{
    out.beta.assign(out.solidFraction.size(), 0.0);
    for (std::size_t c = 0; c < out.beta.size(); ++c)
    {
        if (out.solidFraction[c] <= 0.0) continue;
        const DragState state{f.voidFraction[c], out.sauterDiameter[c], mag(f.U[c] - out.Us[c])};
        out.beta[c] = drag_->beta(state, gas);
    }
}

void MomentumExchange::particleForces(const std::vector<Particle>& particles, const VoidFractionResult& vf,
                                      const GasCellFields& f, const GasProperties& gas, const Vec3& g,
                                      ExchangeResult& out) const
{
    out.dragForce.assign(particles.size(), Vec3{});
    out.pressureForce.assign(particles.size(), Vec3{});
    out.totalForce.assign(particles.size(), Vec3{});
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        const label c0 = vf.centreCell[n];
        if (c0 < 0) continue;
        const Particle& p = particles[n];
        const double volume = p.volume();
        Vec3 drag;
        for (const CellWeight& cw : vf.map.cells(n))
        {
            const double phi = out.solidFraction[cw.cell];
            if (phi <= 0.0) continue;
            drag += (f.U[cw.cell] - p.v) * (cw.weight * volume * out.beta[cw.cell] / phi);
        }
        out.dragForce[n] = drag;
        out.pressureForce[n] = -(f.gradP[c0] * volume) - g * (gas.rho * volume);
        out.totalForce[n] = drag + out.pressureForce[n];
    }
}

} // namespace spoutlab
