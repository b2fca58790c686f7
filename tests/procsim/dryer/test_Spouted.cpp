// procsim dryer spouted: the long-time predictor against what is known
// without it.
//  - no circulation, unlimited air: the single-kernel curve, the physics
//    core advanced as the singleKernel case advances it (drying at T_p,
//    then the explicit heat update), to the bit;
//  - balances of water and energy over a circulating, drying batch;
//  - the same seed gives the same batch to the bit, another seed another;
//  - a dry kernel heated through a cycle of fixed residences: every kernel
//    on the analytic lumped curve after whole cycles, whatever its phase;
//  - the stationary placement: the bed holds the regions' measured shares;
//  - bed.initial_state: samples start at their kernels' moisture and
//    temperature; a row out of range stops with one line.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "DryingModel.hpp"
#include "HeatTransferModel.hpp"
#include "dryer/Spouted.hpp"
#include "dryer/SpoutedInput.hpp"

using namespace procsim::dryer::spouted;

namespace
{

const double kPi = std::acos(-1.0);

// singleKernelDict's kernel and air at 60 C (Cengel and Ghajar's row)
Case singleKernel(const std::string& model, spoutlab::Parameters props)
{
    Case c;
    c.diameter = 8e-3;
    c.initialX = 0.3333;
    c.dryMass = 1231 * kPi / 6 * std::pow(c.diameter, 3) / (1 + c.initialX);
    c.initialC = 25;
    c.inletC = 60;
    c.inletW = 0.00726;
    c.gas = GasProperties{1.059, 2.008e-05, 1007, 0.02808, 0.2178e-4 * std::pow(333.15 / 273.15, 1.81)};
    c.drying = spoutlab::DryingModel::New(model, props);
    c.dryingName = model;
    Region r;
    r.name = "still";
    r.correlation = "RanzMarshall";
    r.voidage = 1 - kPi / 6 * std::pow(c.diameter, 3) / (0.3 * 0.3 * 0.3);
    r.slipReynolds = c.gas.rho * 0.5 * c.diameter / c.gas.mu; // rho u_s d / mu
    c.regions = {r};
    c.circulating = false;
    c.gasAtInlet = true;
    c.samples = 1;
    c.targetX = 0;
    c.stopAtTarget = false;
    c.duration = 400;
    c.outputInterval = 0.5;
    c.step = TimeStepControl{0.5, 0.5, 1e9, 1e9};
    transferCoefficients(c);
    return c;
}

spoutlab::Parameters diffusionProps()
{
    return spoutlab::Parameters("kernelDiffusionProps")
        .set("D0", "4.810e-4")
        .set("activationEnergy", "44748")
        .set("nShells", "15");
}

// the singleKernel case's sequence, written out
void expectSingleKernelCurve(const Case& c)
{
    const Result r = run(c);
    const Region& g = c.regions[0];
    // h of the stream as the solver's cell gives it: slip u_s/eps
    const auto model = spoutlab::HeatTransferModel::New("RanzMarshall", spoutlab::Parameters());
    const spoutlab::GasThermalProperties gas{c.gas.rho, c.gas.mu, c.gas.cp, c.gas.kappa};
    const spoutlab::HeatTransferCell cell{{0, 0, 0}, g.voidage, c.diameter, 0.5 / g.voidage};
    EXPECT_NEAR(g.h, model->h(cell, gas), 1e-14 * g.h);
    EXPECT_NEAR(g.km, model->massTransferCoefficient(cell, gas, c.gas.Dv), 1e-14 * g.km);
    std::vector<double> state(static_cast<std::size_t>(c.drying->stateSize()));
    double X = c.initialX, T = c.initialC + 273.15;
    c.drying->initialise(X, state.data());
    const spoutlab::MoistAir air{c.inletC + 273.15, c.inletW, c.pressure};
    const double dt = 0.5, A = kPi * c.diameter * c.diameter;
    ASSERT_EQ(r.series.size(), 801u);
    for (std::size_t n = 1; n < r.series.size(); ++n)
    {
        double latent = 0;
        const double dW = c.drying->advanceWithLatentHeat(spoutlab::Kernel{c.diameter, c.dryMass, T}, X,
                                                          state.data(), air, g.km, dt, latent);
        const double q = g.h * A * (air.temperature - T);
        T += dt * (q - dW / dt * latent) / (c.dryMass * (c.dryHeatCapacity + X * 4186.0));
        ASSERT_EQ(r.series[n].xMean, X) << "step " << n;
        ASSERT_EQ(r.series[n].tMeanC, T - 273.15) << "step " << n;
        ASSERT_EQ(r.series[n].t, 0.5 * static_cast<double>(n));
    }
}

} // namespace

