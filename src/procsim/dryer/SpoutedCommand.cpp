// procsim dryer spouted: the long-time spouted-bed drying predictor, a batch
// of N sample kernels carried through the circulation a CFD-DEM run measured
// (dryer/Spouted.hpp), with the tray dryer's energy metrics.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "Psychrometrics.hpp"
#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "dryer/Commands.hpp"
#include "dryer/Metrics.hpp"
#include "dryer/SpoutedInput.hpp"
#include "dryer/Texts.hpp"

namespace procsim::dryer
{

namespace
{

using spouted::Case;
using spouted::Result;

struct SpoutedArgs
{
    std::string file;
    std::string out = ".";
    std::optional<long> samples;
};

std::optional<SpoutedArgs> parse(int argc, char** argv)
{
    SpoutedArgs a;
    CommandLine cl("dryer spouted", std::string(texts::help::spouted));
    cl.input(a.file, "spouted-bed case");
    cl.text("--out", a.out);
    cl.integer("--samples", a.samples, 1, 10000000);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

double wetBasis(double x)
{
    return 100 * x / (1 + x);
}

void writeSeries(const std::string& path, const Result& r)
{
    CsvWriter s(path,
                {"time_h", "X_mean_percent_db", "M_mean_percent_wb", "M_p5_percent_wb", "M_p95_percent_wb",
                 "T_kernel_mean_C", "T_kernel_max_C", "T_outlet_C", "RH_outlet_percent", "W_outlet_kg_per_kg",
                 "evaporation_kg_per_h", "heater_kWh", "step_s"});
    for (const auto& p : r.series)
        s.row(std::vector<double>{p.t / 3600, 100 * p.xMean, wetBasis(p.xMean), wetBasis(p.xP5),
                                  wetBasis(p.xP95), p.tMeanC, p.tMaxC, p.outletC, 100 * p.outletRH, p.outletW,
                                  p.evaporation * 3600, p.heaterJ / 3.6e6, p.dt});
    s.close();
}

double relDiff(double model, double file)
{
    return file > 0 ? 100 * (model / file - 1) : std::nan("");
}

void writeRegions(const std::string& path, const Case& c, const Result& r)
{
    CsvWriter s(path, {"region", "heatTransferModel", "slipRe", "voidage", "h_W_per_m2K", "h_file_W_per_m2K",
                       "h_diff_percent", "km_m_per_s", "km_file_m_per_s", "km_diff_percent",
                       "residence_mean_s", "residence_samples", "holdup_share_predicted", "holdup_share_file",
                       "T_gas_C", "T_gas_file_C", "W_gas_kg_per_kg", "W_gas_file_kg_per_kg"});
    for (std::size_t i = 0; i < c.regions.size(); ++i)
    {
        const auto& g = c.regions[i];
        s.row(std::vector<std::string>{
            g.name, g.correlation, formatNumber(g.slipReynolds, 8), formatNumber(g.voidage, 8),
            formatNumber(g.h, 8), formatNumber(g.hFile, 8), formatNumber(relDiff(g.h, g.hFile), 4),
            formatNumber(g.km, 8), formatNumber(g.kmFile, 8), formatNumber(relDiff(g.km, g.kmFile), 4),
            formatNumber(g.residence.mean, 8), std::to_string(g.residence.samples),
            formatNumber(r.holdup[i], 6), formatNumber(g.holdupShare, 6), formatNumber(r.gasT[i] - 273.15, 6),
            g.gasTemperatureFile > 0 ? formatNumber(g.gasTemperatureFile - 273.15, 6) : "nan",
            formatNumber(r.gasW[i], 6), g.gasHumidityFile >= 0 ? formatNumber(g.gasHumidityFile, 6) : "nan"});
    }
    s.close();
}

BatchMetrics metricsOf(const Case& c, const Result& r)
{
    BatchRecord b;
    b.id = "spouted";
    b.hotAirC = c.inletC;
    b.ambientC = c.ambientC;
    b.x1 = c.initialX;
    b.x2 = r.finalX;
    b.timeS = r.endTime;
    b.electricityJ = r.heaterJ;
    b.waterKg = r.waterKg;
    b.dryMassKg = r.dryMassKg;
    return computeMetrics(b, LatentHeatConvention{});
}

std::vector<std::pair<std::string, std::string>> summary(const Case& c, const Result& r,
                                                         const BatchMetrics& m)
{
    const auto f = [](double v, int d) { return formatFixed(v, d); };
    return {{"reached_target", r.reachedTarget ? "1" : "0"},
            {"time_to_target_h", r.reachedTarget ? f(r.targetTime / 3600, 4) : "nan"},
            {"end_time_h", f(r.endTime / 3600, 4)},
            {"M_initial_percent_wb", f(wetBasis(c.initialX), 3)},
            {"M_final_percent_wb", f(wetBasis(r.finalX), 3)},
            {"X_final_std_percent_db", formatNumber(100 * r.finalStd, 6)},
            {"T_kernel_max_C", f(r.highestC, 3)},
            {"kernel_temperature_limit_C", f(c.limitC, 2)},
            {"time_any_kernel_above_limit_h", f(r.timeAnyAbove / 3600, 4)},
            {"mean_time_above_limit_h", f(r.meanTimeAbove / 3600, 4)},
            {"evaporated_water_kg", formatNumber(r.waterKg, 8)},
            {"heater_kWh", formatNumber(r.heaterJ / 3.6e6, 8)},
            {"E_kJ_per_kg", formatNumber(m.specificEnergy / 1e3, 6)},
            {"kWh_per_kg", formatNumber(m.specificEnergy / 3.6e6, 6)},
            {"eta_percent", formatNumber(100 * m.eta, 6)},
            {"water_balance_rel", formatScientific(r.waterBalanceRel, 2)},
            {"energy_balance_rel", formatScientific(r.energyBalanceRel, 2)},
            {"heat_of_sorption_kJ", formatNumber(r.sorptionJ / 1e3, 6)},
            {"steps", std::to_string(r.steps)},
            {"segments", std::to_string(r.segments)},
            {"samples", std::to_string(c.samples)}};
}

void printSummary(const Case& c, const Result& r, const BatchMetrics& m)
{
    fmt::print(
        "spouted bed: {} kernels ({} samples, seed {}), {}, air {:.1f} degC W {:.5f}, {:.4g} kg/s dry air\n",
        c.bedParticles, c.samples, c.seed, c.dryingName, c.inletC, c.inletW, c.airFlow);
    if (!c.statistics.empty())
        fmt::print("statistics: {} (run '{}'), cycle {:.3g} s (sum of the regions' means {:.3g} s)\n",
                   c.statistics, c.statisticsRun, c.cycleMean, [&] {
                       double s = 0;
                       for (const auto& g : c.regions) s += g.residence.mean;
                       return s;
                   }());
    if (!c.initialStateFile.empty())
    {
        const auto& x = c.initialStateX;
        double var = 0;
        for (const double v : x) var += (v - c.initialX) * (v - c.initialX);
        fmt::print("initial state: {} ({} kernels, sample i the row i mod {}): X mean {:.5f}, std {:.5f} "
                   "kg/kg d.b., T mean {:.2f} degC\n",
                   c.initialStateFile, x.size(), x.size(), c.initialX,
                   std::sqrt(var / static_cast<double>(x.size())), c.initialC);
    }
    if (!c.statistics.empty()
        && (std::fabs(c.statisticsInletC - c.inletC) > 0.5
            || std::fabs(c.statisticsInletW - c.inletW) > 1e-4))
        fmt::print(
            "note: the statistics' run had inlet air at {:.1f} degC, W {:.5f}: its measured h, k_m and gas "
            "temperatures are of that air, the circulation is taken as it is\n",
            c.statisticsInletC, c.statisticsInletW);
    fmt::print("{:<12}{:>14}{:>8}{:>9}{:>10}{:>9}{:>10}{:>10}{:>10}\n", "region", "correlation", "Re", "h",
               "h file", "dh %", "km", "km file", "holdup");
    for (std::size_t i = 0; i < c.regions.size(); ++i)
    {
        const auto& g = c.regions[i];
        fmt::print("{:<12}{:>14}{:>8.1f}{:>9.2f}{:>10.2f}{:>9.2f}{:>10.4f}{:>10.4f}{:>10.3f}\n", g.name,
                   g.correlation, g.slipReynolds, g.h, g.hFile, relDiff(g.h, g.hFile), g.km, g.kmFile,
                   r.holdup[i]);
    }
    for (const auto& g : c.regions)
        if (g.partOf >= 0 && g.intoCore > 0)
            fmt::print("{}: exchanges {:.3g} x the inlet air with the rest beside it ({:.3g} crossing, "
                       "{:.0f} % of it carrying heat by gas.carried)\n",
                       g.name, g.exchangeShare * g.intoCore, g.intoCore, 100 * g.exchangeShare);
    fmt::print("moisture {:.2f} -> {:.2f} % w.b. (target {:.2f}): {}\n", wetBasis(c.initialX),
               wetBasis(r.finalX), wetBasis(c.targetX),
               r.reachedTarget ? fmt::format("reached after {:.3f} h", r.targetTime / 3600)
                               : fmt::format("not reached in {:.3f} h", r.endTime / 3600));
    fmt::print(
        "spread of kernel moisture (std) {:.3f} % d.b.; hottest kernel {:.2f} degC, limit {:.1f} degC: "
        "some kernel above it {:.3f} h, each kernel on average {:.3f} h\n",
        100 * r.finalStd, r.highestC, c.limitC, r.timeAnyAbove / 3600, r.meanTimeAbove / 3600);
    fmt::print("water {:.4g} kg, heater {:.4g} kWh: E {:.0f} kJ/kg ({:.3f} kWh/kg), eta {:.1f} %\n",
               r.waterKg, r.heaterJ / 3.6e6, m.specificEnergy / 1e3, m.specificEnergy / 3.6e6, 100 * m.eta);
    fmt::print("balances: water {:.1e}, energy {:.1e} (relative); {} steps, {} segments\n", r.waterBalanceRel,
               r.energyBalanceRel, r.steps, r.segments);
}

} // namespace

int spoutedCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    Case c = spouted::readCase(args->file);
    if (args->samples) c.samples = *args->samples;
    createOutputDirectory(args->out);
    const Result r = spouted::run(c);
    const BatchMetrics m = metricsOf(c, r);
    const std::string base = args->out + "/spouted";
    writeSeries(base + "_series.csv", r);
    writeRegions(base + "_regions.csv", c, r);
    CsvWriter s(base + "_summary.csv", {"quantity", "value"});
    for (const auto& [k, v] : summary(c, r, m)) s.row(std::vector<std::string>{k, v});
    // each core's exchange with the rest beside it: the share of the
    // measured two-way flow that carries heat
    for (const auto& g : c.regions)
        if (g.partOf >= 0 && g.intoCore > 0)
            s.row(std::vector<std::string>{g.name + "_exchange_share", formatFixed(g.exchangeShare, 4)});
    s.close();
    printSummary(c, r, m);
    plotPng(base + ".png", texts::plots::spouted,
            PlotVariables()
                .set("csv", base + "_series.csv")
                .set("limit", c.limitC)
                .set("target", wetBasis(c.targetX)),
            1000, 1000);
    fmt::print("wrote {0}_series.csv, {0}_regions.csv, {0}_summary.csv, {0}.png\n", base);
    return 0;
}

} // namespace procsim::dryer
