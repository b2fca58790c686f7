#pragma once
// The shipped cases of the kinetics paper's figures, and the readings of its
// statements shared by test_PaperTargets.cpp (what the model reproduces) and
// test_PaperDepartures.cpp (where it departs, see the README).
#include <algorithm>
#include <string>
#include <vector>

#include "TestUtil.hpp"
#include "kinetics/Run.hpp"
#include "kinetics/Study.hpp"

namespace kt
{

using namespace procsim::kinetics;

constexpr double hour = 3600.0, minute = 60.0;

inline Results runShipped(const std::string& file, const Overrides& o = {})
{
    return runCase(CaseSource::load(casesDir() + "/" + file).build(o));
}

// 30 mg/L phenol, 30 ppm acetaldehyde, 0.3 mA (the paper's base condition)
inline Results base(const Overrides& o = {})
{
    return runShipped("base_0.3mA_30mgL_30ppm.yaml", o);
}

inline double peak(const Results& r, const std::string& q)
{
    const auto s = r.series(q);
    return *std::max_element(s.begin(), s.end());
}

// Share of TOC held as acetic acid (2 C per molecule).
inline double aceticShareOfToc(const Results& r, double t)
{
    return r.value("AA", t) / 60.052 * 2 * carbonMolarMass / r.value("TOC", t);
}

// "Completely mineralized": below 5 % of the species' own peak.  The paper
// gives no detection limit; 5 % is what a curve that has reached zero on
// Fig 7's scale can still hold.
constexpr double goneFractionOfPeak = 0.05;

// A number the text quotes to one digit ("ca. 7", "ca. 1 mg/L") is read to
// half a unit of that digit: the text cannot be held to more.
constexpr double halfUnit = 0.5;

} // namespace kt
