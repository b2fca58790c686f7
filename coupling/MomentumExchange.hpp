#pragma once
// Gas <-> particle momentum exchange (docs/DESIGN.md §3 steps 4-6).
//
// Per cell c, from the particle-cell map:
//   S_c   = sum_i w_ic V_i                 solid volume, phi_c = S_c/V_c (raw)
//   Us_c  = sum_i w_ic V_i v_i / S_c       volume-weighted particle velocity
//   d_c   = 6 S_c / sum_i w_ic A_i         Sauter mean diameter
//   beta_c = drag(eps_c, d_c, |u_c - Us_c|), eps_c the (clipped) gas fraction
// and beta_c, Us_c go into the gas equation as beta (Us - u).
// Per particle i (centre in cell c0):
//   drag     F_i = sum_c w_ic V_i (beta_c/phi_c) (u_c - v_i)
//   pressure     = -V_i grad(p)_c0 - rho_g g V_i
// grad(p) is the gradient of the pressure the solver keeps, which excludes the
// gas hydrostatic part; -rho_g g V_i puts that part (the buoyancy) back.
//
// Dividing by the raw phi_c rather than 1 - eps_c (which may be clipped) makes
// sum_i F_i = sum_c beta_c V_c (u_c - Us_c) an identity: the momentum the
// particles gain is exactly what the gas loses.
// A lost particle (centre outside the mesh) gets no force at all.
//
// Coarse graining (Particle.hpp): V_i is the parcel's volume, A_i its cg^3
// originals' surface, so d_c is the originals' diameter, the drag law sees
// their Re and F_i is cg^3 times one original's force; no law needs to know.

#include "CellLocator.hpp"
#include "DragModel.hpp"
#include "Particle.hpp"
#include "VoidFractionModel.hpp"

#include <memory>
#include <vector>

namespace spoutlab
{

// Gas fields per cell, as the solver holds them (not owned).
struct GasCellFields
{
    const std::vector<Vec3>& U;              // interstitial gas velocity [m/s]
    const std::vector<Vec3>& gradP;          // grad(p - hydrostatic) [Pa/m]
    const std::vector<double>& voidFraction; // eps, clipped for the drag law
};

struct ExchangeResult
{
    // per cell
    std::vector<double> beta;           // Ksl [kg m^-3 s^-1]; 0 where there is no solid
    std::vector<Vec3> Us;               // [m/s]; 0 where there is no solid
    std::vector<double> solidFraction;  // phi = S/V, not clipped
    std::vector<double> sauterDiameter; // [m]; 0 where there is no solid
    // per particle [N]
    std::vector<Vec3> dragForce;
    std::vector<Vec3> pressureForce; // pressure gradient + buoyancy
    std::vector<Vec3> totalForce;
};

class MomentumExchange
{
public:
    explicit MomentumExchange(std::unique_ptr<DragModel> drag);

    const DragModel& drag() const { return *drag_; }

    // Throws std::invalid_argument if the field or map sizes do not match the
    // mesh and the particle list.
    ExchangeResult compute(const CellLocator& mesh, const std::vector<Particle>& particles,
                           const VoidFractionResult& voidFraction, const GasCellFields& gasFields,
                           const GasProperties& gas, const Vec3& g) const;

private:
    void cellAverages(const CellLocator& mesh, const std::vector<Particle>& particles,
                      const ParticleCellMap& map, ExchangeResult& out) const;
    void cellBeta(const GasCellFields& gasFields, const GasProperties& gas, ExchangeResult& out) const;
    void particleForces(const std::vector<Particle>& particles, const VoidFractionResult& vf,
                        const GasCellFields& gasFields, const GasProperties& gas, const Vec3& g,
                        ExchangeResult& out) const;

    std::unique_ptr<DragModel> drag_;
};

} // namespace spoutlab
