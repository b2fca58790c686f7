#include "plume/Eulerian.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace procsim::plume
{

double stretch(double s, double beta)
{
    if (std::abs(beta) < 1e-9) return s;
    return std::expm1(beta * s) / std::expm1(beta);
}

void TerrainGrid::build()
{
    if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("grid needs nx, ny, nz >= 1");
    fFace.resize(nz + 1);
    fCell.resize(nz);
    for (int k = 0; k <= nz; ++k) fFace[k] = stretch(static_cast<double>(k) / nz, beta);
    for (int k = 0; k < nz; ++k) fCell[k] = stretch((k + 0.5) / nz, beta);
    for (double h : hc)
        if (!(zTop > h)) throw std::invalid_argument("model top below the terrain");
}

TerrainGrid TerrainGrid::box(int nx, int ny, int nz, double x0, double y0, double dx, double dy, double zTop,
                             double elevation)
{
    return TerrainGrid(nx, ny, nz, x0, y0, dx, dy, zTop, 0.0,
                       [elevation](double, double) { return elevation; });
}

Flow Flow::zero(const TerrainGrid& g)
{
    Flow f;
    f.fx.assign(static_cast<std::size_t>(g.nx + 1) * g.ny * g.nz, 0.0);
    f.fy.assign(static_cast<std::size_t>(g.nx) * (g.ny + 1) * g.nz, 0.0);
    f.fs.assign(static_cast<std::size_t>(g.nx) * g.ny * (g.nz + 1), 0.0);
    return f;
}

// ---------------------------------------------------------------- wind ----

struct WindModel::Impl
{
    std::vector<double> tx; // (nx+1)*ny  column conductances of x faces
    std::vector<double> ty; // nx*(ny+1)
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
};

WindModel::WindModel(const TerrainGrid& g, double exponent, double zRef)
    : g_(g), p_(exponent), zRef_(zRef), impl_(std::make_shared<Impl>())
{
    const int nx = g.nx, ny = g.ny;
    impl_->tx.resize(static_cast<std::size_t>(nx + 1) * ny);
    impl_->ty.resize(static_cast<std::size_t>(nx) * (ny + 1));
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i <= nx; ++i)
        {
            const double d = g.zTop - g.hxf[j * (nx + 1) + i];
            const double dist = (i == 0 || i == nx) ? 0.5 * g.dx : g.dx;
            impl_->tx[j * (nx + 1) + i] = d * g.dy / dist;
        }
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const double d = g.zTop - g.hyf[j * nx + i];
            const double dist = (j == 0 || j == ny) ? 0.5 * g.dy : g.dy;
            impl_->ty[j * nx + i] = d * g.dx / dist;
        }
    std::vector<Eigen::Triplet<double>> t;
    auto id = [nx](int i, int j) { return j * nx + i; };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const double tw = impl_->tx[j * (nx + 1) + i], te = impl_->tx[j * (nx + 1) + i + 1];
            const double ts = impl_->ty[j * nx + i], tn = impl_->ty[(j + 1) * nx + i];
            t.emplace_back(id(i, j), id(i, j), tw + te + ts + tn);
            if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -tw);
            if (i < nx - 1) t.emplace_back(id(i, j), id(i + 1, j), -te);
            if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -ts);
            if (j < ny - 1) t.emplace_back(id(i, j), id(i, j + 1), -tn);
        }
    Eigen::SparseMatrix<double> a(nx * ny, nx * ny);
    a.setFromTriplets(t.begin(), t.end());
    impl_->solver.compute(a);
    if (impl_->solver.info() != Eigen::Success)
        throw std::runtime_error("wind adjustment: factorisation failed");
}

