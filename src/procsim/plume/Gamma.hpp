#pragma once
// Gamma distribution: fitting, quantiles and a portable random stream.
// The special functions are Boost.Math's, evaluated in double.
#include <cstdint>
#include <random>
#include <vector>

namespace procsim::plume
{

struct GammaFit
{
    double shape = 1; // k
    double scale = 1; // theta  (mean = k theta, variance = k theta^2)
    int n = 0;
    bool moments = false; // true: fitted by moments (data had zeros)
};

// Maximum likelihood (Minka's start + Newton on ln k - psi(k) = ln mean - mean ln x)
// when all values are positive; by moments (k = m^2/v, theta = v/m) otherwise.
GammaFit fitGamma(const std::vector<double>& x);

double digamma(double x);
double trigamma(double x);
// Regularised lower incomplete gamma P(a, x).
double gammaP(double a, double x);
// x with P(k, x/theta) = p, and the same for p = Phi(z) (normal score z).
double gammaQuantile(const GammaFit& g, double p);
double gammaQuantileZ(const GammaFit& g, double z);
double normalCdf(double z);
double inverseNormal(double p);

// Random numbers that are the same on every platform: mt19937_64 (fully
// specified by the standard) with our own uniform/normal transforms.  Each
// stream is seeded from (seed, index) through splitmix64, so realisation i
// does not depend on which thread runs it.
class Stream
{
public:
    Stream(std::uint64_t seed, std::uint64_t index);
    double uniform(); // (0, 1)
    double normal();  // N(0, 1), Box-Muller
private:
    std::mt19937_64 gen_;
    bool haveSpare_ = false;
    double spare_ = 0;
};

} // namespace procsim::plume
