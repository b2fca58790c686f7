#include "kinetics/Fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "common/Ceres.hpp"
#include "common/Checked.hpp"
#include "common/Csv.hpp"
#include "common/YamlInput.hpp"
#include "kinetics/Run.hpp"

namespace procsim::kinetics
{

namespace
{

std::vector<std::vector<double>> predictAt(const FitDataset& d, const Overrides& values,
                                           const std::vector<double>& tOut)
{
    Overrides o = d.set;
    o.insert(o.end(), values.begin(), values.end());
    const Case c = d.source.build(o);
    const Model model(c);
    std::set<double> grid(tOut.begin(), tOut.end());
    grid.insert(0.0);
    const std::vector<double> times(grid.begin(), grid.end());
    const Results r = analyse(model, solve(model, times, c.solver));
    std::vector<std::vector<double>> out;
    for (const auto& q : d.quantities)
    {
        std::vector<double> v;
        for (double t : tOut) v.push_back(r.value(q, t));
        out.push_back(v);
    }
    return out;
}

Overrides valuesOf(const std::vector<FitParameter>& p, const double* lnValues)
{
    Overrides o;
    for (std::size_t i = 0; i < p.size(); ++i) o.emplace_back(p[i].key, std::exp(lnValues[i]));
    return o;
}

struct Residuals
{
    const std::vector<FitParameter>* params;
    const std::vector<FitDataset>* data;
    // Throws what the model throws; the cost is finite or false is returned.
    bool evaluate(const double* x, double* res) const
    {
        const Overrides o = valuesOf(*params, x);
        std::size_t k = 0;
        double sum = 0;
        for (const auto& d : *data)
        {
            const auto pred = predictAt(d, o, d.t);
            for (std::size_t q = 0; q < d.quantities.size(); ++q)
                for (std::size_t i = 0; i < d.t.size(); ++i)
                    if (!std::isnan(d.measured[q][i]))
                    {
                        res[k] = (pred[q][i] - d.measured[q][i]) / d.sigma;
                        sum += res[k] * res[k];
                        ++k;
                    }
        }
        return std::isfinite(sum);
    }
    // Ceres must not see an exception or a non-finite residual: either is an
    // unsuccessful step it can step back from.
    bool operator()(double const* const* x, double* res) const
    {
        try
        {
            return evaluate(x[0], res);
        }
        catch (const std::exception&)
        {
            return false;
        }
    }
};

std::string num(double v, int p = 6)
{
    return formatNumber(v, p);
}

constexpr double maxConcentration = 1e6; // mg/L: far above any solubility

} // namespace

std::vector<std::vector<double>> predict(const FitDataset& d, const std::vector<FitParameter>& params,
                                         bool useEstimate)
{
    Overrides o;
    for (const auto& p : params) o.emplace_back(p.key, useEstimate ? p.estimate : p.initial);
    return predictAt(d, o, d.t);
}

FitResult fitParameters(std::vector<FitParameter> params, const std::vector<FitDataset>& data,
                        const FitOptions& opt)
{
    int m = 0;
    for (const auto& d : data)
        for (const auto& q : d.measured)
            for (double v : q) m += !std::isnan(v);
    const int p = static_cast<int>(params.size());
    if (p == 0) throw InputError("fit: no parameters to estimate");
    if (m <= p)
        throw InputError("fit: " + std::to_string(m) + " data points cannot determine " + std::to_string(p)
                         + " parameters");

    std::vector<double> x(static_cast<std::size_t>(p));
    for (std::size_t i = 0; i < params.size(); ++i)
    {
        if (!(params[i].initial > 0))
            throw InputError("fit: parameter '" + params[i].key + "' needs a positive initial value");
        x[i] = std::log(params[i].initial);
    }
    {
        std::vector<double> start(static_cast<std::size_t>(m));
        if (!Residuals{&params, &data}.evaluate(x.data(), start.data()))
            throw InputError("fit: the residuals at the initial parameter values are not finite"
                             " (check the data, sigma_mg_per_L and the initial values)");
    }
    auto* cost =
        new ceres::DynamicNumericDiffCostFunction<Residuals, ceres::CENTRAL>(new Residuals{&params, &data});
    cost->AddParameterBlock(p);
    cost->SetNumResiduals(m);
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, x.data());
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = opt.maxIterations;
    so.function_tolerance = 1e-12;
    so.parameter_tolerance = 1e-10;
    so.gradient_tolerance = 1e-14;
    so.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    quietCeres();
    ceres::Solve(so, &problem, &summary);

    FitResult r;
    r.converged = summary.termination_type == ceres::CONVERGENCE;
    r.report = summary.BriefReport();
    r.points = m;
    r.chi2 = 2.0 * summary.final_cost;
    const double s2 = opt.scaleByResidualVariance ? r.chi2 / (m - p) : 1.0;

