// Gas-side corona formulas (toluene paper eqs 1-2, 4; acetaldehyde paper eqs 1-2).
#include <gtest/gtest.h>

#include <cmath>

#include "kinetics/Corona.hpp"

using namespace procsim::kinetics::corona;

TEST(KineticsCorona, NumberDensityIsLoschmidtAtStp)
{
    EXPECT_NEAR(numberDensity(101325.0, 273.15), 2.6867811e25, 1e-6 * 2.6867811e25);
}

TEST(KineticsCorona, MeanEOverNIsTheAreaAverageOfEq1)
{
    // eq 2 is the integral of eq 1 over the annulus divided by its area: check by quadrature
    const double v = 15.3e3, r0 = 0.25e-3, r = 18.5e-3, n = numberDensity(101325.0, 298.15);
    const int m = 200000;
    double integral = 0;
    for (int i = 0; i < m; ++i)
    {
        const double x = r0 + (i + 0.5) * (r - r0) / m; // midpoint rule
        integral += 2 * M_PI * x * field(v, x, r, r0) / n * (r - r0) / m;
    }
    const double mean = integral / (M_PI * (r * r - r0 * r0));
    EXPECT_NEAR(meanEOverN(v, r, r0, n), mean, 1e-9 * mean);
}

TEST(KineticsCorona, PaperVoltagesGiveItsTrends)
{
    // toluene paper: 0.5 mA needs 14.8, 15.3, 17.0 kV (wires 0.3, 0.5, 0.9 mm, 37 mm anode) at room
    // temperature and 4.1, 5.9, 6.4 kV at 400 C; <E/N> is higher for a thicker cathode and falls
    // with temperature.
    const double d[] = {0.3e-3, 0.5e-3, 0.9e-3}, vRoom[] = {14.8e3, 15.3e3, 17.0e3},
                 vHot[] = {4.1e3, 5.9e3, 6.4e3};
    const double nRoom = numberDensity(101325.0, 298.15), nHot = numberDensity(101325.0, 673.15);
    double prev = 0;
    for (int i = 0; i < 3; ++i)
    {
        const double room = meanEOverN(vRoom[i], 18.5e-3, d[i] / 2, nRoom) / townsend;
        const double hot = meanEOverN(vHot[i], 18.5e-3, d[i] / 2, nHot) / townsend;
        EXPECT_GT(room, prev);
        EXPECT_LT(hot, room);
        prev = room;
        // order of magnitude of a dc corona: 10-20 Td here
        EXPECT_GT(room, 5.0);
        EXPECT_LT(room, 50.0);
    }
}

TEST(KineticsCorona, RemovalAndEnergeticEfficiency)
{
    EXPECT_DOUBLE_EQ(removalEfficiency(600.0, 150.0), 0.75);
    // same molar flow at 200 C: residence time shorter by 298.15/473.15, psi' larger by the inverse
    EXPECT_NEAR(residenceCorrected(0.5, 473.15, 298.15), 0.5 * 473.15 / 298.15, 1e-15);
    // J: 1e-7 mol/s removed with 0.5 mA at 10 kV (5 W) -> 2e-8 mol/J
    EXPECT_NEAR(energeticEfficiency(3e-7, 2e-7, 0.5e-3, 10e3), 2e-8, 1e-20);
}