TEST(Spouted, NoCirculationUnlimitedAirIsTheSingleKernelKernelDiffusion)
{
    expectSingleKernelCurve(singleKernel("kernelDiffusion", diffusionProps()));
}

TEST(Spouted, NoCirculationUnlimitedAirIsTheSingleKernelFreeWater)
{
    expectSingleKernelCurve(singleKernel("freeWater", spoutlab::Parameters()));
}

namespace
{

std::string shippedCase()
{
    return std::string(DRYER_CASES) + "/spouted.yaml";
}

Case shortBatch(long samples, double minutes)
{
    Case c = readCase(shippedCase());
    c.samples = samples;
    c.duration = minutes * 60;
    c.stopAtTarget = false;
    return c;
}

} // namespace

TEST(Spouted, WaterAndEnergyBalancesClose)
{
    const Case c = shortBatch(2000, 20);
    const Result r = run(c);
    EXPECT_LT(r.waterBalanceRel, 1e-6);
    EXPECT_LT(r.energyBalanceRel, 1e-6);
    // the water from the final kernels themselves
    double lost = 0;
    for (const double x : r.moisture) lost += c.initialX - x;
    lost *= c.dryMass * c.bedParticles / static_cast<double>(c.samples);
    EXPECT_NEAR(r.waterKg, lost, 1e-9 * lost);
    EXPECT_GT(r.waterKg, 0.01); // the batch dried
    // the gas cooled and humidified on its way
    EXPECT_LT(r.series.back().outletC, c.inletC - 1);
    EXPECT_GT(r.series.back().outletW, c.inletW + 1e-4);
}

TEST(Spouted, SameSeedSameBatchToTheBit)
{
    const Case c = shortBatch(1000, 10);
    const Result a = run(c), b = run(c);
    ASSERT_EQ(a.series.size(), b.series.size());
    for (std::size_t i = 0; i < a.series.size(); ++i)
    {
        EXPECT_EQ(a.series[i].xMean, b.series[i].xMean);
        EXPECT_EQ(a.series[i].xP95, b.series[i].xP95);
        EXPECT_EQ(a.series[i].tMaxC, b.series[i].tMaxC);
        EXPECT_EQ(a.series[i].outletC, b.series[i].outletC);
    }
    EXPECT_EQ(a.moisture, b.moisture);
    EXPECT_EQ(a.steps, b.steps);
    Case other = c;
    other.seed = 2;
    EXPECT_NE(run(other).moisture, a.moisture);
}

namespace
{

// a residence fixed to [t, t + w): all counts in the bin at t
Residence fixedResidence(double t, double w)
{
    Residence r;
    r.binWidth = w;
    const std::size_t bin = static_cast<std::size_t>(std::llround(t / w));
    r.counts.assign(bin + 1, 0.0);
    r.counts[bin] = 1000;
    r.samples = 1000;
    r.mean = r.histogramMean();
    return r;
}

} // namespace

