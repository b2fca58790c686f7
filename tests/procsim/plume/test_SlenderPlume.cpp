// Continuous point source in a uniform wind with constant K_H, K_V between
// the ground and a lid: the Eulerian solver against the exact steady
// solution, and the Gaussian plume with sigma^2 = 2 K x / u (its slender
// limit) against both.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "plume/Eulerian.hpp"
#include "plume/EulerianCase.hpp"
#include "plume/Gaussian.hpp"

using namespace procsim::plume;

namespace
{

// u C_x = K_H (C_xx + C_yy) + K_V C_zz + Q delta: with z' = z sqrt(K_H/K_V),
// C = Q sqrt(K_H/K_V) / (4 pi K_H r') exp(-u (r' - x) / 2K_H); images at
// 2nH +- zs for the no-flux ground (z = 0) and lid (z = H).
double exactPointSource(double q, double u, double kH, double kV, double zs, double H, double x, double y,
                        double z)
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
    const double xs = 210, ys = 0, zs = 55; // a cell centre
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

    // Largest deviations measured: Gaussian 0.83 %, the slender-plume error
    // ~ K_H/(u x) of dropping the along-wind diffusion (<= 0.8 % at 610 m
    // for K_H = 10, u = 2); Eulerian 2.03 %, the 2nd-order discretisation on
    // 20 x 20 x 10 m cells.  The bounds sit just above them, so a change in
    // either model that costs a few tenths of a per cent is caught.
    const double tolGaussian = 0.0085, tolEulerian = 0.021;
    double worstG = 0, worstE = 0, worstEG = 0;
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
                worstEG = std::max(worstEG, std::abs(eul / gau - 1));
                EXPECT_NEAR(gau, exact, tolGaussian * exact)
                    << "Gaussian x=" << x << " y=" << y << " z=" << z;
                EXPECT_NEAR(eul, exact, tolEulerian * exact)
                    << "Eulerian x=" << x << " y=" << y << " z=" << z;
                // the two errors may add, never more
                EXPECT_NEAR(eul, gau, (tolGaussian + tolEulerian) * gau)
                    << "x=" << x << " y=" << y << " z=" << z;
            }
    std::printf("largest deviation from the exact solution: Gaussian %.2f %%, Eulerian %.2f %%; "
                "Eulerian from Gaussian %.2f %%\n",
                100 * worstG, 100 * worstE, 100 * worstEG);
}

namespace
{

// The slender-plume problem with the point source placed by
// distributeSources; concentrations at `receptors` (x, y, height) after 1800 s.
std::vector<double> pointSourceRun(const TerrainGrid& g, const std::vector<std::array<double, 3>>& receptors)
{
    const double u = 2.0, kH = 10.0, kV = 2.0;
    WindModel wind(g, 0.0, 10.0);
    Transport t(g, kH, kV);
    t.setFlow(wind.flow(u, 270.0));
    Source s;
    s.name = "S";
    s.type = Source::Type::Point;
    s.x = 210;
    s.y = 0;
    s.height = 55;
    s.rate = 1e-3;
    t.setSources(distributeSources(g, {s}, 0.0));
    const int steps = static_cast<int>(std::ceil(1800.0 / (0.9 * t.stableDt())));
    for (int n = 0; n < steps; ++n) t.step(1800.0 / steps);
    std::vector<double> c;
    for (const auto& r : receptors) c.push_back(t.sample(r[0], r[1], r[2]));
    return c;
}

} // namespace

