// Psychrometrics (coupling/Psychrometrics, shared by procsim's tray dryer and
// the spouted bed's drying) against published reference values and, for the
// inverse solvers, against their defining equations over 0..200 degC.
#include <gtest/gtest.h>

#include <cmath>

#include "Psychrometrics.hpp"

namespace psy = spoutlab::psy;

// Saturation pressure over liquid water: ASHRAE Fundamentals (2017) ch. 1
// Table 3 / IAPWS steam tables [Pa].
TEST(Psychrometrics, SaturationPressureOverWaterMatchesSteamTables)
{
    const struct
    {
        double t, p, tol;
    } ref[] = {{0.01, 611.66, 2e-3}, {20, 2339.2, 1e-3},    {40, 7384.9, 1e-3},    {60, 19946.0, 1e-3},
               {80, 47416.0, 1e-3},  {100, 101418.0, 1e-3}, {150, 476160.0, 2e-3}, {200, 1554900.0, 3e-3}};
    for (const auto& r : ref) EXPECT_NEAR(psy::saturationPressure(r.t) / r.p, 1.0, r.tol) << "t = " << r.t;
}

// Over ice: ASHRAE Fundamentals ch. 1 Table 3 [Pa].
TEST(Psychrometrics, SaturationPressureOverIce)
{
    EXPECT_NEAR(psy::saturationPressure(-20) / 103.26, 1.0, 2e-3);
    EXPECT_NEAR(psy::saturationPressure(-40) / 12.84, 1.0, 5e-3);
}

TEST(Psychrometrics, BoilingPointAtOneAtmosphere)
{
    // 99.97 degC on ITS-90 (steam tables)
    EXPECT_NEAR(psy::saturationTemperature(101325.0), 99.97, 0.03);
}

// Saturated air at 20 degC, 101.325 kPa: ASHRAE Table 2 gives W_s = 0.014758
// and h_s = 57.555 kJ/kg; the tables include the enhancement factor (~0.4 %)
// that ideal mixing leaves out, hence 0.6 %.
TEST(Psychrometrics, SaturatedAirAt20C)
{
    const double ws = psy::saturationHumidityRatio(20.0, psy::kAtm);
    EXPECT_NEAR(ws / 0.014758, 1.0, 6e-3);
    EXPECT_NEAR(psy::enthalpy(20.0, ws) / 57555.0, 1.0, 6e-3);
}

// ASHRAE Fundamentals ch. 1 worked example: 40 degC dry bulb, 20 degC
// thermodynamic wet bulb, 101.325 kPa -> W ~ 6.5 g/kg, h ~ 56.7 kJ/kg,
// relative humidity ~ 14 %, v ~ 0.896 m3/kg.
TEST(Psychrometrics, AshraeWorkedExample40C20CWetBulb)
{
    const double W = psy::humidityRatioFromWetBulb(40.0, 20.0, psy::kAtm);
    EXPECT_NEAR(W, 0.0065, 0.00015);
    EXPECT_NEAR(psy::enthalpy(40.0, W) / 1e3, 56.7, 0.4);
    EXPECT_NEAR(psy::relativeHumidity(40.0, W, psy::kAtm), 0.14, 0.005);
    EXPECT_NEAR(psy::specificVolume(40.0, W, psy::kAtm), 0.896, 0.002);
    EXPECT_NEAR(psy::wetBulb(40.0, W, psy::kAtm), 20.0, 1e-6);
}

// Common psychrometric-chart reading: 25 degC, 50 % -> wet bulb 17.9 degC,
// dew point 13.9 degC (sea level).
TEST(Psychrometrics, ChartReading25C50Percent)
{
    const double W = psy::humidityRatioFromRH(25.0, 0.5, psy::kAtm);
    EXPECT_NEAR(psy::wetBulb(25.0, W, psy::kAtm), 17.9, 0.1);
    EXPECT_NEAR(psy::dewPoint(W, psy::kAtm), 13.9, 0.1);
}

// The wet-bulb solver converges everywhere from 0 to 200 degC, for dry to
// saturated air and for dryer pressures, and satisfies its defining equation.
TEST(Psychrometrics, WetBulbAlwaysConvergesFrom0To200C)
{
    int cases = 0;
    for (double p : {80e3, psy::kAtm, 110e3})
        for (double t = 0.0; t <= 200.0; t += 2.5)
            for (double rh : {0.0, 1e-4, 0.01, 0.05, 0.1, 0.3, 0.5, 0.8, 0.95, 1.0})
            {
                if (rh * psy::saturationPressure(t) >= p) continue;
                const double W = psy::humidityRatioFromRH(t, rh, p);
                const double twb = psy::wetBulb(t, W, p);
                ASSERT_TRUE(std::isfinite(twb)) << t << " " << rh;
                EXPECT_LE(twb, t + 1e-9);
                if (W > 0)
                {
                    EXPECT_GE(twb, psy::dewPoint(W, p) - 1e-9);
                }
                // (a wet bulb right at 0 degC sits on the ice/water switch of
                // the formulation, where eq 35 and eq 37 do not meet exactly)
                if (std::fabs(twb) > 1e-6)
                {
                    EXPECT_NEAR(psy::humidityRatioFromWetBulb(t, twb, p), W, 1e-9 * (1 + W))
                        << "t " << t << " rh " << rh << " p " << p;
                }
                if (rh == 1.0)
                {
                    EXPECT_NEAR(twb, t, 1e-6);
                }
                ++cases;
            }
    EXPECT_GT(cases, 600);
}

TEST(Psychrometrics, InversesRoundTrip)
{
    for (double t = 0; t <= 200; t += 10)
    {
        const double W = 0.05;
        EXPECT_NEAR(psy::temperatureFromEnthalpy(psy::enthalpy(t, W), W), t, 1e-9);
    }
    for (double td = -50; td <= 95; td += 5)
    {
        const double W = psy::humidityRatioFromPw(psy::saturationPressure(td), psy::kAtm);
        EXPECT_NEAR(psy::dewPoint(W, psy::kAtm), td, 1e-8);
    }
}

TEST(Psychrometrics, OutOfRangeIsAnErrorNotAGuess)
{
    EXPECT_THROW(psy::saturationPressure(250.0), std::domain_error);
    const double wSat = psy::saturationHumidityRatio(30.0, psy::kAtm);
    EXPECT_THROW(psy::wetBulb(30.0, 1.5 * wSat, psy::kAtm), std::domain_error);
}
