// Eulerian transport in terrain-following coordinates: checks against the
// analytic solution, conservation, the mass-consistent wind, flat terrain.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plume/Eulerian.hpp"

using namespace procsim::plume;

namespace
{

// Steady 2D line source of strength q [kg/s per m] at (xs, zs) in a uniform
// wind u with isotropic K (free space):
//     C = q / (2 pi K) exp(u (x - xs) / 2K) K0(u r / 2K).
double lineSource(double q, double u, double k, double x, double z)
{
    const double r = std::hypot(x, z);
    return q / (2 * M_PI * k) * std::exp(u * x / (2 * k)) * std::cyl_bessel_k(0.0, u * r / (2 * k));
}

// The same between a ground at z = 0 and a lid at z = H (both no-flux):
// images at 2nH +- zs.  The source is a square of side b centred at (xc, zs),
// integrated with 4x4 Gauss-Legendre points (field points are far from it).
double channelBoxSource(double q, double u, double k, double xc, double zs, double H, double b, double x,
                        double z)
{
    const double gp[4] = {-0.861136311594053, -0.339981043584856, 0.339981043584856, 0.861136311594053};
    const double gw[4] = {0.347854845137454, 0.652145154862546, 0.652145154862546, 0.347854845137454};
    double sum = 0;
    for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c)
        {
            const double xs = xc + 0.5 * b * gp[a];
            const double z0 = zs + 0.5 * b * gp[c];
            const double w = gw[a] * gw[c] / 4.0;
            for (int n = -3; n <= 3; ++n)
            {
                sum += w * lineSource(q, u, k, x - xs, z - (2 * n * H + z0));
                sum += w * lineSource(q, u, k, x - xs, z - (2 * n * H - z0));
            }
        }
    return sum;
}

struct Case2D
{
    double u = 1.0, k = 0.1, q = 1.0, zs = 4.1, H = 8.0, b = 0.2,
           xs = 0.1; // box [0,0.2]x[4,4.2] is on faces of every grid
    double xmin = -2.0, xmax = 12.0;
    Advection scheme = Advection::LimitedQuick;
    bool implicitVertical = false;
    double tEnd = 20.0; // steady to well below the discretisation error at x <= 10
};

// Runs the 2D problem (one cell across y) to steady state on cells of size h
// and returns the relative L2 error over 3 <= x <= 10.
double error2D(const Case2D& cs, double h, double* massBalance = nullptr)
{
    const int nx = static_cast<int>(std::lround((cs.xmax - cs.xmin) / h));
    const int nz = static_cast<int>(std::lround(cs.H / h));
    TerrainGrid g = TerrainGrid::box(nx, 1, nz, cs.xmin, 0.0, h, 1.0, cs.H);
    WindModel wind(g, 0.0, 10.0); // exponent 0: uniform profile
    Transport t(g, cs.k, cs.k, cs.scheme);
    t.setImplicitVertical(cs.implicitVertical);
    t.setFlow(wind.flow(cs.u, 270.0)); // from the west: along +x
    std::vector<double> src(g.size(), 0.0);
    double total = 0;
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i)
        {
            const double x = g.xc(i), z = g.zc(i, 0, k);
            if (std::abs(x - cs.xs) < 0.5 * cs.b && std::abs(z - cs.zs) < 0.5 * cs.b)
            {
                src[g.idx(i, 0, k)] = 1.0;
                total += 1.0;
            }
        }
    for (auto& s : src) s *= cs.q / total; // q per metre of y (dy = 1)
    t.setSources(src);
    const double dt = 0.9 * t.stableDt();
    const double tEnd = cs.tEnd;
    const int steps = static_cast<int>(std::ceil(tEnd / dt));
    for (int n = 0; n < steps; ++n) t.step(tEnd / steps);
    if (massBalance) *massBalance = t.mass() + t.boundaryOutflow() - cs.q * t.time();
    double num = 0, den = 0;
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i)
        {
            const double x = g.xc(i);
            if (x < 3.0 || x > 10.0) continue;
            const double exact =
                channelBoxSource(cs.q, cs.u, cs.k, cs.xs, cs.zs, cs.H, cs.b, x, g.zc(i, 0, k));
            const double e = t.c[g.idx(i, 0, k)] - exact;
            num += e * e;
            den += exact * exact;
        }
    return std::sqrt(num / den);
}

} // namespace

