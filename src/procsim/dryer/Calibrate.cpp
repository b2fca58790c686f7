#include "dryer/Calibrate.hpp"

#include <ceres/ceres.h>

#include <stdexcept>

#include "common/Cli.hpp"

namespace procsim::dryer
{

namespace
{

// One residual block per batch, so Ceres can evaluate batches in parallel.
struct BatchCost
{
    const Plant* plant;
    std::string batch;

    bool operator()(double const* const* params, double* residuals) const
    {
        Plant p = *plant;
        for (std::size_t i = 0; i < p.fit.size(); ++i) p.set(p.fit[i].name, params[i][0]);
        const BatchSpec& b = p.batch(batch);
        BatchResult r;
        try
        {
            DryerCase c = p.caseFor(b);
            c.relTol = 1e-6;
            c.outputInterval = 3600;
            r = simulate(c);
        }
        catch (const std::exception&)
        {
            return false;   // Ceres shortens the step
        }
        residuals[0] = r.dryingTime / *b.measuredTime - 1.0;
        residuals[1] = r.electricityJ / *b.measuredElectricity - 1.0;
        return true;
    }
};

} // namespace

CalibrationResult calibrate(Plant& plant, int maxIterations)
{
    if (plant.fit.empty() || plant.calibrateOn.empty())
        throw InputError(plant.file + ": key 'calibration' needs 'fit' and 'calibrate_on'");
    for (const auto& id : plant.calibrateOn)
    {
        const BatchSpec& b = plant.batch(id);
        if (!b.measuredTime || !b.measuredElectricity)
            throw InputError(plant.file + ": batch '" + id
                             + "' key 'measured' needs drying_time and electricity_kWh for calibration");
    }
    CalibrationResult out;
    std::vector<double> x(plant.fit.size());
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        x[i] = plant.get(plant.fit[i].name);
        if (x[i] < plant.fit[i].lower || x[i] > plant.fit[i].upper)
            throw InputError(plant.file + ": calibration start value of '" + plant.fit[i].name
                             + "' lies outside its [lower, upper]");
    }
    out.start = x;

    ceres::NumericDiffOptions nd;
    nd.relative_step_size = 1e-3;   // well above the ODE tolerance noise
    ceres::Problem problem;
    std::vector<double*> blocks;
    for (double& v : x) blocks.push_back(&v);
    const Plant frozen = plant;
    for (const auto& id : plant.calibrateOn)
    {
        auto* cost = new ceres::DynamicNumericDiffCostFunction<BatchCost, ceres::FORWARD>(
            new BatchCost{&frozen, id}, ceres::TAKE_OWNERSHIP, nd);
        for (std::size_t i = 0; i < x.size(); ++i) cost->AddParameterBlock(1);
        cost->SetNumResiduals(2);
        problem.AddResidualBlock(cost, nullptr, blocks);
    }
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        problem.SetParameterLowerBound(&x[i], 0, plant.fit[i].lower);
        problem.SetParameterUpperBound(&x[i], 0, plant.fit[i].upper);
    }
    ceres::Solver::Options opt;
    opt.linear_solver_type = ceres::DENSE_QR;
    opt.max_num_iterations = maxIterations;
    opt.function_tolerance = 1e-10;
    opt.parameter_tolerance = 1e-8;
    opt.logging_type = ceres::SILENT;
    opt.num_threads = 2;
    ceres::Solver::Summary summary;
    ceres::Solve(opt, &problem, &summary);
    out.fitted = x;
    out.initialCost = summary.initial_cost;
    out.finalCost = summary.final_cost;
    out.iterations = static_cast<int>(summary.iterations.size());
    out.report = summary.BriefReport();
    for (std::size_t i = 0; i < x.size(); ++i) plant.set(plant.fit[i].name, x[i]);
    return out;
}

} // namespace procsim::dryer
