#include "dryer/Model.hpp"

#include "common/Cvode.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <stdexcept>

#include "Arrhenius.hpp"      // coupling/: shared with the spouted-bed drying models
#include "Psychrometrics.hpp" // coupling/: the one psychrometrics of the project

namespace procsim::dryer
{

namespace psy = spoutlab::psy;
using spoutlab::arrhenius;

double DryerCase::areaPerTray() const
{
    return piecesPerTray * M_PI * pieceDiameter * pieceLength;
}

std::vector<double> DryerCase::airShares() const
{
    std::vector<double> phi(static_cast<std::size_t>(trays()), 1.0);
    for (int c = 0; c < carts; ++c)
        for (int k = 0; k < traysPerCart; ++k)
        {
            double v = 1.0;
            if (!cartFactors.empty()) v *= cartFactors[static_cast<std::size_t>(c)];
            if (!trayFactors.empty()) v *= trayFactors[static_cast<std::size_t>(k)];
            phi[static_cast<std::size_t>(c * traysPerCart + k)] = v;
        }
    const double mean = std::accumulate(phi.begin(), phi.end(), 0.0) / phi.size();
    for (double& v : phi) v /= mean;
    return phi;
}

std::vector<double> DryerCase::initialTrayMoisture() const
{
    const std::size_t n = static_cast<std::size_t>(trays());
    std::vector<double> x(n, x0);
    if (x0Spread <= 0.0 || n < 2) return x;
    // Standard normal deviates by Box-Muller on mt19937 (fully specified
    // generator, so the pattern is the same on every platform), then shifted
    // and scaled to mean 0 and standard deviation 1 exactly.
    std::mt19937 gen(seed);
    auto uniform = [&gen]() { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; };
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; i += 2)
    {
        const double r = std::sqrt(-2.0 * std::log(uniform())), a = 2.0 * M_PI * uniform();
        z[i] = r * std::cos(a);
        if (i + 1 < n) z[i + 1] = r * std::sin(a);
    }
    const double mean = std::accumulate(z.begin(), z.end(), 0.0) / n;
    double var = 0;
    for (double& v : z)
    {
        v -= mean;
        var += v * v;
    }
    const double sd = std::sqrt(var / n);
    for (std::size_t i = 0; i < n; ++i) x[i] = x0 * (1.0 + x0Spread * z[i] / sd);
    for (double v : x)
        if (v <= 0.0) throw std::domain_error("initial moisture spread too large: a tray starts dry");
    return x;
}

double DryerCase::equilibriumMoisture(double rh) const
{
    const double a = std::clamp(rh, 0.0, 0.999);
    return oswinA * std::pow(a / (1.0 - a), oswinB);
}

void nonUniformity(const std::vector<double>& x, double& f1, double& f2)
{
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / x.size();
    int n1 = 0, n2 = 0;
    for (double v : x)
    {
        const double d = std::fabs(v - mean) / mean * 100.0;
        if (d > 10.0)
            ++n2;
        else if (d >= 5.0)
            ++n1;
    }
    f1 = 100.0 * n1 / x.size();
    f2 = 100.0 * n2 / x.size();
}

namespace
{

// State layout: [m_w(0..n-1), H_p(0..n-1), W_r, h_r, counters...]
constexpr double kCondensationRate = 10.0; // x circulation, kg/s per unit (W - W_s)

enum Counter
{
    kHeater = 0,
    kFan,
    kWall,
    kVentHOut,
    kVentHIn,
    kVentWOut,
    kVentWIn,
    kCondensateW, // water condensed on walls from supersaturated return air
    kCondensateH, // its enthalpy (liquid at the return-air temperature)
    kCounters
};

struct Loop
{
    const DryerCase& c;
    std::size_t n;
    std::vector<double> hA;    // W/K per tray
    std::vector<double> mDry;  // kg per tray
    double wAmb, hAmb, gv, gt; // gt: air over the trays

    explicit Loop(const DryerCase& cs) : c(cs), n(static_cast<std::size_t>(cs.trays()))
    {
        const auto phi = c.airShares();
        hA.resize(n);
        mDry.assign(n, c.dryMass / n);
        for (std::size_t i = 0; i < n; ++i)
            hA[i] = c.hConv * std::pow(phi[i], c.velocityExponent) * c.areaPerTray();
        wAmb = psy::humidityRatioFromRH(c.ambientC, c.ambientRH, c.pressure);
        hAmb = psy::enthalpy(c.ambientC, wAmb);
        gv = c.ventedFraction * c.circulation;
        gt = c.circulation - c.ventShortCircuit * gv;
        if (!(gt > 0.0)) throw std::domain_error("vented air exceeds the circulation");
    }

