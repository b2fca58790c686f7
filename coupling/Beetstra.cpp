#include "Beetstra.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "dragModel Beetstra;"
const Registration<DragModel, Beetstra> registeredBeetstra("Beetstra");

namespace
{

// The inertial term with numerator and denominator multiplied by Re^a,
// a = (1 + 4 phi)/2, so only positive powers of Re remain and Re = 0 is exact
// (the term vanishes) instead of inf/inf.
double inertialTerm(double eps, double re)
{
    const double phi = 1.0 - eps;
    const double a = 0.5 * (1.0 + 4.0 * phi);
    const double numerator =
        std::pow(re, 1.0 + a) * (1.0 / eps + 3.0 * eps * phi) + 8.4 * std::pow(re, 1.0 + a - 0.343);
    const double denominator = std::pow(re, a) + std::pow(10.0, 3.0 * phi);
    return 0.413 / (24.0 * eps * eps) * numerator / denominator;
}

double normalisedDrag(double eps, double re)
{
    const double phi = 1.0 - eps;
    return 10.0 * phi / (eps * eps) + eps * eps * (1.0 + 1.5 * std::sqrt(phi)) + inertialTerm(eps, re);
}

} // namespace

Beetstra::Beetstra(const Parameters&) {}

double Beetstra::beta(const DragState& s, const GasProperties& gas) const
{
    const double eps = s.voidFraction;
    const double d = s.diameter;
    const double re = particleReynolds(s, gas);
    return 18.0 * gas.mu * eps * (1.0 - eps) * normalisedDrag(eps, re) / (d * d);
}

} // namespace spoutlab
