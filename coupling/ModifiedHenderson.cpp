#include "ModifiedHenderson.hpp"

#include <cmath>
#include <limits>

namespace spoutlab
{

// selected by "isotherm modifiedHenderson;"
const Registration<SorptionIsotherm, ModifiedHenderson> registeredModifiedHenderson("modifiedHenderson");

namespace
{

// ASAE D245.5, corn (yellow dent), M in % d.b., t in degC
constexpr double kA = 8.6541e-5;
constexpr double kB = 1.8634;
constexpr double kC = 49.810;

// A (t + C) M^B, the exponent of 1 - a_w
double exponent(double moisture, double temperature)
{
    return kA * (temperature - 273.15 + kC) * std::pow(100.0 * moisture, kB);
}

} // namespace

ModifiedHenderson::ModifiedHenderson(const Parameters&) {}

double ModifiedHenderson::equilibriumMoisture(double waterActivity, double temperature) const
{
    if (!(waterActivity > 0.0)) return 0.0;
    if (!(waterActivity < 1.0)) return std::numeric_limits<double>::infinity();
    const double t = temperature - 273.15;
    return 0.01 * std::pow(-std::log1p(-waterActivity) / (kA * (t + kC)), 1.0 / kB);
}

double ModifiedHenderson::waterActivity(double moisture, double temperature) const
{
    return -std::expm1(-exponent(moisture, temperature));
}

// With z = A (t + C) M^B: a_w = 1 - e^-z, from expm1 for small z, and e^-z
// taken as 1 + expm1(-z) so that one pow and one expm1 give all three.
double ModifiedHenderson::waterActivityDerivative(double moisture, double temperature) const
{
    // d/dX (1 - e^-z) = e^-z dz/dX, dz/dX = B z/X (z = 0 at X = 0 with B > 1)
    if (!(moisture > 0.0)) return 0.0;
    const double z = exponent(moisture, temperature);
    return (1.0 + std::expm1(-z)) * kB * z / moisture;
}

double ModifiedHenderson::lnWaterActivitySlope(double moisture, double temperature) const
{
    const double z = exponent(moisture, temperature);
    const double tPlusC = temperature - 273.15 + kC;
    if (z == 0.0) return 1.0 / tPlusC; // a_w -> z, d ln a_w/dt -> 1/(t + C)
    // A M^B (1 - a_w)/a_w = (z/(t + C)) e^-z / (1 - e^-z)
    const double em = std::expm1(-z);
    return z / tPlusC * (1.0 + em) / -em;
}

SorptionIsotherm::Activity ModifiedHenderson::activity(double moisture, double temperature) const
{
    const double z = exponent(moisture, temperature);
    const double tPlusC = temperature - 273.15 + kC;
    const double em = std::expm1(-z);
    return {-em, moisture > 0.0 ? (1.0 + em) * kB * z / moisture : 0.0,
            z == 0.0 ? 1.0 / tPlusC : z / tPlusC * (1.0 + em) / -em};
}

std::vector<StatedRange> ModifiedHenderson::statedRanges() const
{
    const std::string source = "ASAE D245.5";
    return {{"temperature", 273.15, 323.15, source}, {"relative humidity", 0.10, 0.90, source}};
}

} // namespace spoutlab