Flow WindModel::flow(double speedRef, double directionFromDeg) const
{
    const TerrainGrid& g = g_;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    Flow f = Flow::zero(g);
    const double th = directionFromDeg * M_PI / 180.0;
    const double ex = -std::sin(th), ey = -std::cos(th); // direction the air moves to
    const double p = p_, zr = zRef_;
    // integral of U(z') dz' from 0 to a
    auto cum = [&](double a) { return speedRef * zr / (p + 1) * std::pow(a / zr, p + 1); };

    std::vector<double> mx(static_cast<std::size_t>(nx + 1) * ny, 0.0);
    std::vector<double> my(static_cast<std::size_t>(nx) * (ny + 1), 0.0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i <= nx; ++i)
        {
            const double d = g.zTop - g.hxf[j * (nx + 1) + i];
            double sum = 0;
            for (int k = 0; k < nz; ++k)
            {
                const double q = ex * g.dy * (cum(d * g.fFace[k + 1]) - cum(d * g.fFace[k]));
                f.fx[(static_cast<std::size_t>(k) * ny + j) * (nx + 1) + i] = q;
                sum += q;
            }
            mx[j * (nx + 1) + i] = sum;
        }
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const double d = g.zTop - g.hyf[j * nx + i];
            double sum = 0;
            for (int k = 0; k < nz; ++k)
            {
                const double q = ey * g.dx * (cum(d * g.fFace[k + 1]) - cum(d * g.fFace[k]));
                f.fy[(static_cast<std::size_t>(k) * (ny + 1) + j) * nx + i] = q;
                sum += q;
            }
            my[j * nx + i] = sum;
        }
    // column divergence and the potential correction
    Eigen::VectorXd div(nx * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            div[j * nx + i] =
                mx[j * (nx + 1) + i + 1] - mx[j * (nx + 1) + i] + my[(j + 1) * nx + i] - my[j * nx + i];
    const Eigen::VectorXd lam = impl_->solver.solve(div);
    auto L = [&](int i, int j) { return (i < 0 || i >= nx || j < 0 || j >= ny) ? 0.0 : lam[j * nx + i]; };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i <= nx; ++i)
        {
            const double dm = impl_->tx[j * (nx + 1) + i] * (L(i, j) - L(i - 1, j));
            for (int k = 0; k < nz; ++k)
                f.fx[(static_cast<std::size_t>(k) * ny + j) * (nx + 1) + i] +=
                    dm * (g.fFace[k + 1] - g.fFace[k]);
        }
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const double dm = impl_->ty[j * nx + i] * (L(i, j) - L(i, j - 1));
            for (int k = 0; k < nz; ++k)
                f.fy[(static_cast<std::size_t>(k) * (ny + 1) + j) * nx + i] +=
                    dm * (g.fFace[k + 1] - g.fFace[k]);
        }
    // flux through the s-surfaces from continuity, ground up
    double top = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            double w = 0;
            for (int k = 0; k < nz; ++k)
            {
                const std::size_t ix = (static_cast<std::size_t>(k) * ny + j) * (nx + 1) + i;
                const std::size_t iy = (static_cast<std::size_t>(k) * (ny + 1) + j) * nx + i;
                w -= f.fx[ix + 1] - f.fx[ix] + f.fy[iy + nx] - f.fy[iy];
                f.fs[(static_cast<std::size_t>(k + 1) * ny + j) * nx + i] = w;
            }
            top = std::max(top, std::abs(w));
        }
    f.maxTopFlux = top;
    return f;
}

// ----------------------------------------------------------- transport ----