    std::size_t size() const { return 2 * n + 2 + kCounters; }

    double relativeRate(double x, double xeq) const
    {
        if (x >= c.xCritical) return 1.0;
        if (x <= xeq) return 0.0;
        return std::pow((x - xeq) / (c.xCritical - xeq), c.fallingExponent);
    }

    double productT(std::size_t i, const double* y) const
    {
        return y[n + i] / (mDry[i] * c.cpDry + y[i] * psy::kCpWater);
    }

    struct Supply
    {
        double w, h, t, rh, xeq; // air over the trays
        double hShort;           // short-circuited make-up air leaving the vents
        double heater;           // total heater power
    };

    // Heaters bring the tray stream (recirculated + (1-s) make-up, plus fan
    // heat) and the short-circuited make-up stream to the set-point; if the
    // installed power is short, both get the same fraction of their demand.
    Supply supply(double wr, double hr) const
    {
        const double G = c.circulation, s = c.ventShortCircuit;
        Supply out;
        out.w = ((G - gv) * wr + (1.0 - s) * gv * wAmb) / gt;
        const double hMix = ((G - gv) * hr + (1.0 - s) * gv * hAmb + c.fanPower) / gt;
        const double wantMain = std::max(0.0, gt * (psy::enthalpy(c.hotAirC, out.w) - hMix));
        const double wantShort = s * gv * std::max(0.0, psy::enthalpy(c.hotAirC, wAmb) - hAmb);
        const double want = wantMain + wantShort;
        const double scale = want > c.heaterPower ? c.heaterPower / want : 1.0;
        out.heater = scale * want;
        out.h = hMix + scale * wantMain / gt;
        out.hShort = hAmb + (s * gv > 0.0 ? scale * wantShort / (s * gv) : 0.0);
        out.t = psy::temperatureFromEnthalpy(out.h, out.w);
        out.rh = psy::relativeHumidity(std::clamp(out.t, -100.0, 200.0), out.w, c.pressure);
        out.xeq = c.equilibriumMoisture(out.rh);
        return out;
    }

    // Evaporation [kg/s] and convective heat [W] on tray i.
    void exchange(std::size_t i, const double* y, const Supply& s, double& mdot, double& q) const
    {
        const double tp = productT(i, y);
        const double x = y[i] / mDry[i];
        q = hA[i] * (s.t - tp);
        const double cHumid = psy::kCpAir + psy::kCpVapour * s.w;
        const double pw = psy::pwFromHumidityRatio(s.w, c.pressure);
        const double ps = psy::saturationPressure(std::clamp(tp, -100.0, 200.0));
        const double ext = hA[i] / cHumid * psy::kMolarRatio * (ps - pw) / (c.pressure - pw);
        if (c.kinetics == DryerCase::Kinetics::CharacteristicCurve)
        {
            mdot = relativeRate(x, s.xeq) * ext;
            return;
        }
        if (x <= s.xeq || ext <= 0.0)
        {
            // dry below equilibrium: nothing leaves; cold wet product in humid
            // air: condensation limited by the gas film
            mdot = (ext < 0.0 && x > s.xeq) ? ext : 0.0;
            return;
        }
        const double k = arrhenius(c.rateConstant, c.activationEnergy, tp + 273.15, c.referenceC + 273.15);
        const double internal = mDry[i] * k * (x - s.xeq);
        mdot = internal * ext / (internal + ext);
    }

    void rhs(const double* y, double* dy) const
    {
        const double wr = y[2 * n], hr = y[2 * n + 1];
        const Supply s = supply(wr, hr);
        double sumM = 0, sumE = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            double mdot, q;
            exchange(i, y, s, mdot, q);
            const double hv = psy::kHfg0 + psy::kCpVapour * productT(i, y);
            dy[i] = -mdot;
            dy[n + i] = q - mdot * hv;
            sumM += mdot;
            sumE += mdot * hv - q;
        }
        const double tr = psy::temperatureFromEnthalpy(hr, wr);
        const double qWall = c.wallUA * (tr - c.ambientC);
        // Return air above saturation (warm-up of a wet load): the excess
        // condenses on the walls and drains, relaxing within ~0.1 of the
        // air-holdup residence time.  The latent heat stays in the air.
        const double wsr = psy::saturationHumidityRatio(std::clamp(tr, -100.0, 200.0), c.pressure);
        const double cond = wr > wsr ? kCondensationRate * c.circulation * (wr - wsr) : 0.0;
        const double hCond = cond * psy::kCpWater * tr;
        const double sc = c.ventShortCircuit;
        dy[2 * n] = (gt * (s.w - wr) + sumM - cond) / c.airHoldup;
        dy[2 * n + 1] = (gt * (s.h - hr) + sumE - qWall - hCond) / c.airHoldup;
        double* k = dy + 2 * n + 2;
        k[kHeater] = s.heater;
        k[kFan] = c.fanPower;
        k[kWall] = qWall;
        k[kVentHOut] = (1.0 - sc) * gv * hr + sc * gv * s.hShort;
        k[kVentHIn] = gv * hAmb;
        k[kVentWOut] = (1.0 - sc) * gv * wr + sc * gv * wAmb;
        k[kVentWIn] = gv * wAmb;
        k[kCondensateW] = cond;
        k[kCondensateH] = hCond;
    }

