#pragma once
// Least-squares estimation of rate constants and [OH]-model parameters from
// measured time series (Ceres, Levenberg-Marquardt).  Parameters are fitted as
// ln(p), so they stay positive; standard errors come from the covariance
// (J^T J)^-1 of the weighted residuals, scaled by the residual variance unless
// the measurement standard deviations are trusted as given.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "kinetics/Case.hpp"

namespace procsim::kinetics
{

struct FitParameter
{
    std::string key; // "k.k3", "oh.slope_mg_per_L_per_mA", any numeric case key
    double initial = 0;
    double estimate = 0;
    double stdError = 0;   // of the estimate (delta method from ln p)
    double lnStdError = 0; // of ln(estimate)
};

struct FitDataset
{
    std::string name;
    CaseSource source;
    Overrides set;                             // fixed inputs of this experiment
    std::vector<double> t;                     // s
    std::vector<std::string> quantities;       // species names or TOC
    std::vector<std::vector<double>> measured; // [quantity][time], mg/L (TOC mg C/L); NaN = missing
    double sigma = 1.0;                        // measurement standard deviation, mg/L
};

struct FitResidual
{
    std::string dataset, quantity;
    double t, measured, predicted;
};

struct FitResult
{
    std::vector<FitParameter> parameters;
    std::vector<FitResidual> residuals;
    Eigen::MatrixXd correlation;
    double ssr = 0;  // sum of squared (unweighted) residuals, (mg/L)^2
    double chi2 = 0; // sum of squared weighted residuals
    int points = 0;
    double rmse = 0; // mg/L
    double r2 = 0;
    bool converged = false;
    std::string report; // Ceres brief report
};

struct FitOptions
{
    bool scaleByResidualVariance = true;
    int maxIterations = 100;
};

FitResult fitParameters(std::vector<FitParameter> params, const std::vector<FitDataset>& data,
                        const FitOptions& opt);
// the model's values for a dataset at its times with the given parameter values
std::vector<std::vector<double>> predict(const FitDataset& d, const std::vector<FitParameter>& params,
                                         bool useEstimate);

// the model at other times (e.g. a fine grid for plots), with the estimates
std::vector<std::vector<double>> predictCurve(const FitDataset& d, const std::vector<FitParameter>& params,
                                              const std::vector<double>& times);

// A fit file (format: procsim kinetics fit --help): what to estimate, from
// which experiments, with which options.
struct FitProblem
{
    std::string title; // default: the file name
    std::vector<FitParameter> parameters;
    std::vector<FitDataset> data;
    FitOptions options;
};
FitProblem readFitProblem(const std::string& file);

} // namespace procsim::kinetics
