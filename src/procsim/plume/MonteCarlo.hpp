#pragma once
// Monte Carlo meteorology (the stochastic Saraburi study): gamma
// distributions fitted to historical hourly meteorology per calendar month
// and 6-hour block of the day, synthetic years whose hours are correlated
// through the weighting parameter w, and the Gaussian model run for each.
//
// Correlation: each variable carries a normal score z_t with
//     z_t = w z_{t-1} + sqrt(1 - w^2) e_t,   e_t ~ N(0, 1),
// and its value is the gamma quantile of Phi(z_t) for the month/block of hour
// t.  w weights the previous hour (w = 0: independent hours; w -> 1: a
// persistent state), the lag-1 correlation of the scores is w, and every hour
// keeps exactly the fitted gamma distribution.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "plume/Gamma.hpp"
#include "plume/Met.hpp"

namespace procsim::plume
{

enum MetVariable
{
    kDirection = 0,
    kSpeed,
    kTemperature,
    kMixingHeight,
    kCloud,
    kMetVariables
};
const char* metVariableName(int v);

struct Climate
{
    // [variable][month 0..11][block 0..3 = 0-6 h, 6-12 h, 12-18 h, 18-24 h]
    std::array<std::array<std::array<GammaFit, 4>, 12>, kMetVariables> fit;
};

int monthOfDay(int dayOfYear); // 0..11 for day 1..365

// startDay/startHour: calendar position of the first history row.
Climate fitClimate(const MetSeries& history, int startDay, double startHour);
// One synthetic year (8760 h from 1 January, 0 h).
std::vector<MetHour> synthesiseYear(const Climate& c, double w, Stream& rng);

} // namespace procsim::plume
