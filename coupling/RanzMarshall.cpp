#include "RanzMarshall.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "heatTransferModel RanzMarshall;"
const Registration<HeatTransferModel, RanzMarshall> registeredRanzMarshall("RanzMarshall");

RanzMarshall::RanzMarshall(const Parameters&) {}

double RanzMarshall::h(const HeatTransferCell& cell, const GasThermalProperties& gas) const
{
    const double re = heatTransferReynolds(cell, gas);
    const double nu = 2.0 + 0.6 * std::cbrt(gas.prandtl()) * std::sqrt(re);
    return nu * gas.kappa / cell.diameter;
}

} // namespace spoutlab
