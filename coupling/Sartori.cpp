#include "Sartori.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "heatTransferModel Sartori;"
const Registration<HeatTransferModel, Sartori> registeredSartori("Sartori");

Sartori::Sartori(const Parameters&) {}

double Sartori::nusselt(const HeatTransferCell&, double re, double pr) const
{
    return 1.54 * std::cbrt(pr) * std::pow(re, 0.57);
}

} // namespace spoutlab