// The same point source (210, 0, 55) m on two grids of 20 x 20 x 10 m cells:
// on grid A it sits at a cell centre, on grid B -- shifted by half a cell in
// x, y and z (a 5 m ground cell under the 10 m cells) -- on a corner of eight
// cells.  Placed in the cell that contains it, the source moved by half a
// cell on grid B (to 220, 10, 60 m), a first-order error: up to 56 % at
// these receptors, about -13 % at the ground 1 km downwind (exp(-(60^2 -
// 55^2) / (2 sigma_z^2)), sigma_z^2 = 2 K_V x/u).  Spread by trilinear weights it keeps
// its position, and what is left is second order, the spread itself: on grid
// B the source is the mean of eight point sources at (210 +- 10, 0 +- 10,
// 55 +- 5) m.  So
//  - grid B must match the mean of those eight exact solutions as closely as
//    grid A matches the exact one (2.1 %, the bound of the test above: same
//    scheme, same cell size; measured 1.1 % and 2.0 %);
//  - beyond 800 m, where the added variance (dz^2/4 = 25 m^2 against
//    sigma_z^2 >= 1600 m^2, dx^2/4 = 100 m^2 against sigma_y^2 >= 8000 m^2)
//    changes the exact values by at most 1.3 %, the two grids must agree to
//    2.5 % outright (that plus the grids' discretisation errors, which differ
//    in sign; measured 2.3 %).  At 400 m the spread alone is worth 3.7 %.
TEST(SlenderPlume, PointSourceResultDoesNotDependOnWhereTheFacesFall)
{
    const double H = 200.0;
    const TerrainGrid a = TerrainGrid::box(100, 31, 20, 0.0, -310.0, 20.0, 20.0, H);
    TerrainGrid b = TerrainGrid::box(101, 32, 21, -10.0, -320.0, 20.0, 20.0, H);
    // faces 0, 5, 15, ..., 195, 200 m: the 10 m cells of grid A shifted by 5 m
    for (int k = 1; k < b.nz; ++k) b.fFace[k] = (5.0 + 10.0 * (k - 1)) / H;
    for (int k = 0; k < b.nz; ++k) b.fCell[k] = 0.5 * (b.fFace[k] + b.fFace[k + 1]);
    ASSERT_NEAR(b.xc(10) + 0.5 * b.dx, 210.0, 1e-9); // the source on faces of grid B
    ASSERT_NEAR(b.yc(15) + 0.5 * b.dy, 0.0, 1e-9);
    ASSERT_NEAR(H * b.fFace[6], 55.0, 1e-9);
    ASSERT_NEAR(a.zc(10, 15, 5), 55.0, 1e-9); // and at a centre of grid A

    std::vector<std::array<double, 3>> receptors;
    for (double x : {610.0, 1010.0, 1510.0})
        for (double y : {0.0, 60.0})
            for (double z : {5.0, 55.0}) receptors.push_back({x, y, z});
    const auto ca = pointSourceRun(a, receptors), cb = pointSourceRun(b, receptors);
    auto exact = [&](const std::array<double, 3>& r, double xs, double ys, double zs) {
        return exactPointSource(1e-3, 2.0, 10.0, 2.0, zs, H, r[0] - xs, r[1] - ys, r[2]);
    };
    double worstFar = 0, worstB = 0;
    for (std::size_t n = 0; n < receptors.size(); ++n)
    {
        const auto& r = receptors[n];
        const double point = exact(r, 210, 0, 55);
        double spread = 0;
        for (double dx : {-10.0, 10.0})
            for (double dy : {-10.0, 10.0})
                for (double dz : {-5.0, 5.0}) spread += exact(r, 210 + dx, dy, 55 + dz) / 8;
        const std::string at =
            "x=" + std::to_string(r[0]) + " y=" + std::to_string(r[1]) + " z=" + std::to_string(r[2]);
        EXPECT_NEAR(ca[n], point, 0.021 * point) << "grid A " << at;
        EXPECT_NEAR(cb[n], spread, 0.021 * spread) << "grid B " << at;
        worstB = std::max(worstB, std::abs(cb[n] / spread - 1));
        if (r[0] - 210 >= 800)
        {
            EXPECT_NEAR(cb[n], ca[n], 0.025 * ca[n]) << at;
            worstFar = std::max(worstFar, std::abs(cb[n] / ca[n] - 1));
        }
    }
    std::printf("point source on faces: %.2f %% from its exact solution; beyond 800 m %.2f %% from the "
                "same source at a cell centre\n",
                100 * worstB, 100 * worstFar);
}

namespace
{

// 3D run of a box source [200,240] x [-40,0] x [40,60] m (faces of both grids)
// with QUICK; relative L2 error against the exact solution integrated over
// the box (Gauss-Legendre 3x3x3) on the cells with 600 <= x <= 1500.
double error3D(int refine)
{
    const double u = 2.0, kH = 10.0, kV = 2.0, q = 1e-3, H = 200.0;
    const double dx = 40.0 / refine, dz = 20.0 / refine;
    TerrainGrid g = TerrainGrid::box(50 * refine, 16 * refine, 10 * refine, 0.0, -320.0, dx, dx, H);
    WindModel wind(g, 0.0, 10.0);
    Transport t(g, kH, kV, Advection::Quick);
    t.setFlow(wind.flow(u, 270.0));
    std::vector<double> src(g.size(), 0.0);
    double vol = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (g.xc(i) > 200 && g.xc(i) < 240 && g.yc(j) > -40 && g.yc(j) < 0 && g.zc(i, j, k) > 40
                    && g.zc(i, j, k) < 60)
                {
                    src[g.idx(i, j, k)] = 1;
                    vol += g.volume(i, j, k);
                }
    EXPECT_NEAR(vol, 40.0 * 40.0 * 20.0, 1e-6);
    for (auto& v : src) v *= q / (40.0 * 40.0 * 20.0) * (dx * dx * dz);
    t.setSources(src);
    const double dt = 0.9 * t.stableDt();
    const int steps = static_cast<int>(std::ceil(1800.0 / dt));
    for (int n = 0; n < steps; ++n) t.step(1800.0 / steps);
    const double gp[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double num = 0, den = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
            {
                const double x = g.xc(i), y = g.yc(j), z = g.zc(i, j, k);
                if (x < 600 || x > 1500) continue;
                double e = 0;
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        for (int c = 0; c < 3; ++c)
                        {
                            const double xs = 220 + 20 * gp[a], ys = -20 + 20 * gp[b], zs = 50 + 10 * gp[c];
                            e += gw[a] * gw[b] * gw[c] / 8
                                 * exactPointSource(q, u, kH, kV, zs, H, x - xs, y - ys, z);
                        }
                num += (t.c[g.idx(i, j, k)] - e) * (t.c[g.idx(i, j, k)] - e);
                den += e * e;
            }
    return std::sqrt(num / den);
}

} // namespace

TEST(SlenderPlume, PointSource3DConvergesUnderRefinement)
{
    const double e1 = error3D(1), e2 = error3D(2);
    const double p = std::log2(e1 / e2);
    std::printf("3D box source, QUICK: relative L2 errors %.3e (40 m), %.3e (20 m); observed order %.2f\n",
                e1, e2, p);
    // measured: 6.52e-2, 1.47e-2, order 2.15 (README); two coarse grids are
    // pre-asymptotic, so the order is held to 2 +- 0.25 and the fine error
    // to what it reaches
    EXPECT_NEAR(p, 2.0, 0.25);
    EXPECT_LT(e2, 0.016);
}