TEST(Spouted, DryKernelThroughFixedCycleFollowsTheLumpedSolution)
{
    Case c = singleKernel("freeWater", spoutlab::Parameters());
    c.initialX = 0; // dry: nothing evaporates, C = m_d c_d
    const double w = 1e-4;
    const double times[4] = {0.3, 0.5, 5.0, 1.0}, reynolds[4] = {3000, 1000, 50, 400};
    c.regions.clear();
    for (int k = 0; k < 4; ++k)
    {
        Region r;
        r.name = "region" + std::to_string(k);
        r.correlation = "RanzMarshall";
        r.voidage = 0.9;
        r.slipReynolds = reynolds[k];
        r.residence = fixedResidence(times[k], w);
        c.regions.push_back(r);
    }
    c.circulating = true;
    transferCoefficients(c);
    const double cycle = 6.8 + 4 * 0.5 * w;
    const int m = 5;
    c.duration = m * cycle;
    c.outputInterval = c.duration;
    c.samples = 500;
    c.step = TimeStepControl{0.02, 0.02, 1e9, 1e9};
    const Result r = run(c);
    const double A = kPi * c.diameter * c.diameter, C = c.dryMass * c.dryHeatCapacity;
    double I = 0, kMax = 0; // the exposure over one cycle, sum h A t / C, and the fastest rate
    for (int k = 0; k < 4; ++k)
    {
        I += c.regions[k].h * A * (times[k] + 0.5 * w) / C;
        kMax = std::max(kMax, c.regions[k].h * A / C);
    }
    const double dT0 = c.initialC - c.inletC, expected = c.inletC + dT0 * std::exp(-m * I);
    // explicit Euler per segment (at most 0.02 s): exp(-x) against (1 - x),
    // x^2/2 per segment; the residences' spread within their bin, w per
    // visit; a started residence's last partial visit
    const double euler = m * I * 0.5 * kMax * 0.02, jitter = (m + 1) * 4 * w * kMax;
    const double tolerance = std::fabs(dT0) * std::exp(-m * I) * (euler + jitter) + 1e-9;
    for (const double T : r.temperature) ASSERT_NEAR(T - 273.15, expected, tolerance);
    EXPECT_LT(tolerance, 0.02 * std::fabs(expected - c.initialC)); // a check, not a tautology
}

TEST(Spouted, TheBedHoldsTheMeasuredShares)
{
    // over 3 s, far shorter than a downcomer residence (60 s): only a bed
    // that starts stationary holds its shares from the start
    const Case c = shortBatch(10000, 0.05);
    const Result r = run(c);
    double total = 0;
    for (const Region& g : c.regions) total += g.residence.histogramMean();
    for (std::size_t k = 0; k < c.regions.size(); ++k)
    {
        const double share = c.regions[k].residence.histogramMean() / total;
        // binomial sampling error of 10000 samples, 4 sigma
        EXPECT_NEAR(r.holdup[k], share, 4 * std::sqrt(share * (1 - share) / 1e4) + 1e-4) << c.regions[k].name;
    }
}

TEST(Spouted, KernelsStartAtTheirOwnInitialState)
{
    // data/spouted_initial_state.csv: three kernels (X 0.30, 0.33, 0.36 at
    // 30, 40, 50 C); six samples take the rows in turn, twice each
    Case c = readCase(std::string(DRYER_DATA) + "/spouted_initial_state.yaml");
    EXPECT_EQ(c.initialStateX.size(), 3u);
    EXPECT_NEAR(c.initialX, 0.33, 1e-15);
    EXPECT_NEAR(c.initialC, 40, 1e-12);
    c.samples = 6;
    c.duration = 1;
    c.outputInterval = 1;
    const Result r = run(c);
    const SeriesPoint& p = r.series.front();
    EXPECT_EQ(p.t, 0.0);
    EXPECT_NEAR(p.xMean, 0.33, 1e-15);
    EXPECT_EQ(p.xP5, 0.30);
    EXPECT_EQ(p.xP95, 0.36);
    EXPECT_NEAR(p.tMeanC, 40, 1e-12);
    EXPECT_NEAR(p.tMaxC, 50, 1e-12);
    // samples i and i + 3 start alike: after 1 s (kernel diffusion at 80 C
    // takes off about 1e-4 kg/kg a second) still within 0.01 of each other
    ASSERT_EQ(r.moisture.size(), 6u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(r.moisture[i], r.moisture[i + 3], 0.01) << i;
}

TEST(Spouted, AnInitialStateOutOfRangeStopsWithOneLine)
{
    try
    {
        readCase(std::string(DRYER_DATA) + "/spouted_bad_initial_state.yaml");
        FAIL() << "no error";
    }
    catch (const std::exception& e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("spouted_bad_initial_state.csv: line 4: column 'moisture_db' expected a moisture "
                         "from 0 to 5 kg/kg dry basis, got '-0.1'"),
                  std::string::npos)
            << m;
        EXPECT_EQ(m.find('\n'), std::string::npos);
    }
}

