// plumeBench: speed and accuracy of the Eulerian transport solver on the
// verification problem of the tests (steady line source in a uniform wind
// between a ground and a lid, K = 0.1, u = 1, x in [-2, 12], z in [0, 8],
// source box [0, 0.2] x [4, 4.2]).  Prints cell updates per second and the
// relative L2 error against the exact solution over 3 <= x <= 10.  With
// --evaluate FILE it scores another solver's field ("x z C" per line) the
// same way (used by bench/plume/scalarTransportBench for OpenFOAM).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/Csv.hpp"
#include "plume/Eulerian.hpp"

using namespace procsim::plume;

namespace
{

const double U = 1.0, K = 0.1, Q = 1.0, ZS = 4.1, XS = 0.1, H = 8.0, B = 0.2, XMIN = -2, XMAX = 12;

double lineSource(double x, double z)
{
    const double r = std::hypot(x, z);
    return Q / (2 * M_PI * K) * std::exp(U * x / (2 * K)) * std::cyl_bessel_k(0.0, U * r / (2 * K));
}

double exact(double x, double z)
{
    const double gp[4] = {-0.861136311594053, -0.339981043584856, 0.339981043584856, 0.861136311594053};
    const double gw[4] = {0.347854845137454, 0.652145154862546, 0.652145154862546, 0.347854845137454};
    double s = 0;
    for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c)
        {
            const double xs = XS + 0.5 * B * gp[a], z0 = ZS + 0.5 * B * gp[c], w = gw[a] * gw[c] / 4;
            for (int n = -3; n <= 3; ++n)
                s +=
                    w * (lineSource(x - xs, z - (2 * n * H + z0)) + lineSource(x - xs, z - (2 * n * H - z0)));
        }
    return s;
}

struct Score
{
    double num = 0, den = 0;
    void add(double x, double z, double c)
    {
        if (x < 3 || x > 10) return;
        const double e = exact(x, z);
        num += (c - e) * (c - e);
        den += e * e;
    }
    double error() const { return std::sqrt(num / den); }
};

int usage()
{
    std::cerr
        << "usage: plumeBench [--h H] [--dt DT] [--t-end T] [--scheme limited_quick|quick|upwind] [--write FILE]\n"
           "       plumeBench --evaluate FILE\n";
    return 2;
}

} // namespace

int main(int argc, char** argv)
{
    double h = 0.05, dt = 0, tEnd = 20;
    Advection scheme = Advection::LimitedQuick;
    std::string write, evaluate;
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        if (a + 1 >= argc && arg != "-h" && arg != "--help") return usage();
        if (arg == "--h")
            h = std::stod(argv[++a]);
        else if (arg == "--dt")
            dt = std::stod(argv[++a]);
        else if (arg == "--t-end")
            tEnd = std::stod(argv[++a]);
        else if (arg == "--write")
            write = argv[++a];
        else if (arg == "--evaluate")
            evaluate = argv[++a];
        else if (arg == "--scheme")
        {
            const std::string s = argv[++a];
            scheme = s == "quick"    ? Advection::Quick
                     : s == "upwind" ? Advection::Upwind
                                     : Advection::LimitedQuick;
        }
        else
            return usage();
    }
    if (!evaluate.empty())
    {
        std::ifstream in(evaluate);
        if (!in)
        {
            std::cerr << "plumeBench: cannot read " << evaluate << '\n';
            return 1;
        }
        Score s;
        double x, z, c;
        long n = 0;
        while (in >> x >> z >> c)
        {
            s.add(x, z, c);
            ++n;
        }
        std::printf("evaluated %ld cells: relative L2 error %.4e\n", n, s.error());
        return 0;
    }
    const int nx = static_cast<int>(std::lround((XMAX - XMIN) / h)),
              nz = static_cast<int>(std::lround(H / h));
    TerrainGrid g = TerrainGrid::box(nx, 1, nz, XMIN, 0.0, h, 1.0, H);
    WindModel wind(g, 0.0, 10.0);
    Transport t(g, K, K, scheme);
    t.setFlow(wind.flow(U, 270.0));
    std::vector<double> src(g.size(), 0.0);
    double cells = 0;
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i)
            if (std::abs(g.xc(i) - XS) < 0.5 * B && std::abs(g.zc(i, 0, k) - ZS) < 0.5 * B)
            {
                src[g.idx(i, 0, k)] = 1;
                cells += 1;
            }
    for (auto& v : src) v *= Q / cells;
    t.setSources(src);
    const double limit = t.stableDt();
    if (dt <= 0) dt = 0.9 * limit;
    if (dt > limit)
    {
        std::fprintf(stderr, "plumeBench: dt %g above the stability limit %g\n", dt, limit);
        return 1;
    }
    const long steps = static_cast<long>(std::ceil(tEnd / dt - 1e-9));
    dt = tEnd / steps;
    const auto t0 = std::chrono::steady_clock::now();
    for (long n = 0; n < steps; ++n) t.step(dt);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Score s;
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) s.add(g.xc(i), g.zc(i, 0, k), t.c[g.idx(i, 0, k)]);
    if (!write.empty())
    {
        procsim::OutputFile file(write);
        std::ostream& out = file.out();
        out.precision(12);
        for (int k = 0; k < nz; ++k)
            for (int i = 0; i < nx; ++i)
                out << g.xc(i) << ' ' << g.zc(i, 0, k) << ' ' << t.c[g.idx(i, 0, k)] << '\n';
        file.close();
    }
    std::printf("grid %d x %d (h = %g), %ld steps of %.6g s (limit %.6g s), wall %.3f s, "
                "%.1f million cell-updates/s, relative L2 error %.4e\n",
                nx, nz, h, steps, dt, limit, wall, static_cast<double>(nx) * nz * steps / wall / 1e6,
                s.error());
    return 0;
}
