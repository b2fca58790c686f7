// procsim dryer psychro: the moist-air state at one dry bulb and pressure,
// given one humidity measure.
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Format.hpp"
#include "dryer/Commands.hpp"
#include "Psychrometrics.hpp" // coupling/: the one psychrometrics of the project
#include "dryer/Texts.hpp"

namespace procsim::dryer
{

namespace psy = spoutlab::psy;

namespace
{

// The dry bulb T and pressure P, and exactly one of the humidity measures.
struct PsychroArgs
{
    std::optional<double> t, p, rh, w, twb, tdew; // degC, kPa, %, kg/kg, degC, degC
};

std::optional<PsychroArgs> parse(CommandLine& cl, int argc, char** argv)
{
    PsychroArgs a;
    cl.number("--t", a.t);
    cl.number("--rh", a.rh);
    cl.number("--w", a.w);
    cl.number("--twb", a.twb);
    cl.number("--tdew", a.tdew);
    cl.number("--p", a.p);
    if (!cl.parse(argc, argv)) return std::nullopt;
    if (!a.t) throw InputError("dryer psychro: option --t (dry bulb, degC) is required");
    if (!(*a.t >= -100 && *a.t <= 200))
        throw cl.refuse("--t", "a dry bulb from -100 to 200 degC", formatNumber(*a.t));
    if (a.p && !(*a.p > 0)) throw cl.refuse("--p", "a positive pressure [kPa]", formatNumber(*a.p));
    if (bool(a.rh) + bool(a.w) + bool(a.twb) + bool(a.tdew) != 1)
        throw InputError("dryer psychro: give exactly one of --rh, --w, --twb, --tdew");
    return a;
}

// The humidity ratio W [kg/kg dry air] from the measure given, checked
// against what the dry bulb and pressure allow.
double humidityRatio(const CommandLine& cl, const PsychroArgs& a, double t, double p)
{
    if (a.rh)
    {
        if (!(*a.rh >= 0 && *a.rh <= 100)) throw cl.refuse("--rh", "0 to 100 %", formatNumber(*a.rh));
        if (*a.rh / 100 * psy::saturationPressure(t) >= p)
            throw InputError(
                "dryer psychro: option --rh gives a vapour pressure at or above the total pressure");
        return psy::humidityRatioFromRH(t, *a.rh / 100, p);
    }
    if (a.w)
    {
        if (!(*a.w >= 0)) throw cl.refuse("--w", "a humidity ratio >= 0", formatNumber(*a.w));
        if (psy::relativeHumidity(t, *a.w, p) > 1 + 1e-12)
            throw InputError(
                "dryer psychro: option --w is above saturation at this dry bulb (relative humidity over 100 %)");
        return *a.w;
    }
    if (a.twb)
    {
        if (!(*a.twb <= t && *a.twb >= -100))
            throw cl.refuse("--twb", "a wet bulb at or below the dry bulb", formatNumber(*a.twb));
        const double W = psy::humidityRatioFromWetBulb(t, *a.twb, p);
        if (!(W >= 0))
            throw InputError("dryer psychro: option --twb is too low for any humidity at this dry bulb");
        return W;
    }
    if (!(*a.tdew <= t && *a.tdew >= -100))
        throw cl.refuse("--tdew", "a dew point at or below the dry bulb", formatNumber(*a.tdew));
    return psy::humidityRatioFromPw(psy::saturationPressure(*a.tdew), p);
}

void report(double t, double W, double p)
{
    const auto g = [](double v) { return formatNumber(v); };
    fmt::print("dry bulb                {} degC\n", g(t));
    fmt::print("pressure                {} kPa\n", g(p / 1e3));
    fmt::print("saturation pressure     {} kPa\n", g(psy::saturationPressure(t) / 1e3));
    fmt::print("humidity ratio          {} kg/kg dry air\n", g(W));
    fmt::print("relative humidity       {} %\n", g(psy::relativeHumidity(t, W, p) * 100));
    fmt::print("enthalpy                {} kJ/kg dry air\n", g(psy::enthalpy(t, W) / 1e3));
    fmt::print("dew point               {} degC\n", W > 0 ? formatFixed(psy::dewPoint(W, p), 3) : "-inf");
    fmt::print("thermodynamic wet bulb  {} degC\n", g(psy::wetBulb(t, W, p)));
    fmt::print("specific volume         {} m3/kg dry air\n", g(psy::specificVolume(t, W, p)));
    fmt::print("density                 {} kg/m3\n", g(psy::density(t, W, p)));
}

} // namespace

int psychroCommand(int argc, char** argv)
{
    CommandLine cl("dryer psychro", std::string(texts::help::psychro));
    const auto args = parse(cl, argc, argv);
    if (!args) return 0;
    const double t = *args->t, p = args->p ? *args->p * 1e3 : psy::kAtm;
    try
    {
        report(t, humidityRatio(cl, *args, t, p), p);
    }
    catch (const std::domain_error& e) // a state the formulation cannot reach
    {
        throw InputError(std::string("dryer psychro: ") + e.what());
    }
    return 0;
}

} // namespace procsim::dryer
