#include "ModifiedChungPfost.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spoutlab
{

// selected by "isotherm modifiedChungPfost;"
const Registration<SorptionIsotherm, ModifiedChungPfost> registeredModifiedChungPfost("modifiedChungPfost");

namespace
{

// ASAE D245.4 / Brooker et al. (1992), shelled corn, X decimal d.b., t in degC
constexpr double kE = 0.33872;
constexpr double kF = 0.058970;
constexpr double kC = 30.205;

} // namespace

ModifiedChungPfost::ModifiedChungPfost(const Parameters&) {}

double ModifiedChungPfost::equilibriumMoisture(double waterActivity, double temperature) const
{
    if (!(waterActivity > 0.0)) return 0.0;
    if (!(waterActivity < 1.0)) return std::numeric_limits<double>::infinity();
    const double t = temperature - 273.15;
    return std::max(0.0, kE - kF * std::log(-(t + kC) * std::log(waterActivity)));
}

double ModifiedChungPfost::waterActivity(double moisture, double temperature) const
{
    const double t = temperature - 273.15;
    return std::exp(-std::exp((kE - moisture) / kF) / (t + kC));
}

double ModifiedChungPfost::waterActivityDerivative(double moisture, double temperature) const
{
    // a_w = exp(-u/(t + C)), u = exp((E - X)/F): da_w/dX = a_w u/((t + C) F)
    const double tPlusC = temperature - 273.15 + kC;
    const double u = std::exp((kE - moisture) / kF);
    return std::exp(-u / tPlusC) * u / (tPlusC * kF);
}

double ModifiedChungPfost::lnWaterActivitySlope(double moisture, double temperature) const
{
    const double tPlusC = temperature - 273.15 + kC;
    return std::exp((kE - moisture) / kF) / (tPlusC * tPlusC);
}

SorptionIsotherm::Activity ModifiedChungPfost::activity(double moisture, double temperature) const
{
    const double tPlusC = temperature - 273.15 + kC;
    const double u = std::exp((kE - moisture) / kF);
    const double aw = std::exp(-u / tPlusC);
    return {aw, aw * u / (tPlusC * kF), u / (tPlusC * tPlusC)};
}

} // namespace spoutlab
