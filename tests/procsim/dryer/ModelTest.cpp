// Batch simulation: water and energy balances, non-uniformity counting,
// heater saturation, the initial-moisture pattern.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "dryer/Model.hpp"
#include "dryer/Plant.hpp"

using namespace procsim::dryer;

namespace
{
DryerCase batchCase(const std::string& id)
{
    const Plant p = readPlant(DRYER_CASES "/plant.yaml");
    return p.caseFor(p.batch(id));
}
}

// Water: product + air holdup + vented - admitted is constant; energy: product
// + air enthalpy + vented - admitted + wall losses - heaters - fans is
// constant.  Both to 1e-6 relative (the requirement).
TEST(Model, WaterAndEnergyBalancesClose)
{
    for (const char* id : {"1", "4"})
    {
        const BatchResult r = simulate(batchCase(id));
        EXPECT_TRUE(r.reachedTarget) << id;
        EXPECT_LT(r.waterBalanceRel, 1e-6) << id;
        EXPECT_LT(r.energyBalanceRel, 1e-6) << id;
    }
}

// Heater capped well below demand: balances still close, the supply air
// stays below the set-point.
TEST(Model, BalancesCloseWithSaturatedHeaterAndShortCircuit)
{
    DryerCase c = batchCase("1");
    c.heaterPower = 20e3;
    c.ventShortCircuit = 0.8;
    c.ventedFraction = 0.1;
    c.maxTime = 6 * 3600;
    const BatchResult r = simulate(c);
    EXPECT_LT(r.waterBalanceRel, 1e-6);
    EXPECT_LT(r.energyBalanceRel, 1e-6);
    for (const auto& p : r.series) EXPECT_LT(p.tSupply, c.hotAirC);
}

// Energy bookkeeping at the end of the batch: electricity = evaporation
// enthalpy + losses; eta computed from the definition.
TEST(Model, MetricsFollowDefinitions)
{
    const DryerCase c = batchCase("1");
    const BatchResult r = simulate(c);
    EXPECT_NEAR(r.waterEvaporated, c.dryMass * (c.x0 - c.xTarget), 1e-6 * c.dryMass);
    EXPECT_DOUBLE_EQ(r.specificEnergy, r.electricityJ / r.waterEvaporated);
    EXPECT_NEAR(r.eta, r.waterEvaporated * r.latentPerKg / r.electricityJ, 1e-12);
    EXPECT_LT(r.eta, 1.0);
}

TEST(Model, NonUniformityCounts)
{
    // mean 10: deviations 0, 6, 6, 12, 12 -> f1 = 40 %, f2 = 40 %
    std::vector<double> x{10.0, 10.6, 9.4, 11.2, 8.8};
    double f1, f2;
    nonUniformity(x, f1, f2);
    EXPECT_DOUBLE_EQ(f1, 40.0);
    EXPECT_DOUBLE_EQ(f2, 40.0);
}

TEST(Model, InitialMoisturePatternKeepsTheBatchAverage)
{
    DryerCase c = batchCase("2");
    c.x0Spread = 0.08;
    const auto x = c.initialTrayMoisture();
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / x.size();
    EXPECT_NEAR(mean, c.x0, 1e-12);
    double var = 0;
    for (double v : x) var += (v - mean) * (v - mean);
    EXPECT_NEAR(std::sqrt(var / x.size()) / c.x0, 0.08, 1e-12);
}

// No air-distribution differences and no initial spread: every tray dries
// alike, f1 = f2 = 0.
TEST(Model, UniformAirGivesUniformProduct)
{
    DryerCase c = batchCase("3");
    c.cartFactors.clear();
    c.trayFactors.clear();
    c.x0Spread = 0;
    const BatchResult r = simulate(c);
    EXPECT_DOUBLE_EQ(r.f1, 0.0);
    EXPECT_DOUBLE_EQ(r.f2, 0.0);
}

// Better venting of humid air (less short-circuit) dries faster and cheaper,
// the paper's qualitative finding.
TEST(Model, VentingHumidAirHelps)
{
    DryerCase c = batchCase("1");
    c.ventShortCircuit = 0.7;
    const BatchResult oldVent = simulate(c);
    c.ventShortCircuit = 0.0;
    const BatchResult newVent = simulate(c);
    EXPECT_LT(newVent.dryingTime, oldVent.dryingTime);
    EXPECT_LT(newVent.specificEnergy, oldVent.specificEnergy);
}

// Warm-up of a wet load in a poorly vented dryer with a strong gas film
// supersaturates the return air; the excess condenses and drains, the
// balances still close and the relative humidity stays at saturation (within
// the relaxation).  (With the estimated film of plant.yaml the cold product
// evaporates too slowly for that, so the film is raised here.)
TEST(Model, SupersaturatedReturnAirCondenses)
{
    DryerCase c = batchCase("2");
    c.hConv = 20;
    c.ventShortCircuit = 0.64;
    const BatchResult r = simulate(c);
    EXPECT_GT(r.condensateKg, 0.0);
    double rhMax = 0;
    for (const auto& p : r.series) rhMax = std::max(rhMax, p.rhReturn);
    EXPECT_LT(rhMax, 1.02);
    EXPECT_LT(r.waterBalanceRel, 1e-6);
    EXPECT_LT(r.energyBalanceRel, 1e-6);
}

// The paper: 70 degC was the suitable hot-air temperature, 80 degC scorched
// the product.  With the scorch limit between the two, the calibrated model
// flags 80 and not 70 (the product heats towards the air as drying slows).
TEST(Model, EightyDegreesScorchesSeventyDoesNot)
{
    const Plant p = readPlant(DRYER_CASES "/plant.yaml");
    DryerCase c = p.caseFor(p.batch("1"), "modified");
    c.hotAirC = 70;
    EXPECT_FALSE(simulate(c).scorched);
    c.hotAirC = 80;
    EXPECT_TRUE(simulate(c).scorched);
}
