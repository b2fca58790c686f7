#include "DemTimeStep.hpp"

#include <gtest/gtest.h>

#include <cmath>

// Draft-plate paper eq 11 with its own numbers: d = 8 mm, rho = 1231 kg/m3,
// k = 800 N/m. By hand: m = 1231 pi (8e-3)^3/6 = 3.3001e-4 kg,
// sqrt(m/k) = 6.4227e-4 s, times pi/5 = 4.0355e-4 s (the paper rounds to 4.0e-4).
TEST(DemTimeStep, PaperNumbers)
{
    const double pi = std::acos(-1.0);
    const double mass = 1231.0 * pi * 8e-3 * 8e-3 * 8e-3 / 6.0;
    const double dt = spoutlab::demTimeStepLimit(mass, 800.0);
    EXPECT_NEAR(dt, 4.0355e-4, 1e-8);
    EXPECT_LT(3e-4, dt); // the papers' chosen step is inside the limit
}

TEST(DemTimeStep, ScalesWithSqrtMassOverStiffness)
{
    const double base = spoutlab::demTimeStepLimit(1e-4, 100.0);
    EXPECT_NEAR(spoutlab::demTimeStepLimit(4e-4, 100.0) / base, 2.0, 1e-14);
    EXPECT_NEAR(spoutlab::demTimeStepLimit(1e-4, 400.0) / base, 0.5, 1e-14);
}
