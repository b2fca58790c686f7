#pragma once
// Gas <-> particle water exchange (drying), the partner of HeatExchange
// (docs/DESIGN.md §3.8).
//
// Per particle i, with the weights w_ic of the void fraction's particle-cell
// map, the gas it sees is the weighted gas of its cells,
//   T_g,i = sum_c w_ic T_c,   W_i = sum_c w_ic W_c,   k_m,i = sum_c w_ic k_m,c
// (k_m,c the Sherwood form of the cell's heat correlation, HeatExchange), and
// the drying model advances its moisture X_i (and its state) over dt at its
// temperature T_p,i: the water lost dW_i [kg] and the heat of vaporisation
// L_i [J/kg] it takes (at the start of the step). Per cell c
//   S_v,c = sum_i w_ic dW_i / (dt V_c)                      [kg m^-3 s^-1]
//   H_v,c = c_pv sum_i w_ic dW_i T_p,i / (dt V_c)           [W m^-3]
// the vapour the gas receives and the sensible enthalpy it brings (at the
// particle's temperature, c_pv of Psychrometrics). Summed over cells, the gas
// receives exactly the water the particles lose, to round-off. A lost
// particle (empty map row) neither dries nor gives anything.
// A coarse-grained parcel (Particle.hpp) dries as one of its originals: the
// model sees the original's diameter and dry mass m_d/cg^3, and dW_i is cg^3
// times that original's water; X_i and the state are each original's.
//
// The exchange is explicit in the gas: a coupling step's vapour source comes
// from the particles advanced in the gas state of the step before. In a cell
// the vapour relaxes towards the particles' surface vapour in about
// eps/(k_m a), a = 6 (1 - eps)/d: 0.02 s in a packed layer of 8 mm kernels
// (k_m 0.05 m/s), against coupling steps of 3e-4 s.

#include "CellLocator.hpp"
#include "DryingModel.hpp"
#include "Particle.hpp"
#include "VoidFractionModel.hpp"

#include <memory>
#include <vector>

namespace spoutlab
{

// The per-particle state the caller keeps (in LIGGGHTS, per atom), one entry
// per particle of the list the exchange is given.
struct KernelMoisture
{
    std::vector<double> dryMass;  // m_d [kg], the parcel's (all its originals')
    std::vector<double> moisture; // X [kg water / kg dry solid]
    std::vector<double> state;    // the model's stateSize() values per particle
    // or, when not empty, where particle i's stateSize() values are kept
    // (the DEM's own per-atom rows, used in place: valid only until the DEM
    // moves its atoms again); state is then unused
    std::vector<double*> stateRows;

    // particle i's state (width: the model's stateSize())
    double* stateOf(std::size_t i, std::size_t width)
    {
        if (!width) return nullptr;
        return stateRows.empty() ? &state[width * i] : stateRows[i];
    }
};

// Gas per cell (own and halo cells; not owned).
struct MoistureCellFields
{
    const std::vector<double>& temperature;   // T_g [K]
    const std::vector<double>& humidityRatio; // W [kg vapour / kg dry air]
    const std::vector<double>& massTransfer;  // k_m [m/s], HeatCellCoefficients::km
};

struct MoistureStep
{
    std::vector<double> waterLost;      // per particle, over dt [kg] (< 0 condensing)
    std::vector<double> latentHeat;     // per particle [J/kg]
    std::vector<double> vapourSource;   // per cell, S_v [kg m^-3 s^-1]
    std::vector<double> vapourEnthalpy; // per cell, H_v [W m^-3]
};

class MoistureExchange
{
public:
    // pressure: the total pressure of the gas [Pa] (the psychrometrics')
    MoistureExchange(std::unique_ptr<DryingModel> model, double pressure);

    const DryingModel& model() const { return *model_; }
    double pressure() const { return pressure_; }

    // The state of particle i at uniform moisture X_i (a particle new to the
    // coupling: a fresh run or an inserted particle).
    void initialise(KernelMoisture& kernels, std::size_t i) const;

    MoistureStep advance(const CellLocator& mesh, const std::vector<Particle>& particles,
                         const ParticleCellMap& map, const MoistureCellFields& gas, KernelMoisture& kernels,
                         double dt) const;

private:
    // One original of particle p (dry mass m_d) over dt in the weighted gas
    // of its cells: the water it loses [kg].
    double dryInGas(const Particle& p, double dryMass, ParticleCellMap::Row cells,
                    const MoistureCellFields& gas, double& moisture, double* state, double dt,
                    double& latentHeat) const;

    std::unique_ptr<DryingModel> model_;
    double pressure_;
};

} // namespace spoutlab
