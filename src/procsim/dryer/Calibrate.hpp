#pragma once
// Least-squares calibration of the plant's uncertain parameters on measured
// batches (drying time and electricity), with Ceres, and the profile of that
// fit along directions the calibration batches cannot resolve.
#include <functional>
#include <string>
#include <vector>

#include "dryer/Plant.hpp"

namespace procsim::dryer
{

struct CalibrationResult
{
    std::vector<double> start, fitted; // in Plant::fit order
    double initialCost = 0, finalCost = 0;
    int iterations = 0;
    std::string report; // Ceres brief report
};

// Fits plant.fit on plant.calibrateOn; on return `plant` holds the fitted
// values.  Residuals: relative errors of drying time and electricity.
// functionTolerance: Ceres stops when the cost changes by less than this
// fraction in one step.
CalibrationResult calibrate(Plant& plant, int maxIterations = 50, double functionTolerance = 1e-10);

// Model against measurement for one batch, with relative errors.
struct BatchCheck
{
    std::string id;
    BatchResult result;
    double timeError = 0, electricityError = 0; // model / measured - 1 (NaN if unmeasured)
};

// Runs a batch with the given venting and compares it with its measurement.
BatchCheck checkBatch(const Plant& plant, const std::string& id, const std::string& venting);

// One point of the profile: the held values, the refit of the rest, how well
// it reproduces the calibration batches and what it predicts.
struct ProfilePoint
{
    std::vector<double> held;                             // in Plant::profile order
    std::vector<std::string> refitNames;                  // the parameters refitted here
    std::vector<double> refitted;                         // their values
    double cost = 0;                                      // Ceres cost of the refit
    std::vector<BatchCheck> fitted;                       // plant.calibrateOn, own venting
    std::vector<BatchCheck> predicted;                    // plant.predict, plant.predictVenting
    bool failed = false;                                  // a run did not integrate
    bool accepted = false;                                // every fitted error within the tolerances
    double worstTimeError = 0, worstElectricityError = 0; // largest |error| over fitted
};

// Holds Plant::profile on every grid point (last axis fastest), refits the
// remaining plant.fit parameters on plant.calibrateOn from the previous
// point's values, and runs plant.predict.  `plant` is the central fit.
// `done` (optional) sees each point as soon as it is finished.
std::vector<ProfilePoint> profile(const Plant& plant, int maxIterations = 50,
                                  const std::function<void(const ProfilePoint&)>& done = {});

// Smallest and largest value of a predicted or fitted quantity over the
// accepted points of a profile.
struct Band
{
    double lo = 0, hi = 0;
    int members = 0;
    bool contains(double v) const { return members > 0 && v >= lo && v <= hi; }
};
Band band(const std::vector<ProfilePoint>& points, const std::string& id,
          const std::function<double(const BatchResult&)>& quantity);

} // namespace procsim::dryer
