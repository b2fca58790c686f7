#include "kinetics/Corona.hpp"

#include <cmath>

namespace procsim::kinetics::corona
{

double numberDensity(double p, double t)
{
    return p / (boltzmann * t);
}

double field(double v, double r, double anodeR, double wireR)
{
    return v / (r * std::log(anodeR / wireR));
}

double meanEOverN(double v, double anodeR, double wireR, double n)
{
    return 2.0 * v / (n * (anodeR + wireR) * std::log(anodeR / wireR));
}

double removalEfficiency(double c0, double c)
{
    return (c0 - c) / c0;
}

double residenceCorrected(double psi, double t, double tRef)
{
    return psi * t / tRef;
}

double energeticEfficiency(double qIn, double qOut, double i, double v)
{
    return (qIn - qOut) / (i * v);
}

} // namespace procsim::kinetics::corona