namespace
{

// The gas each region's kernels saw over a short batch in which only the
// kernels of region `exchanging` take heat and water (h, k_m zero elsewhere).
Result onlyOneRegionExchanges(const std::string& exchanging, Case& c)
{
    c = shortBatch(2000, 1);
    for (Region& r : c.regions)
        if (r.name != exchanging) r.h = r.km = 0;
    return run(c);
}

std::size_t regionOf(const Case& c, const std::string& name)
{
    for (std::size_t k = 0; k < c.regions.size(); ++k)
        if (c.regions[k].name == name) return k;
    ADD_FAILURE() << "no region " << name;
    return 0;
}

double gasTemperatureOf(const Case& c, const Result& r, const std::string& name)
{
    return r.gasT[regionOf(c, name)] - 273.15;
}

} // namespace

TEST(Spouted, AllTheGasCrossesTheEntrainmentZoneSplitsAndMeetsInTheFountain)
{
    // the jet enters at the base: what the entrainment zone's kernels take
    // from it, every region downstream sees; what the downcomer's take, the
    // downcomer and, mixed with the spout's gas, the fountain region above
    // the plates, through which all the gas leaves
    Case c;
    const Result base = onlyOneRegionExchanges("entrainment", c);
    const double entrained = gasTemperatureOf(c, base, "entrainment");
    EXPECT_LT(entrained, c.inletC - 1); // the zone's kernels cooled it
    for (const char* name : {"spout", "fountain", "downcomer"})
        EXPECT_NEAR(gasTemperatureOf(c, base, name), entrained, 1e-9) << name;
    const double s = c.spoutShare;
    ASSERT_GT(s, 0.05);
    ASSERT_LT(s, 0.95);
    const auto W = [&](const Result& r, const char* name) { return r.gasW[regionOf(c, name)]; };
    const Result seep = onlyOneRegionExchanges("downcomer", c);
    EXPECT_LT(gasTemperatureOf(c, seep, "downcomer"), c.inletC - 1);
    for (const char* name : {"entrainment", "spout"})
        EXPECT_NEAR(gasTemperatureOf(c, seep, name), c.inletC, 1e-9) << name;
    EXPECT_NEAR(W(seep, "fountain"), s * c.inletW + (1 - s) * W(seep, "downcomer"), 1e-12);
    const Result spout = onlyOneRegionExchanges("spout", c);
    EXPECT_LT(gasTemperatureOf(c, spout, "spout"), c.inletC - 1);
    EXPECT_NEAR(W(spout, "fountain"), s * W(spout, "spout") + (1 - s) * c.inletW, 1e-12);
    EXPECT_NEAR(gasTemperatureOf(c, spout, "downcomer"), c.inletC, 1e-9);
}

namespace
{

// the shipped case with its entrainment zone split: a jet holding `share` of
// the zone's kernels with the zone's means (the rest's then the same)
Case withJet(Case c, double share)
{
    for (Region& r : c.regions)
        if (r.name == "entrainment") addCore(c, "entrainment", "jet", share, r);
    transferCoefficients(c);
    return c;
}

} // namespace