Transport::Transport(const TerrainGrid& g, double kH, double kV, Advection scheme, bool trueHorizontal)
    : g_(g), kH_(kH), kV_(kV), scheme_(scheme), trueHorizontal_(trueHorizontal)
{
    const double cross = trueHorizontal ? 1.0 : 0.0;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    const std::size_t n = g.size();
    c.assign(n, 0.0);
    src_.assign(n, 0.0);
    vol_.resize(n);
    r_.assign(n, 0.0);
    rPrev_.assign(n, 0.0);
    gz_.assign(n, 0.0);
    gxs_.assign(n, 0.0);
    gys_.assign(n, 0.0);
    flow_ = Flow::zero(g);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) vol_[g.idx(i, j, k)] = g.volume(i, j, k);

    axF_.assign(flow_.fx.size(), 0.0);
    bxF_.assign(flow_.fx.size(), 0.0);
    ayF_.assign(flow_.fy.size(), 0.0);
    byF_.assign(flow_.fy.size(), 0.0);
    asF_.assign(flow_.fs.size(), 0.0);
    bsxF_.assign(flow_.fs.size(), 0.0);
    bsyF_.assign(flow_.fs.size(), 0.0);
    for (int k = 0; k < nz; ++k)
    {
        const double dfk = g.fFace[k + 1] - g.fFace[k];
        for (int j = 0; j < ny; ++j)
            for (int i = 1; i < nx; ++i)
            {
                const std::size_t f = (static_cast<std::size_t>(k) * ny + j) * (nx + 1) + i;
                const double area = g.dy * (g.zTop - g.hxf[j * (nx + 1) + i]) * dfk;
                const double zx = (g.zc(i, j, k) - g.zc(i - 1, j, k)) / g.dx;
                axF_[f] = kH * area / g.dx;
                bxF_[f] = cross * kH * area * zx;
            }
        for (int j = 1; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t f = (static_cast<std::size_t>(k) * (ny + 1) + j) * nx + i;
                const double area = g.dx * (g.zTop - g.hyf[j * nx + i]) * dfk;
                const double zy = (g.zc(i, j, k) - g.zc(i, j - 1, k)) / g.dy;
                ayF_[f] = kH * area / g.dy;
                byF_[f] = cross * kH * area * zy;
            }
    }
    for (int k = 1; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t f = (static_cast<std::size_t>(k) * ny + j) * nx + i;
                const double hx = (g.hxf[j * (nx + 1) + i + 1] - g.hxf[j * (nx + 1) + i]) / g.dx;
                const double hy = (g.hyf[(j + 1) * nx + i] - g.hyf[j * nx + i]) / g.dy;
                const double zx = hx * (1 - g.fFace[k]);
                const double zy = hy * (1 - g.fFace[k]);
                const double area = g.dx * g.dy;
                const double dz = g.zc(i, j, k) - g.zc(i, j, k - 1);
                asF_[f] = area * (kV + cross * kH * (zx * zx + zy * zy)) / dz;
                bsxF_[f] = cross * area * kH * zx;
                bsyF_[f] = cross * area * kH * zy;
            }
}

void Transport::setImplicitVertical(bool on)
{
    if (on && trueHorizontal_ && kH_ > 0)
    {
        bool flat = true;
        for (std::size_t n = 0; n < bxF_.size() && flat; ++n) flat = bxF_[n] == 0.0;
        for (std::size_t n = 0; n < byF_.size() && flat; ++n) flat = byF_[n] == 0.0;
        if (!flat)
            throw std::invalid_argument(
                "true-horizontal diffusion over terrain needs the explicit vertical term");
    }
    implicit_ = on;
}

void Transport::setFlow(const Flow& flow)
{
    if (flow.fx.size() != flow_.fx.size() || flow.fy.size() != flow_.fy.size()
        || flow.fs.size() != flow_.fs.size())
        throw std::invalid_argument("flow does not match the grid");
    flow_ = flow;
}

void Transport::setSources(std::vector<double> kgPerS)
{
    if (kgPerS.size() != g_.size()) throw std::invalid_argument("sources do not match the grid");
    src_ = std::move(kgPerS);
}

double Transport::mass() const
{
    double m = 0;
    for (std::size_t n = 0; n < c.size(); ++n) m += c[n] * vol_[n];
    return m;
}

double Transport::stableDt() const
{
    const TerrainGrid& g = g_;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    double rate = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const double dz = g.depth(i, j) * (g.fFace[k + 1] - g.fFace[k]);
                const double hx = (g.hxf[j * (nx + 1) + i + 1] - g.hxf[j * (nx + 1) + i]) / g.dx;
                const double hy = (g.hyf[(j + 1) * nx + i] - g.hyf[j * nx + i]) / g.dy;
                const double slope2 =
                    trueHorizontal_ ? (hx * hx + hy * hy) * (1 - g.fCell[k]) * (1 - g.fCell[k]) : 0.0;
                double diff = 0;
                if (nx > 1) diff += kH_ / (g.dx * g.dx);
                if (ny > 1) diff += kH_ / (g.dy * g.dy);
                if (nz > 1 && !implicit_) diff += (kV_ + kH_ * slope2) / (dz * dz);
                const std::size_t ix = (static_cast<std::size_t>(k) * ny + j) * (nx + 1) + i;
                const std::size_t iy = (static_cast<std::size_t>(k) * (ny + 1) + j) * nx + i;
                const std::size_t is = (static_cast<std::size_t>(k) * ny + j) * nx + i;
                const double adv = (std::abs(flow_.fx[ix]) + std::abs(flow_.fx[ix + 1])
                                    + std::abs(flow_.fy[iy]) + std::abs(flow_.fy[iy + nx])
                                    + std::abs(flow_.fs[is]) + std::abs(flow_.fs[is + nx * ny]))
                                   / vol_[g.idx(i, j, k)];
                rate = std::max(rate, 4 * diff + adv);
            }
    return rate > 0 ? 1.0 / rate : 1e300;
}

