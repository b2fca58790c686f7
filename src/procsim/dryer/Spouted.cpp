#include "dryer/Spouted.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

void Residence::censor(const std::vector<double>& censored, double littleMean, double littleError)
{
    const std::size_t bins = std::max(counts.size(), censored.size());
    counts.resize(bins, 0.0);
    double atRisk = 0;
    for (std::size_t i = 0; i < bins; ++i) atRisk += counts[i] + (i < censored.size() ? censored[i] : 0.0);
    // a visit censored in bin i was at risk for half of it
    double survival = 1, restricted = 0;
    for (std::size_t i = 0; i < bins; ++i)
    {
        const double c = i < censored.size() ? censored[i] : 0.0, exposed = atRisk - 0.5 * c;
        const double next = exposed > 0 ? survival * (1 - counts[i] / exposed) : survival;
        atRisk -= counts[i] + c;
        restricted += 0.5 * binWidth * (survival + next);
        counts[i] = survival - next;
        survival = next;
    }
    tailShare = survival;
    tailMean = 0;
    mean = restricted;
    if (tailShare == 0) return;
    if (littleMean < restricted - 3 * littleError)
    {
        char text[200];
        std::snprintf(text, sizeof text,
                      "a mean by Little's law at most 3 errors below the %.4g s its visits within the window "
                      "give; Little's is %.4g +- %.2g s",
                      restricted, littleMean, littleError);
        throw std::invalid_argument(text);
    }
    // within its error of the bins' mean, the tail ends at the window's edge
    tailMean = std::max(0.0, littleMean - restricted) / tailShare;
    mean = restricted + tailShare * tailMean;
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
    if (tailShare == 0) return binWidth * (binOf(cumulative, u1) + u2);
    const double bins = 1 - tailShare; // the bins' share, cumulative.back()
    if (u1 < bins) return binWidth * (binOf(cumulative, u1 / bins) + u2);
    return binWidth * static_cast<double>(counts.size()) - tailMean * std::log1p(-u2);
}

double Residence::drawResidual(double u1, double u2, double u3) const
{
    // length-biased: bin i with weight count_i (i + 1/2), density ~ t within it
    const auto inBin = [&](double u) {
        const double i = binOf(lengthCumulative, u);
        return binWidth * std::sqrt(i * i + u2 * (2 * i + 1));
    };
    if (tailShare == 0) return u3 * inBin(u1);
    // the tail past E, length-biased: density ~ t exp(-(t - E)/theta), the
    // mixture of E + Exp(theta) (weight E) and E + Gamma(2, theta) (theta)
    const double E = binWidth * static_cast<double>(counts.size()), theta = tailMean;
    const double bins = lengthCumulative.back() * binWidth, tail = tailShare * (E + theta);
    const double u = u1 * (bins + tail);
    if (u < bins) return u3 * inBin(u / bins);
    const double v = (u - bins) / tail, exponential = E / (E + theta); // v uniform in [0, 1)
    double t = E - theta * std::log1p(-u2);
    if (v >= exponential) t -= theta * std::log1p(-(v - exponential) / (1 - exponential));
    return u3 * t;
}

namespace
{

std::size_t regionNamed(const Case& c, const std::string& name)
{
    for (std::size_t k = 0; k < c.regions.size(); ++k)
        if (c.regions[k].name == name) return k;
    throw std::invalid_argument("spouted bed: no region " + name);
}

} // namespace

double meanBeside(double regionMean, double coreMean, double share)
{
    return (regionMean - share * coreMean) / (1 - share);
}

void addCore(Case& c, const std::string& region, const std::string& name, double share, Region core)
{
    const std::size_t k = regionNamed(c, region);
    Region& rest = c.regions[k];
    core.name = name;
    core.correlation = rest.correlation;
    core.residence = Residence{};
    core.partOf = static_cast<int>(k);
    core.share = share;
    core.holdupShare = rest.holdupShare * share;
    core.measured = rest.measured;
    const auto beside = [share](double regionMean, double coreMean) {
        return meanBeside(regionMean, coreMean, share);
    };
    rest.slipReynolds = beside(rest.slipReynolds, core.slipReynolds);
    rest.voidage = beside(rest.voidage, core.voidage);
    rest.hFile = beside(rest.hFile, core.hFile);
    rest.kmFile = beside(rest.kmFile, core.kmFile);
    rest.core = static_cast<int>(c.regions.size());
    c.regions.push_back(core);
}

