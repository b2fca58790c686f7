#include "plume/Gamma.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <boost/math/special_functions/digamma.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/special_functions/trigamma.hpp>

namespace procsim::plume
{

namespace
{

// Boost.Math evaluates double arguments in long double by default, whose
// width differs between platforms (80 bits on x86-64, 64 or 128 elsewhere);
// held to double, a seed gives the same synthetic years everywhere.
using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

} // namespace

double digamma(double x)
{
    return boost::math::digamma(x, DoublePolicy());
}

double trigamma(double x)
{
    return boost::math::trigamma(x, DoublePolicy());
}

GammaFit fitGamma(const std::vector<double>& x)
{
    GammaFit g;
    g.n = static_cast<int>(x.size());
    if (x.size() < 2) throw std::invalid_argument("gamma fit needs at least two values");
    double mean = 0, meanLog = 0;
    bool positive = true;
    for (double v : x)
    {
        if (!(v >= 0)) throw std::invalid_argument("gamma fit needs values >= 0");
        mean += v;
        if (v > 0)
            meanLog += std::log(v);
        else
            positive = false;
    }
    mean /= x.size();
    if (!(mean > 0)) throw std::invalid_argument("gamma fit: all values are zero");
    if (!positive)
    {
        double var = 0;
        for (double v : x) var += (v - mean) * (v - mean);
        var /= (x.size() - 1);
        var = std::max(var, 1e-12 * mean * mean);
        g.shape = mean * mean / var;
        g.scale = var / mean;
        g.moments = true;
        return g;
    }
    meanLog /= x.size();
    const double s = std::log(mean) - meanLog;
    if (!(s > 1e-12))
    {
        // (nearly) constant data: a very narrow gamma
        g.shape = 1e6;
        g.scale = mean / g.shape;
        return g;
    }
    double k = (3 - s + std::sqrt((s - 3) * (s - 3) + 24 * s)) / (12 * s);
    for (int it = 0; it < 50; ++it)
    {
        const double f = std::log(k) - digamma(k) - s;
        const double d = 1 / k - trigamma(k);
        const double kn = k - f / d;
        const double next = kn > 0 ? kn : 0.5 * k;
        if (std::abs(next - k) < 1e-12 * k)
        {
            k = next;
            break;
        }
        k = next;
    }
    g.shape = k;
    g.scale = mean / k;
    return g;
}

double gammaP(double a, double x)
{
    return x <= 0 ? 0.0 : boost::math::gamma_p(a, x, DoublePolicy());
}

double gammaQuantileZ(const GammaFit& g, double z)
{
    // |z| <= 7 keeps Phi(z) and 1 - Phi(z) above 1e-12; the upper tail is
    // inverted through Q = Phi(-z), which keeps its digits where P -> 1
    z = std::clamp(z, -7.0, 7.0);
    const double y = z <= 0 ? boost::math::gamma_p_inv(g.shape, normalCdf(z), DoublePolicy())
                            : boost::math::gamma_q_inv(g.shape, normalCdf(-z), DoublePolicy());
    return y * g.scale;
}

double inverseNormal(double p)
{
    p = std::clamp(p, 1e-15, 1 - 1e-15);
    return -std::sqrt(2.0) * boost::math::erfc_inv(2 * p, DoublePolicy());
}

double gammaQuantile(const GammaFit& g, double p)
{
    return gammaQuantileZ(g, inverseNormal(p));
}

double normalCdf(double z)
{
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

namespace
{

std::uint64_t splitmix64(std::uint64_t& s)
{
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

} // namespace

Stream::Stream(std::uint64_t seed, std::uint64_t index)
{
    std::uint64_t s = seed ^ (0xd1b54a32d192ed03ULL * (index + 1));
    splitmix64(s);
    gen_.seed(splitmix64(s));
}

double Stream::uniform()
{
    // 53 random bits, shifted off 0
    return ((gen_() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

double Stream::normal()
{
    if (haveSpare_)
    {
        haveSpare_ = false;
        return spare_;
    }
    const double u1 = uniform(), u2 = uniform();
    const double r = std::sqrt(-2 * std::log(u1));
    spare_ = r * std::sin(2 * M_PI * u2);
    haveSpare_ = true;
    return r * std::cos(2 * M_PI * u2);
}

} // namespace procsim::plume
