#include "dryer/Calibrate.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/Ceres.hpp"
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
            return false; // Ceres shortens the step
        }
        residuals[0] = r.dryingTime / *b.measuredTime - 1.0;
        residuals[1] = r.electricityJ / *b.measuredElectricity - 1.0;
        return true;
    }
};

} // namespace

CalibrationResult calibrate(Plant& plant, int maxIterations, double functionTolerance)
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
    nd.relative_step_size = 1e-3; // well above the ODE tolerance noise
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
    opt.function_tolerance = functionTolerance;
    opt.parameter_tolerance = 1e-8;
    opt.logging_type = ceres::SILENT;
    opt.num_threads = 2;
    ceres::Solver::Summary summary;
    quietCeres();
    ceres::Solve(opt, &problem, &summary);
    out.fitted = x;
    out.initialCost = summary.initial_cost;
    out.finalCost = summary.final_cost;
    out.iterations = static_cast<int>(summary.iterations.size());
    out.report = summary.BriefReport();
    for (std::size_t i = 0; i < x.size(); ++i) plant.set(plant.fit[i].name, x[i]);
    return out;
}

BatchCheck checkBatch(const Plant& plant, const std::string& id, const std::string& venting)
{
    const BatchSpec& b = plant.batch(id);
    BatchCheck out;
    out.id = id;
    out.result = simulate(plant.caseFor(b, venting));
    out.timeError = b.measuredTime ? out.result.dryingTime / *b.measuredTime - 1.0 : std::nan("");
    out.electricityError =
        b.measuredElectricity ? out.result.electricityJ / *b.measuredElectricity - 1.0 : std::nan("");
    return out;
}

namespace
{

// Grid point `index` of the profile, last axis fastest.
std::vector<double> gridPoint(const std::vector<ProfileAxis>& axes, std::size_t index)
{
    std::vector<double> v(axes.size());
    for (std::size_t a = axes.size(); a-- > 0;)
    {
        v[a] = axes[a].values[index % axes[a].values.size()];
        index /= axes[a].values.size();
    }
    return v;
}

bool held(const std::vector<ProfileAxis>& axes, const std::string& name)
{
    for (const auto& a : axes)
        if (a.name == name) return true;
    return false;
}

// The refit, checks and predictions at one grid point; `warm` carries the
// refitted values from one point to the next (starting values).
ProfilePoint profilePoint(const Plant& central, const std::vector<double>& values, Plant& warm,
                          int maxIterations)
{
    ProfilePoint pt;
    pt.held = values;
    Plant p = warm;
    for (std::size_t a = 0; a < values.size(); ++a) p.set(central.profile[a].name, values[a]);
    p.fit.clear();
    for (const auto& f : central.fit)
        if (!held(central.profile, f.name)) p.fit.push_back(f);
    try
    {
        // acceptance is judged at the percent level: a refit may stop as
        // soon as the cost settles to 1e-6, which saves most iterations
        if (!p.fit.empty()) pt.cost = calibrate(p, maxIterations, 1e-6).finalCost;
        for (const auto& f : p.fit)
        {
            pt.refitNames.push_back(f.name);
            pt.refitted.push_back(p.get(f.name));
        }
        for (const auto& id : p.calibrateOn) pt.fitted.push_back(checkBatch(p, id, p.batch(id).venting));
        for (const auto& id : p.predict) pt.predicted.push_back(checkBatch(p, id, p.predictVenting));
    }
    catch (const std::exception&)
    {
        pt.failed = true; // e.g. a held value outside what the model integrates
        return pt;
    }
    pt.accepted = true;
    for (const auto& c : pt.fitted)
    {
        pt.worstTimeError = std::max(pt.worstTimeError, std::fabs(c.timeError));
        pt.worstElectricityError = std::max(pt.worstElectricityError, std::fabs(c.electricityError));
    }
    pt.accepted = pt.worstTimeError <= central.timeTolerance
                  && pt.worstElectricityError <= central.electricityTolerance;
    // the next point starts from here unless this refit went astray
    if (pt.accepted) warm = p;
    return pt;
}

} // namespace

std::vector<ProfilePoint> profile(const Plant& plant, int maxIterations,
                                  const std::function<void(const ProfilePoint&)>& done)
{
    std::size_t n = plant.profile.empty() ? 0 : 1;
    for (const auto& a : plant.profile) n *= a.values.size();
    std::vector<ProfilePoint> out;
    Plant warm = plant;
    for (std::size_t i = 0; i < n; ++i)
    {
        out.push_back(profilePoint(plant, gridPoint(plant.profile, i), warm, maxIterations));
        if (done) done(out.back());
    }
    return out;
}

Band band(const std::vector<ProfilePoint>& points, const std::string& id,
          const std::function<double(const BatchResult&)>& quantity)
{
    Band b;
    for (const auto& pt : points)
    {
        if (!pt.accepted) continue;
        for (const auto* list : {&pt.fitted, &pt.predicted})
            for (const auto& c : *list)
            {
                if (c.id != id) continue;
                const double v = quantity(c.result);
                b.lo = b.members ? std::min(b.lo, v) : v;
                b.hi = b.members ? std::max(b.hi, v) : v;
                ++b.members;
            }
    }
    return b;
}

} // namespace procsim::dryer
