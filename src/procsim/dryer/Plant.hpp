#pragma once
// The plant file: one YAML describing the dryer, the product, the kinetics,
// the venting arrangements and a list of batches, plus optional
// calibration and what-if sections.  See README.md for every key.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dryer/Model.hpp"

namespace procsim::dryer
{

struct Venting
{
    double ventedFraction = 0;
    double shortCircuit = 0;
};

struct BatchSpec
{
    std::string id;
    std::string venting; // key into Plant::venting
    double hotAirC = 70;
    double dryMass = 0;
    double x0 = 0, xTarget = 0, x0Spread = 0;
    unsigned seed = 1;
    std::optional<double> measuredTime;        // s
    std::optional<double> measuredElectricity; // J
    std::optional<double> measuredF1, measuredF2;
};

struct FitParameter
{
    std::string name; // see Plant::parameterNames()
    double lower = 0, upper = 0;
};

// One direction along which batches 1-3 cannot tell parameter sets apart:
// the parameter is held at each value in turn while the rest are refitted.
struct ProfileAxis
{
    std::string name; // see Plant::parameterNames()
    std::vector<double> values;
};

struct Plant
{
    std::string file;
    DryerCase base; // dryer, product, kinetics, operation, run
    std::map<std::string, Venting> venting;
    std::vector<BatchSpec> batches;
    // calibration
    std::vector<FitParameter> fit;
    std::vector<std::string> calibrateOn, predict;
    std::string predictVenting; // venting used for the predicted batches
    // profile: grid over the held parameters; a refit counts as fitting the
    // calibration batches if every relative error is within the tolerances
    std::vector<ProfileAxis> profile;
    double timeTolerance = 0, electricityTolerance = 0; // relative
    // what-if
    std::string whatifBatch;
    std::string whatifVenting;
    std::vector<double> whatifTemperatures; // degC
    std::vector<double> whatifVentedFractions;

    const BatchSpec& batch(const std::string& id) const;
    DryerCase caseFor(const BatchSpec& b) const;
    DryerCase caseFor(const BatchSpec& b, const std::string& ventingName) const;

    // Named model parameters that calibration may fit.
    static std::vector<std::string> parameterNames();
    double get(const std::string& name) const;
    void set(const std::string& name, double value);
};

Plant readPlant(const std::string& path);
// Writes the plant back as YAML (used to save calibrated parameters).
void writePlant(const Plant& p, const std::string& path, const std::string& comment);

} // namespace procsim::dryer
