#include "RanzMarshall.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "heatTransferModel RanzMarshall;"
const Registration<HeatTransferModel, RanzMarshall> registeredRanzMarshall("RanzMarshall");

RanzMarshall::RanzMarshall(const Parameters&) {}

double RanzMarshall::nusselt(const HeatTransferCell&, double re, double pr) const
{
    return 2.0 + 0.6 * std::cbrt(pr) * std::sqrt(re);
}

} // namespace spoutlab