TEST(Spouted, TheJetFeedsBothPathsItsRestOnlyTheSeepage)
{
    const double share = 0.35;
    Case c = withJet(shortBatch(2000, 1), share);
    ASSERT_EQ(c.regions.back().name, "jet");
    const Case zoneExchanging = c;
    for (Region& r : c.regions)
        if (r.name != "jet") r.h = r.km = 0;
    const Result jet = run(c);
    const double jetT = gasTemperatureOf(c, jet, "jet");
    EXPECT_LT(jetT, c.inletC - 1);
    EXPECT_GT(jet.waterKg, 1e-6); // its kernels dried there
    for (const char* name : {"spout", "downcomer", "fountain"})
        EXPECT_NEAR(gasTemperatureOf(c, jet, name), jetT, 1e-9) << name;
    c = zoneExchanging;
    for (Region& r : c.regions)
        if (r.name != "entrainment") r.h = r.km = 0;
    const Result rest = run(c);
    const double restT = (gasTemperatureOf(c, rest, "entrainment") - share * c.inletC) / (1 - share);
    EXPECT_LT(restT, c.inletC - 1);
    EXPECT_NEAR(gasTemperatureOf(c, rest, "downcomer"), restT, 1e-6);
    for (const char* name : {"jet", "spout"})
        EXPECT_NEAR(gasTemperatureOf(c, rest, name), c.inletC, 1e-9) << name;
    const auto W = [&](const char* name) { return rest.gasW[regionOf(c, name)]; };
    EXPECT_NEAR(W("fountain"), c.spoutShare * c.inletW + (1 - c.spoutShare) * W("downcomer"), 1e-12);
    // the jet's kernels are its share of the zone's; the balances close
    EXPECT_NEAR(rest.holdup.back(), share * rest.holdup[3], 1e-15);
    const Result all = run(zoneExchanging);
    EXPECT_LT(all.waterBalanceRel, 1e-6);
    EXPECT_LT(all.energyBalanceRel, 1e-6);
    // unlimited air: the jet at the inlet air as every region
    Case unlimited = zoneExchanging;
    unlimited.gasAtInlet = true;
    EXPECT_NEAR(gasTemperatureOf(unlimited, run(unlimited), "jet"), c.inletC, 1e-9);
}

TEST(Spouted, EachVisitSpendsItsDrawnShareInTheJet)
{
    // only the jet dries: visits all in the jet or all beside it (half each)
    // give the jet the same holdup as every visit half in it, and a wider
    // spread of the kernels' moisture
    Case c = withJet(shortBatch(2000, 1), 0.5);
    for (Region& r : c.regions)
        if (r.name != "jet") r.h = r.km = 0;
    const Result half = run(c);
    Residence f;
    f.binWidth = 0.05;
    f.counts.assign(20, 0.0);
    f.counts.front() = f.counts.back() = 500;
    f.samples = 1000;
    c.regions.back().visitFractions = f;
    const Result split = run(c);
    const std::size_t zone = regionOf(c, "entrainment"), jet = regionOf(c, "jet");
    EXPECT_NEAR(half.holdup[jet], 0.5 * half.holdup[zone], 1e-12);
    EXPECT_NEAR(split.holdup[jet] / split.holdup[zone], 0.5, 0.03); // sampling: 2000 kernels
    EXPECT_GT(split.finalStd, 1.5 * half.finalStd);
    EXPECT_LT(split.waterBalanceRel, 1e-6);
    EXPECT_LT(split.energyBalanceRel, 1e-6);
}

