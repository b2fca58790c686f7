// The properties the drying models are built on, by hand from their published
// formulas: vapour densities and diffusivity of moist air, the Arrhenius law,
// the heat capacity of a corn kernel and Thompson's thin-layer equation.

#include "Arrhenius.hpp"
#include "CornProperties.hpp"
#include "MoistAir.hpp"
#include "Psychrometrics.hpp"
#include "ThompsonThinLayer.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace spoutlab;

namespace
{

void expectRel(double value, double expected, double tol)
{
    EXPECT_LT(std::fabs(value - expected), tol * std::fabs(expected)) << value << " vs " << expected;
}

} // namespace

// Air at 60 C, W = 0.01, 101.325 kPa:
//   p_w = 101325 0.01/0.631945 = 1603.38 Pa, R_v = 287.042/0.621945 = 461.523
//   rho_v,inf = 1603.38/(461.523 333.15) = 0.0104281 kg/m^3
//   p_ws(60 C) = 19946 Pa (steam tables), so RH = 0.080386 to the table's 1e-3
TEST(MoistAir, VapourDensityAndHumidityByHand)
{
    const MoistAir air{333.15, 0.01, 101325.0};
    expectRel(waterVapourGasConstant(), 461.523, 1e-6);
    expectRel(vapourPressure(air), 1603.38, 1e-5);
    expectRel(vapourDensity(air), 0.0104281, 1e-5);
    expectRel(relativeHumidity(air), 1603.38 / 19946.0, 1e-3);
    // no vapour, no density
    EXPECT_EQ(vapourDensity({333.15, 0.0, 101325.0}), 0.0);
}

// Saturated vapour as an ideal gas, p_ws/(R_v T): at 60 C 19946/(461.523
// 333.15) = 0.129725 kg/m^3; the steam tables' 1/v_g = 1/7.667 = 0.13043 lies
// 0.5 % above (non-ideality of the vapour, which the psychrometrics neglect).
TEST(MoistAir, SaturatedVapourDensity)
{
    expectRel(saturationVapourDensity(333.15), 0.129725, 1e-3);
    expectRel(saturationVapourDensity(333.15), 1.0 / 7.667, 6e-3);
    // the humidity ratio and the densities agree: rho_v,sat = W_s rho_dry air
    const double ws = psy::saturationHumidityRatio(60.0, 101325.0);
    const double dryAir = (101325.0 - psy::saturationPressure(60.0)) / (287.042 * 333.15);
    expectRel(saturationVapourDensity(333.15), ws * dryAir, 1e-12);
}

// Massman (1998): D_v = 0.2178e-4 (p_0/p)(T/273.15)^1.81;
// 60 C: (333.15/273.15)^1.81 = 1.21966^1.81 = 1.43249, D_v = 3.11997e-5 m^2/s;
// at 90 kPa 101325/90000 times that, 3.51256e-5.
TEST(MoistAir, VapourDiffusivityMassman)
{
    expectRel(vapourDiffusivity(273.15, 101325.0), 0.2178e-4, 1e-12);
    expectRel(vapourDiffusivity(333.15, 101325.0), 3.11997e-5, 1e-5);
    expectRel(vapourDiffusivity(333.15, 90000.0), 3.51256e-5, 1e-5);
}

// k(T) = k_ref exp(-E_a/R (1/T - 1/T_ref)): E_a = 30 kJ/mol from 313.15 to
// 333.15 K is exp(30000/8.314462618 (1/313.15 - 1/333.15)) = exp(0.691711)
// = 1.99713 times faster; about an infinite reference it is D_0 exp(-E_a/RT),
// 5e-6 exp(-10.8311) = 9.89367e-11.
TEST(Arrhenius, ByHand)
{
    expectRel(arrhenius(1.0, 30000.0, 333.15, 313.15), 1.99713, 1e-5);
    EXPECT_EQ(arrhenius(2.5, 30000.0, 313.15, 313.15), 2.5);
    expectRel(arrhenius(5e-6, 30000.0, 333.15, INFINITY), 9.89367e-11, 1e-5);
}

// m_d (c_d + X c_w): 2.48e-4 kg at X = 0.33, (1465 + 0.33 4186) = 2846.38,
// C = 0.705902 J/K.
TEST(CornProperties, HeatCapacityOfDrySolidAndWater)
{
    expectRel(corn::heatCapacity(2.48e-4, 0.33), 0.705902, 1e-6);
    EXPECT_EQ(corn::heatCapacity(1.0, 0.0), 1465.0);
    EXPECT_EQ(corn::kWaterSpecificHeat, 4186.0);
}

// Thompson et al. (1968), T in degF, t in h: t = A ln MR + B (ln MR)^2
//   60 C = 140 F: A = -1.862 + 0.6832 = -1.17880, B = 427.4 e^-4.62 = 4.21108
//     t(MR 0.5) = 1.17880 0.693147 + 4.21108 0.480453 = 2.84031 h
//   40 C = 104 F: A = -1.35448, B = 13.8145, t(0.5) = 7.57608 h
//   80 C = 176 F: A = -1.00312, B = 1.28367, t(0.5) = 1.31205 h
TEST(ThompsonThinLayer, TimeToHalfTheFreeMoistureByHand)
{
    expectRel(thompson::dryingTime(0.5, 333.15), 2.84031 * 3600.0, 1e-5);
    expectRel(thompson::dryingTime(0.5, 313.15), 7.57608 * 3600.0, 1e-5);
    expectRel(thompson::dryingTime(0.5, 353.15), 1.31205 * 3600.0, 1e-5);
    EXPECT_EQ(thompson::dryingTime(1.0, 333.15), 0.0);
}

TEST(ThompsonThinLayer, MoistureRatioIsTheInverse)
{
    EXPECT_EQ(thompson::moistureRatio(0.0, 333.15), 1.0);
    for (double t : {60.0, 3600.0, 2.84031 * 3600.0, 36000.0})
    {
        const double mr = thompson::moistureRatio(t, 333.15);
        EXPECT_NEAR(thompson::dryingTime(mr, 333.15), t, 1e-9 * t);
    }
    expectRel(thompson::moistureRatio(2.84031 * 3600.0, 333.15), 0.5, 1e-5);
    // hotter air dries faster
    EXPECT_LT(thompson::moistureRatio(3600.0, 353.15), thompson::moistureRatio(3600.0, 333.15));
}