namespace
{

// Face value on the side of the upwind cell C, with U the cell upwind of C
// and D the cell downwind.  QUICK is phi_f = 6/8 C + 3/8 D - 1/8 U, i.e. in
// flux-limiter form phi_f = C + psi(r)/2 (D - C) with psi = (3 + r)/4 and
// r = (C - U)/(D - C).  The limited scheme keeps QUICK where it is inside
// Sweby's TVD region and clips it to it elsewhere:
//     psi = max(0, min(2r, (3 + r)/4, 2)),
// which is QUICK itself for 3/7 <= r <= 5 (smooth monotone profiles keep
// its accuracy) and falls back to upwind at extrema (r <= 0), so advection
// creates no negative concentrations and no new extrema.
inline double faceValue(Advection s, double u, double cc, double d)
{
    if (s == Advection::Upwind) return cc;
    if (s == Advection::Quick) return 0.75 * cc + 0.375 * d - 0.125 * u;
    const double den = d - cc;
    const double num = cc - u;
    if (den == 0.0) return cc;
    const double r = num / den;
    if (r <= 0) return cc;
    const double psi = std::min({2 * r, 0.75 + 0.25 * r, 2.0});
    return cc + 0.5 * psi * den;
}

} // namespace

// Cell gradients of C for the cross-diffusion terms of the transform: dC/dz
// along the column, dC/dx and dC/dy along the terrain-following surface
// (central differences, one-sided at the boundaries; unused, and not
// computed, when K_H acts along the terrain).
void Transport::crossTermGradients()
{
    const TerrainGrid& g = g_;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t n = g.idx(i, j, k);
                const int kl = std::max(k - 1, 0), ku = std::min(k + 1, nz - 1);
                gz_[n] = ku > kl
                             ? (c[g.idx(i, j, ku)] - c[g.idx(i, j, kl)]) / (g.zc(i, j, ku) - g.zc(i, j, kl))
                             : 0.0;
                const int il = std::max(i - 1, 0), iu = std::min(i + 1, nx - 1);
                gxs_[n] = iu > il ? (c[g.idx(iu, j, k)] - c[g.idx(il, j, k)]) / ((iu - il) * g.dx) : 0.0;
                const int jl = std::max(j - 1, 0), ju = std::min(j + 1, ny - 1);
                gys_[n] = ju > jl ? (c[g.idx(i, ju, k)] - c[g.idx(i, jl, k)]) / ((ju - jl) * g.dy) : 0.0;
            }
}

// Fluxes through the x faces: advection (QUICK face values, the background
// flowing in at the west and east boundaries) and K_H diffusion with its
// cross term; what leaves the domain is added to `out`.
void Transport::xFaceFluxes(std::vector<double>& r, double& out) const
{
    const TerrainGrid& g = g_;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    const double bg = background_;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
        {
            const std::size_t row = (static_cast<std::size_t>(k) * ny + j) * nx;
            const double* cr = &c[row];
            double* rr = &r[row];
            const std::size_t frow = (static_cast<std::size_t>(k) * ny + j) * (nx + 1);
            for (int i = 0; i <= nx; ++i)
            {
                const double F = flow_.fx[frow + i];
                double phi;
                if (i == 0)
                {
                    phi = F * (F > 0 ? bg : cr[0]);
                    out -= phi;
                    rr[0] += phi;
                    continue;
                }
                if (i == nx)
                {
                    phi = F * (F > 0 ? cr[nx - 1] : bg);
                    out += phi;
                    rr[nx - 1] -= phi;
                    continue;
                }
                double cf;
                if (F >= 0)
                    cf = faceValue(scheme_, i >= 2 ? cr[i - 2] : cr[i - 1], cr[i - 1], cr[i]);
                else
                    cf = faceValue(scheme_, i + 1 < nx ? cr[i + 1] : cr[i], cr[i], cr[i - 1]);
                phi = F * cf - axF_[frow + i] * (cr[i] - cr[i - 1])
                      + bxF_[frow + i] * 0.5 * (gz_[row + i] + gz_[row + i - 1]);
                rr[i - 1] -= phi;
                rr[i] += phi;
            }
        }
}

