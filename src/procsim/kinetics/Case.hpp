#pragma once
// A kinetics case: reactor, gas feed, initial liquid concentrations, the [OH]
// model, duration, output interval and solver; read from YAML with optional
// overrides "key.path=value" (sweeps, sensitivity, fitting).
#include <string>
#include <utility>
#include <vector>

#include "kinetics/Mechanism.hpp"

namespace procsim::kinetics
{

constexpr double gasConstant = 8.314462618; // J/(mol K)

struct SolverOptions
{
    std::string method = "expm"; // expm | rk4 | cvode
    double rk4Step = 10;         // s
    double rtol = 1e-8;
    double atol = 1e-16; // mol/L
};

struct OhModel
{
    std::string kind = "none"; // none | constant | linear_current | dynamic
    double concentration = 0;  // mg/L (constant)
    double slope = 0;          // mg/L per mA (linear_current)
    double intercept = 0;      // mg/L (linear_current)
};

struct SweepDim
{
    std::string key;
    std::vector<double> values;
};

// one override: a case key path ("corona.current_mA") or "k.<reaction id>"
using Override = std::pair<std::string, double>;
using Overrides = std::vector<Override>;

struct Case
{
    std::string file;
    std::string title;
    Mechanism mech;

    double volume = 1;            // L of liquid
    double gasFlow = 0;           // mol/s of feed gas (from volumetric flow, T, p)
    std::vector<double> inletPpm; // per species, mol ppm in the feed gas
    std::vector<double> effluentPpm;
    std::vector<double> initial; // per species, mol/L
    double current = 0;          // mA
    double voltage = 0;          // kV (0 = not given)
    OhModel oh;
    double duration = 0;       // s
    double outputInterval = 0; // s
    SolverOptions solver;
    std::vector<double> reportTimes; // s
    std::vector<std::string> plotSpecies;
    std::vector<SweepDim> sweep;

    // sensitivity defaults (case section 'sensitivity')
    std::vector<std::string> sensParameters;
    std::vector<std::string> sensOutputs;
    double sensTime = 0;      // s (0 = end of run)
    double sensChange = 0.10; // relative change

    // pseudo-steady radical concentration, mol/L (0 if no fixed radical)
    double radicalConcentration() const;
    bool radicalFixed() const { return mech.hasRadical() && oh.kind != "dynamic" && oh.kind != "none"; }
    // liquid-phase feed of each species by gas absorption, mol/(L s)
    std::vector<double> feedRate() const;
};

class CaseSource
{
public:
    static CaseSource load(const std::string& path);
    Case build(const Overrides& overrides = {}) const;
    const std::string& file() const { return file_; }

private:
    std::string file_;
    YAML::Node node_;
    Mechanism mech_;
};

// "I" -> "corona.current_mA" etc.; other keys unchanged
std::string expandAlias(const std::string& key);
// parse "key=v1,v2,v3"
SweepDim parseSweep(const std::string& arg);

} // namespace procsim::kinetics
