#include "Psychrometrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace spoutlab::psy
{

namespace
{

constexpr double kTmin = -100.0;
constexpr double kTmax = 200.0;
constexpr double kKelvin = 273.15;

// Bisection on a function that is increasing in x, with f(lo) <= 0 <= f(hi).
// 200 halvings take any bracket below 1e-12 K; the loop stops earlier once
// the bracket stops shrinking in floating point.
template <class F>
double bisect(F f, double lo, double hi)
{
    for (int i = 0; i < 200; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (f(mid) > 0.0)
            hi = mid;
        else
            lo = mid;
        if (hi - lo < 1e-12) break;
    }
    return 0.5 * (lo + hi);
}

} // namespace

double saturationPressure(double tC)
{
    if (!(tC >= kTmin - 1e-9 && tC <= kTmax + 1e-9))
    {
        throw std::domain_error("saturation pressure: temperature " + std::to_string(tC)
                                + " degC outside -100..200 degC");
    }
    const double T = tC + kKelvin;
    if (tC < 0.0)
    {
        // Hyland-Wexler over ice (ASHRAE Fundamentals ch. 1, eq 5)
        const double c1 = -5.6745359e3, c2 = 6.3925247, c3 = -9.677843e-3, c4 = 6.2215701e-7,
                     c5 = 2.0747825e-9, c6 = -9.484024e-13, c7 = 4.1635019;
        return std::exp(c1 / T + c2 + T * (c3 + T * (c4 + T * (c5 + T * c6))) + c7 * std::log(T));
    }
    // Hyland-Wexler over liquid water (eq 6), 0..200 degC
    const double c8 = -5.8002206e3, c9 = 1.3914993, c10 = -4.8640239e-2, c11 = 4.1764768e-5,
                 c12 = -1.4452093e-8, c13 = 6.5459673;
    return std::exp(c8 / T + c9 + T * (c10 + T * (c11 + T * c12)) + c13 * std::log(T));
}

double saturationTemperature(double pw)
{
    const double plo = saturationPressure(kTmin), phi = saturationPressure(kTmax);
    if (!(pw >= plo && pw <= phi))
    {
        throw std::domain_error("vapour pressure " + std::to_string(pw)
                                + " Pa outside the saturation range of -100..200 degC");
    }
    return bisect([pw](double t) { return saturationPressure(t) - pw; }, kTmin, kTmax);
}

double humidityRatioFromPw(double pw, double p)
{
    if (!(pw >= 0.0)) throw std::domain_error("negative vapour pressure");
    if (pw >= p) return std::numeric_limits<double>::infinity();
    return kMolarRatio * pw / (p - pw);
}

double pwFromHumidityRatio(double W, double p)
{
    if (!(W >= 0.0)) throw std::domain_error("negative humidity ratio");
    return p * W / (kMolarRatio + W);
}

double saturationHumidityRatio(double tC, double p)
{
    return humidityRatioFromPw(saturationPressure(tC), p);
}

double relativeHumidity(double tC, double W, double p)
{
    return pwFromHumidityRatio(W, p) / saturationPressure(tC);
}

double humidityRatioFromRH(double tC, double rh, double p)
{
    if (!(rh >= 0.0 && rh <= 1.0)) throw std::domain_error("relative humidity outside 0..1");
    const double pw = rh * saturationPressure(tC);
    if (pw >= p) throw std::domain_error("vapour pressure reaches the total pressure (boiling)");
    return humidityRatioFromPw(pw, p);
}

double enthalpy(double tC, double W)
{
    return kCpAir * tC + W * (kHfg0 + kCpVapour * tC);
}

double temperatureFromEnthalpy(double h, double W)
{
    return (h - W * kHfg0) / (kCpAir + W * kCpVapour);
}

double dewPoint(double W, double p)
{
    return saturationTemperature(pwFromHumidityRatio(W, p));
}

double specificVolume(double tC, double W, double p)
{
    return kRa * (tC + kKelvin) * (1.0 + W / kMolarRatio) / p;
}

double density(double tC, double W, double p)
{
    return (1.0 + W) / specificVolume(tC, W, p);
}

double humidityRatioFromWetBulb(double tC, double twb, double p)
{
    const double ws = saturationHumidityRatio(twb, p);
    if (twb >= 0.0)
    {
        // ASHRAE eq (35), kJ form scaled to J
        return ((kHfg0 - (kCpWater - kCpVapour) * twb) * ws - kCpAir * (tC - twb))
               / (kHfg0 + kCpVapour * tC - kCpWater * twb);
    }
    // over ice, eq (37): sublimation 2830 kJ/kg, ice cp 2.1 kJ/(kg K)
    return ((2830.0e3 - 240.0 * twb) * ws - kCpAir * (tC - twb)) / (2830.0e3 + kCpVapour * tC - 2100.0 * twb);
}

double wetBulb(double tC, double W, double p)
{
    if (!(tC >= kTmin && tC <= kTmax)) throw std::domain_error("wet bulb: dry bulb outside -100..200 degC");
    if (!(W >= 0.0)) throw std::domain_error("wet bulb: negative humidity ratio");
    // The wet bulb lies between the dew point and the dry bulb, and below the
    // boiling point at p (where W_s* is infinite).
    double hi = tC;
    if (p <= saturationPressure(kTmax))
    {
        const double tBoil = saturationTemperature(p);
        if (tBoil - 1e-6 < hi) hi = tBoil - 1e-6;
    }
    double lo = kTmin;
    if (W > 0.0)
    {
        const double pw = pwFromHumidityRatio(W, p);
        if (pw >= saturationPressure(kTmin)) lo = std::min(saturationTemperature(pw), hi);
    }
    auto g = [&](double t) { return humidityRatioFromWetBulb(tC, t, p) - W; };
    // Saturated air (up to round-off): the wet bulb is the dry bulb.
    if (hi == tC && std::fabs(g(hi)) <= 1e-12 * (1.0 + W)) return tC;
    if (g(hi) < 0.0)
    {
        throw std::domain_error("wet bulb: air is supersaturated (W above saturation at " + std::to_string(tC)
                                + " degC)");
    }
    if (g(lo) > 0.0) return lo; // only at saturation, where lo == hi up to round-off
    return bisect(g, lo, hi);
}

double latentHeat(double tC)
{
    return kHfg0 + (kCpVapour - kCpWater) * tC;
}

} // namespace spoutlab::psy