TEST(Spouted, TheRecycleBringsTheRestsGasBackIntoTheJet)
{
    // only the rest of the zone exchanges: without a recycle the jet sees the
    // inlet air; with one, some of the rest's cooled gas, and the rest, which
    // more of the jet's gas crosses, is warmer
    Case c = withJet(shortBatch(2000, 1), 0.35);
    for (Region& r : c.regions)
        if (r.name != "entrainment") r.h = r.km = 0;
    const Result alone = run(c);
    c.regions.back().intoCore = 0.05;
    const Result back = run(c);
    EXPECT_NEAR(gasTemperatureOf(c, alone, "jet"), c.inletC, 1e-9);
    EXPECT_LT(gasTemperatureOf(c, back, "jet"), c.inletC - 0.1);
    EXPECT_GT(gasTemperatureOf(c, back, "entrainment"), gasTemperatureOf(c, alone, "entrainment") + 0.1);
    EXPECT_LT(back.waterBalanceRel, 1e-6);
    EXPECT_LT(back.energyBalanceRel, 1e-6);
}

namespace
{

// the shipped case with both cores, each holding `share` of its region's
// kernels with the region's means, and the given flows across the fountain
// core's sides
Case withCores(Case c, double share, double into, double out)
{
    for (const char* name : {"entrainment", "fountain"})
    {
        const Region means = c.regions[regionOf(c, name)];
        addCore(c, name, name == std::string("fountain") ? "fountainCore" : "jet", share, means);
    }
    c.regions[regionOf(c, "jet")].intoCore = 0.03;
    c.regions.back().intoCore = into;
    c.regions.back().outOfCore = out;
    transferCoefficients(c);
    return c;
}

} // namespace

TEST(Spouted, EveryGasCompartmentPassesOnTheDryAirItTakes)
{
    // in every compartment what enters leaves (to the compartments it feeds
    // and the outlet), every region is one compartment, the outlet takes all
    for (const Case& c : {shortBatch(10, 1), withCores(shortBatch(10, 1), 0.4, 0.02, 0.07),
                          withCores(shortBatch(10, 1), 0.4, 0.07, 0.02)})
    {
        const GasNetwork n = gasNetwork(c);
        ASSERT_EQ(n.order.size(), c.regions.size());
        std::vector<double> in(c.regions.size(), 0.0), out(c.regions.size(), 0.0);
        std::vector<int> seen(c.regions.size(), 0);
        const auto take = [&](const GasInflow& f) {
            if (f.from >= 0) out[static_cast<std::size_t>(f.from)] += f.flow;
        };
        for (const GasCompartment& k : n.order)
        {
            ++seen[k.region];
            for (const GasInflow& f : k.in)
            {
                in[k.region] += f.flow;
                take(f);
                EXPECT_GE(f.flow, 0.0);
            }
        }
        double leaving = 0;
        for (const GasInflow& f : n.outlet)
        {
            take(f);
            leaving += f.flow;
        }
        EXPECT_NEAR(leaving, c.airFlow, 1e-15 * c.airFlow);
        for (std::size_t r = 0; r < c.regions.size(); ++r)
        {
            EXPECT_EQ(seen[r], 1) << c.regions[r].name;
            EXPECT_NEAR(in[r], out[r], 1e-15 * c.airFlow) << c.regions[r].name;
        }
    }
    // a core losing more gas across its sides than the spout brings
    const Case c = shortBatch(10, 1);
    EXPECT_THROW(gasNetwork(withCores(c, 0.4, 0.0, c.spoutShare + 0.01)), std::invalid_argument);
}

