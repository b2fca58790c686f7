#include "DiFelice.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "dragModel DiFelice;"
const Registration<DragModel, DiFelice> registeredDiFelice("DiFelice");

namespace
{

// C_d |w| = (0.63 sqrt|w| + 4.8 sqrt(mu/(eps rho d)))^2 is C_d times the slip
// written without 1/sqrt(Re), so zero slip gives zero drag instead of 0 * inf.
double dragCoeffTimesSlip(const DragState& s, const GasProperties& gas)
{
    const double root =
        0.63 * std::sqrt(s.slip) + 4.8 * std::sqrt(gas.mu / (s.voidFraction * gas.rho * s.diameter));
    return root * root;
}

// As Re -> 0, log10 Re -> -inf and the Gaussian term vanishes: chi -> 3.7.
// Below 1e-12 that term is under 1e-40, so the limit is used directly.
double chi(double re)
{
    if (re < 1e-12) return 3.7;
    const double a = 1.5 - std::log10(re);
    return 3.7 - 0.65 * std::exp(-0.5 * a * a);
}

} // namespace

DiFelice::DiFelice(const Parameters&) {}

double DiFelice::beta(const DragState& s, const GasProperties& gas) const
{
    const double eps = s.voidFraction;
    const double re = particleReynolds(s, gas);
    return 0.75 * gas.rho * (1.0 - eps) * std::pow(eps, 2.0 - chi(re)) / s.diameter
           * dragCoeffTimesSlip(s, gas);
}

} // namespace spoutlab
