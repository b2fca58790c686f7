#pragma once
// Hourly meteorology from a CSV file with units in the column names:
//   hour                       consecutive integers (one row per hour, no gaps)
//   wind_speed_m_s             at the reference height (10 m)
//   wind_direction_deg         the direction the wind blows FROM, clockwise from north
//   temperature_C              ambient temperature             (Gaussian/Monte Carlo)
//   mixing_height_m            mixing height                   (Gaussian/Monte Carlo)
//   cloud_cover_oktas          total cloud cover, 0..8         (Gaussian/Monte Carlo)
//   stability                  optional: Pasquill-Gifford class 1..6 (A..F); if absent
//                              it is derived from wind, cloud and time of day
#include <string>
#include <vector>

namespace procsim::plume
{

struct MetHour
{
    double speed = 0;         // m/s at 10 m
    double directionFrom = 0; // deg
    double temperatureC = 25;
    double mixingHeight = 1000; // m
    double cloudOktas = 4;
    int stability = 0; // 1..6 (A..F), 0 = derive
};

struct MetSeries
{
    std::vector<MetHour> hours;
    int firstHour = 0; // value in the 'hour' column of the first row
};

// `full` = require temperature, mixing height and cloud cover as well.
MetSeries readMet(const std::string& path, bool full);
void writeMet(const std::string& path, const std::vector<MetHour>& hours, bool full);

} // namespace procsim::plume