TEST(EulerianAnalytic, ContinuousSourceConvergesAtSecondOrderWithQuick)
{
    // Unlimited QUICK: second order in space; AB2 at 0.9 of the stability
    // limit adds a time error far below the spatial one.
    Case2D cs;
    cs.scheme = Advection::Quick;
    const double e1 = error2D(cs, 0.2), e2 = error2D(cs, 0.1), e3 = error2D(cs, 0.05);
    const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
    std::printf("QUICK: relative L2 errors h=0.2 %.3e  h=0.1 %.3e  h=0.05 %.3e; observed order %.2f, %.2f\n",
                e1, e2, e3, p1, p2);
    EXPECT_NEAR(p1, 2.0, 0.25);
    EXPECT_NEAR(p2, 2.0, 0.25);
    EXPECT_LT(e3, 1e-3);
}

TEST(EulerianAnalytic, LimitedQuickConvergesAboveFirstOrder)
{
    // The TVD limiter turns QUICK into upwind at extrema along the wind (off
    // the plume axis every height has one), so the global order drops below
    // 2 but must stay clearly above upwind's 1, with small errors.
    Case2D cs;
    const double e1 = error2D(cs, 0.2), e2 = error2D(cs, 0.1), e3 = error2D(cs, 0.05);
    const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
    std::printf(
        "limited QUICK: relative L2 errors h=0.2 %.3e  h=0.1 %.3e  h=0.05 %.3e; observed order %.2f, %.2f\n",
        e1, e2, e3, p1, p2);
    EXPECT_GT(p1, 1.3);
    EXPECT_GT(p2, 1.3);
    EXPECT_LT(e3, 1e-3);
}

TEST(EulerianAnalytic, ImplicitVerticalDiffusionKeepsSecondOrder)
{
    // IMEX: AB2 for advection and horizontal diffusion, Crank-Nicolson for
    // the vertical diffusion; the steady solution is the same scheme's, so
    // the spatial order must be unchanged.
    Case2D cs;
    cs.scheme = Advection::Quick;
    cs.implicitVertical = true;
    const double e1 = error2D(cs, 0.2), e2 = error2D(cs, 0.1);
    const double p1 = std::log2(e1 / e2);
    std::printf("QUICK + CN vertical: relative L2 errors %.3e %.3e; observed order %.2f\n", e1, e2, p1);
    EXPECT_NEAR(p1, 2.0, 0.25);
}

namespace
{

double hills(double x, double y)
{
    return 120.0 * std::exp(-((x - 400) * (x - 400) + (y - 300) * (y - 300)) / (2 * 150.0 * 150.0))
           - 40.0 * std::exp(-((x - 800) * (x - 800)) / (2 * 120.0 * 120.0)) + 0.05 * y;
}

TerrainGrid hillGrid(int nx = 14, int ny = 12, int nz = 8)
{
    return TerrainGrid(nx, ny, nz, 0.0, 0.0, 80.0, 60.0, 500.0, 2.0, hills);
}

} // namespace

TEST(EulerianConservation, ClosedBoxOnTerrainConservesMassToRoundOff)
{
    TerrainGrid g = hillGrid();
    Flow f = Flow::zero(g);
    // recirculating, discretely divergence-free flow from streamfunctions in
    // the (x, s) and (y, s) planes that vanish on the boundary: closed box
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    auto psi = [](int a, int na, int k, int nk) {
        if (a == 0 || a == na || k == 0 || k == nk) return 0.0;
        return 3.0e4 * std::sin(M_PI * a / na) * std::sin(M_PI * k / nk);
    };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i <= nx; ++i)
                f.fx[(k * ny + j) * (nx + 1) + i] = psi(i, nx, k + 1, nz) - psi(i, nx, k, nz);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i < nx; ++i)
                f.fy[(k * (ny + 1) + j) * nx + i] = 0.5 * (psi(j, ny, k + 1, nz) - psi(j, ny, k, nz));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                f.fs[(k * ny + j) * nx + i] = -(psi(i + 1, nx, k, nz) - psi(i, nx, k, nz))
                                              - 0.5 * (psi(j + 1, ny, k, nz) - psi(j, ny, k, nz));
    // full transform (explicit vertical) and along-terrain K_H (implicit vertical)
    for (bool implicit : {false, true})
    {
        Transport t(g, 200.0, 5.0, Advection::LimitedQuick, !implicit);
        t.setImplicitVertical(implicit);
        t.setFlow(f);
        std::vector<double> src(g.size(), 0.0);
        src[g.idx(3, 4, 0)] = 2.0;
        src[g.idx(9, 7, 2)] = 0.5;
        t.setSources(src);
        const double dt = 0.9 * t.stableDt();
        for (int n = 0; n < 400; ++n) t.step(dt);
        const double expected = 2.5 * t.time();
        EXPECT_EQ(t.boundaryOutflow(), 0.0);
        EXPECT_NEAR(t.mass(), expected, 1e-12 * expected) << (implicit ? "implicit" : "explicit");
    }
}

