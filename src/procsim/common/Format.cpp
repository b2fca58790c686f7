#include "common/Format.hpp"

#include <cmath>

#include <fmt/format.h>

namespace procsim
{

std::string formatNumber(double v, int significant)
{
    return fmt::format("{:.{}g}", v, significant);
}

std::string formatFixed(double v, int decimals)
{
    return fmt::format("{:.{}f}", v, decimals);
}

std::string formatScientific(double v, int decimals)
{
    return fmt::format("{:.{}e}", v, decimals);
}

std::string formatHoursMinutes(double seconds)
{
    const long minutes = std::lround(seconds / 60);
    return fmt::format("{}:{:02}", minutes / 60, minutes % 60);
}

} // namespace procsim
