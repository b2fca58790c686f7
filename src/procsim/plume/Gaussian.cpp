#include "plume/Gaussian.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace procsim::plume
{

double solarElevationDeg(double latitudeDeg, int dayOfYear, double solarHour)
{
    const double rad = M_PI / 180.0;
    const double decl = 23.45 * std::sin(2 * M_PI * (284 + dayOfYear) / 365.0); // deg (Cooper)
    const double hourAngle = 15.0 * (solarHour - 12.0);
    const double s = std::sin(latitudeDeg * rad) * std::sin(decl * rad)
                     + std::cos(latitudeDeg * rad) * std::cos(decl * rad) * std::cos(hourAngle * rad);
    return std::asin(std::clamp(s, -1.0, 1.0)) / rad;
}

int stabilityClass(double u, double cloud, double sun)
{
    enum
    {
        A = 1,
        B,
        C,
        D,
        E,
        F
    };
    if (cloud >= 8.0 - 1e-9) return D; // overcast, day or night
    if (sun > 0)
    {
        int ins = sun > 60 ? 3 : (sun > 35 ? 2 : 1); // 3 strong, 2 moderate, 1 slight
        if (cloud > 4) ins = std::max(1, ins - 1);
        // rows: u < 2, 2-3, 3-5, 5-6, >= 6; columns: slight, moderate, strong
        static const int day[5][3] = {{B, B, A}, {C, B, B}, {C, C, B}, {D, D, C}, {D, D, C}};
        const int row = u < 2 ? 0 : u < 3 ? 1 : u < 5 ? 2 : u < 6 ? 3 : 4;
        return day[row][ins - 1];
    }
    const bool cloudy = cloud >= 4;
    if (u < 3) return cloudy ? E : F;
    if (u < 5) return cloudy ? D : E;
    return D;
}

char className(int cls)
{
    return static_cast<char>('A' + cls - 1);
}

double ruralWindExponent(int cls)
{
    static const double p[6] = {0.07, 0.07, 0.10, 0.15, 0.35, 0.55};
    return p[cls - 1];
}

double verticalTerm(double z, double h, double sz, double zi)
{
    auto g = [sz](double d) { return std::exp(-0.5 * (d / sz) * (d / sz)); };
    if (zi > 0 && sz > 1.6 * zi) return std::sqrt(2 * M_PI) * sz / zi;
    double v = g(z - h) + g(z + h);
    if (zi > 0)
    {
        for (int i = 1; i <= 50; ++i)
        {
            const double t = g(z - (2 * i * zi - h)) + g(z + (2 * i * zi - h)) + g(z - (2 * i * zi + h))
                             + g(z + (2 * i * zi + h));
            v += t;
            if (t < 1e-12 * v) break;
        }
    }
    return v;
}

// ------------------------------------------------------------------------

struct GaussianModel::Element
{
    double x, y, q, h;
    double sy0 = 0, sz0 = 0;
    std::array<double, 7> xy{}, xz{}; // virtual distances per class
    int group = 0;                    // depletion table group (source index)
};

// Cumulative depletion integrals J(x) = sqrt(2/pi) int_1^x dxi / (sz e^{h^2/2sz^2})
// on a logarithmic grid of x, one table per (source, class).
struct GaussianModel::Tables
{
    static constexpr double x0 = 1.0, ratio = 1.05;
    static constexpr int n = 300;                      // up to 1.05^299 ~ 2e6 m
    std::vector<std::array<std::vector<double>, 7>> j; // [group][cls][k]
    double lookup(int group, int cls, double x) const
    {
        if (x <= x0) return 0.0;
        const double f = std::log(x / x0) / std::log(ratio);
        const int k = std::min(static_cast<int>(f), n - 2);
        const double t = std::min(f - k, 1.0);
        const auto& v = j[group][cls];
        return (1 - t) * v[k] + t * v[k + 1];
    }
};

namespace
{

double integrand(double sz, double h)
{
    return 1.0 / (sz * std::exp(0.5 * (h / sz) * (h / sz)));
}

// virtual distance: x with sigma(x) = s0 (sigma increasing in x)
template <class F>
double virtualDistance(F sigma, double s0)
{
    if (s0 <= 0) return 0;
    double lo = 0, hi = 1;
    while (sigma(hi) < s0 && hi < 1e8) hi *= 2;
    for (int it = 0; it < 100; ++it)
    {
        const double mid = 0.5 * (lo + hi);
        (sigma(mid) < s0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace

GaussianModel::GaussianModel(std::vector<Source> sources, GaussianOptions options)
    : sources_(std::move(sources)), opt_(options), curves_(DispersionCurves::create(opt_.curves)),
      tables_(std::make_unique<Tables>())
{
    if (!curves_) throw std::invalid_argument("unknown dispersion curves '" + opt_.curves + "'");
    for (std::size_t s = 0; s < sources_.size(); ++s)
    {
        const Source& src = sources_[s];
        const double q = src.rate * (src.controlled ? 1.0 - opt_.reduction : 1.0);
        if (src.type == Source::Type::Area)
        {
            const int n = std::max(1, opt_.areaSubdivisions);
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b)
                {
                    Element e;
                    e.x = src.x - 0.5 * src.lx + (a + 0.5) * src.lx / n;
                    e.y = src.y - 0.5 * src.ly + (b + 0.5) * src.ly / n;
                    e.q = q / (n * n);
                    e.h = src.height;
                    e.group = static_cast<int>(s);
                    elements_.push_back(e);
                }
        }
        else
        {
            Element e;
            e.x = src.x;
            e.y = src.y;
            e.q = q;
            e.h = src.height;
            e.group = static_cast<int>(s);
            if (src.type == Source::Type::Volume)
            {
                e.sy0 = std::sqrt(src.lx * src.ly) / 4.3;
                e.sz0 = (src.top - src.bottom) / (src.bottom <= 0 ? 2.15 : 4.3);
                for (int c = 1; c <= 6; ++c)
                {
                    e.xy[c] = virtualDistance([&, c](double x) { return curves_->sigmaY(c, x); }, e.sy0);
                    e.xz[c] = virtualDistance([&, c](double x) { return curves_->sigmaZ(c, x); }, e.sz0);
                }
            }
            elements_.push_back(e);
        }
    }
    if (opt_.depositionVelocity > 0 && !opt_.constantK)
    {
        // one table per source (all elements of a source share h and sz0)
        tables_->j.resize(sources_.size());
        for (std::size_t s = 0; s < sources_.size(); ++s)
        {
            const Element* e = nullptr;
            for (const auto& el : elements_)
                if (el.group == static_cast<int>(s))
                {
                    e = &el;
                    break;
                }
            for (int c = 1; c <= 6; ++c)
            {
                auto& v = tables_->j[s][c];
                v.assign(Tables::n, 0.0);
                // Simpson on each log interval, in ln x (dx = x dlnx)
                for (int k = 1; k < Tables::n; ++k)
                {
                    const double a = Tables::x0 * std::pow(Tables::ratio, k - 1);
                    const double b = a * Tables::ratio;
                    const double m = std::sqrt(a * b);
                    auto f = [&](double x) { return x * integrand(curves_->sigmaZ(c, x + e->xz[c]), e->h); };
                    v[k] = v[k - 1] + std::log(Tables::ratio) / 6 * (f(a) + 4 * f(m) + f(b));
                }
                for (auto& x : v) x *= std::sqrt(2 / M_PI);
            }
        }
    }
}

GaussianModel::~GaussianModel() = default;

std::string GaussianModel::dispersionTitle() const
{
    return opt_.constantK ? "constant K" : curves_->title();
}

PlumeHour GaussianModel::hourConditions(const MetHour& m, int index) const
{
    PlumeHour p;
    p.u10 = m.speed;
    p.directionFrom = m.directionFrom;
    p.mixingHeight = m.mixingHeight;
    if (m.stability > 0)
    {
        p.cls = m.stability;
    }
    else
    {
        // mid-hour solar time
        const double hour = opt_.startHour + index + 0.5;
        const int day = (opt_.startDayOfYear - 1 + static_cast<int>(std::floor(hour / 24))) % 365 + 1;
        const double sun = solarElevationDeg(opt_.latitudeDeg, day, std::fmod(hour, 24.0));
        p.cls = stabilityClass(m.speed, m.cloudOktas, sun);
    }
    return p;
}

double GaussianModel::depletion(int cls, double u, double h, double x, double xz) const
{
    const double vd = opt_.depositionVelocity;
    if (vd <= 0 || x <= Tables::x0) return 1.0;
    // direct quadrature (used for constant K and for checks)
    const int n = 400;
    const double la = std::log(Tables::x0), lb = std::log(x), dl = (lb - la) / n;
    double s = 0;
    for (int k = 0; k <= n; ++k)
    {
        const double xi = std::exp(la + k * dl);
        const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
        const double sz = opt_.constantK ? std::sqrt(2 * opt_.kV * xi / u) : curves_->sigmaZ(cls, xi + xz);
        s += w * xi * integrand(sz, h);
    }
    s *= dl / 3 * std::sqrt(2 / M_PI);
    return std::exp(-vd / u * s);
}

double GaussianModel::concentration(const PlumeHour& hr, const Receptor& r) const
{
    const int cls = hr.cls;
    const double th = hr.directionFrom * M_PI / 180.0;
    const double ex = -std::sin(th), ey = -std::cos(th); // downwind unit vector
    const bool lid = cls <= 4 || opt_.mixingLidStable;
    const double zi = lid ? hr.mixingHeight : 0.0;
    const double p = opt_.windExponent >= 0 ? opt_.windExponent : ruralWindExponent(cls);
    double sum = 0;
    for (const auto& e : elements_)
    {
        const double dx = r.x - e.x, dy = r.y - e.y;
        const double x = dx * ex + dy * ey;  // downwind distance
        if (x < 1.0) continue;               // ISC: no contribution within 1 m or upwind
        const double y = -dx * ey + dy * ex; // crosswind
        if (lid && e.h >= zi) continue;      // release above the mixing layer
        const double u = std::max(opt_.minWind, hr.u10 * std::pow(std::max(e.h, 10.0) / 10.0, p));
        double sy, sz;
        if (opt_.constantK)
        {
            sy = std::sqrt(2 * opt_.kH * x / u + e.sy0 * e.sy0);
            sz = std::sqrt(2 * opt_.kV * x / u + e.sz0 * e.sz0);
        }
        else
        {
            sy = curves_->sigmaY(cls, x + e.xy[cls]);
            sz = curves_->sigmaZ(cls, x + e.xz[cls]);
        }
        if (std::abs(y) > 6 * sy) continue;
        double dep = 1.0;
        if (opt_.depositionVelocity > 0)
        {
            dep = opt_.constantK ? depletion(cls, u, e.h, x)
                                 : std::exp(-opt_.depositionVelocity / u * tables_->lookup(e.group, cls, x));
        }
        sum += e.q * dep / (2 * M_PI * u * sy * sz) * std::exp(-0.5 * (y / sy) * (y / sy))
               * verticalTerm(r.height, e.h, sz, zi);
    }
    return sum;
}

} // namespace procsim::plume
