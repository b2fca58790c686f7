#include "plume/Gamma.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace procsim::plume
{

double digamma(double x)
{
    double r = 0;
    while (x < 6)
    {
        r -= 1 / x;
        x += 1;
    }
    const double f = 1 / (x * x);
    return r + std::log(x) - 0.5 / x
           - f * (1.0 / 12 - f * (1.0 / 120 - f * (1.0 / 252 - f * (1.0 / 240 - f / 132))));
}

double trigamma(double x)
{
    double r = 0;
    while (x < 6)
    {
        r += 1 / (x * x);
        x += 1;
    }
    const double f = 1 / (x * x);
    return r + 1 / x + f / 2
           + f / x * (1.0 / 6 - f * (1.0 / 30 - f * (1.0 / 42 - f * (1.0 / 30))));
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
        if (v > 0) meanLog += std::log(v);
        else positive = false;
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
    if (x <= 0) return 0.0;
    const double lead = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1)
    {
        // series: P = e^{-x} x^a / Gamma(a+1) sum x^n / ((a+1)...(a+n))
        double term = 1 / a, sum = term;
        for (int n = 1; n < 100000; ++n)
        {
            term *= x / (a + n);
            sum += term;
            if (term < sum * 1e-16) break;
        }
        return std::min(1.0, sum * std::exp(lead));
    }
    // continued fraction for Q = 1 - P (modified Lentz)
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i)
    {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        const double del = d * c;
        h *= del;
        if (std::abs(del - 1) < 1e-16) break;
    }
    return std::max(0.0, 1.0 - std::exp(lead) * h);
}

double gammaQuantileZ(const GammaFit& g, double z)
{
    const double a = g.shape;
    z = std::clamp(z, -7.0, 7.0);
    const double p = normalCdf(z);
    // Wilson-Hilferty start, then safeguarded Newton on P(a, y) = p
    double y = a * std::pow(1 - 1 / (9 * a) + z / (3 * std::sqrt(a)), 3);
    if (!(y > 0) || !std::isfinite(y)) y = std::exp((std::log(p) + std::lgamma(a + 1)) / a);
    if (!(y > 0) || !std::isfinite(y)) y = 1e-300;
    double lo = 0, hi = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 100; ++it)
    {
        const double f = gammaP(a, y) - p;
        if (f < 0) lo = y;
        else hi = y;
        const double dens = std::exp((a - 1) * std::log(y) - y - std::lgamma(a));
        double next = dens > 0 ? y - f / dens : y;
        if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * y + 1e-8;
        if (std::abs(next - y) <= 1e-12 * y)
        {
            y = next;
            break;
        }
        y = next;
    }
    return y * g.scale;
}

double inverseNormal(double p)
{
    p = std::clamp(p, 1e-15, 1 - 1e-15);
    double lo = -9, hi = 9;
    for (int i = 0; i < 80; ++i)
    {
        const double m = 0.5 * (lo + hi);
        (normalCdf(m) < p ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

double gammaQuantile(const GammaFit& g, double p) { return gammaQuantileZ(g, inverseNormal(p)); }

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

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