TEST(Spouted, TheFountainCoreTakesTheSpoutsGasItsRestTheSeepage)
{
    // only the spout exchanges: the fountain's core sees the spout's gas,
    // the rest beside it the seepage (still at the inlet air) and what
    // crosses from the core into it
    Case c = withCores(shortBatch(2000, 1), 0.4, 0.0, 0.0);
    for (Region& r : c.regions)
        if (r.name != "spout") r.h = r.km = 0;
    const auto W = [&](const Result& r, const char* name) { return r.gasW[regionOf(c, name)]; };
    const Result apart = run(c);
    EXPECT_GT(W(apart, "spout"), c.inletW + 1e-5);
    EXPECT_NEAR(W(apart, "fountainCore"), W(apart, "spout"), 1e-15);
    EXPECT_NEAR(W(apart, "downcomer"), c.inletW, 1e-15);
    // the fountain region's kernels saw both, by their shares
    EXPECT_NEAR(W(apart, "fountain"), 0.4 * W(apart, "spout") + 0.6 * c.inletW, 1e-12);
    c.regions.back().outOfCore = 0.1;
    const Result crossing = run(c);
    const double seep = 1 - c.spoutShare, out = 0.1;
    const double rest = (seep * c.inletW + out * W(crossing, "spout")) / (seep + out);
    EXPECT_NEAR((W(crossing, "fountain") - 0.4 * W(crossing, "fountainCore")) / 0.6, rest, 1e-12);
    Case exchanging = withCores(shortBatch(2000, 1), 0.4, 0.05, 0.1);
    const Result all = run(exchanging);
    EXPECT_LT(all.waterBalanceRel, 1e-6);
    EXPECT_LT(all.energyBalanceRel, 1e-6);
}

TEST(Spouted, TheCoresExchangeCountsTheShareThatCarriesHeat)
{
    // (T_out - T_in) / (T_core - T_rest) by hand, within [0, 1], 1 where
    // the compartments hardly differ
    EXPECT_NEAR(exchangeShare(383, 375, 398, 358), 8.0 / 40, 1e-15);
    EXPECT_EQ(exchangeShare(415, 342, 412, 354), 1.0);
    EXPECT_EQ(exchangeShare(370, 380, 398, 358), 0.0);
    EXPECT_EQ(exchangeShare(383, 375, 358.5, 358), 1.0);
    // in the network a share 1/2 of into 0.2, out 0.3 is into 0.1, out 0.2:
    // the two-way part halved, the net across the sides kept
    Case half = withCores(shortBatch(10, 1), 0.4, 0.2, 0.3);
    half.regions.back().exchangeShare = 0.5;
    half.regions[regionOf(half, "jet")].exchangeShare = 0.5;
    Case whole = withCores(shortBatch(10, 1), 0.4, 0.1, 0.2);
    whole.regions[regionOf(whole, "jet")].intoCore = 0.015;
    const GasNetwork a = gasNetwork(half), b = gasNetwork(whole);
    ASSERT_EQ(a.order.size(), b.order.size());
    for (std::size_t k = 0; k < a.order.size(); ++k)
    {
        ASSERT_EQ(a.order[k].in.size(), b.order[k].in.size());
        for (std::size_t i = 0; i < a.order[k].in.size(); ++i)
        {
            EXPECT_EQ(a.order[k].in[i].from, b.order[k].in[i].from);
            EXPECT_NEAR(a.order[k].in[i].flow, b.order[k].in[i].flow, 1e-15 * half.airFlow);
        }
    }
}

TEST(Spouted, PlugFlowGasLeavesAsTheExponentialRelaxationWellMixedAsItsLimit)
{
    // one region of 1000 kernels at 25 C that take heat but no water, in a
    // flow that carries as much per kelvin as they take (N = h A n /(G c_p)
    // = 1): over the first step the outlet is T_p + (T_in - T_p) e^-N in
    // plug flow, T_p + (T_in - T_p)/(1 + N) well mixed
    for (const bool plug : {true, false})
    {
        Case c = singleKernel("freeWater", spoutlab::Parameters());
        c.regions[0].km = 0;
        c.gasAtInlet = false;
        c.plugFlow = plug;
        c.bedParticles = 1000;
        const double A = kPi * c.diameter * c.diameter, cp = 1006 + c.inletW * 1860;
        const double N = 1.0;
        c.airFlow = c.bedParticles * c.regions[0].h * A / (cp * N);
        c.duration = c.outputInterval = 0.5;
        const Result r = run(c);
        ASSERT_EQ(r.series.size(), 2u);
        const double drop = plug ? std::exp(-N) : 1 / (1 + N);
        const double expected = c.initialC + (c.inletC - c.initialC) * drop;
        EXPECT_NEAR(r.series[1].outletC, expected, 1e-9) << (plug ? "plug flow" : "well mixed");
        EXPECT_LT(r.energyBalanceRel, 1e-9);
    }
}

