// Calibration recovers known parameters from synthetic measurements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dryer/Calibrate.hpp"
#include "dryer/Plant.hpp"

using namespace procsim::dryer;

TEST(Calibrate, RecoversRateConstantAndWallLossFromSyntheticBatches)
{
    Plant p = readPlant(DRYER_DATA "/small_plant.yaml");
    // truth: k = 0.30 1/h, UA = 80 W/K; "measure" batch a at 70 and a copy at 60 degC
    p.set("rate_constant_per_h", 0.30);
    p.set("wall_UA_W_per_K", 80);
    BatchSpec hot = p.batch("a"), cold = hot;
    cold.id = "cold";
    cold.hotAirC = 60;
    p.batches = {hot, cold};
    for (auto& b : p.batches)
    {
        const BatchResult r = simulate(p.caseFor(b));
        ASSERT_TRUE(r.reachedTarget);
        b.measuredTime = r.dryingTime;
        b.measuredElectricity = r.electricityJ;
    }
    p.fit = {{"rate_constant_per_h", 0.02, 2.0}, {"wall_UA_W_per_K", 0.0, 500.0}};
    p.calibrateOn = {"a", "cold"};
    p.set("rate_constant_per_h", 0.20);
    p.set("wall_UA_W_per_K", 30);
    const CalibrationResult c = calibrate(p);
    // the ODE tolerance during calibration (1e-6) bounds how well the
    // synthetic data are matched; 1 % on the parameters is well above it
    EXPECT_NEAR(c.fitted[0] / 0.30, 1.0, 0.01);
    EXPECT_NEAR(c.fitted[1] / 80.0, 1.0, 0.01);
    EXPECT_NEAR(p.get("rate_constant_per_h"), c.fitted[0], 1e-12);
}

namespace
{

// The small plant "measured" by the model itself: batch a (old venting) and a
// copy at 60 degC, with k = 0.30 1/h and an old-duct short-circuit of 0.6.
Plant syntheticPlant()
{
    Plant p = readPlant(DRYER_DATA "/small_plant.yaml");
    p.set("rate_constant_per_h", 0.30);
    p.set("venting.old.vent_short_circuit_fraction", 0.6);
    BatchSpec hot = p.batch("a"), cold = hot, next = p.batch("b");
    cold.id = "cold";
    cold.hotAirC = 60;
    p.batches = {hot, cold, next};
    for (auto* b : {&p.batches[0], &p.batches[1]})
    {
        const BatchResult r = simulate(p.caseFor(*b));
        b->measuredTime = r.dryingTime;
        b->measuredElectricity = r.electricityJ;
    }
    p.fit = {{"rate_constant_per_h", 0.02, 2.0}, {"venting.old.vent_short_circuit_fraction", 0.0, 0.95}};
    p.calibrateOn = {"a", "cold"};
    p.predict = {"b"};
    p.predictVenting = "modified";
    p.timeTolerance = 0.01;
    p.electricityTolerance = 0.01;
    return p;
}

// The plant of one profile point: held and refitted values applied.
Plant atPoint(Plant p, const ProfilePoint& pt)
{
    for (std::size_t a = 0; a < pt.held.size(); ++a) p.set(p.profile[a].name, pt.held[a]);
    for (std::size_t i = 0; i < pt.refitNames.size(); ++i) p.set(pt.refitNames[i], pt.refitted[i]);
    return p;
}

} // namespace

TEST(Profile, AcceptedRefitsReproduceTheCalibrationBatchesWithinTolerance)
{
    Plant p = syntheticPlant();
    p.profile = {{"venting.old.vent_short_circuit_fraction", {0.0, 0.6, 0.9}}};
    const auto points = profile(p);
    ASSERT_EQ(points.size(), 3u);
    // the true short-circuit is refitted to the truth and accepted
    EXPECT_TRUE(points[1].accepted);
    ASSERT_EQ(points[1].refitNames, std::vector<std::string>{"rate_constant_per_h"});
    EXPECT_NEAR(points[1].refitted[0] / 0.30, 1.0, 0.01);
    int accepted = 0;
    for (const auto& pt : points)
    {
        ASSERT_FALSE(pt.failed);
        if (!pt.accepted) continue;
        ++accepted;
        // re-run the accepted parameter set independently of the profile
        const Plant q = atPoint(p, pt);
        for (const auto& id : q.calibrateOn)
        {
            const BatchCheck c = checkBatch(q, id, q.batch(id).venting);
            EXPECT_LE(std::fabs(c.timeError), p.timeTolerance) << id;
            EXPECT_LE(std::fabs(c.electricityError), p.electricityTolerance) << id;
            EXPECT_LT(c.result.waterBalanceRel, 1e-6);
            EXPECT_LT(c.result.energyBalanceRel, 1e-6);
        }
        for (const auto& c : pt.predicted)
        {
            EXPECT_LT(c.result.waterBalanceRel, 1e-6);
            EXPECT_LT(c.result.energyBalanceRel, 1e-6);
        }
    }
    EXPECT_GE(accepted, 1);
}

TEST(Profile, HoldingAWrongRateConstantIsRejected)
{
    Plant p = syntheticPlant();
    // with k held at a third of the truth, the short-circuit alone cannot
    // bring both batches back within 1 %
    p.profile = {{"rate_constant_per_h", {0.10}}};
    const auto points = profile(p);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_FALSE(points[0].failed);
    EXPECT_FALSE(points[0].accepted);
    EXPECT_GT(std::max(points[0].worstTimeError, points[0].worstElectricityError), 0.01);
    EXPECT_EQ(band(points, "b", [](const BatchResult& r) { return r.dryingTime; }).members, 0);
}

TEST(Profile, BandContainsTheCentralPrediction)
{
    Plant p = syntheticPlant();
    p.set("rate_constant_per_h", 0.25);
    p.set("venting.old.vent_short_circuit_fraction", 0.3);
    calibrate(p);
    // the grid brackets the fitted 0.6 without containing it
    p.profile = {{"venting.old.vent_short_circuit_fraction", {0.45, 0.55, 0.65, 0.75}}};
    p.timeTolerance = p.electricityTolerance = 0.03;
    const auto points = profile(p);
    const BatchResult central = simulate(p.caseFor(p.batch("b"), p.predictVenting));
    const auto time = [](const BatchResult& r) { return r.dryingTime; };
    const auto energy = [](const BatchResult& r) { return r.specificEnergy; };
    const Band bt = band(points, "b", time), be = band(points, "b", energy);
    ASSERT_GE(bt.members, 2);
    EXPECT_TRUE(bt.contains(central.dryingTime)) << bt.lo << " " << bt.hi;
    EXPECT_TRUE(be.contains(central.specificEnergy)) << be.lo << " " << be.hi;
    // the venting direction matters for the prediction: the band has width
    EXPECT_GT(bt.hi - bt.lo, 0.01 * central.dryingTime);
}
