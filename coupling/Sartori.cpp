#include "Sartori.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "heatTransferModel Sartori;"
const Registration<HeatTransferModel, Sartori> registeredSartori("Sartori");

Sartori::Sartori(const Parameters&) {}

double Sartori::h(const HeatTransferCell& cell, const GasThermalProperties& gas) const
{
    const double re = heatTransferReynolds(cell, gas);
    const double nu = 1.54 * std::cbrt(gas.prandtl()) * std::pow(re, 0.57);
    return nu * gas.kappa / cell.diameter;
}

} // namespace spoutlab
