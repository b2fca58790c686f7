#include "Gunn.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "heatTransferModel Gunn;"
const Registration<HeatTransferModel, Gunn> registeredGunn("Gunn");

Gunn::Gunn(const Parameters&) {}

double Gunn::nusselt(const HeatTransferCell& cell, double re, double pr) const
{
    const double eps = cell.voidFraction;
    const double pr3 = std::cbrt(pr);
    // The first term dominates at low Re, the second at high Re.
    const double lowRe = (7.0 - 10.0 * eps + 5.0 * eps * eps) * (1.0 + 0.7 * std::pow(re, 0.2) * pr3);
    const double highRe = (1.33 - 2.4 * eps + 1.2 * eps * eps) * std::pow(re, 0.7) * pr3;
    return lowRe + highRe;
}

std::vector<StatedRange> Gunn::statedRanges() const
{
    const std::string source = "Gunn 1978";
    return {{"Re", 0.0, 1e5, source}, {"voidage", 0.35, 1.0, source}};
}

} // namespace spoutlab
