// procsim dryer simulate: batches of a plant file, each until its average
// moisture reaches the target: air, moisture per tray, energy.
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "dryer/Commands.hpp"
#include "dryer/Model.hpp"
#include "dryer/Plant.hpp"
#include "dryer/Texts.hpp"

namespace procsim::dryer
{

namespace
{

struct SimulateArgs
{
    std::string plant;
    std::optional<std::string> batch; // none: every batch
    std::string out = ".";
};

std::optional<SimulateArgs> parse(int argc, char** argv)
{
    SimulateArgs a;
    CommandLine cl("dryer simulate",
                   std::string(texts::help::simulate) + "\n" + std::string(texts::help::plant));
    cl.input(a.plant, "plant file");
    cl.text("--batch", a.batch);
    cl.text("--out", a.out);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

void writeSeries(const std::string& base, const BatchResult& r)
{
    CsvWriter s(base + "_series.csv",
                {"time_h", "T_supply_C", "T_return_C", "W_supply_kg_per_kg", "W_return_kg_per_kg",
                 "RH_return_percent", "X_mean_percent_db", "X_min_percent_db", "X_max_percent_db",
                 "T_product_mean_C", "T_product_max_C", "heater_kW", "evaporation_kg_per_h",
                 "electricity_kWh"});
    for (const auto& p : r.series)
        s.row(std::vector<double>{p.t / 3600, p.tSupply, p.tReturn, p.wSupply, p.wReturn, p.rhReturn * 100,
                                  p.xAvg * 100, p.xMin * 100, p.xMax * 100, p.tProductMean, p.tProductMax,
                                  p.heaterW / 1e3, p.evaporationKgPerS * 3600, p.electricityJ / 3.6e6});
    s.close();
}

// Per tray: its air share, initial and final moisture and its deviation
// from the batch mean (the paper's f1/f2 count these).
void writeTrays(const std::string& base, const DryerCase& c, const BatchResult& r)
{
    const auto phi = c.airShares();
    double mean = 0;
    for (double x : r.trayX) mean += x / r.trayX.size();
    CsvWriter t(base + "_trays.csv", {"cart", "tray", "air_share", "X_initial_percent_db",
                                      "X_final_percent_db", "deviation_percent", "T_product_final_C"});
    for (int ci = 0; ci < c.carts; ++ci)
        for (int k = 0; k < c.traysPerCart; ++k)
        {
            const std::size_t i = static_cast<std::size_t>(ci * c.traysPerCart + k);
            t.row(std::vector<double>{double(ci + 1), double(k + 1), phi[i], r.trayX0[i] * 100,
                                      r.trayX[i] * 100, (r.trayX[i] / mean - 1) * 100, r.trayT[i]});
        }
    t.close();
}

void writeTrayMoisture(const std::string& base, const DryerCase& c, const BatchResult& r)
{
    std::vector<std::string> h{"time_h"};
    for (int ci = 0; ci < c.carts; ++ci)
        for (int k = 0; k < c.traysPerCart; ++k)
            h.push_back(fmt::format("X_cart{}_tray{}_percent_db", ci + 1, k + 1));
    CsvWriter m(base + "_tray_moisture.csv", h);
    for (std::size_t j = 0; j < r.series.size(); ++j)
    {
        std::vector<double> row{r.series[j].t / 3600};
        for (double x : r.trayXSeries[j]) row.push_back(x * 100);
        m.row(row);
    }
    m.close();
}

void writeBatchOutputs(const std::string& dir, const DryerCase& c, const BatchResult& r)
{
    const std::string base = dir + "/" + c.name;
    writeSeries(base, r);
    writeTrays(base, c, r);
    writeTrayMoisture(base, c, r);
    plotPng(base + "_batch.png", texts::plots::batch,
            PlotVariables().set("csv", base + "_series.csv").set("name", c.name), 1000, 1000);
}

std::string timeCell(const BatchResult& r) // "7:05", or ">30:00" when the target was not reached
{
    return (r.reachedTarget ? "" : ">") + formatHoursMinutes(r.dryingTime);
}

void printHeader()
{
    fmt::print("{:<7}{:>8}{:>10}{:>10}{:>10}{:>8}{:>8}{:>7}{:>7}{:>11}{:>11}\n", "batch", "time", "kWh",
               "water kg", "E kJ/kg", "eta %", "Tp max", "f1 %", "f2 %", "water bal", "energy bal");
}

void printBatch(const std::string& id, const BatchResult& r)
{
    fmt::print("{:<7}{:>8}{:>10.1f}{:>10.1f}{:>10.0f}{:>8.1f}{:>8.1f}{:>7.1f}{:>7.1f}{:>11.1e}{:>11.1e}{}\n",
               id, timeCell(r), r.electricityJ / 3.6e6, r.waterEvaporated, r.specificEnergy / 1e3,
               r.eta * 100, r.tProductMax, r.f1, r.f2, r.waterBalanceRel, r.energyBalanceRel,
               r.scorched ? "  SCORCHED" : "");
}

std::vector<std::string> summaryRow(const std::string& id, const BatchResult& r)
{
    return {id,
            r.reachedTarget ? "1" : "0",
            formatFixed(r.dryingTime / 3600, 4),
            formatFixed(r.electricityJ / 3.6e6, 3),
            formatFixed(r.waterEvaporated, 3),
            formatFixed(r.specificEnergy / 1e3, 3),
            formatFixed(r.eta * 100, 3),
            formatFixed(r.tProductMax, 3),
            r.scorched ? "1" : "0",
            formatFixed(r.f1, 2),
            formatFixed(r.f2, 2),
            formatFixed(r.condensateKg, 3),
            formatScientific(r.waterBalanceRel, 1),
            formatScientific(r.energyBalanceRel, 1)};
}

} // namespace

int simulateCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const Plant plant = readPlant(args->plant);
    createOutputDirectory(args->out);
    std::vector<const BatchSpec*> todo;
    if (args->batch)
        todo.push_back(&plant.batch(*args->batch));
    else
        for (const auto& b : plant.batches) todo.push_back(&b);
    CsvWriter sum(args->out + "/simulate_summary.csv",
                  {"batch", "reached_target", "drying_time_h", "electricity_kWh", "evaporated_water_kg",
                   "E_kJ_per_kg", "eta_percent", "T_product_max_C", "scorched", "f1_percent", "f2_percent",
                   "condensate_kg", "water_balance_rel", "energy_balance_rel"});
    printHeader();
    for (const BatchSpec* b : todo)
    {
        const DryerCase c = plant.caseFor(*b);
        const BatchResult r = simulate(c);
        writeBatchOutputs(args->out, c, r);
        printBatch(b->id, r);
        sum.row(summaryRow(b->id, r));
    }
    sum.close();
    fmt::print("\nwrote {}/simulate_summary.csv and per-batch CSV/PNG\n", args->out);
    return 0;
}

} // namespace procsim::dryer
