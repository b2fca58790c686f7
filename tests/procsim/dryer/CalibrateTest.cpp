// Calibration recovers known parameters from synthetic measurements.
#include <gtest/gtest.h>

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