    ceres::Covariance::Options co;
    co.algorithm_type = ceres::DENSE_SVD;
    co.null_space_rank = -1;
    ceres::Covariance cov(co);
    std::vector<std::pair<const double*, const double*>> blocks = {{x.data(), x.data()}};
    Eigen::MatrixXd c = Eigen::MatrixXd::Constant(p, p, NAN);
    if (cov.Compute(blocks, &problem))
    {
        std::vector<double> buf(static_cast<std::size_t>(p * p));
        cov.GetCovarianceBlock(x.data(), x.data(), buf.data());
        for (int i = 0; i < p; ++i)
            for (int j = 0; j < p; ++j) c(i, j) = buf[static_cast<std::size_t>(i * p + j)] * s2;
    }
    r.correlation = Eigen::MatrixXd(p, p);
    for (int i = 0; i < p; ++i)
        for (int j = 0; j < p; ++j) r.correlation(i, j) = c(i, j) / std::sqrt(c(i, i) * c(j, j));
    for (std::size_t i = 0; i < params.size(); ++i)
    {
        params[i].estimate = std::exp(x[i]);
        params[i].lnStdError = std::sqrt(c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)));
        params[i].stdError = params[i].estimate * params[i].lnStdError;
    }
    r.parameters = params;

    double sst = 0, ssr = 0;
    for (const auto& d : data)
    {
        const auto pred = predict(d, params, true);
        for (std::size_t q = 0; q < d.quantities.size(); ++q)
        {
            double mean = 0;
            int n = 0;
            for (double v : d.measured[q])
                if (!std::isnan(v)) mean += v, ++n;
            mean /= std::max(n, 1);
            for (std::size_t i = 0; i < d.t.size(); ++i)
            {
                if (std::isnan(d.measured[q][i])) continue;
                r.residuals.push_back({d.name, d.quantities[q], d.t[i], d.measured[q][i], pred[q][i]});
                ssr += std::pow(pred[q][i] - d.measured[q][i], 2);
                sst += std::pow(d.measured[q][i] - mean, 2);
            }
        }
    }
    r.ssr = ssr;
    r.rmse = std::sqrt(ssr / m);
    r.r2 = sst > 0 ? 1 - ssr / sst : NAN;
    return r;
}

