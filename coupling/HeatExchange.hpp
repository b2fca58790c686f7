#pragma once
// Gas <-> particle heat exchange (draft-plate paper eqs 4, 5 and 10).
//
// Per cell c holding solid, from the particle-cell map of the void fraction:
//   h_c  = model(eps_c, d_c, |Us_c - u_c|, centre_c)        [W m^-2 K^-1]
//   K_c  = h_c sum_i w_ic A_i / V_c                          [W m^-3 K^-1]
//   S_c  = h_c sum_i w_ic A_i T_i / V_c                      [W m^-3]
// so the gas energy source of eq 5 is Q_s = S_c - K_c T_c: K_c is the
// implicit coefficient of the gas temperature (as beta is in the momentum
// equation) and sum_i w_ic A_i / V_c is the paper's 6 (1 - eps)/d_p.
// Per particle i, with the gas temperatures T_c the energy equation solved:
//   q_i = A_i sum_c w_ic h_c (T_c - T_i)                     [W into the particle]
// Summed over particles this is sum_c V_c (K_c T_c - S_c): the heat the
// particles receive is the heat the gas equation gave, to round-off.
// A lost particle (empty map row) exchanges nothing.
// A coarse-grained parcel (Particle.hpp): A_i is its cg^3 originals' surface
// and d_c (MomentumExchange) their diameter, so h is an original's and q_i
// cg^3 times an original's heat; the parcel's mass is cg^3 originals', so its
// temperature moves as each original's.

#include "CellLocator.hpp"
#include "HeatTransferModel.hpp"
#include "MomentumExchange.hpp"
#include "Particle.hpp"
#include "VoidFractionModel.hpp"

#include <memory>
#include <vector>

namespace spoutlab
{

// Gas fields per cell that the heat-transfer coefficient depends on (not owned).
struct GasHeatCellFields
{
    const std::vector<Vec3>& centre;         // cell centres [m]
    const std::vector<Vec3>& U;              // interstitial gas velocity [m/s]
    const std::vector<double>& voidFraction; // eps, clipped as for the drag
};

struct HeatCellCoefficients
{
    std::vector<double> h;        // [W m^-2 K^-1]; 0 where there is no solid
    std::vector<double> reynolds; // Re = eps rho |Us - u| d/mu; 0 where there is no solid
    std::vector<int> region;      // 1 spout, 0 downcomer, -1 no rule or no solid
    std::vector<int> correlation; // index into model().correlations(); -1 no solid
    std::vector<double> K;        // implicit coefficient [W m^-3 K^-1]
    std::vector<double> S;        // explicit part [W m^-3]
    std::vector<double> km;       // k_m [m/s] of the same correlation at Sc (with drying); else empty
};

class HeatExchange
{
public:
    explicit HeatExchange(std::unique_ptr<HeatTransferModel> model);

    const HeatTransferModel& model() const { return *model_; }

    // momentum: the cell averages (Us, Sauter diameter) of the same step.
    // vapourDiffusivity > 0 [m^2/s] (drying): also each cell's mass-transfer
    // coefficient k_m, the Sherwood form of the cell's correlation at the same
    // Re, so heat and mass see the same flow.
    HeatCellCoefficients cellCoefficients(const CellLocator& mesh, const std::vector<Particle>& particles,
                                          const ParticleCellMap& map, const ExchangeResult& momentum,
                                          const GasHeatCellFields& gasFields, const GasThermalProperties& gas,
                                          double vapourDiffusivity = 0.0) const;

    // q_i [W into particle i] for the gas temperatures Tgas [K] per cell.
    std::vector<double> particleHeatFlux(const std::vector<Particle>& particles, const ParticleCellMap& map,
                                         const HeatCellCoefficients& cells,
                                         const std::vector<double>& Tgas) const;

    // The coefficient each particle sees, sum_c w_ic h_c (for output).
    static std::vector<double> particleH(const ParticleCellMap& map, const HeatCellCoefficients& cells);

private:
    std::unique_ptr<HeatTransferModel> model_;
};

} // namespace spoutlab
