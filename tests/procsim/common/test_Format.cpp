// The one number formatter: the same text as C's printf conversions (the
// reference), whose %g, %f and %e every earlier table and CSV was written with.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "common/Format.hpp"

namespace
{

std::string printfOf(const char* format, int precision, double v)
{
    char buf[512]; // room for DBL_MAX in %f
    std::snprintf(buf, sizeof buf, format, precision, v);
    return buf;
}

const double values[] = {0.0,
                         1.0,
                         -2.5,
                         1.0 / 3.0,
                         2.0 / 3.0 * 1e-10,
                         123456789.0,
                         1e21,
                         0.1 + 0.2,
                         9.9999996,
                         1e-300,
                         5e-324,
                         1.7976931348623157e308,
                         0.000123456,
                         -7.25e5,
                         std::numeric_limits<double>::quiet_NaN()};

} // namespace

TEST(Format, SignificantDigitsAsPrintfG)
{
    for (double v : values)
        for (int p : {1, 3, 4, 6, 10, 17})
            EXPECT_EQ(procsim::formatNumber(v, p), printfOf("%.*g", p, v)) << v << " with " << p << " digits";
}

TEST(Format, FixedDecimalsAsPrintfF)
{
    for (double v : values)
        for (int p : {0, 1, 2, 4, 6})
            EXPECT_EQ(procsim::formatFixed(v, p), printfOf("%.*f", p, v))
                << v << " with " << p << " decimals";
}

TEST(Format, ScientificAsPrintfE)
{
    for (double v : values)
        for (int p : {1, 3}) EXPECT_EQ(procsim::formatScientific(v, p), printfOf("%.*e", p, v)) << v;
}

TEST(Format, HoursAndMinutesRoundToTheMinute)
{
    EXPECT_EQ(procsim::formatHoursMinutes(0), "0:00");
    EXPECT_EQ(procsim::formatHoursMinutes(25500), "7:05");  // 425 min
    EXPECT_EQ(procsim::formatHoursMinutes(3599.9), "1:00"); // 59.998 min rounds up
    EXPECT_EQ(procsim::formatHoursMinutes(89.9), "0:01");   // 1.498 min
    EXPECT_EQ(procsim::formatHoursMinutes(30 * 3600.0), "30:00");
}