namespace
{

std::vector<FitParameter> readParameters(const YamlInput& in)
{
    std::vector<FitParameter> params;
    for (const auto& it : in.child("parameters").items())
    {
        it.rejectUnknown({"key", "initial"});
        FitParameter p;
        p.key = expandAlias(it.text("key"));
        p.initial = it.positive("initial");
        params.push_back(p);
    }
    // after the aliases: I and corona.current_mA are one parameter
    rejectDuplicates(params, &FitParameter::key, in.file() + ": key 'parameters'", "parameter");
    return params;
}

// The CSV's measured columns, <species>_mg_per_L or TOC_mgC_per_L, into d;
// each holds at least one measurement.
void readMeasured(FitDataset& d, const CsvTable& table, std::size_t timeColumn, const Case& c,
                  const std::string& csvFile)
{
    for (std::size_t col = 0; col < table.header.size(); ++col)
    {
        if (col == timeColumn) continue;
        const std::string h = table.header[col];
        std::string q;
        if (h == "TOC_mgC_per_L")
            q = "TOC";
        else if (h.size() > 9 && h.substr(h.size() - 9) == "_mg_per_L")
            q = h.substr(0, h.size() - 9);
        if (q.empty() || (q != "TOC" && !c.mech.hasSpecies(q)))
            throw InputError(csvFile + ": column '" + h
                             + "' is not time_h, TOC_mgC_per_L or <species>_mg_per_L of the mechanism");
        d.quantities.push_back(q);
        std::vector<double> v;
        for (std::size_t r = 0; r < table.rows.size(); ++r)
        {
            const double x = table.rows[r][col];
            if (!std::isnan(x) && !(std::fabs(x) <= maxConcentration)) // noise may dip below 0
                throw InputError(csvFile + ": line " + std::to_string(table.lines[r]) + ": column '" + h
                                 + "' expected a concentration from -" + num(maxConcentration) + " to "
                                 + num(maxConcentration) + " mg/L (or nan: not measured), got " + num(x));
            v.push_back(x);
        }
        if (std::all_of(v.begin(), v.end(), [](double x) { return std::isnan(x); }))
            throw InputError(csvFile + ": column '" + h
                             + "' expected at least one measured value, got only nan (not measured)");
        d.measured.push_back(v);
    }
    if (d.quantities.empty()) throw InputError(csvFile + ": no measured columns");
}

// The CSV's measurement times: within the run, each after the one before.
void readTimes(FitDataset& d, const CsvTable& table, std::size_t timeColumn, const Case& c,
               const std::string& csvFile)
{
    const double tMax = c.duration / 3600.0;
    for (std::size_t r = 0; r < table.rows.size(); ++r)
    {
        const double t = table.rows[r][timeColumn];
        const std::string where = csvFile + ": line " + std::to_string(table.lines[r]) + ": column 'time_h'";
        if (!(t >= 0 && t <= tMax))
            throw InputError(where + " expected a time from 0 to " + num(tMax)
                             + " h (the case's duration), got " + num(t));
        if (r > 0 && !(t * 3600.0 > d.t.back()))
            throw InputError(where + " expected times in increasing order, got " + num(t) + " after "
                             + num(d.t.back() / 3600.0));
        d.t.push_back(t * 3600.0);
    }
}

// An experiment's fixed inputs ('set'): each key once (after the aliases)
// and none of them a parameter the fit estimates.
Overrides readFixedInputs(const YamlInput& s, const std::vector<FitParameter>& params)
{
    Overrides set;
    std::vector<std::string> keys;
    for (const auto& k : s.keys())
    {
        keys.push_back(expandAlias(k));
        for (const auto& p : params)
            if (p.key == keys.back())
                throw InputError(s.file() + ": key '" + s.path() + "." + k + "' fixes parameter '" + p.key
                                 + "', which the fit estimates (expected only inputs the fit leaves alone)");
        set.emplace_back(keys.back(), s.number(k));
    }
    rejectDuplicates(keys, s.file() + ": key '" + s.path() + "'", "input");
    return set;
}

// One experiment: its case, fixed inputs, measurements and their sigma.
FitDataset readDataset(const YamlInput& it, std::size_t index, const std::filesystem::path& base,
                       const std::vector<FitParameter>& params)
{
    auto rel = [&](const std::string& f) {
        std::filesystem::path p(f);
        return (p.is_relative() ? base / p : p).string();
    };
    it.rejectUnknown({"name", "case", "set", "csv", "sigma_mg_per_L"});
    FitDataset d;
    d.name = it.text("name", "dataset " + std::to_string(index + 1));
    d.source = CaseSource::load(rel(it.text("case")));
    if (it.has("set")) d.set = readFixedInputs(it.child("set"), params);
    if (it.has("sigma_mg_per_L")) d.sigma = it.positive("sigma_mg_per_L", "mg/L");
    const std::string csvFile = rel(it.text("csv"));
    const CsvTable table = readCsv(csvFile, true); // "nan" or empty: not measured
    if (table.rows.empty())
        throw InputError(csvFile + ": no data rows under the header (expected one row per measurement time)");
    const Case c = d.source.build(d.set); // validates the set keys
    readMeasured(d, table, table.column("time_h", csvFile), c, csvFile);
    readTimes(d, table, table.column("time_h", csvFile), c, csvFile);
    Overrides o = d.set;
    for (const auto& p : params) o.emplace_back(p.key, p.initial);
    d.source.build(o); // the parameter keys exist
    return d;
}

FitOptions readOptions(const YamlInput& in)
{
    FitOptions opt;
    if (!in.has("options")) return opt;
    const YamlInput o = in.child("options");
    o.rejectUnknown({"scale_by_residual_variance", "max_iterations"});
    const std::string s = o.text("scale_by_residual_variance", "true");
    if (s != "true" && s != "false") throw o.error("scale_by_residual_variance", "true or false");
    opt.scaleByResidualVariance = s == "true";
    if (o.has("max_iterations")) opt.maxIterations = static_cast<int>(o.integer("max_iterations", 1, 100000));
    return opt;
}

} // namespace

FitProblem readFitProblem(const std::string& file)
{
    const YamlInput in = YamlInput::load(file);
    in.rejectUnknown({"title", "parameters", "data", "options"});
    FitProblem f;
    f.title = in.text("title", file);
    f.parameters = readParameters(in);
    const std::filesystem::path base = std::filesystem::path(file).parent_path();
    for (const auto& it : in.child("data").items())
        f.data.push_back(readDataset(it, f.data.size(), base, f.parameters));
    rejectDuplicates(f.data, &FitDataset::name, file + ": key 'data'", "dataset name");
    f.options = readOptions(in);
    return f;
}

std::vector<std::vector<double>> predictCurve(const FitDataset& d, const std::vector<FitParameter>& params,
                                              const std::vector<double>& times)
{
    Overrides o;
    for (const auto& p : params) o.emplace_back(p.key, p.estimate);
    return predictAt(d, o, times);
}

} // namespace procsim::kinetics
