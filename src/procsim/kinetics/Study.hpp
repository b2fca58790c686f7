#pragma once
// Studies built on single runs: parameter sweeps (families of curves) and the
// +-10 % sensitivity table of rate constants (the paper's Table S1).
#include <string>
#include <vector>

#include "kinetics/Case.hpp"
#include "kinetics/Run.hpp"

namespace procsim::kinetics
{

// short column name of a swept key: "initial_mg_per_L.PH" -> "PH0_mg_per_L"
std::string shortKey(const std::string& key);

struct SweepRun
{
    Overrides values;  // the swept keys and their values for this run
    std::string label; // "current_mA=0.3"
    Results results;
    Efficiency eff;
};

// one or two swept keys (cartesian product); writes <dir>/<label>/..., sweep_summary.csv, family plots
std::vector<SweepRun> runSweep(const CaseSource& src, const Overrides& set, const std::vector<SweepDim>& dims,
                               const std::string& dir, bool plots, bool quiet, const std::string& solver);

struct SensitivityRow
{
    std::string parameter;
    double change; // relative, e.g. +0.1
    std::string output;
    double base; // at the chosen time
    double perturbed;
    double deviation;        // (perturbed - base) / base
    double maxDeviation;     // largest |deviation| over the run (signed)
    double maxDeviationTime; // s
};

std::vector<SensitivityRow> sensitivity(const CaseSource& src, const Overrides& set,
                                        std::vector<std::string> parameters, std::vector<std::string> outputs,
                                        double time, double change);
void writeSensitivity(const std::vector<SensitivityRow>& rows, const std::string& dir);
std::string sensitivityTable(const std::vector<SensitivityRow>& rows);

} // namespace procsim::kinetics
