#include "plume/MonteCarlo.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/Cli.hpp"

namespace procsim::plume
{

namespace
{

const int kMonthDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};

double value(const MetHour& h, int v)
{
    switch (v)
    {
    case kDirection: return h.directionFrom;
    case kSpeed: return h.speed;
    case kTemperature: return h.temperatureC + 273.15; // fitted in kelvin (always > 0)
    case kMixingHeight: return h.mixingHeight;
    default: return h.cloudOktas;
    }
}

} // namespace

const char* metVariableName(int v)
{
    static const char* names[] = {"wind_direction_deg", "wind_speed_m_s", "temperature_K", "mixing_height_m",
                                  "cloud_cover_oktas"};
    return names[v];
}

int monthOfDay(int day)
{
    int d = (day - 1) % 365;
    for (int m = 0; m < 12; ++m)
    {
        if (d < kMonthDays[m]) return m;
        d -= kMonthDays[m];
    }
    return 11;
}

Climate fitClimate(const MetSeries& history, int startDay, double startHour)
{
    std::array<std::array<std::array<std::vector<double>, 4>, 12>, kMetVariables> samples;
    for (std::size_t t = 0; t < history.hours.size(); ++t)
    {
        const double hour = startHour + static_cast<double>(t);
        const int day = (startDay - 1 + static_cast<int>(hour / 24)) % 365 + 1;
        const int month = monthOfDay(day);
        const int block = static_cast<int>(std::fmod(hour, 24.0)) / 6;
        for (int v = 0; v < kMetVariables; ++v)
            samples[v][month][block].push_back(value(history.hours[t], v));
    }
    Climate c;
    for (int v = 0; v < kMetVariables; ++v)
        for (int m = 0; m < 12; ++m)
            for (int b = 0; b < 4; ++b)
            {
                const auto& s = samples[v][m][b];
                if (s.size() < 10)
                {
                    throw InputError("history: month " + std::to_string(m + 1) + ", hours "
                                     + std::to_string(6 * b) + "-" + std::to_string(6 * b + 6) + " has only "
                                     + std::to_string(s.size())
                                     + " values (give at least one full year of hourly meteorology)");
                }
                try
                {
                    c.fit[v][m][b] = fitGamma(s);
                }
                catch (const std::exception& e)
                {
                    throw InputError(std::string("history: ") + metVariableName(v) + ", month "
                                     + std::to_string(m + 1) + ": " + e.what());
                }
            }
    return c;
}

std::vector<MetHour> synthesiseYear(const Climate& c, double w, Stream& rng)
{
    std::vector<MetHour> out(8760);
    std::array<double, kMetVariables> z{};
    for (auto& v : z) v = rng.normal(); // stationary start
    const double s = std::sqrt(1 - w * w);
    for (int t = 0; t < 8760; ++t)
    {
        const int day = t / 24 + 1;
        const int month = monthOfDay(day);
        const int block = (t % 24) / 6;
        std::array<double, kMetVariables> x{};
        for (int v = 0; v < kMetVariables; ++v)
        {
            if (t > 0) z[v] = w * z[v] + s * rng.normal();
            x[v] = gammaQuantileZ(c.fit[v][month][block], z[v]);
        }
        MetHour& h = out[t];
        h.directionFrom = std::fmod(x[kDirection], 360.0);
        h.speed = x[kSpeed];
        h.temperatureC = x[kTemperature] - 273.15;
        h.mixingHeight = std::max(x[kMixingHeight], 50.0);
        h.cloudOktas = std::min(x[kCloud], 8.0);
    }
    return out;
}

} // namespace procsim::plume
