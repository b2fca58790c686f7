#include "ThompsonThinLayer.hpp"

#include <cmath>

namespace spoutlab::thompson
{

namespace
{

double fahrenheit(double kelvin)
{
    return (kelvin - 273.15) * 1.8 + 32.0;
}

// Thompson et al. (1968): A [h], B [h], T in degF
double coefficientA(double airTemperature)
{
    return -1.862 + 0.00488 * fahrenheit(airTemperature);
}

double coefficientB(double airTemperature)
{
    return 427.4 * std::exp(-0.033 * fahrenheit(airTemperature));
}

} // namespace

double dryingTime(double moistureRatio, double airTemperature)
{
    const double lnMr = std::log(moistureRatio);
    const double hours = coefficientA(airTemperature) * lnMr + coefficientB(airTemperature) * lnMr * lnMr;
    return 3600.0 * hours;
}

double moistureRatio(double time, double airTemperature)
{
    const double a = coefficientA(airTemperature), b = coefficientB(airTemperature);
    const double hours = time / 3600.0;
    return std::exp((-a - std::sqrt(a * a + 4.0 * b * hours)) / (2.0 * b));
}

} // namespace spoutlab::thompson