namespace
{

Residence histogram(double w, std::vector<double> counts)
{
    Residence r;
    r.binWidth = w;
    r.counts = std::move(counts);
    for (const double n : r.counts) r.samples += static_cast<long>(n);
    r.mean = r.histogramMean();
    return r;
}

} // namespace

// Kaplan-Meier by hand: ended in bins 1 and 3, censored in bins 0 and 2 (at
// risk 4, 3, 2, 1; a censored visit half of its bin): S at the edges 1, 1,
// 2/3, 2/3, 0, every visit within the bins, the mean the area under S.
TEST(SpoutedResidence, CensoredVisitsByKaplanMeier)
{
    Residence r = histogram(0.1, {0, 1, 0, 1});
    r.censor({1, 0, 1}, 99.0, 0.1); // Little's mean unused: nothing lasts beyond
    const double want[4] = {0, 1.0 / 3, 0, 2.0 / 3};
    ASSERT_EQ(r.counts.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.counts[i], want[i], 1e-15) << i;
    EXPECT_EQ(r.tailShare, 0.0);
    EXPECT_NEAR(r.mean, 0.1 * (1 + 5.0 / 6 + 2.0 / 3 + 1.0 / 3), 1e-15);
}

// Visits beyond the window: two of four ended in bin 0, two still open in
// bin 1 (S 1/2 from bin 0 on); the tail past E = 2 s takes the mean to
// Little's 3 s: theta = (3 - 1.25) / 0.5 = 3.5 s. Draws: mean 3 s; the
// residual at a random instant E[T^2] / (2 E[T]), E[T^2] = 0.5 / 3 + 0.5
// (E^2 + 2 E theta + 2 theta^2) = 21.4167 s^2.
TEST(SpoutedResidence, VisitsLongerThanTheWindowFollowLittlesMean)
{
    Residence r = histogram(1.0, {2, 0});
    r.censor({0, 2}, 3.0, 0.01);
    EXPECT_NEAR(r.tailShare, 0.5, 1e-15);
    EXPECT_NEAR(r.tailMean, 3.5, 1e-14);
    EXPECT_EQ(r.mean, 3.0);
    r.prepare();
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const int n = 1000000;
    double sum = 0, sumSq = 0, residual = 0;
    for (int k = 0; k < n; ++k)
    {
        const double t = r.draw(u(rng), u(rng));
        sum += t;
        sumSq += t * t;
        residual += r.drawResidual(u(rng), u(rng), u(rng));
    }
    const double second = 0.5 / 3 + 0.5 * (4 + 2 * 2 * 3.5 + 2 * 3.5 * 3.5);
    const double sigma = std::sqrt(second - 9) / std::sqrt(n);
    EXPECT_NEAR(sum / n, 3.0, 4 * sigma);
    EXPECT_NEAR(sumSq / n, second, 0.01 * second);
    EXPECT_NEAR(residual / n, second / 6, 0.01 * second / 6);
    // a Little's mean below the 1.25 s the window's visits give: within 3
    // of its errors the tail ends at the window's edge, beyond them refused
    Residence edge = histogram(1.0, {2, 0});
    edge.censor({0, 2}, 1.2, 0.02);
    EXPECT_EQ(edge.tailMean, 0.0);
    EXPECT_NEAR(edge.mean, 1.25, 1e-15);
    edge.prepare();
    EXPECT_EQ(edge.draw(0.75, 0.5), 2.0);
    Residence short_ = histogram(1.0, {2, 0});
    EXPECT_THROW(short_.censor({0, 2}, 1.0, 0.05), std::invalid_argument);
}
