#pragma once
// Gas-to-particle heat transfer coefficient h_p (draft-plate paper eqs 5-6).
//
// A model gives h [W m^-2 K^-1] for one gas cell from the cell's state:
//   Re = eps rho |Us - u| d / mu   (the paper's Re, Us the cell-averaged
//                                   particle velocity, d the Sauter diameter)
//   Pr = c_p mu / k_c,   Nu = h d / k_c
// and where the cell is (region rules apply one correlation in the spout and
// another in the downcomer). The heat a particle receives is then
//   q_i = h A_i (T_g - T_i)   (eq 10), and the gas loses the same (eq 5).
//
// Each model is its Nusselt correlation Nu(cell, Re, Pr); h follows from it in
// the base class. The same correlation with the Schmidt number in place of the
// Prandtl number is the Sherwood number of the mass transfer (the heat and mass
// transfer analogy), so drying sees the Re and the correlation the heat
// transfer uses in that cell:
//   Sc = mu/(rho D_v),   Sh = Nu(cell, Re, Sc),   k_m = Sh D_v / d
//
// Run-time selection by name, the couplingProperties entry "heatTransferModel",
// with settings in "<name>Props".

#include "ModelRegistry.hpp"
#include "Parameters.hpp"
#include "StatedRange.hpp"
#include "Vec3.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spoutlab
{

// Gas properties the energy equation and the correlations need, constant at a
// film temperature (assumption (i) of the paper).
struct GasThermalProperties
{
    double rho;   // density [kg/m^3]
    double mu;    // dynamic viscosity [Pa s]
    double cp;    // specific heat at constant pressure [J/(kg K)]
    double kappa; // thermal conductivity k_c [W/(m K)]

    double prandtl() const { return cp * mu / kappa; }
};

// What a heat-transfer model sees of one gas cell that holds solid.
// Preconditions: 0 < voidFraction <= 1, diameter > 0, slip >= 0.
struct HeatTransferCell
{
    Vec3 centre;         // cell centre [m] (for region rules)
    double voidFraction; // eps (clipped as for the drag)
    double diameter;     // d_p [m], Sauter mean of the cell's particles
    double slip;         // |Us - u| [m/s]
};

// The paper's particle Reynolds number, Re = eps rho |Us - u| d / mu.
double heatTransferReynolds(const HeatTransferCell& cell, const GasThermalProperties& gas);

class HeatTransferModel
{
public:
    virtual ~HeatTransferModel();

    // The correlation: Nu at the cell's Reynolds number and at the Prandtl
    // number pr, or Sh with the Schmidt number in its place.
    virtual double nusselt(const HeatTransferCell& cell, double reynolds, double pr) const = 0;

    // Heat-transfer coefficient h = Nu(cell, Re, Pr) k_c/d [W m^-2 K^-1] in
    // this cell.
    double h(const HeatTransferCell& cell, const GasThermalProperties& gas) const;

    // Mass-transfer coefficient k_m = Sh D_v/d [m/s] of a vapour of
    // diffusivity D_v [m^2/s] in this gas, Sh = Nu(cell, Re, Sc) with
    // Sc = mu/(rho D_v).
    double massTransferCoefficient(const HeatTransferCell& cell, const GasThermalProperties& gas,
                                   double vapourDiffusivity) const;

    // 1 where the cell counts as spout, 0 where it counts as downcomer, for
    // models that tell the two apart; -1 for a single correlation everywhere.
    virtual int region(const HeatTransferCell& cell) const;

    // The single correlations this model applies (itself, or a region rule's
    // sub-models), and which of them applies in a cell: what a run checks
    // against each correlation's stated ranges.
    virtual std::vector<const HeatTransferModel*> correlations() const;
    virtual int correlationIndex(const HeatTransferCell& cell) const;

    // The ranges of "Re" and "voidage" the correlation's source states (none
    // unless the model says so).
    virtual std::vector<StatedRange> statedRanges() const;

    virtual std::string name() const = 0;

    // Run-time selection; a correlation joins the registry from its own .cpp.
    static ModelRegistry<HeatTransferModel>& registry();
    static std::unique_ptr<HeatTransferModel> New(const std::string& typeName, const Parameters& props);
    static std::vector<std::string> available();
};

} // namespace spoutlab