// Fluxes through the y faces, as for x (south and north boundaries).
void Transport::yFaceFluxes(std::vector<double>& r, double& out) const
{
    const TerrainGrid& g = g_;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    const double bg = background_;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j <= ny; ++j)
        {
            const std::size_t frow = (static_cast<std::size_t>(k) * (ny + 1) + j) * nx;
            for (int i = 0; i < nx; ++i)
            {
                const double F = flow_.fy[frow + i];
                double phi;
                if (j == 0)
                {
                    const std::size_t n = g.idx(i, 0, k);
                    phi = F * (F > 0 ? bg : c[n]);
                    out -= phi;
                    r[n] += phi;
                    continue;
                }
                const std::size_t nR = g.idx(i, std::min(j, ny - 1), k);
                const std::size_t nL = g.idx(i, j - 1, k);
                if (j == ny)
                {
                    phi = F * (F > 0 ? c[nL] : bg);
                    out += phi;
                    r[nL] -= phi;
                    continue;
                }
                double cf;
                if (F >= 0)
                    cf = faceValue(scheme_, j >= 2 ? c[nL - nx] : c[nL], c[nL], c[nR]);
                else
                    cf = faceValue(scheme_, j + 1 < ny ? c[nR + nx] : c[nR], c[nR], c[nL]);
                phi = F * cf - ayF_[frow + i] * (c[nR] - c[nL]) + byF_[frow + i] * 0.5 * (gz_[nR] + gz_[nL]);
                r[nL] -= phi;
                r[nR] += phi;
            }
        }
}

// Fluxes through the s faces: vertical advection, K_V diffusion (left to the
// Crank-Nicolson step when implicit) and the cross terms; no flux through
// the ground (k = 0), open at the top.
void Transport::sFaceFluxes(std::vector<double>& r, double& out) const
{
    const TerrainGrid& g = g_;
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    const std::size_t nxy = static_cast<std::size_t>(nx) * ny;
    const double bg = background_;
    for (int k = 1; k <= nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t f = (static_cast<std::size_t>(k) * ny + j) * nx + i;
                const double F = flow_.fs[f];
                const std::size_t nL = g.idx(i, j, k - 1);
                double phi;
                if (k == nz)
                {
                    phi = F * (F > 0 ? c[nL] : bg);
                    out += phi;
                    r[nL] -= phi;
                    continue;
                }
                const std::size_t nR = nL + nxy;
                double cf;
                if (F >= 0)
                    cf = faceValue(scheme_, k >= 2 ? c[nL - nxy] : c[nL], c[nL], c[nR]);
                else
                    cf = faceValue(scheme_, k + 1 < nz ? c[nR + nxy] : c[nR], c[nR], c[nL]);
                phi = F * cf - (implicit_ ? 0.0 : asF_[f]) * (c[nR] - c[nL])
                      + bsxF_[f] * 0.5 * (gxs_[nL] + gxs_[nR]) + bsyF_[f] * 0.5 * (gys_[nL] + gys_[nR]);
                r[nL] -= phi;
                r[nR] += phi;
            }
}

// dM/dt of every cell: its sources plus the net flux through its faces.
void Transport::residual(std::vector<double>& r)
{
    for (std::size_t n = 0; n < r.size(); ++n) r[n] = src_[n];
    if (trueHorizontal_) crossTermGradients();
    double out = 0; // through the open boundaries
    xFaceFluxes(r, out);
    yFaceFluxes(r, out);
    sFaceFluxes(r, out);
    lastOut_ = out;
}

