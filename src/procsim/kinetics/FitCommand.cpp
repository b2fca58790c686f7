// procsim kinetics fit: rate constants and [OH]-model parameters estimated
// from measured concentrations, with standard errors, residuals and plots.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "kinetics/Commands.hpp"
#include "kinetics/Fit.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

struct FitArgs
{
    std::string file;
    std::string output; // empty: <fit file name>_out
    bool noPlots = false;
};

std::optional<FitArgs> parse(int argc, char** argv)
{
    FitArgs a;
    CommandLine cl("kinetics fit", std::string(texts::help::fit));
    cl.input(a.file, "fit file");
    cl.text("-o,--output", a.output);
    cl.flag("--no-plots", a.noPlots);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

std::string num(double v, int p = 6)
{
    return formatNumber(v, p);
}

void writeParameters(const FitResult& r, const std::string& path)
{
    CsvWriter csv(path,
                  {"key", "initial", "estimate", "std_error", "rel_std_error", "ci95_low", "ci95_high"});
    for (const auto& p : r.parameters)
        csv.row(std::vector<std::string>{p.key, num(p.initial), num(p.estimate), num(p.stdError),
                                         num(p.stdError / p.estimate),
                                         num(p.estimate * std::exp(-1.96 * p.lnStdError)),
                                         num(p.estimate * std::exp(1.96 * p.lnStdError))});
    csv.close();
}

void writeResiduals(const FitResult& r, const std::string& path)
{
    CsvWriter csv(path, {"dataset", "time_h", "quantity", "measured", "predicted", "residual"});
    for (const auto& e : r.residuals)
        csv.row(std::vector<std::string>{e.dataset, num(e.t / 3600.0), e.quantity, num(e.measured),
                                         num(e.predicted), num(e.measured - e.predicted)});
    csv.close();
}

// Estimates, standard errors, correlations and goodness of fit, as printed
// and as fit_summary.txt.
std::string summary(const FitProblem& f, const FitResult& r)
{
    std::string os =
        fmt::format("fit {}: {} ({})\n", f.title, r.converged ? "converged" : "NOT converged", r.report);
    os += fmt::format("  {:<28}{:<14}{:<14}{:<14}rel. error\n", "parameter", "initial", "estimate",
                      "std error");
    for (const auto& p : r.parameters)
        os += fmt::format("  {:<28}{:<14}{:<14}{:<14}{} %\n", p.key, num(p.initial, 4), num(p.estimate, 5),
                          num(p.stdError, 3), num(100 * p.stdError / p.estimate, 3));
    os += "  correlation of ln(parameters):\n";
    for (Eigen::Index i = 0; i < r.correlation.rows(); ++i)
    {
        os += "   ";
        for (Eigen::Index j = 0; j < r.correlation.cols(); ++j)
            os += fmt::format("{:>8}", num(r.correlation(i, j), 3));
        os += '\n';
    }
    os += fmt::format("  points {}, RMSE {} mg/L, R^2 {}, chi2 {}{}\n", r.points, num(r.rmse, 4),
                      num(r.r2, 5), num(r.chi2, 5),
                      f.options.scaleByResidualVariance ? " (errors scaled by chi2/(n-p))"
                                                        : " (errors from the given sigma)");
    return os;
}

// A table with time_h and one column per quantity.
void writeSeries(const std::string& path, const FitDataset& d, const std::vector<double>& t,
                 const std::vector<std::vector<double>>& values)
{
    std::vector<std::string> h = {"time_h"};
    for (const auto& q : d.quantities) h.push_back(q);
    CsvWriter csv(path, h);
    for (std::size_t i = 0; i < t.size(); ++i)
    {
        std::vector<double> row = {t[i] / 3600.0};
        for (const auto& v : values) row.push_back(v[i]);
        csv.row(row);
    }
    csv.close();
}

// fit_<n>.png: the fitted model on 200 steps to the last measurement (at
// least an hour) over the data of dataset n.
void plotDataset(const FitDataset& d, const FitResult& r, std::size_t k, const std::string& dir)
{
    const double tEnd = std::max(d.t.empty() ? 0.0 : *std::max_element(d.t.begin(), d.t.end()), 3600.0);
    std::vector<double> fine;
    for (int i = 0; i <= 200; ++i) fine.push_back(tEnd * i / 200.0);
    const std::string n = std::to_string(k + 1);
    const std::string curve = dir + "/fit_curve_" + n + ".csv", data = dir + "/fit_data_" + n + ".csv";
    writeSeries(curve, d, fine, predictCurve(d, r.parameters, fine));
    writeSeries(data, d, d.t, d.measured);
    std::string names;
    for (const auto& q : d.quantities) names += q + " ";
    plotPng(
        dir + "/fit_" + n + ".png", texts::plots::fit_curves,
        PlotVariables().set("curve", curve).set("data", data).set("names", names).set("title_text", d.name));
}

void plot(const FitProblem& f, const FitResult& r, const std::string& dir)
{
    for (std::size_t k = 0; k < f.data.size(); ++k) plotDataset(f.data[k], r, k, dir);
    const std::string res = dir + "/fit_residuals.csv";
    plotPng(dir + "/fit_parity.png", texts::plots::fit_parity,
            PlotVariables().set("csv", res).set("r2_text", num(r.r2, 4)));
    plotPng(dir + "/fit_residuals.png", texts::plots::fit_residuals, PlotVariables().set("csv", res));
}

} // namespace

int fitCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const FitProblem f = readFitProblem(args->file);
    const FitResult r = fitParameters(f.parameters, f.data, f.options);
    const std::string dir =
        args->output.empty() ? std::filesystem::path(args->file).stem().string() + "_out" : args->output;
    createOutputDirectory(dir);
    writeParameters(r, dir + "/fit_parameters.csv");
    writeResiduals(r, dir + "/fit_residuals.csv");
    const std::string text = summary(f, r);
    writeTextFile(dir + "/fit_summary.txt", text);
    fmt::print("{}  output: {}/\n", text, dir);
    if (!args->noPlots) plot(f, r, dir);
    return 0;
}

} // namespace procsim::kinetics
