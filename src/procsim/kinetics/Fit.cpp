#include "kinetics/Fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

#include "common/Ceres.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "kinetics/Run.hpp"

namespace procsim::kinetics
{

namespace
{

std::vector<std::vector<double>> predictAt(const FitDataset& d, const Overrides& values, const std::vector<double>& tOut)
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

std::string num(double v, int p = 6) { return formatNumber(v, p); }

constexpr double maxConcentration = 1e6;   // mg/L: far above any solubility

} // namespace

std::vector<std::vector<double>> predict(const FitDataset& d, const std::vector<FitParameter>& params, bool useEstimate)
{
    Overrides o;
    for (const auto& p : params) o.emplace_back(p.key, useEstimate ? p.estimate : p.initial);
    return predictAt(d, o, d.t);
}

FitResult fitParameters(std::vector<FitParameter> params, const std::vector<FitDataset>& data, const FitOptions& opt)
{
    int m = 0;
    for (const auto& d : data)
        for (const auto& q : d.measured)
            for (double v : q) m += !std::isnan(v);
    const int p = static_cast<int>(params.size());
    if (p == 0) throw InputError("fit: no parameters to estimate");
    if (m <= p) throw InputError("fit: " + std::to_string(m) + " data points cannot determine " + std::to_string(p) + " parameters");

    std::vector<double> x(static_cast<std::size_t>(p));
    for (std::size_t i = 0; i < params.size(); ++i)
    {
        if (!(params[i].initial > 0)) throw InputError("fit: parameter '" + params[i].key + "' needs a positive initial value");
        x[i] = std::log(params[i].initial);
    }
    {
        std::vector<double> start(static_cast<std::size_t>(m));
        if (!Residuals{&params, &data}.evaluate(x.data(), start.data()))
            throw InputError("fit: the residuals at the initial parameter values are not finite"
                             " (check the data, sigma_mg_per_L and the initial values)");
    }
    auto* cost = new ceres::DynamicNumericDiffCostFunction<Residuals, ceres::CENTRAL>(new Residuals{&params, &data});
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

const char* fitHelp()
{
    return R"(usage: procsim kinetics fit FIT.yaml [-o DIR] [--no-plots]

Estimates rate constants and/or [OH]-model parameters by least squares
(Ceres, Levenberg-Marquardt) from measured concentrations, with standard errors.
Each parameter is fitted as ln(value) (it stays positive); its standard error is
from the covariance (J^T J)^-1 of the weighted residuals, times the residual
variance chi2/(n - p) unless scale_by_residual_variance is false.

FIT file:
  title: text
  parameters:                         what to estimate
    - key: k.k3                       k.<reaction id>, or any numeric case key, e.g.
                                      oh.slope_mg_per_L_per_mA ([OH] per mA) or
                                      oh.concentration_mg_per_L
      initial: 2.0e9                  starting value (> 0), in the key's units
  data:                               one item per experiment
    - name: "0.1 mA"                  label for tables and plots
      case: ../base.yaml              case file (relative to the fit file)
      set: {corona.current_mA: 0.1}   inputs of this experiment that differ from the case
      csv: measured_0.1mA.csv         measurements: column time_h, then any of
                                      <species>_mg_per_L and TOC_mgC_per_L ('nan' = missing)
      sigma_mg_per_L: 0.3             measurement standard deviation (weights; default 1)
  options:
    scale_by_residual_variance: true
    max_iterations: 100

Writes to DIR (default <fit file name>_out):
  fit_parameters.csv   key, initial, estimate, std_error, rel_std_error, ci95_low, ci95_high
  fit_residuals.csv    dataset, time_h, quantity, measured, predicted, residual
  fit_summary.txt      estimates, standard errors, correlation matrix, n, RMSE, R^2
  fit_<n>.png          fitted curves over the data, one per dataset
  fit_parity.png       predicted vs measured;  fit_residuals.png  residuals vs time
)";
}

int fitMain(int argc, char** argv)
{
    std::string file, dir;
    bool plots = true;
    for (int i = 2; i < argc; ++i)
    {
        const std::string s = argv[i];
        if (s == "-o" || s == "--output")
        {
            if (i + 1 >= argc) throw InputError("kinetics fit: -o needs a directory");
            if (!dir.empty()) throw InputError("kinetics fit: option -o given twice");
            dir = argv[++i];
        }
        else if (s == "--no-plots") plots = false;
        else if (!s.empty() && s[0] == '-') throw InputError("kinetics fit: unknown option '" + s + "'");
        else if (file.empty()) file = s;
        else throw InputError("kinetics fit: expected one fit file");
    }
    if (file.empty()) throw InputError("kinetics fit: expected one fit file");
    const YamlInput in = YamlInput::load(file);
    in.rejectUnknown({"title", "parameters", "data", "options"});
    const std::filesystem::path base = std::filesystem::path(file).parent_path();
    auto rel = [&](const std::string& f) {
        std::filesystem::path p(f);
        return (p.is_relative() ? base / p : p).string();
    };
    std::vector<FitParameter> params;
    for (const auto& it : in.child("parameters").items())
    {
        it.rejectUnknown({"key", "initial"});
        FitParameter p;
        p.key = expandAlias(it.text("key"));
        p.initial = it.positive("initial");
        params.push_back(p);
    }
    std::vector<FitDataset> data;
    for (const auto& it : in.child("data").items())
    {
        it.rejectUnknown({"name", "case", "set", "csv", "sigma_mg_per_L"});
        FitDataset d;
        d.name = it.text("name", "dataset " + std::to_string(data.size() + 1));
        d.source = CaseSource::load(rel(it.text("case")));
        if (it.has("set"))
        {
            const YamlInput s = it.child("set");
            for (const auto& k : s.keys()) d.set.emplace_back(expandAlias(k), s.number(k));
        }
        if (it.has("sigma_mg_per_L")) d.sigma = it.positive("sigma_mg_per_L", "mg/L");
        const std::string csvFile = rel(it.text("csv"));
        const CsvTable table = readCsv(csvFile, true);   // "nan" or empty: not measured
        const std::size_t tc = table.column("time_h", csvFile);
        const Case c = d.source.build(d.set);   // validates the set keys
        for (std::size_t col = 0; col < table.header.size(); ++col)
        {
            if (col == tc) continue;
            const std::string h = table.header[col];
            std::string q;
            if (h == "TOC_mgC_per_L") q = "TOC";
            else if (h.size() > 9 && h.substr(h.size() - 9) == "_mg_per_L") q = h.substr(0, h.size() - 9);
            if (q.empty() || (q != "TOC" && !c.mech.hasSpecies(q)))
                throw InputError(csvFile + ": column '" + h + "' is not time_h, TOC_mgC_per_L or <species>_mg_per_L of the mechanism");
            d.quantities.push_back(q);
            std::vector<double> v;
            for (std::size_t r = 0; r < table.rows.size(); ++r)
            {
                const double x = table.rows[r][col];
                if (!std::isnan(x) && !(std::fabs(x) <= maxConcentration))   // noise may dip below 0
                    throw InputError(csvFile + ": data row " + std::to_string(r + 1) + ": column '" + h
                                     + "' expected a concentration from -" + num(maxConcentration) + " to " + num(maxConcentration)
                                     + " mg/L (or nan: not measured), got " + num(x));
                v.push_back(x);
            }
            d.measured.push_back(v);
        }
        const double tMax = c.duration / 3600.0;
        for (std::size_t r = 0; r < table.rows.size(); ++r)
        {
            const double t = table.rows[r][tc];
            if (!(t >= 0 && t <= tMax))
                throw InputError(csvFile + ": data row " + std::to_string(r + 1) + ": column 'time_h' expected a time from 0 to "
                                 + num(tMax) + " h (the case's duration), got " + num(t));
            d.t.push_back(t * 3600.0);
        }
        if (d.quantities.empty()) throw InputError(csvFile + ": no measured columns");
        Overrides o = d.set;
        for (const auto& p : params) o.emplace_back(p.key, p.initial);
        d.source.build(o);   // the parameter keys exist
        data.push_back(std::move(d));
    }
    FitOptions opt;
    if (in.has("options"))
    {
        const YamlInput o = in.child("options");
        o.rejectUnknown({"scale_by_residual_variance", "max_iterations"});
        const std::string s = o.text("scale_by_residual_variance", "true");
        if (s != "true" && s != "false") throw o.error("scale_by_residual_variance", "true or false");
        opt.scaleByResidualVariance = s == "true";
        if (o.has("max_iterations")) opt.maxIterations = static_cast<int>(o.integer("max_iterations", 1, 100000));
    }

    const FitResult r = fitParameters(params, data, opt);
    if (dir.empty()) dir = std::filesystem::path(file).stem().string() + "_out";
    std::filesystem::create_directories(dir);
    {
        CsvWriter csv(dir + "/fit_parameters.csv", {"key", "initial", "estimate", "std_error", "rel_std_error", "ci95_low", "ci95_high"});
        for (const auto& p : r.parameters)
            csv.row(std::vector<std::string>{p.key, num(p.initial), num(p.estimate), num(p.stdError), num(p.stdError / p.estimate),
                                             num(p.estimate * std::exp(-1.96 * p.lnStdError)),
                                             num(p.estimate * std::exp(1.96 * p.lnStdError))});
        csv.close();
    }
    {
        CsvWriter csv(dir + "/fit_residuals.csv", {"dataset", "time_h", "quantity", "measured", "predicted", "residual"});
        for (const auto& e : r.residuals)
            csv.row(std::vector<std::string>{e.dataset, num(e.t / 3600.0), e.quantity, num(e.measured), num(e.predicted),
                                             num(e.measured - e.predicted)});
        csv.close();
    }
    std::ostringstream os;
    os << "fit " << in.text("title", file) << ": " << (r.converged ? "converged" : "NOT converged") << " (" << r.report << ")\n";
    os << "  " << std::left << std::setw(28) << "parameter" << std::setw(14) << "initial" << std::setw(14) << "estimate"
       << std::setw(14) << "std error" << "rel. error\n";
    for (const auto& p : r.parameters)
        os << "  " << std::setw(28) << p.key << std::setw(14) << num(p.initial, 4) << std::setw(14) << num(p.estimate, 5)
           << std::setw(14) << num(p.stdError, 3) << num(100 * p.stdError / p.estimate, 3) << " %\n";
    os << std::right << "  correlation of ln(parameters):\n";
    for (Eigen::Index i = 0; i < r.correlation.rows(); ++i)
    {
        os << "   ";
        for (Eigen::Index j = 0; j < r.correlation.cols(); ++j) os << std::setw(8) << num(r.correlation(i, j), 3);
        os << '\n';
    }
    os << "  points " << r.points << ", RMSE " << num(r.rmse, 4) << " mg/L, R^2 " << num(r.r2, 5) << ", chi2 " << num(r.chi2, 5)
       << (opt.scaleByResidualVariance ? " (errors scaled by chi2/(n-p))" : " (errors from the given sigma)") << '\n';
    writeTextFile(dir + "/fit_summary.txt", os.str());
    std::cout << os.str() << "  output: " << dir << "/\n";
    if (!plots) return 0;

    // fitted curves over the data
    for (std::size_t k = 0; k < data.size(); ++k)
    {
        const auto& d = data[k];
        const double tEnd = std::max(d.t.empty() ? 0.0 : *std::max_element(d.t.begin(), d.t.end()), 3600.0);
        std::vector<double> fine;
        for (int i = 0; i <= 200; ++i) fine.push_back(tEnd * i / 200.0);
        Overrides best;
        for (const auto& p : r.parameters) best.emplace_back(p.key, p.estimate);
        const auto curve = predictAt(d, best, fine);
        const std::string cf = dir + "/fit_curve_" + std::to_string(k + 1) + ".csv";
        const std::string mf = dir + "/fit_data_" + std::to_string(k + 1) + ".csv";
        std::vector<std::string> h = {"time_h"};
        for (const auto& q : d.quantities) h.push_back(q);
        {
            CsvWriter csv(cf, h);
            for (std::size_t i = 0; i < fine.size(); ++i)
            {
                std::vector<double> row = {fine[i] / 3600.0};
                for (const auto& c : curve) row.push_back(c[i]);
                csv.row(row);
            }
            csv.close();
            CsvWriter mcsv(mf, h);
            for (std::size_t i = 0; i < d.t.size(); ++i)
            {
                std::vector<double> row = {d.t[i] / 3600.0};
                for (const auto& c : d.measured) row.push_back(c[i]);
                mcsv.row(row);
            }
            mcsv.close();
        }
        std::ostringstream gp;
        gp << "set termoption noenhanced\nset datafile separator ','\nset grid\nset key outside right\nset xlabel 'time (h)'\n"
              "set ylabel 'mg/L (TOC: mg C/L)'\nset title 'fit: " << d.name << "'\nplot ";
        for (std::size_t q = 0; q < d.quantities.size(); ++q)
            gp << (q ? ", " : "") << "'" << cf << "' using 1:" << q + 2 << " with lines lw 2 lc " << q + 1 << " title '" << d.quantities[q]
               << " model', '" << mf << "' using 1:" << q + 2 << " with points pt 7 lc " << q + 1 << " title '" << d.quantities[q] << " data'";
        gp << '\n';
        plotPng(dir + "/fit_" + std::to_string(k + 1) + ".png", gp.str());
    }
    const std::string res = dir + "/fit_residuals.csv";
    plotPng(dir + "/fit_parity.png",
            "set termoption noenhanced\nset datafile separator ','\nset grid\nset xlabel 'measured (mg/L)'\nset ylabel 'predicted (mg/L)'\n"
            "set title 'goodness of fit: R^2 = " + num(r.r2, 4) + "'\nset size square\nplot '" + res +
                "' using 4:5 with points pt 7 title 'data', x with lines dt 2 title 'y = x'\n");
    plotPng(dir + "/fit_residuals.png",
            "set termoption noenhanced\nset datafile separator ','\nset grid\nset xlabel 'time (h)'\nset ylabel 'measured - predicted (mg/L)'\n"
            "set title 'residuals'\nplot '" + res + "' using 2:6 with points pt 7 title 'residual', 0 with lines dt 2 notitle\n");
    return 0;
}

} // namespace procsim::kinetics