    double xAverage(const double* y) const
    {
        double w = 0;
        for (std::size_t i = 0; i < n; ++i) w += y[i];
        return w / c.dryMass;
    }

    double waterInvariant(const double* y) const
    {
        double w = 0;
        for (std::size_t i = 0; i < n; ++i) w += y[i];
        const double* k = y + 2 * n + 2;
        return w + c.airHoldup * y[2 * n] + k[kVentWOut] - k[kVentWIn] + k[kCondensateW];
    }

    double energyInvariant(const double* y) const
    {
        double e = 0;
        for (std::size_t i = 0; i < n; ++i) e += y[n + i];
        const double* k = y + 2 * n + 2;
        return e + c.airHoldup * y[2 * n + 1] + k[kVentHOut] - k[kVentHIn] + k[kWall] + k[kCondensateH]
               - k[kHeater] - k[kFan];
    }
};

int cvRhs(sunrealtype, N_Vector y, N_Vector dy, void* data)
{
    static_cast<const Loop*>(data)->rhs(N_VGetArrayPointer(y), N_VGetArrayPointer(dy));
    return 0;
}

int cvRoot(sunrealtype, N_Vector y, sunrealtype* g, void* data)
{
    const Loop* loop = static_cast<const Loop*>(data);
    g[0] = loop->xAverage(N_VGetArrayPointer(y)) - loop->c.xTarget;
    return 0;
}

// CVODE's own messages would add lines to procsim's one-line errors; the
// failure is reported by checkCvode() instead.
void quietCvode(int, const char*, const char*, char*, void*) {}

TimePoint sample(const Loop& L, double t, const double* y)
{
    const std::size_t n = L.n;
    TimePoint p;
    p.t = t;
    const double wr = y[2 * n], hr = y[2 * n + 1];
    const auto s = L.supply(wr, hr);
    p.tSupply = s.t;
    p.wSupply = s.w;
    p.wReturn = wr;
    p.tReturn = psy::temperatureFromEnthalpy(hr, wr);
    p.rhReturn = psy::relativeHumidity(std::clamp(p.tReturn, -100.0, 200.0), wr, L.c.pressure);
    p.xAvg = L.xAverage(y);
    p.xMin = 1e300;
    p.xMax = -1e300;
    p.tProductMax = -1e300;
    p.tProductMean = 0;
    p.evaporationKgPerS = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double x = y[i] / L.mDry[i], tp = L.productT(i, y);
        p.xMin = std::min(p.xMin, x);
        p.xMax = std::max(p.xMax, x);
        p.tProductMax = std::max(p.tProductMax, tp);
        p.tProductMean += tp / n;
        double mdot, q;
        L.exchange(i, y, s, mdot, q);
        p.evaporationKgPerS += mdot;
    }
    p.heaterW = s.heater;
    const double* k = y + 2 * n + 2;
    p.electricityJ = k[kHeater] + k[kFan];
    return p;
}

} // namespace

