#pragma once
// The one number formatter of procsim ({fmt}): CSV cells, tables, summaries
// and messages all print numbers through these, so a value reads the same
// wherever it appears.
#include <string>

namespace procsim
{

// v with `significant` digits, as printf's %g (the CSV and summary style).
std::string formatNumber(double v, int significant = 6);

// v with a fixed number of decimals (table columns: 12.35).
std::string formatFixed(double v, int decimals);

// v in scientific notation with `decimals` after the point (1.2e-10).
std::string formatScientific(double v, int decimals);

// A duration as hours and minutes, "7:05" (the dryer papers' drying times).
std::string formatHoursMinutes(double seconds);

} // namespace procsim
