#pragma once
// Least-squares calibration of the plant's uncertain parameters on measured
// batches (drying time and electricity), with Ceres.
#include <string>
#include <vector>

#include "dryer/Plant.hpp"

namespace procsim::dryer
{

struct CalibrationResult
{
    std::vector<double> start, fitted;   // in Plant::fit order
    double initialCost = 0, finalCost = 0;
    int iterations = 0;
    std::string report;                  // Ceres brief report
};

// Fits plant.fit on plant.calibrateOn; on return `plant` holds the fitted
// values.  Residuals: relative errors of drying time and electricity.
CalibrationResult calibrate(Plant& plant, int maxIterations = 50);

} // namespace procsim::dryer
