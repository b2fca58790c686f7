#pragma once
// The case of `procsim dryer spouted` (YAML) and the circulation statistics
// it names (circulation.json, "spoutlab-circulation 1", written by
// spoutFoam), read into a spouted::Case with one-line errors.
//
// The statistics must come from the case's bed and operating point: run.u_s
// (or the inlet mass flow), every geometry entry and the particle diameter
// agree with the case's within 0.1 %. Every residence histogram needs at
// least kMinResidences residence times, more where the times scatter more:
// n >= (cv / 0.05)^2, cv = std/mean, so that the mean a sample's hops follow
// is within 5 % (one standard error) of the bed's. 400 is that for cv = 1,
// an exponential distribution's, the widest a well-mixed region gives.
// Visits still open at the window's end (residence.<key>.censored), which a
// window shorter than the longest visits has, enter by Kaplan-Meier, and
// what lasts beyond the window as an exponential tail that puts the mean at
// Little's law's, holdup / entryRate, within three of its errors, 1/sqrt of
// the entries (Residence::censor); that mean is within 5 % from 400
// entries, completed or open, whatever the spread, and none need have
// ended within the window. A target moisture at or below the kernels' equilibrium with the inlet air
// (the driest, hottest air in the bed) can never be reached and is refused.
#include <string>

#include "dryer/Spouted.hpp"

namespace procsim::dryer::spouted
{

constexpr long kMinResidences = 400;
constexpr double kSameRel = 1e-3; // case and statistics agree within 0.1 %

Case readCase(const std::string& path);

} // namespace procsim::dryer::spouted