BatchResult simulate(const DryerCase& c, double latentPerKg)
{
    const Loop L(c);
    const std::size_t n = L.n, N = L.size();
    CvodeSession cv;
    checkCvode(SUNContext_Create(nullptr, &cv.ctx), "context");
    cv.y = N_VNew_Serial(static_cast<sunindextype>(N), cv.ctx);
    cv.atol = N_VNew_Serial(static_cast<sunindextype>(N), cv.ctx);
    double* y = N_VGetArrayPointer(cv.y);
    double* at = N_VGetArrayPointer(cv.atol);

    BatchResult r;
    r.trayX0 = c.initialTrayMoisture();
    for (std::size_t i = 0; i < n; ++i)
    {
        y[i] = r.trayX0[i] * L.mDry[i];
        y[n + i] = (L.mDry[i] * c.cpDry + y[i] * psy::kCpWater) * c.ambientC;
        at[i] = 1e-7 * L.mDry[i];
        at[n + i] = 1e-3 * L.mDry[i] * c.cpDry;
    }
    y[2 * n] = L.wAmb;
    y[2 * n + 1] = L.hAmb;
    at[2 * n] = 1e-8;
    at[2 * n + 1] = 1e-2;
    for (std::size_t k = 0; k < kCounters; ++k)
    {
        y[2 * n + 2 + k] = 0.0;
        at[2 * n + 2 + k] = (k == kVentWOut || k == kVentWIn || k == kCondensateW) ? 1e-6 : 10.0;
    }
    const double water0 = L.waterInvariant(y), energy0 = L.energyInvariant(y);
    const double productWater0 = L.xAverage(y) * c.dryMass;

    cv.mem = CVodeCreate(CV_BDF, cv.ctx);
    CVodeSetErrFile(cv.mem, nullptr); // failures are reported as one line by checkCvode
    checkCvode(CVodeInit(cv.mem, cvRhs, 0.0, cv.y), "init");
    checkCvode(CVodeSetErrHandlerFn(cv.mem, quietCvode, nullptr), "error handler");
    checkCvode(CVodeSetUserData(cv.mem, const_cast<Loop*>(&L)), "user data");
    checkCvode(CVodeSVtolerances(cv.mem, c.relTol, cv.atol), "tolerances");
    cv.A = SUNDenseMatrix(static_cast<sunindextype>(N), static_cast<sunindextype>(N), cv.ctx);
    cv.LS = SUNLinSol_Dense(cv.y, cv.A, cv.ctx);
    checkCvode(CVodeSetLinearSolver(cv.mem, cv.LS, cv.A), "linear solver");
    checkCvode(CVodeSetMaxNumSteps(cv.mem, 100000), "max steps");
    checkCvode(CVodeSetMaxStep(cv.mem, std::min(c.outputInterval, 600.0)), "max step");
    checkCvode(CVodeRootInit(cv.mem, 1, cvRoot), "root init");
    int dir = -1;
    checkCvode(CVodeSetRootDirection(cv.mem, &dir), "root direction");

    auto record = [&](double t) {
        r.series.push_back(sample(L, t, y));
        r.tProductMax = std::max(r.tProductMax, r.series.back().tProductMax);
        std::vector<double> xs(n);
        for (std::size_t i = 0; i < n; ++i) xs[i] = y[i] / L.mDry[i];
        r.trayXSeries.push_back(std::move(xs));
    };
    record(0.0);
    double t = 0.0;
    while (t < c.maxTime)
    {
        const double tout = std::min(c.maxTime, t + c.outputInterval);
        double tret = t;
        const int flag = CVode(cv.mem, tout, cv.y, &tret, CV_NORMAL);
        checkCvode(flag, "integration");
        t = tret;
        record(t);
        if (flag == CV_ROOT_RETURN)
        {
            r.reachedTarget = true;
            break;
        }
    }
    r.dryingTime = t;
    const double* k = y + 2 * n + 2;
    r.heaterJ = k[kHeater];
    r.fanJ = k[kFan];
    r.wallLossJ = k[kWall];
    r.ventNetJ = k[kVentHOut] - k[kVentHIn];
    r.condensateKg = k[kCondensateW];
    r.electricityJ = r.heaterJ + r.fanJ;
    r.waterEvaporated = productWater0 - L.xAverage(y) * c.dryMass;
    r.specificEnergy = r.electricityJ / r.waterEvaporated;
    r.latentPerKg =
        latentPerKg > 0 ? latentPerKg : psy::kHfg0 + psy::kCpVapour * c.hotAirC - psy::kCpWater * c.ambientC;
    r.eta = r.waterEvaporated * r.latentPerKg / r.electricityJ;
    r.scorched = r.tProductMax > c.scorchC;
    r.trayX.resize(n);
    r.trayT.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        r.trayX[i] = y[i] / L.mDry[i];
        r.trayT[i] = L.productT(i, y);
    }
    nonUniformity(r.trayX, r.f1, r.f2);
    r.waterBalanceRel = std::fabs(L.waterInvariant(y) - water0) / productWater0;
    r.energyBalanceRel = std::fabs(L.energyInvariant(y) - energy0) / r.electricityJ;
    return r;
}

} // namespace procsim::dryer