// Gas crossing back and forth by a core's edge carries the edge's
// temperatures, which differ far less than the compartments' means, so the
// mass crossing overstates the mixing: the share that carries heat is
// (T_out - T_in) / (T_core - T_rest), the core's and the rest's gas as their
// kernels saw it; within [0, 1], 1 (the mass) where they differ by under 1 K.
double exchangeShare(double outT, double inT, double coreT, double restT)
{
    if (std::fabs(coreT - restT) < 1) return 1;
    return std::clamp((outT - inT) / (coreT - restT), 0.0, 1.0);
}

GasNetwork gasNetwork(const Case& c)
{
    GasNetwork n;
    const double G = c.airFlow;
    if (!c.circulating)
    {
        n.order.push_back({0, {{-1, G}}});
        n.outlet.push_back({0, G});
        return n;
    }
    const double up = G * c.spoutShare, seep = G * (1 - c.spoutShare);
    const auto at = [&](const std::string& name) { return static_cast<int>(regionNamed(c, name)); };
    const int zone = at("entrainment"), spout = at("spout"), downcomer = at("downcomer"),
              fountain = at("fountain");
    const auto index = [](int r) { return static_cast<std::size_t>(r); };
    const int jet = c.regions[index(zone)].core, over = c.regions[index(fountain)].core;
    // the base: all the gas through the jet, which exchanges a recycle with
    // the rest of the zone beside it and sends it the seepage
    int toSpout = zone;
    if (jet >= 0)
    {
        const Region& core = c.regions[index(jet)];
        const double back = G * core.exchangeShare * core.intoCore;
        n.order.push_back({index(jet), {{-1, G}, {zone, back}}});
        n.order.push_back({index(zone), {{jet, seep + back}}});
        toSpout = jet;
    }
    else
        n.order.push_back({index(zone), {{-1, G}}});
    n.order.push_back({index(spout), {{toSpout, up}}});
    n.order.push_back({index(downcomer), {{zone, seep}}});
    // the top: the spout's gas into the fountain's core, the seepage into
    // the rest beside it, the two exchanging across the core's sides
    if (over >= 0)
    {
        const Region& core = c.regions[index(over)];
        const double into = G * core.exchangeShare * core.intoCore,
                     out = into + G * (core.outOfCore - core.intoCore);
        if (up + into - out < 0 || seep + out - into < 0)
            throw std::invalid_argument("spouted bed: the fountain core's flows out " + std::to_string(out)
                                        + " and in " + std::to_string(into)
                                        + " kg/s leave a compartment more gas than enters it");
        n.order.push_back({index(over), {{spout, up}, {fountain, into}}});
        n.order.push_back({index(fountain), {{downcomer, seep}, {over, out}}});
        n.outlet = {{over, up + into - out}, {fountain, seep + out - into}};
    }
    else
    {
        n.order.push_back({index(fountain), {{spout, up}, {downcomer, seep}}});
        n.outlet = {{fountain, G}};
    }
    return n;
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
    std::vector<double> inCore; // the share of its current visit a sample spends in its region's core
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
    std::vector<GasState> leaving;     // the gas leaving each compartment (seen: as its kernels see it)
    double gasWater = 0, gasEnergy = 0, initialWater = 0, initialEnthalpy = 0, exchangeScale = 0;
    std::vector<double> holdupTime;
    std::vector<double> gasTTime, gasWTime; // the compartments' gas times dt
    std::vector<Residence> residence;       // the regions', prepared for drawing
    std::vector<Residence> fractions;       // the cores' visitFractions, prepared
    GasNetwork network;
    std::vector<double> occupancy; // kernels per region at the step's start
    std::size_t cycle;             // the regions of the cycle (the first)

private:
    void place(std::size_t i);
    void enter(std::size_t i, std::size_t r);
    void advance(std::size_t i, double dt, Exchange& ex);
    void visit(std::size_t i, double tau, Exchange& ex);
    void segment(std::size_t i, std::size_t r, double tau, Exchange& ex);
    GasField gasFor(const Exchange& ex, double dt) const;
    void solveGas();
    // dry air [kg/s], humidity ratio, enthalpy [J/kg dry air]
    struct Entering
    {
        double flow, W, h;
    };
    Entering entering(const GasCompartment& k) const;
    struct CompartmentGas
    {
        GasState leaving, seen;
    };
    CompartmentGas solveRegion(std::size_t r, double flow, double W, double h, double kernels,
                               double sumT) const;
    double seenShare(double N) const;
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
    inCore.assign(n, 0.0);
    cycle = static_cast<std::size_t>(
        std::count_if(c.regions.begin(), c.regions.end(), [](const Region& r) { return r.partOf < 0; }));
    holdupTime.assign(c.regions.size(), 0.0);
    gasTTime.assign(c.regions.size(), 0.0);
    gasWTime.assign(c.regions.size(), 0.0);
    for (const Region& r : c.regions)
    {
        residence.push_back(r.residence);
        residence.back().prepare();
        fractions.push_back(r.visitFractions);
        fractions.back().prepare();
    }
    if (!c.gasAtInlet) network = gasNetwork(c);
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
    leaving = seen.region;
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

// A visit of region r begins: the share of it in the region's core.
void Bed::enter(std::size_t i, std::size_t r)
{
    const int core = c.regions[r].core;
    if (core < 0) return;
    const std::size_t k = static_cast<std::size_t>(core);
    if (c.regions[k].visitFractions.counts.empty())
        inCore[i] = c.regions[k].share;
    else
    {
        const double u1 = uniform(rng[i]), u2 = uniform(rng[i]);
        inCore[i] = std::min(fractions[k].draw(u1, u2), 1.0);
    }
}

// The outlet of a step's exchange: all the compartments' gas leaves the bed
// through it, so it carries all their water and energy, whatever way each
// took (the regions' gas stays at the inlet air: only the outlet is booked).
GasField Bed::gasFor(const Exchange& ex, double dt) const
{
    GasField g;
    const double hIn = inletEnthalpy();
    g.region.assign(c.regions.size(), GasState{c.inletC + kKelvin, c.inletW});
    g.outlet = g.region.front();
    g.outletEnthalpy = hIn;
    if (c.gasAtInlet) return g;
    const double flow = c.airFlow * dt;
    const double W = c.inletW + std::accumulate(ex.water.begin(), ex.water.end(), 0.0) / flow;
    g.outletEnthalpy = hIn + std::accumulate(ex.energy.begin(), ex.energy.end(), 0.0) / flow;
    g.outlet = GasState{psy::temperatureFromEnthalpy(g.outletEnthalpy, W) + kKelvin, W};
    return g;
}

// Where in a compartment between its entering (0) and leaving (1) gas the
// gas its kernels see lies on average, for N = (what the kernels exchange
// per kelvin or per kg/kg of the gas) / (what the flow carries): 1 when it is
// well mixed; in plug flow, along which the gas relaxes as exp(-N z) towards
// the kernels, the mean over z of 1 - exp(-N z) over that of the outlet,
// (1 - (1 - e^-N)/N)/(1 - e^-N), from 1/2 (N -> 0: half the change) to 1.
double Bed::seenShare(double N) const
{
    if (!c.plugFlow) return 1.0;
    if (N < 1e-6) return 0.5 + N / 12;
    const double a = -std::expm1(-N);
    return (1 - a / N) / a;
}

// The gas of region r (a compartment of dry-air flow `flow` entering at W,
// h [J/kg]) in balance with the region's kernels: leaving it and as its
// kernels see it, entering + seenShare x (leaving - entering). Their heat
// h A (T_seen - T_p) is linear in the gas, their water is the last step's
// rate per kernel corrected by the film, -k_m A (rho_v - rho_v,last):
// implicit in the gas (the particles take far more heat and water than the
// seepage carries, an explicit gas would diverge), a Newton step in time of
// the water. In plug flow the leaving gas is then exactly the exponential
// relaxation's, T_p + (T_in - T_p) e^-N, for kernels at one temperature.
Bed::CompartmentGas Bed::solveRegion(std::size_t r, double flow, double W, double h, double kernels,
                                     double sumT) const
{
    const Region& reg = c.regions[r];
    const double area = spoutlab::surfaceArea(spoutlab::Kernel{c.diameter, c.dryMass, 300});
    const double H = kernels * reg.h * area, B = reg.h * area * sumT, K = kernels * reg.km * area;
    const double s0 = kernels * ratePerKernel[r];
    const double tp = kernels > 0 ? sumT / kernels - kKelvin : 0.0;
    const double hv = psy::kHfg0 + psy::kCpVapour * tp;
    const double rv = spoutlab::waterVapourGasConstant();
    const double tIn = psy::temperatureFromEnthalpy(h, W);
    CompartmentGas g{leaving[r], seen.region[r]};
    for (int k = 0; k < 4; ++k)
    {
        const GasState& s = g.seen;
        const double rho = c.pressure * s.W / ((psy::kMolarRatio + s.W) * rv * s.T);
        const double slope = c.pressure * psy::kMolarRatio / std::pow(psy::kMolarRatio + s.W, 2) / (rv * s.T);
        const double bw = seenShare(K * slope / flow);
        const double Wg = (flow * W + s0 - K * (rho - lastVapour[r]) + K * slope * (s.W - W * (1 - bw)))
                          / (flow + K * slope * bw);
        const double S = flow * (Wg - W);
        const double cp = psy::kCpAir + Wg * psy::kCpVapour;
        const double bt = seenShare(H / (flow * cp));
        const double t = (flow * h - flow * Wg * psy::kHfg0 + S * hv - H * (1 - bt) * tIn - H * kKelvin + B)
                         / (flow * cp + H * bt);
        g.leaving = GasState{t + kKelvin, std::max(Wg, 0.0)};
        g.seen = c.plugFlow ? GasState{tIn + bt * (t - tIn) + kKelvin, std::max(W + bw * (Wg - W), 0.0)}
                            : g.leaving;
    }
    return g;
}

// The gas entering compartment k, its inflows mixed (one inflow taken as it
// is): each compartment's as this step has solved it so far.
Bed::Entering Bed::entering(const GasCompartment& k) const
{
    Entering e{0, 0, 0};
    double water = 0, energy = 0;
    int sources = 0;
    for (const GasInflow& in : k.in)
    {
        if (!(in.flow > 0)) continue;
        const bool inlet = in.from < 0;
        const GasState g =
            inlet ? GasState{c.inletC + kKelvin, c.inletW} : leaving[static_cast<std::size_t>(in.from)];
        e.h = inlet ? inletEnthalpy() : psy::enthalpy(g.T - kKelvin, g.W);
        e.W = g.W;
        e.flow += in.flow, water += in.flow * g.W, energy += in.flow * e.h;
        ++sources;
    }
    if (sources > 1) e.W = water / e.flow, e.h = energy / e.flow;
    return e;
}

void Bed::solveGas()
{
    const std::size_t nr = c.regions.size();
    std::vector<double> kernels(nr, 0.0), sumT(nr, 0.0);
    for (std::size_t i = 0; i < X.size(); ++i)
    {
        // a sample in a region with a core: its share of the visit there
        const std::size_t r = static_cast<std::size_t>(region[i]);
        const int core = c.regions[r].core;
        const double there = core < 0 ? 0.0 : inCore[i];
        kernels[r] += weight * (1 - there);
        sumT[r] += weight * (1 - there) * T[i];
        if (core < 0) continue;
        kernels[static_cast<std::size_t>(core)] += weight * there;
        sumT[static_cast<std::size_t>(core)] += weight * there * T[i];
    }
    occupancy = kernels;
    if (c.gasAtInlet) return;
    for (const GasCompartment& k : network.order)
    {
        const Entering e = entering(k);
        if (e.flow > 0)
        {
            const CompartmentGas g =
                solveRegion(k.region, e.flow, e.W, e.h, kernels[k.region], sumT[k.region]);
            leaving[k.region] = g.leaving;
            seen.region[k.region] = g.seen;
        }
    }
}

// One kernel over tau in its region: in a region with a core first the time
// beside it, then its share in the core (as the kernels go through the
// entrainment zone; in the fountain the order is a choice, the exchange over
// a step hardly depends on it).
void Bed::visit(std::size_t i, double tau, Exchange& ex)
{
    const std::size_t r = static_cast<std::size_t>(region[i]);
    const int core = c.regions[r].core;
    if (core < 0) return segment(i, r, tau, ex);
    const double coreTime = inCore[i] * tau;
    segment(i, r, tau - coreTime, ex);
    segment(i, static_cast<std::size_t>(core), coreTime, ex);
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
        if (c.regions[r].core >= 0) holdupTime[static_cast<std::size_t>(c.regions[r].core)] += inCore[i] * dt;
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
