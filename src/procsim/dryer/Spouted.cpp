#include "dryer/Spouted.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "CornProperties.hpp"
#include "MoistAir.hpp"
#include "Psychrometrics.hpp"

namespace procsim::dryer::spouted
{

namespace psy = spoutlab::psy;

double Residence::histogramMean() const
{
    double sum = 0, n = 0;
    for (std::size_t i = 0; i < counts.size(); ++i)
    {
        sum += counts[i] * (static_cast<double>(i) + 0.5);
        n += counts[i];
    }
    return n > 0 ? binWidth * sum / n : 0.0;
}

void Residence::prepare()
{
    cumulative.clear();
    lengthCumulative.clear();
    double run = 0, biased = 0;
    for (std::size_t i = 0; i < counts.size(); ++i)
    {
        run += counts[i];
        biased += counts[i] * (static_cast<double>(i) + 0.5);
        cumulative.push_back(run);
        lengthCumulative.push_back(biased);
    }
}

namespace
{

// the bin whose share of the running sums `sums` holds u in [0, 1)
double binOf(const std::vector<double>& sums, double u)
{
    const auto it = std::upper_bound(sums.begin(), sums.end(), u * sums.back());
    std::size_t i = static_cast<std::size_t>(it - sums.begin());
    if (i == sums.size())
        i = static_cast<std::size_t>(std::lower_bound(sums.begin(), sums.end(), sums.back()) - sums.begin());
    return static_cast<double>(i);
}

} // namespace

double Residence::draw(double u1, double u2) const
{
    return binWidth * (binOf(cumulative, u1) + u2);
}

double Residence::drawResidual(double u1, double u2, double u3) const
{
    // length-biased: bin i with weight count_i (i + 1/2), density ~ t within it
    const double i = binOf(lengthCumulative, u1);
    const double t = binWidth * std::sqrt(i * i + u2 * (2 * i + 1));
    return u3 * t;
}

void addJet(Case& c, double share, Region jet)
{
    const auto named = [&](const std::string& name) {
        for (std::size_t k = 0; k < c.regions.size(); ++k)
            if (c.regions[k].name == name) return k;
        throw std::invalid_argument("addJet: no region " + name);
    };
    const std::size_t k = named("entrainment");
    Region& rest = c.regions[k];
    jet.name = "jet";
    jet.correlation = rest.correlation;
    jet.residence = Residence{};
    jet.partOf = static_cast<int>(k);
    jet.share = share;
    jet.holdupShare = rest.holdupShare * share;
    jet.measured = rest.measured;
    jet.path = kShared;
    jet.gasRank = 0;
    const auto beside = [share](double zoneMean, double jetMean) {
        return (zoneMean - share * jetMean) / (1 - share);
    };
    rest.slipReynolds = beside(rest.slipReynolds, jet.slipReynolds);
    rest.voidage = beside(rest.voidage, jet.voidage);
    rest.hFile = beside(rest.hFile, jet.hFile);
    rest.kmFile = beside(rest.kmFile, jet.kmFile);
    rest.jet = static_cast<int>(c.regions.size());
    // jet -> spout -> fountain; jet -> the rest of the zone -> downcomer -> fountain
    rest.path = 1;
    rest.gasRank = 1;
    c.regions[named("downcomer")].gasRank = 2;
    c.regions.push_back(jet);
}

void transferCoefficients(Case& c)
{
    const spoutlab::GasThermalProperties gas{c.gas.rho, c.gas.mu, c.gas.cp, c.gas.kappa};
    for (Region& r : c.regions)
    {
        const auto model = spoutlab::HeatTransferModel::New(
            r.correlation, spoutlab::Parameters(c.file + ": regions." + r.name));
        // the slip that gives the region's Re in the correlations' definition
        const double slip = r.slipReynolds * c.gas.mu / (r.voidage * c.gas.rho * c.diameter);
        const spoutlab::HeatTransferCell cell{{0, 0, 0}, r.voidage, c.diameter, slip};
        r.hCorrelation = model->h(cell, gas);
        r.kmCorrelation = model->massTransferCoefficient(cell, gas, c.gas.Dv);
        r.h = c.measuredTransfer ? r.hFile : r.hCorrelation;
        r.km = c.measuredTransfer ? r.kmFile : r.kmCorrelation;
    }
}

namespace
{

constexpr double kKelvin = 273.15;

// splitmix64 (Steele, Lea and Flood 2014): one 64-bit state per sample, so a
// sample's draws do not depend on the order the samples are advanced in
double uniform(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

struct GasState
{
    double T; // [K]
    double W;
};

// What the samples of each region gave the gas over a step (bed totals).
struct Exchange
{
    std::vector<double> water;    // [kg]
    std::vector<double> energy;   // [J] into the gas: sum dW h_v(T_p) - q tau
    std::vector<double> sorption; // [J]
    explicit Exchange(std::size_t n) : water(n, 0.0), energy(n, 0.0), sorption(n, 0.0) {}
};

// The compartments' gas and the outlet for one step's exchange.
struct GasField
{
    std::vector<GasState> region;
    GasState outlet;
    double outletEnthalpy; // [J/kg dry air]
};

class Bed
{
public:
    explicit Bed(const Case& c);
    void step(double dt);
    double meanMoisture() const;
    const Case& c;
    Result result;
    double t = 0;
    // the samples
    std::vector<int> region;
    std::vector<double> left, X, T, above;
    std::vector<double> inJet; // the share of its current visit a sample spends in its region's jet
    std::vector<std::uint64_t> rng;
    std::vector<double> state;
    std::size_t width;
    double weight;
    // the step
    GasField seen;
    double maxSegmentChange = 0;
    double lastEvaporation = 0;
    // since the last output: time, and the outlet's W, enthalpy and the water evaporated times dt
    double spanTime = 0, spanW = 0, spanH = 0, spanWater = 0;
    GasField booked;
    std::vector<double> ratePerKernel; // the last step's evaporation per kernel in each region [kg/s]
    std::vector<double> lastVapour;    // the vapour density the last step's particles saw [kg/m3]
    double gasWater = 0, gasEnergy = 0, initialWater = 0, initialEnthalpy = 0, exchangeScale = 0;
    std::vector<double> holdupTime;
    std::vector<double> gasTTime, gasWTime; // the compartments' gas times dt
    std::vector<Residence> residence;       // the regions', prepared for drawing
    Residence jetFractions;                 // the jet's visitFractions, prepared
    std::vector<double> occupancy;          // kernels per region at the step's start
    std::size_t cycle;                      // the regions of the cycle (the first)

private:
    void place(std::size_t i);
    void enter(std::size_t i, std::size_t r);
    void advance(std::size_t i, double dt, Exchange& ex);
    void visit(std::size_t i, double tau, Exchange& ex);
    void segment(std::size_t i, std::size_t r, double tau, Exchange& ex);
    GasField gasFor(const Exchange& ex, double dt) const;
    void solveGas();
    GasState solveRegion(std::size_t r, double flow, double W, double h, double kernels, double sumT) const;
    double inletEnthalpy() const { return psy::enthalpy(c.inletC, c.inletW); }
};

Bed::Bed(const Case& cs) : c(cs)
{
    const std::size_t n = static_cast<std::size_t>(c.samples);
    width = static_cast<std::size_t>(c.drying->stateSize());
    weight = c.bedParticles / static_cast<double>(c.samples);
    region.assign(n, 0);
    left.assign(n, std::numeric_limits<double>::infinity());
    X.assign(n, c.initialX);
    T.assign(n, c.initialC + kKelvin);
    above.assign(n, 0.0);
    rng.resize(n);
    state.assign(n * width, 0.0);
    inJet.assign(n, 0.0);
    for (const Region& r : c.regions)
        if (r.partOf >= 0)
        {
            jetFractions = r.visitFractions;
            jetFractions.prepare();
        }
    cycle = static_cast<std::size_t>(
        std::count_if(c.regions.begin(), c.regions.end(), [](const Region& r) { return r.partOf < 0; }));
    holdupTime.assign(c.regions.size(), 0.0);
    gasTTime.assign(c.regions.size(), 0.0);
    gasWTime.assign(c.regions.size(), 0.0);
    for (const Region& r : c.regions)
    {
        residence.push_back(r.residence);
        residence.back().prepare();
    }
    const std::size_t rows = c.initialStateX.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        if (rows)
        {
            X[i] = c.initialStateX[i % rows];
            T[i] = c.initialStateT[i % rows];
        }
        rng[i] = c.seed * 0x2545F4914F6CDD1DULL + i;
        c.drying->initialise(X[i], width ? &state[i * width] : nullptr);
        if (c.circulating) place(i);
        initialWater += weight * c.dryMass * X[i];
        initialEnthalpy += weight * spoutlab::corn::heatCapacity(c.dryMass, X[i]) * (T[i] - kKelvin);
    }
    const Exchange none(c.regions.size());
    seen = gasFor(none, 1.0);
    ratePerKernel.assign(c.regions.size(), 0.0);
    for (const GasState& g : seen.region)
        lastVapour.push_back(spoutlab::vapourDensity(spoutlab::MoistAir{g.T, g.W, c.pressure}));
}

// the stationary circulation: region r with probability mean_r / sum, the
// residual of a residence in progress
void Bed::place(std::size_t i)
{
    double total = 0;
    for (std::size_t k = 0; k < cycle; ++k) total += c.regions[k].residence.histogramMean();
    const double u = uniform(rng[i]) * total;
    double run = 0;
    std::size_t k = 0;
    for (; k + 1 < cycle; ++k)
    {
        run += c.regions[k].residence.histogramMean();
        if (u < run) break;
    }
    region[i] = static_cast<int>(k);
    const double u1 = uniform(rng[i]), u2 = uniform(rng[i]), u3 = uniform(rng[i]);
    left[i] = residence[k].drawResidual(u1, u2, u3);
    enter(i, k);
}

// A visit of region r begins: the share of it in the region's jet.
void Bed::enter(std::size_t i, std::size_t r)
{
    const int jet = c.regions[r].jet;
    if (jet < 0) return;
    const Region& j = c.regions[static_cast<std::size_t>(jet)];
    if (j.visitFractions.counts.empty())
        inJet[i] = j.share;
    else
    {
        const double u1 = uniform(rng[i]), u2 = uniform(rng[i]);
        inJet[i] = std::min(jetFractions.draw(u1, u2), 1.0);
    }
}

// The gas along its paths, in the gas's order: all of it crosses the
// entrainment zone's first compartment (kShared), then spoutShare rises
// through the spout (path 0) and the rest seeps through the downcomer (path
// 1), and the two meet again in the fountain region above the plates
// (kShared, later in the order), which all the gas leaves the bed through.
struct GasPaths
{
    double flow[3], W[3], h[3]; // dry air [kg/s], humidity ratio, enthalpy [J/kg] per path
    bool split = false;         // a region of path 0 or 1 has been crossed
    GasPaths(const Case& c, double hIn)
        : flow{c.airFlow * c.spoutShare, c.airFlow * (1 - c.spoutShare), c.airFlow},
          W{c.inletW, c.inletW, c.inletW}, h{hIn, hIn, hIn}
    {}
    // the gas entering a region of path p: a shared region after the split
    // takes the two paths mixed
    void entering(int p, double& w, double& enthalpy) const
    {
        if (p == kShared && split)
        {
            w = (flow[0] * W[0] + flow[1] * W[1]) / (flow[0] + flow[1]);
            enthalpy = (flow[0] * h[0] + flow[1] * h[1]) / (flow[0] + flow[1]);
            return;
        }
        w = W[p], enthalpy = h[p];
    }
    // the gas leaving a region of path p enters the next region of p (of both
    // paths after a shared region)
    void leave(int p, double w, double enthalpy)
    {
        const int first = p == kShared ? 0 : p, last = p == kShared ? kShared : p;
        for (int q = first; q <= last; ++q) W[q] = w, h[q] = enthalpy;
        if (p != kShared) split = true;
    }
    // the gas leaving the bed: the two paths mixed (one after the fountain)
    void outlet(double& w, double& enthalpy) const { entering(kShared, w, enthalpy); }
    // calls f(region, path) for the regions holding gas, in the gas's order
    template <class F>
    static void walk(const Case& c, const GasPaths& paths, F f)
    {
        for (int rank = 0; rank < kGasRanks; ++rank)
            for (std::size_t r = 0; r < c.regions.size(); ++r)
            {
                const int p = c.regions[r].path;
                if (c.regions[r].gasRank == rank && paths.flow[p] > 0) f(r, p);
            }
    }
};

GasField Bed::gasFor(const Exchange& ex, double dt) const
{
    GasField g;
    const double hIn = inletEnthalpy();
    g.region.assign(c.regions.size(), GasState{c.inletC + kKelvin, c.inletW});
    g.outlet = g.region.front();
    g.outletEnthalpy = hIn;
    if (c.gasAtInlet) return g;
    GasPaths paths(c, hIn);
    const double recycle = c.airFlow * c.jetRecycle;
    GasPaths::walk(c, paths, [&](std::size_t r, int p) {
        double W, h;
        paths.entering(p, W, h);
        const Region& reg = c.regions[r];
        double flow = paths.flow[p];
        if (reg.partOf >= 0)
        {
            // the jet: the share of the rest's water and energy that the
            // recycle brings back (what it does not, the seepage carries on)
            const std::size_t rest = static_cast<std::size_t>(reg.partOf);
            const double back = recycle / (paths.flow[1] + recycle);
            W += back * ex.water[rest] / (flow * dt);
            h += back * ex.energy[rest] / (flow * dt);
        }
        else if (reg.jet >= 0)
            flow += recycle; // the rest of the zone: the seepage and the recycle
        W += ex.water[r] / (flow * dt);
        h += ex.energy[r] / (flow * dt);
        paths.leave(p, W, h);
        g.region[r] = GasState{psy::temperatureFromEnthalpy(h, W) + kKelvin, W};
    });
    double Wout;
    paths.outlet(Wout, g.outletEnthalpy);
    g.outlet = GasState{psy::temperatureFromEnthalpy(g.outletEnthalpy, Wout) + kKelvin, Wout};
    return g;
}

// The gas leaving region r (a well-mixed compartment of dry-air flow `flow`
// entering at W, h [J/kg]) in balance with the region's kernels: their heat
// h A (T_g - T_p) is linear in T_g, their water is the last step's rate per
// kernel corrected by the film, -k_m A (rho_v - rho_v,last): implicit in the
// gas (the particles take far more heat and water than the seepage carries,
// an explicit gas would diverge), a Newton step in time of the water.
GasState Bed::solveRegion(std::size_t r, double flow, double W, double h, double kernels, double sumT) const
{
    const Region& reg = c.regions[r];
    const double area = spoutlab::surfaceArea(spoutlab::Kernel{c.diameter, c.dryMass, 300});
    const double H = kernels * reg.h * area, B = reg.h * area * sumT, K = kernels * reg.km * area;
    const double s0 = kernels * ratePerKernel[r];
    const double tp = kernels > 0 ? sumT / kernels - kKelvin : 0.0;
    const double hv = psy::kHfg0 + psy::kCpVapour * tp;
    const double rv = spoutlab::waterVapourGasConstant();
    GasState g = seen.region[r];
    for (int k = 0; k < 4; ++k)
    {
        const double rho = c.pressure * g.W / ((psy::kMolarRatio + g.W) * rv * g.T);
        const double slope = c.pressure * psy::kMolarRatio / std::pow(psy::kMolarRatio + g.W, 2) / (rv * g.T);
        const double Wg = (flow * W + s0 - K * (rho - lastVapour[r]) + K * slope * g.W) / (flow + K * slope);
        const double S = flow * (Wg - W);
        const double t = (flow * h - flow * Wg * psy::kHfg0 + S * hv - H * kKelvin + B)
                         / (flow * (psy::kCpAir + Wg * psy::kCpVapour) + H);
        g = GasState{t + kKelvin, std::max(Wg, 0.0)};
    }
    return g;
}

void Bed::solveGas()
{
    const std::size_t nr = c.regions.size();
    std::vector<double> kernels(nr, 0.0), sumT(nr, 0.0);
    for (std::size_t i = 0; i < X.size(); ++i)
    {
        // a sample in a region with a jet: its share of the visit there
        const std::size_t r = static_cast<std::size_t>(region[i]);
        const int jet = c.regions[r].jet;
        const double there = jet < 0 ? 0.0 : inJet[i];
        kernels[r] += weight * (1 - there);
        sumT[r] += weight * (1 - there) * T[i];
        if (jet < 0) continue;
        kernels[static_cast<std::size_t>(jet)] += weight * there;
        sumT[static_cast<std::size_t>(jet)] += weight * there * T[i];
    }
    occupancy = kernels;
    if (c.gasAtInlet) return;
    GasPaths paths(c, inletEnthalpy());
    const double recycle = c.airFlow * c.jetRecycle;
    GasPaths::walk(c, paths, [&](std::size_t r, int p) {
        double W, h;
        paths.entering(p, W, h);
        const Region& reg = c.regions[r];
        double flow = paths.flow[p];
        if (reg.partOf >= 0 && recycle > 0)
        {
            // the jet: the inlet gas and the recycle of the rest's last gas
            const GasState& back = seen.region[static_cast<std::size_t>(reg.partOf)];
            W = (flow * W + recycle * back.W) / (flow + recycle);
            h = (flow * h + recycle * psy::enthalpy(back.T - kKelvin, back.W)) / (flow + recycle);
            flow += recycle;
        }
        else if (reg.jet >= 0)
            flow += recycle;
        seen.region[r] = solveRegion(r, flow, W, h, kernels[r], sumT[r]);
        paths.leave(p, seen.region[r].W, psy::enthalpy(seen.region[r].T - kKelvin, seen.region[r].W));
    });
}

// One kernel over tau in its region: in a region with a jet first the time
// beside it, then its share in the jet, as the kernels go through the zone.
void Bed::visit(std::size_t i, double tau, Exchange& ex)
{
    const std::size_t r = static_cast<std::size_t>(region[i]);
    const int jet = c.regions[r].jet;
    if (jet < 0) return segment(i, r, tau, ex);
    const double jetTime = inJet[i] * tau;
    segment(i, r, tau - jetTime, ex);
    segment(i, static_cast<std::size_t>(jet), jetTime, ex);
}

// One kernel over tau in gas compartment r: the CFD-DEM coupling step's sequence.
void Bed::segment(std::size_t i, std::size_t r, double tau, Exchange& ex)
{
    const Region& reg = c.regions[r];
    const GasState& g = seen.region[r];
    const spoutlab::MoistAir air{g.T, g.W, c.pressure};
    const spoutlab::Kernel kernel{c.diameter, c.dryMass, T[i]};
    double latent = 0;
    const double dW = c.drying->advanceWithLatentHeat(kernel, X[i], width ? &state[i * width] : nullptr, air,
                                                      reg.km, tau, latent);
    const double area = spoutlab::surfaceArea(kernel);
    const double q = reg.h * area * (g.T - T[i]);
    const double capacity = c.dryMass * (c.dryHeatCapacity + X[i] * psy::kCpWater);
    const double before = T[i];
    T[i] += tau * (q - dW / tau * latent) / capacity;
    const double tC = before - kKelvin;
    ex.water[r] += dW;
    ex.energy[r] += dW * (psy::kHfg0 + psy::kCpVapour * tC) - q * tau;
    ex.sorption[r] += dW * (latent - psy::latentHeat(std::clamp(tC, 0.0, 200.0)));
    exchangeScale += std::fabs(q * tau) + std::fabs(dW * latent);
    maxSegmentChange = std::max(maxSegmentChange, std::fabs(T[i] - before));
    // time above the limit, the temperature linear over the segment
    const double limit = c.limitC + kKelvin, lo = std::min(before, T[i]), hi = std::max(before, T[i]);
    if (lo >= limit)
        above[i] += tau;
    else if (hi > limit)
        above[i] += tau * (hi - limit) / (hi - lo);
    ++result.segments;
}

void Bed::advance(std::size_t i, double dt, Exchange& ex)
{
    double rest = dt;
    while (rest > 0)
    {
        const double tau = std::min(rest, left[i]);
        if (tau > 0) visit(i, tau, ex);
        rest -= tau;
        left[i] -= tau;
        if (left[i] <= 0 && c.circulating)
        {
            const std::size_t next = (static_cast<std::size_t>(region[i]) + 1) % cycle;
            region[i] = static_cast<int>(next);
            const double u1 = uniform(rng[i]), u2 = uniform(rng[i]);
            left[i] = residence[next].draw(u1, u2);
            enter(i, next);
        }
    }
}

void Bed::step(double dt)
{
    const std::size_t nr = c.regions.size();
    Exchange ex(nr);
    maxSegmentChange = 0;
    solveGas();
    for (std::size_t r = 0; r < nr; ++r)
    {
        gasTTime[r] += seen.region[r].T * dt;
        gasWTime[r] += seen.region[r].W * dt;
    }
    for (std::size_t r = cycle; r < nr; ++r)
    {
        // a region with a compartment: the gas its kernels saw, time-weighted
        const std::size_t in = static_cast<std::size_t>(c.regions[r].partOf);
        const double all = occupancy[r] + occupancy[in];
        const double s = all > 0 ? occupancy[r] / all : c.regions[r].share;
        gasTTime[in] += s * (seen.region[r].T - seen.region[in].T) * dt;
        gasWTime[in] += s * (seen.region[r].W - seen.region[in].W) * dt;
    }
    for (std::size_t i = 0; i < X.size(); ++i) advance(i, dt, ex);
    for (std::size_t r = 0; r < nr; ++r)
    {
        ex.water[r] *= weight;
        ex.energy[r] *= weight;
        ex.sorption[r] *= weight;
        result.sorptionJ += ex.sorption[r];
    }
    for (std::size_t i = 0; i < X.size(); ++i)
    {
        const std::size_t r = static_cast<std::size_t>(region[i]);
        holdupTime[r] += dt;
        if (c.regions[r].jet >= 0) holdupTime[static_cast<std::size_t>(c.regions[r].jet)] += inJet[i] * dt;
    }
    booked = gasFor(ex, dt);
    const double G = c.airFlow;
    gasWater += G * (booked.outlet.W - c.inletW) * dt;
    gasEnergy += G * (booked.outletEnthalpy - inletEnthalpy()) * dt;
    lastEvaporation = std::accumulate(ex.water.begin(), ex.water.end(), 0.0) / dt;
    spanTime += dt;
    spanW += booked.outlet.W * dt;
    spanH += booked.outletEnthalpy * dt;
    spanWater += lastEvaporation * dt;
    if (!c.gasAtInlet)
        for (std::size_t r = 0; r < nr; ++r)
        {
            ratePerKernel[r] = occupancy[r] > 0 ? ex.water[r] / dt / occupancy[r] : 0.0;
            const GasState& g = seen.region[r];
            lastVapour[r] = spoutlab::vapourDensity(spoutlab::MoistAir{g.T, g.W, c.pressure});
        }
    t += dt;
    ++result.steps;
}

double Bed::meanMoisture() const
{
    return std::accumulate(X.begin(), X.end(), 0.0) / static_cast<double>(X.size());
}

double percentile(std::vector<double> v, double p)
{
    const std::size_t k = static_cast<std::size_t>(std::floor(p * static_cast<double>(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
}

// The state at an output time; the outlet and the evaporation as means
// over the time since the last output (a step's own outlet carries the
// noise of the samples that crossed between regions in it).
SeriesPoint point(Bed& bed, double heaterJ, double dt)
{
    SeriesPoint p{};
    p.t = bed.t;
    p.xMean = bed.meanMoisture();
    p.xP5 = percentile(bed.X, 0.05);
    p.xP95 = percentile(bed.X, 0.95);
    p.tMeanC = std::accumulate(bed.T.begin(), bed.T.end(), 0.0) / static_cast<double>(bed.T.size()) - kKelvin;
    p.tMaxC = *std::max_element(bed.T.begin(), bed.T.end()) - kKelvin;
    const double span = bed.spanTime;
    p.outletW = span > 0 ? bed.spanW / span : bed.booked.outlet.W;
    p.outletC =
        span > 0 ? psy::temperatureFromEnthalpy(bed.spanH / span, p.outletW) : bed.booked.outlet.T - kKelvin;
    p.outletRH = psy::relativeHumidity(p.outletC, p.outletW, bed.c.pressure);
    p.evaporation = span > 0 ? bed.spanWater / span : 0.0;
    bed.spanTime = bed.spanW = bed.spanH = bed.spanWater = 0;
    p.heaterJ = heaterJ;
    p.dt = dt;
    return p;
}

// The shortest heating time m_d c_d / (h A) over the regions [s].
double shortestHeatingTime(const Case& c)
{
    double h = 0;
    for (const Region& r : c.regions) h = std::max(h, r.h);
    const spoutlab::Kernel k{c.diameter, c.dryMass, 300};
    return c.dryMass * c.dryHeatCapacity / (h * spoutlab::surfaceArea(k));
}

double nextStep(const Case& c, double dt, double segmentChange, double moistureChange)
{
    double ratio = 2;
    if (segmentChange > 0) ratio = std::min(ratio, 0.9 * c.step.kernelTemperatureChange / segmentChange);
    if (moistureChange > 0) ratio = std::min(ratio, 0.9 * c.step.bedMoistureChange / moistureChange);
    return std::min({dt * std::max(ratio, 0.5), c.step.maxStep, 0.5 * shortestHeatingTime(c)});
}

void finish(Bed& bed, double heaterJ)
{
    Result& r = bed.result;
    const Case& c = bed.c;
    r.endTime = bed.t;
    r.heaterJ = heaterJ;
    r.dryMassKg = c.bedParticles * c.dryMass;
    double water = 0, enthalpy = 0;
    for (std::size_t i = 0; i < bed.X.size(); ++i)
    {
        water += bed.weight * c.dryMass * bed.X[i];
        enthalpy += bed.weight * spoutlab::corn::heatCapacity(c.dryMass, bed.X[i]) * (bed.T[i] - kKelvin);
    }
    r.waterKg = bed.initialWater - water;
    const double wScale = std::max(std::fabs(r.waterKg), 1e-300);
    r.waterBalanceRel = std::fabs(r.waterKg - bed.gasWater) / wScale;
    const double residual = (enthalpy - bed.initialEnthalpy) + bed.gasEnergy + r.sorptionJ;
    r.energyBalanceRel = std::fabs(residual) / std::max(bed.weight * bed.exchangeScale, 1e-300);
    r.finalX = bed.meanMoisture();
    double var = 0;
    for (const double x : bed.X) var += (x - r.finalX) * (x - r.finalX);
    r.finalStd = std::sqrt(var / static_cast<double>(bed.X.size()));
    double above = 0;
    for (const double a : bed.above) above += a;
    r.meanTimeAbove = above / static_cast<double>(bed.above.size());
    double total = 0;
    for (std::size_t k = 0; k < bed.cycle; ++k) total += bed.holdupTime[k];
    for (const double h : bed.holdupTime) r.holdup.push_back(total > 0 ? h / total : 0.0);
    for (std::size_t k = 0; k < bed.gasTTime.size(); ++k)
    {
        r.gasT.push_back(bed.t > 0 ? bed.gasTTime[k] / bed.t : bed.seen.region[k].T);
        r.gasW.push_back(bed.t > 0 ? bed.gasWTime[k] / bed.t : bed.seen.region[k].W);
    }
    r.moisture = bed.X;
    r.temperature = bed.T;
}

} // namespace

Result run(const Case& c)
{
    Bed bed(c);
    const double heaterPower =
        c.airFlow * (psy::enthalpy(c.inletC, c.inletW) - psy::enthalpy(c.ambientC, c.inletW)) + c.fanPower;
    double heaterJ = 0, dt = std::min(c.step.initialStep, c.step.maxStep);
    bed.booked = bed.seen;
    bed.result.series.push_back(point(bed, 0.0, 0.0));
    bed.result.highestC = bed.result.series.back().tMaxC;
    double nextOutput = c.outputInterval;
    while (bed.t < c.duration)
    {
        const double target = std::min(nextOutput, c.duration);
        bool lands = false;
        if (bed.t + dt >= target * (1 - 1e-12)) dt = target - bed.t, lands = true;
        const double before = bed.meanMoisture(), tBefore = bed.t;
        const double hottest = *std::max_element(bed.T.begin(), bed.T.end());
        bed.step(dt);
        if (lands) bed.t = target;
        heaterJ += heaterPower * dt;
        const double after = bed.meanMoisture();
        const double hot = *std::max_element(bed.T.begin(), bed.T.end());
        bed.result.highestC = std::max(bed.result.highestC, hot - kKelvin);
        const double limit = c.limitC + kKelvin;
        if (std::max(hottest, hot) > limit) bed.result.timeAnyAbove += dt; // the step's end or start
        const bool reached = after <= c.targetX && !bed.result.reachedTarget;
        if (reached)
        {
            bed.result.reachedTarget = true;
            bed.result.targetTime = tBefore + dt * (before - c.targetX) / std::max(before - after, 1e-300);
        }
        if (lands || (reached && c.stopAtTarget)) bed.result.series.push_back(point(bed, heaterJ, dt));
        if (lands && target == nextOutput) nextOutput += c.outputInterval;
        if (reached && c.stopAtTarget) break;
        dt = nextStep(c, dt, bed.maxSegmentChange, std::fabs(after - before));
    }
    finish(bed, heaterJ);
    return bed.result;
}

} // namespace procsim::dryer::spouted
