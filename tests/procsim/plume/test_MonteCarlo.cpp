// Gamma fitting and the synthetic meteorology of the Monte Carlo study.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "plume/Gamma.hpp"
#include "plume/MonteCarlo.hpp"

using namespace procsim::plume;

namespace
{

// samples from the standard library's gamma generator (independent of ours)
std::vector<double> gammaSamples(double k, double theta, int n, unsigned seed)
{
    std::mt19937_64 gen(seed);
    std::gamma_distribution<double> d(k, theta);
    std::vector<double> x(n);
    for (auto& v : x) v = d(gen);
    return x;
}

} // namespace

TEST(GammaFit, RecoversKnownParametersByMaximumLikelihood)
{
    // asymptotic standard error of the ML shape: sqrt(k / (n (k psi'(k) - 1)))
    // is about 1.1 % of k for k = 2.5, n = 20000; allow 4 standard errors
    for (auto [k, theta] : {std::pair{2.5, 1.3}, std::pair{0.7, 40.0}, std::pair{12.0, 25.0}})
    {
        const auto x = gammaSamples(k, theta, 20000, 7);
        const GammaFit f = fitGamma(x);
        const double se = std::sqrt(k / (20000 * (k * trigamma(k) - 1)));
        EXPECT_FALSE(f.moments);
        EXPECT_NEAR(f.shape, k, 4 * se) << "k=" << k;
        EXPECT_NEAR(f.shape * f.scale, k * theta, 4 * theta * std::sqrt(k / 20000.0)) << "mean";
    }
}

TEST(GammaFit, MomentsWhenTheDataHoldZeros)
{
    auto x = gammaSamples(3.0, 2.0, 20000, 11);
    for (int i = 0; i < 200; ++i) x[i] = 0.0; // 1 % calm hours
    const GammaFit f = fitGamma(x);
    EXPECT_TRUE(f.moments);
    EXPECT_NEAR(f.shape * f.scale, 0.99 * 6.0, 0.1);
}

TEST(GammaFit, QuantileInvertsTheDistribution)
{
    // k = 1 is the exponential: x_p = -theta ln(1 - p)
    GammaFit e;
    e.shape = 1;
    e.scale = 3;
    for (double p : {0.01, 0.3, 0.5, 0.9, 0.999})
        EXPECT_NEAR(gammaQuantile(e, p), -3 * std::log(1 - p), 1e-9 * 3 * (1 - std::log(1 - p)));
    // k = 2: P(2, x) = 1 - e^{-x}(1 + x)
    GammaFit g;
    g.shape = 2;
    g.scale = 1;
    for (double x : {0.1, 1.0, 3.0, 8.0}) EXPECT_NEAR(gammaP(2, x), 1 - std::exp(-x) * (1 + x), 1e-13);
    for (double a : {0.4, 3.0, 40.0, 4e4})
    {
        g.shape = a;
        for (double p : {0.02, 0.5, 0.97}) EXPECT_NEAR(gammaP(a, gammaQuantile(g, p)), p, 1e-10) << a;
    }
}

// Closed forms: psi(1) = -gamma_Euler, psi(1/2) = -gamma_Euler - 2 ln 2,
// psi(x + 1) = psi(x) + 1/x; psi'(1) = pi^2/6, psi'(1/2) = pi^2/2;
// P(1/2, x) = erf(sqrt x); Phi^-1(0.975) = 1.959963984540054.
TEST(GammaFit, SpecialFunctionsAgainstClosedForms)
{
    const double euler = 0.5772156649015329;
    EXPECT_NEAR(digamma(1.0), -euler, 1e-15);
    EXPECT_NEAR(digamma(0.5), -euler - 2 * std::log(2.0), 1e-15);
    EXPECT_NEAR(digamma(3.5), digamma(2.5) + 1 / 2.5, 1e-15);
    EXPECT_NEAR(trigamma(1.0), M_PI * M_PI / 6, 1e-15);
    EXPECT_NEAR(trigamma(0.5), M_PI * M_PI / 2, 1e-14);
    for (double x : {1e-3, 0.2, 2.0, 30.0}) EXPECT_NEAR(gammaP(0.5, x), std::erf(std::sqrt(x)), 1e-15) << x;
    EXPECT_NEAR(inverseNormal(0.975), 1.959963984540054, 1e-14);
    EXPECT_NEAR(inverseNormal(0.025), -1.959963984540054, 1e-14);
    // far upper tail of the exponential, kept to its digits: x = -theta ln(1 - Phi(z))
    GammaFit e;
    e.shape = 1;
    e.scale = 1;
    EXPECT_NEAR(gammaQuantileZ(e, 6.5), -std::log(normalCdf(-6.5)), 1e-12 * 25);
}

TEST(SyntheticMet, KeepsTheFittedGammaAndTheWeighting)
{
    // one climate for every month/block: speed ~ Gamma(2, 0.8)
    Climate c;
    GammaFit one;
    one.shape = 2;
    one.scale = 0.8;
    for (auto& v : c.fit)
        for (auto& m : v)
            for (auto& b : m) b = one;
    const double w = 0.5;
    std::vector<double> speed;
    for (int year = 0; year < 3; ++year)
    {
        Stream rng(99, year);
        for (const auto& h : synthesiseYear(c, w, rng)) speed.push_back(h.speed);
    }
    const GammaFit f = fitGamma(speed);
    const double se = std::sqrt(2 / (speed.size() * (2 * trigamma(2) - 1)));
    // hours are correlated, so fewer effective samples: allow 10 standard errors
    EXPECT_NEAR(f.shape, 2.0, 10 * se);
    EXPECT_NEAR(f.shape * f.scale, 1.6, 0.05);
    // lag-1 correlation of the normal scores is w
    std::vector<double> z(speed.size());
    for (std::size_t i = 0; i < z.size(); ++i) z[i] = inverseNormal(gammaP(2, speed[i] / 0.8));
    double s01 = 0, s00 = 0;
    for (std::size_t i = 1; i < z.size(); ++i)
    {
        s01 += z[i] * z[i - 1];
        s00 += z[i - 1] * z[i - 1];
    }
    EXPECT_NEAR(s01 / s00, w, 0.03);
}

TEST(SyntheticMet, StreamsDependOnlyOnSeedAndIndex)
{
    Stream a(5, 17), b(5, 17), c(5, 18);
    for (int i = 0; i < 100; ++i)
    {
        const double x = a.normal();
        EXPECT_EQ(x, b.normal());
        EXPECT_NE(x, c.normal());
    }
}
