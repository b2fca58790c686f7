#include "MomentumExchange.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace spoutlab {

namespace {

void checkSizes(const CellLocator& mesh, const std::vector<Particle>& particles,
                const VoidFractionResult& vf, const GasCellFields& f) {
  const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
  const bool ok = f.U.size() == nCells && f.gradP.size() == nCells &&
                  f.voidFraction.size() == nCells && vf.map.nParticles() == particles.size() &&
                  vf.centreCell.size() == particles.size();
  if (!ok) throw std::invalid_argument("MomentumExchange: field or particle map sizes do not match");
}

}  // namespace

MomentumExchange::MomentumExchange(std::unique_ptr<DragModel> drag) : drag_(std::move(drag)) {
  if (!drag_) throw std::invalid_argument("MomentumExchange: no drag model");
}

ExchangeResult MomentumExchange::compute(const CellLocator& mesh,
                                         const std::vector<Particle>& particles,
                                         const VoidFractionResult& voidFraction,
                                         const GasCellFields& gasFields, const GasProperties& gas,
                                         const Vec3& g) const {
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
                                    const ParticleCellMap& map, ExchangeResult& out) const {
  const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
  std::vector<double> solid(nCells, 0.0), area(nCells, 0.0);
  std::vector<Vec3> momentum(nCells);
  const double pi = std::acos(-1.0);
  for (std::size_t n = 0; n < particles.size(); ++n) {
    const Particle& p = particles[n];
    const double volume = p.volume();
    const double surface = 4.0 * pi * p.radius * p.radius;
    for (const CellWeight& cw : map.cells(n)) {
      solid[cw.cell] += cw.weight * volume;
      momentum[cw.cell] += p.v * (cw.weight * volume);
      area[cw.cell] += cw.weight * surface;
    }
  }
  out.solidFraction.assign(nCells, 0.0);
  out.Us.assign(nCells, Vec3{});
  out.sauterDiameter.assign(nCells, 0.0);
  for (std::size_t c = 0; c < nCells; ++c) {
    if (solid[c] <= 0.0) continue;
    out.solidFraction[c] = solid[c] / mesh.cellVolume(static_cast<label>(c));
    out.Us[c] = momentum[c] / solid[c];
    out.sauterDiameter[c] = 6.0 * solid[c] / area[c];
  }
}

void MomentumExchange::cellBeta(const GasCellFields& f, const GasProperties& gas,
                                ExchangeResult& out) const {
  out.beta.assign(out.solidFraction.size(), 0.0);
  for (std::size_t c = 0; c < out.beta.size(); ++c) {
    if (out.solidFraction[c] <= 0.0) continue;
    const DragState state{f.voidFraction[c], out.sauterDiameter[c], mag(f.U[c] - out.Us[c])};
    out.beta[c] = drag_->beta(state, gas);
  }
}

void MomentumExchange::particleForces(const std::vector<Particle>& particles,
                                      const VoidFractionResult& vf, const GasCellFields& f,
                                      const GasProperties& gas, const Vec3& g,
                                      ExchangeResult& out) const {
  out.dragForce.assign(particles.size(), Vec3{});
  out.pressureForce.assign(particles.size(), Vec3{});
  out.totalForce.assign(particles.size(), Vec3{});
  for (std::size_t n = 0; n < particles.size(); ++n) {
    const label c0 = vf.centreCell[n];
    if (c0 < 0) continue;
    const Particle& p = particles[n];
    const double volume = p.volume();
    Vec3 drag;
    for (const CellWeight& cw : vf.map.cells(n)) {
      const double phi = out.solidFraction[cw.cell];
      if (phi <= 0.0) continue;
      drag += (f.U[cw.cell] - p.v) * (cw.weight * volume * out.beta[cw.cell] / phi);
    }
    out.dragForce[n] = drag;
    out.pressureForce[n] = -(f.gradP[c0] * volume) - g * (gas.rho * volume);
    out.totalForce[n] = drag + out.pressureForce[n];
  }
}

}  // namespace spoutlab
