#include "Gidaspow.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "dragModel Gidaspow;"
const Registration<DragModel, Gidaspow> registeredGidaspow("Gidaspow");

namespace
{

double ergun(const DragState& s, const GasProperties& gas)
{
    const double eps = s.voidFraction;
    const double d = s.diameter;
    const double solid = 1.0 - eps;
    return 150.0 * solid * solid * gas.mu / (eps * d * d) + 1.75 * solid * gas.rho * s.slip / d;
}

// C_d |w| rather than C_d alone: 24/Re is singular at zero slip but
// 24/Re |w| = 24 mu/(eps rho d) is not, so the Stokes limit comes out exactly.
double dragCoeffTimesSlip(const DragState& s, const GasProperties& gas)
{
    const double re = particleReynolds(s, gas);
    if (re >= 1000.0) return 0.44 * s.slip;
    const double stokes = 24.0 * gas.mu / (s.voidFraction * gas.rho * s.diameter);
    return stokes * (1.0 + 0.15 * std::pow(re, 0.687));
}

double wenYu(const DragState& s, const GasProperties& gas)
{
    const double eps = s.voidFraction;
    return 0.75 * gas.rho * eps * (1.0 - eps) / s.diameter * std::pow(eps, -2.65)
           * dragCoeffTimesSlip(s, gas);
}

} // namespace

Gidaspow::Gidaspow(const Parameters& props)
    : smooth_(false), epsilonSwitch_(props.getScalar("epsilonSwitch", 0.8))
{
    const std::string mode = props.getWord("switch", "sharp");
    if (mode != "sharp" && mode != "smooth") throw props.badValue("switch", "one of: sharp, smooth");
    smooth_ = mode == "smooth";
    if (!(epsilonSwitch_ > 0.0 && epsilonSwitch_ <= 1.0))
    {
        throw props.badValue("epsilonSwitch", "a void fraction in (0, 1]");
    }
}

double Gidaspow::beta(const DragState& s, const GasProperties& gas) const
{
    if (!smooth_) return s.voidFraction < epsilonSwitch_ ? ergun(s, gas) : wenYu(s, gas);
    const double pi = std::acos(-1.0);
    const double phi = 0.5 + std::atan(262.5 * (s.voidFraction - epsilonSwitch_)) / pi;
    return (1.0 - phi) * ergun(s, gas) + phi * wenYu(s, gas);
}

} // namespace spoutlab