TEST(EulerianWind, AdjustedWindIsDivergenceFreeAndStopsAtTheLid)
{
    TerrainGrid g = hillGrid();
    WindModel wind(g, 0.25, 10.0);
    const Flow f = wind.flow(3.0, 225.0);
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    double scale = 0, worst = 0;
    for (double v : f.fx) scale = std::max(scale, std::abs(v));
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const double div = f.fx[(k * ny + j) * (nx + 1) + i + 1] - f.fx[(k * ny + j) * (nx + 1) + i]
                                   + f.fy[(k * (ny + 1) + j + 1) * nx + i] - f.fy[(k * (ny + 1) + j) * nx + i]
                                   + f.fs[((k + 1) * ny + j) * nx + i] - f.fs[(k * ny + j) * nx + i];
                worst = std::max(worst, std::abs(div));
            }
    EXPECT_LT(worst, 1e-12 * scale);
    EXPECT_LT(f.maxTopFlux, 1e-9 * scale);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) EXPECT_EQ(f.fs[j * nx + i], 0.0); // ground
}

TEST(EulerianWind, UniformConcentrationStaysUniformOverTerrain)
{
    // free-stream preservation: with the background equal to the field, the
    // mass-consistent wind and the transformed diffusion must not create
    // gradients
    TerrainGrid g = hillGrid();
    WindModel wind(g, 0.25, 10.0);
    for (bool implicit : {false, true})
    {
        Transport t(g, 200.0, 1.0, Advection::LimitedQuick, !implicit);
        t.setImplicitVertical(implicit);
        t.setFlow(wind.flow(4.0, 200.0));
        t.setBackground(7.0e-8);
        for (auto& v : t.c) v = 7.0e-8;
        const double dt = 0.9 * t.stableDt();
        for (int n = 0; n < 200; ++n) t.step(dt);
        for (double v : t.c) ASSERT_NEAR(v, 7.0e-8, 1e-12 * 7.0e-8);
    }
}

TEST(EulerianStability, CalmWindOverSteepTerrainStaysBoundedAtTheAutomaticStep)
{
    // The demo case's set-up (implicit vertical, K_H along the terrain) in a
    // near-calm hour, where the step is set by K_H alone: after many steps
    // the field must stay finite, essentially non-negative and balanced.
    TerrainGrid g(14, 12, 10, 0.0, 0.0, 80.0, 60.0, 400.0, 2.5, hills);
    WindModel wind(g, 0.25, 10.0);
    Transport t(g, 200.0, 1.0, Advection::LimitedQuick, false);
    t.setImplicitVertical(true);
    t.setFlow(wind.flow(0.5, 270.0));
    std::vector<double> src(g.size(), 0.0);
    src[g.idx(4, 6, 0)] = 1e-3;
    t.setSources(src);
    const double dt = 0.9 * t.stableDt();
    for (int n = 0; n < 3000; ++n) t.step(dt);
    double cmax = 0, cmin = 0;
    for (double v : t.c)
    {
        ASSERT_TRUE(std::isfinite(v));
        cmax = std::max(cmax, v);
        cmin = std::min(cmin, v);
    }
    EXPECT_GT(cmin, -1e-6 * cmax);
    const double emitted = 1e-3 * t.time();
    EXPECT_NEAR(t.mass() + t.boundaryOutflow(), emitted, 1e-11 * emitted);
}

TEST(EulerianStability, FullTransformRefusesImplicitVertical)
{
    TerrainGrid g = hillGrid();
    Transport t(g, 200.0, 1.0);
    EXPECT_THROW(t.setImplicitVertical(true), std::invalid_argument);
}

