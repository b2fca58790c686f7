// procsim dryer metrics: E, eta, water evaporated and dry mass of batch
// records (the paper's Table 1).
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "dryer/Commands.hpp"
#include "dryer/Metrics.hpp"
#include "dryer/Texts.hpp"

namespace procsim::dryer
{

namespace
{

struct MetricsArgs
{
    std::string records;
    std::string out = ".";
    std::optional<double> latentKJPerKg; // a constant latent heat instead of the default convention
};

struct MetricsRow
{
    BatchRecord batch;
    BatchMetrics metrics;
    double paperEta, paperE; // % and kJ/kg, NaN when not published
};

std::optional<MetricsArgs> parse(int argc, char** argv)
{
    MetricsArgs a;
    CommandLine cl("dryer metrics", std::string(texts::help::metrics));
    cl.input(a.records, "records file");
    cl.text("--out", a.out);
    cl.number("--latent-heat-kJ-per-kg", a.latentKJPerKg);
    if (!cl.parse(argc, argv)) return std::nullopt;
    if (a.latentKJPerKg && !(*a.latentKJPerKg > 0))
        throw cl.refuse("--latent-heat-kJ-per-kg", "a positive number", formatNumber(*a.latentKJPerKg));
    return a;
}

std::vector<MetricsRow> run(const BatchFile& f)
{
    std::vector<MetricsRow> rows;
    for (const auto& b : f.batches)
    {
        rows.push_back({b, computeMetrics(b, f.latentHeat), b.paperEta ? *b.paperEta * 100 : std::nan(""),
                        b.paperE ? *b.paperE / 1e3 : std::nan("")});
    }
    return rows;
}

void printRow(const MetricsRow& r)
{
    const BatchMetrics& m = r.metrics;
    const double dE = (m.specificEnergy / 1e3 / r.paperE - 1) * 100;
    fmt::print("{:<7}{:>10.1f}{:>10.1f}{:>9.2f}{:>9.1f}{:>9.2f}{:>9.2f}{:>10.2f}{:>10.2f}{:>9.3f}\n",
               r.batch.id, m.waterKg, m.dryMassKg, m.rateKgPerH, m.latentJPerKg / 1e3, m.eta * 100,
               r.paperEta, m.specificEnergy / 1e3, r.paperE, dE);
    if (m.rateDisagrees)
    {
        fmt::print("        warning: the reported rate x drying time gives {:.1f} kg, not {:.1f} kg ({}); "
                   "{:.2f} h would match\n",
                   m.rateWaterKg, m.waterKg, m.waterFrom, m.waterKg / (*r.batch.rateKgPerS * 3600));
    }
}

std::vector<std::string> csvRow(const MetricsRow& r)
{
    const BatchRecord& b = r.batch;
    const BatchMetrics& m = r.metrics;
    const double dEta = (m.eta * 100 / r.paperEta - 1) * 100,
                 dE = (m.specificEnergy / 1e3 / r.paperE - 1) * 100;
    auto f4 = [](double v) { return formatFixed(v, 4); };
    return {b.id,
            formatFixed(b.hotAirC, 2),
            f4(b.x1 * 100),
            f4(b.x2 * 100),
            formatFixed(b.timeS / 3600, 6),
            f4(m.electricityKWh),
            f4(m.waterKg),
            f4(m.dryMassKg),
            f4(m.rateKgPerH),
            f4(m.latentJPerKg / 1e3),
            f4(m.eta * 100),
            f4(m.specificEnergy / 1e3),
            f4(r.paperEta),
            f4(r.paperE),
            f4(dEta),
            f4(dE)};
}

void report(const std::string& dir, const LatentHeatConvention& latent, const std::vector<MetricsRow>& rows)
{
    CsvWriter csv(dir + "/metrics.csv",
                  {"batch", "hot_air_temperature_C", "X1_percent_db", "X2_percent_db", "drying_time_h",
                   "electricity_kWh", "evaporated_water_kg", "dry_mass_kg", "evaporation_rate_kg_per_h",
                   "latent_heat_kJ_per_kg", "eta_percent", "E_kJ_per_kg", "paper_eta_percent",
                   "paper_E_kJ_per_kg", "eta_dev_percent", "E_dev_percent"});
    fmt::print("latent heat: {}\n\n", latent.describe());
    fmt::print("{:<7}{:>10}{:>10}{:>9}{:>9}{:>9}{:>9}{:>10}{:>10}{:>9}\n", "batch", "water kg", "dry kg",
               "kg/h", "L kJ/kg", "eta %", "paper", "E kJ/kg", "paper", "dE %");
    for (const auto& r : rows)
    {
        printRow(r);
        csv.row(csvRow(r));
    }
    csv.close();
    fmt::print("\nwrote {}/metrics.csv\n", dir);
}

} // namespace

int metricsCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    BatchFile f = readBatchFile(args->records);
    if (args->latentKJPerKg)
    {
        f.latentHeat.kind = LatentHeatConvention::Kind::Constant;
        f.latentHeat.constant = *args->latentKJPerKg * 1e3;
    }
    createOutputDirectory(args->out);
    report(args->out, f.latentHeat, run(f));
    return 0;
}

} // namespace procsim::dryer