void Transport::step(double dt)
{
    residual(r_);
    const double outPrev = prevOut_;
    const double wNew = first_ ? 1.0 : 1.5, wOld = first_ ? 0.0 : -0.5;
    if (!implicit_)
    {
        for (std::size_t n = 0; n < c.size(); ++n) c[n] += dt * (wNew * r_[n] + wOld * rPrev_[n]) / vol_[n];
    }
    else
    {
        // Crank-Nicolson for the vertical diffusion, column by column:
        //  (V/dt) C' - 1/2 I(C') = (V/dt) C + AB2(R) + 1/2 I(C)
        const TerrainGrid& g = g_;
        const int nz = g.nz;
        const std::size_t nxy = static_cast<std::size_t>(g.nx) * g.ny;
        rhsCol_.resize(nz);
        aCol_.resize(nz);
        bCol_.resize(nz);
        cCol_.resize(nz);
        for (std::size_t col = 0; col < nxy; ++col)
        {
            for (int k = 0; k < nz; ++k)
            {
                const std::size_t n = col + k * nxy;
                const double aDn = k > 0 ? 0.5 * asF_[col + k * nxy] : 0.0;
                const double aUp = k + 1 < nz ? 0.5 * asF_[col + (k + 1) * nxy] : 0.0;
                const double vdt = vol_[n] / dt;
                double rhs = vdt * c[n] + wNew * r_[n] + wOld * rPrev_[n];
                if (k > 0) rhs += aDn * (c[n - nxy] - c[n]);
                if (k + 1 < nz) rhs += aUp * (c[n + nxy] - c[n]);
                aCol_[k] = -aDn;
                bCol_[k] = vdt + aDn + aUp;
                cCol_[k] = -aUp;
                rhsCol_[k] = rhs;
            }
            // Thomas algorithm (diagonally dominant)
            for (int k = 1; k < nz; ++k)
            {
                const double m = aCol_[k] / bCol_[k - 1];
                bCol_[k] -= m * cCol_[k - 1];
                rhsCol_[k] -= m * rhsCol_[k - 1];
            }
            rhsCol_[nz - 1] /= bCol_[nz - 1];
            for (int k = nz - 2; k >= 0; --k)
                rhsCol_[k] = (rhsCol_[k] - cCol_[k] * rhsCol_[k + 1]) / bCol_[k];
            for (int k = 0; k < nz; ++k) c[col + k * nxy] = rhsCol_[k];
        }
    }
    outflow_ += dt * (wNew * lastOut_ + wOld * outPrev);
    first_ = false;
    prevOut_ = lastOut_;
    std::swap(r_, rPrev_);
    time_ += dt;
}

double Transport::sample(double x, double y, double hag) const
{
    const TerrainGrid& g = g_;
    double fx = (x - g.x0) / g.dx - 0.5;
    double fy = (y - g.y0) / g.dy - 0.5;
    fx = std::clamp(fx, 0.0, static_cast<double>(g.nx - 1));
    fy = std::clamp(fy, 0.0, static_cast<double>(g.ny - 1));
    const int i0 = std::min(static_cast<int>(fx), std::max(g.nx - 2, 0));
    const int j0 = std::min(static_cast<int>(fy), std::max(g.ny - 2, 0));
    const int i1 = std::min(i0 + 1, g.nx - 1), j1 = std::min(j0 + 1, g.ny - 1);
    const double a = fx - i0, b = fy - j0;
    auto column = [&](int i, int j) {
        const double d = g.depth(i, j);
        if (hag <= d * g.fCell[0]) return c[g.idx(i, j, 0)];
        for (int k = 0; k + 1 < g.nz; ++k)
        {
            const double z0 = d * g.fCell[k], z1 = d * g.fCell[k + 1];
            if (hag <= z1)
            {
                const double t = (hag - z0) / (z1 - z0);
                return (1 - t) * c[g.idx(i, j, k)] + t * c[g.idx(i, j, k + 1)];
            }
        }
        return c[g.idx(i, j, g.nz - 1)];
    };
    return (1 - a) * (1 - b) * column(i0, j0) + a * (1 - b) * column(i1, j0) + (1 - a) * b * column(i0, j1)
           + a * b * column(i1, j1);
}

} // namespace procsim::plume
