#include "MoistAir.hpp"

#include "Psychrometrics.hpp"

#include <cmath>

namespace spoutlab
{

namespace
{

constexpr double kKelvin = 273.15;

} // namespace

double waterVapourGasConstant()
{
    return psy::kRa / psy::kMolarRatio;
}

double vapourPressure(const MoistAir& air)
{
    return psy::pwFromHumidityRatio(air.humidityRatio, air.pressure);
}

double relativeHumidity(const MoistAir& air)
{
    return psy::relativeHumidity(air.temperature - kKelvin, air.humidityRatio, air.pressure);
}

double vapourDensity(const MoistAir& air)
{
    return vapourPressure(air) / (waterVapourGasConstant() * air.temperature);
}

double saturationVapourDensity(double temperature)
{
    return psy::saturationPressure(temperature - kKelvin) / (waterVapourGasConstant() * temperature);
}

double vapourDiffusivity(double temperature, double pressure)
{
    // Massman (1998), water vapour in air (MoistAir.hpp)
    constexpr double d0 = 0.2178e-4; // m^2/s at T_0, p_0
    constexpr double t0 = 273.15;    // K
    constexpr double p0 = 101325.0;  // Pa
    return d0 * (p0 / pressure) * std::pow(temperature / t0, 1.81);
}

} // namespace spoutlab
