// Continuous point source in a uniform wind with constant K_H, K_V between
// the ground and a lid: the Eulerian solver against the exact steady
// solution, and the Gaussian plume with sigma^2 = 2 K x / u (its slender
// limit) against both.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plume/Eulerian.hpp"
#include "plume/Gaussian.hpp"

using namespace procsim::plume;

namespace
{

// u C_x = K_H (C_xx + C_yy) + K_V C_zz + Q delta: with z' = z sqrt(K_H/K_V),
// C = Q sqrt(K_H/K_V) / (4 pi K_H r') exp(-u (r' - x) / 2K_H); images at
// 2nH +- zs for the no-flux ground (z = 0) and lid (z = H).
double exactPointSource(double q, double u, double kH, double kV, double zs, double H, double x,
                        double y, double z)
{
    const double a = std::sqrt(kH / kV);
    double c = 0;
    for (int n = -4; n <= 4; ++n)
        for (double zi : {2 * n * H + zs, 2 * n * H - zs})
        {
            const double r = std::sqrt(x * x + y * y + (z - zi) * (z - zi) * a * a);
            c += q * a / (4 * M_PI * kH * r) * std::exp(-u * (r - x) / (2 * kH));
        }
    return c;
}

} // namespace

TEST(SlenderPlume, EulerianAndGaussianAgreeWithTheExactSolution)
{
    const double u = 2.0, kH = 10.0, kV = 2.0, q = 1e-3, H = 200.0;
    const double xs = 210, ys = 0, zs = 55;   // a cell centre
    TerrainGrid g = TerrainGrid::box(100, 31, 20, 0.0, -310.0, 20.0, 20.0, H);
    WindModel wind(g, 0.0, 10.0);
    Transport t(g, kH, kV);
    t.setFlow(wind.flow(u, 270.0));
    std::vector<double> src(g.size(), 0.0);
    src[g.idx(10, 15, 5)] = q;
    ASSERT_NEAR(g.xc(10), xs, 1e-9);
    ASSERT_NEAR(g.yc(15), ys, 1e-9);
    ASSERT_NEAR(g.zc(10, 15, 5), zs, 1e-9);
    t.setSources(src);
    const double dt = 0.9 * t.stableDt();
    const int steps = static_cast<int>(std::ceil(1800.0 / dt));
    for (int n = 0; n < steps; ++n) t.step(1800.0 / steps);

    GaussianOptions o;
    o.constantK = true;
    o.kH = kH;
    o.kV = kV;
    o.windExponent = 0;
    Source s;
    s.type = Source::Type::Point;
    s.x = xs;
    s.y = ys;
    s.height = zs;
    s.rate = q;
    GaussianModel gm({s}, o);
    PlumeHour h;
    h.u10 = u;
    h.directionFrom = 270;
    h.cls = 4;
    h.mixingHeight = H;

    double worstG = 0, worstE = 0;
    for (double x : {610.0, 1010.0, 1510.0})
        for (double y : {0.0, 60.0})
            for (double z : {5.0, 55.0})
            {
                const double exact = exactPointSource(q, u, kH, kV, zs, H, x - xs, y - ys, z);
                const double eul = t.sample(x, y, z);
                Receptor r;
                r.x = x;
                r.y = y;
                r.height = z;
                const double gau = gm.concentration(h, r);
                worstG = std::max(worstG, std::abs(gau / exact - 1));
                worstE = std::max(worstE, std::abs(eul / exact - 1));
                // slender-plume error of the Gaussian ~ K_H/(u x) <= 2.5 %
                // here; the Eulerian error is the 2nd-order discretisation
                EXPECT_NEAR(gau, exact, 0.04 * exact) << "Gaussian x=" << x << " y=" << y << " z=" << z;
                EXPECT_NEAR(eul, exact, 0.04 * exact) << "Eulerian x=" << x << " y=" << y << " z=" << z;
                EXPECT_NEAR(eul, gau, 0.05 * gau) << "x=" << x << " y=" << y << " z=" << z;
            }
    std::printf("largest deviation from the exact solution: Gaussian %.2f %%, Eulerian %.2f %%\n",
                100 * worstG, 100 * worstE);
}