namespace
{

// Independent Cartesian reference: uniform cells, wind along +x with speed
// u[k] in layer k, explicit AB2, limited QUICK, K_H/K_V diffusion, zero-flux
// ground, lid and side walls, inflow of zero, upwind outflow.
std::vector<double> cartesianReference(int nx, int ny, int nz, double dx, double dy, double dz,
                                       const std::vector<double>& u, double kH, double kV, int si, int sj,
                                       int sk, double q, double dt, int steps)
{
    auto id = [=](int i, int j, int k) { return (static_cast<std::size_t>(k) * ny + j) * nx + i; };
    std::vector<double> c(static_cast<std::size_t>(nx) * ny * nz, 0.0), r(c.size()), rp(c.size());
    const double vol = dx * dy * dz;
    auto lim = [](double cu, double cc, double cd) {
        if (cd == cc) return cc;
        const double rr = (cc - cu) / (cd - cc);
        if (rr <= 0) return cc;
        return cc + 0.5 * std::min({2 * rr, 0.75 + 0.25 * rr, 2.0}) * (cd - cc);
    };
    for (int n = 0; n < steps; ++n)
    {
        std::fill(r.begin(), r.end(), 0.0);
        r[id(si, sj, sk)] += q;
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
            {
                const double F = u[k] * dy * dz;
                r[id(nx - 1, j, k)] -= F * c[id(nx - 1, j, k)];
                for (int i = 1; i < nx; ++i)
                {
                    const double cu = c[id(std::max(i - 2, 0), j, k)];
                    const double phi =
                        F * lim(i >= 2 ? cu : c[id(i - 1, j, k)], c[id(i - 1, j, k)], c[id(i, j, k)])
                        - kH * dy * dz / dx * (c[id(i, j, k)] - c[id(i - 1, j, k)]);
                    r[id(i - 1, j, k)] -= phi;
                    r[id(i, j, k)] += phi;
                }
                for (int i = 0; i < nx; ++i)
                {
                    if (j > 0)
                    {
                        const double phi = -kH * dx * dz / dy * (c[id(i, j, k)] - c[id(i, j - 1, k)]);
                        r[id(i, j - 1, k)] -= phi;
                        r[id(i, j, k)] += phi;
                    }
                    if (k > 0)
                    {
                        const double phi = -kV * dx * dy / dz * (c[id(i, j, k)] - c[id(i, j, k - 1)]);
                        r[id(i, j, k - 1)] -= phi;
                        r[id(i, j, k)] += phi;
                    }
                }
            }
        for (std::size_t m = 0; m < c.size(); ++m)
            c[m] += dt * (n == 0 ? r[m] : 1.5 * r[m] - 0.5 * rp[m]) / vol;
        std::swap(r, rp);
    }
    return c;
}

} // namespace

TEST(EulerianFlatTerrain, TransformEqualsCartesianScheme)
{
    const int nx = 16, ny = 9, nz = 6;
    const double dx = 50, dy = 40, depth = 300, u10 = 2.0, p = 0.25;
    for (double elevation : {0.0, 350.0})
        for (bool trueHorizontal : {true, false})
        {
            TerrainGrid g = TerrainGrid::box(nx, ny, nz, 0.0, 0.0, dx, dy, elevation + depth, elevation);
            WindModel wind(g, p, 10.0);
            Transport t(g, 30.0, 2.0, Advection::LimitedQuick, trueHorizontal);
            t.setFlow(wind.flow(u10, 270.0));
            std::vector<double> src(g.size(), 0.0);
            src[g.idx(3, 4, 1)] = 1.0;
            t.setSources(src);
            const double dt = 0.8 * t.stableDt();
            for (int n = 0; n < 150; ++n) t.step(dt);

            // layer speeds: the power law averaged over each layer, written out here
            const double dz = depth / nz;
            std::vector<double> u(nz);
            for (int k = 0; k < nz; ++k)
            {
                const double a = k * dz, b = (k + 1) * dz;
                u[k] = u10 * 10.0 / (p + 1) * (std::pow(b / 10.0, p + 1) - std::pow(a / 10.0, p + 1)) / dz;
            }
            const auto ref = cartesianReference(nx, ny, nz, dx, dy, dz, u, 30.0, 2.0, 3, 4, 1, 1.0, dt, 150);
            double cmax = 0;
            for (double v : ref) cmax = std::max(cmax, v);
            for (std::size_t m = 0; m < ref.size(); ++m) ASSERT_NEAR(t.c[m], ref[m], 1e-10 * cmax) << m;
        }
}
