// procsim dryer whatif: one batch at every hot-air temperature x vented
// fraction; which settings scorch, which use least energy, which are fastest.
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

struct WhatifArgs
{
    std::string plant;
    std::string out = ".";
};

std::optional<WhatifArgs> parse(int argc, char** argv)
{
    WhatifArgs a;
    CommandLine cl("dryer whatif", std::string(texts::help::whatif) + "\n" + std::string(texts::help::plant));
    cl.input(a.plant, "plant file");
    cl.text("--out", a.out);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

// The best settings that reach the target without scorching.
struct Best
{
    double energy = 1e300, time = 1e300;
    std::string lowestEnergy, fastest; // descriptions, empty if none qualifies

    void consider(double T, double v, const BatchResult& r)
    {
        if (!r.reachedTarget || r.scorched) return;
        const std::string setting = fmt::format(
            "hot air {:.1f} degC, vented fraction {:.3f}: {} h, E = {:.0f} kJ/kg, highest product temperature "
            "{:.1f} degC",
            T, v, formatHoursMinutes(r.dryingTime), r.specificEnergy / 1e3, r.tProductMax);
        if (r.dryingTime < time) time = r.dryingTime, fastest = setting;
        if (r.specificEnergy < energy) energy = r.specificEnergy, lowestEnergy = setting;
    }
};

void printPoint(double T, double v, const BatchResult& r)
{
    fmt::print("{:>8.1f}{:>9.3f}{:>9}{:>10.0f}{:>9.1f}{}\n", T, v,
               (r.reachedTarget ? "" : ">") + formatHoursMinutes(r.dryingTime), r.specificEnergy / 1e3,
               r.tProductMax, r.scorched ? "  SCORCHED" : "");
}

// Every setting simulated, printed and written to whatif.csv, one data
// block per vented fraction (two blank lines apart, as gnuplot's `index` reads).
Best sweep(const Plant& plant, const BatchSpec& b, const std::string& path)
{
    CsvWriter csv(path, {"hot_air_temperature_C", "vented_fraction", "reached_target", "drying_time_h",
                         "electricity_kWh", "E_kJ_per_kg", "eta_percent", "T_product_max_C", "scorched"});
    fmt::print("{:>8}{:>9}{:>9}{:>10}{:>9}\n", "T_hot", "vented", "time", "E kJ/kg", "Tp max");
    Best best;
    for (double v : plant.whatifVentedFractions)
    {
        for (double T : plant.whatifTemperatures)
        {
            DryerCase c = plant.caseFor(b, plant.whatifVenting);
            c.hotAirC = T;
            c.ventedFraction = v;
            const BatchResult r = simulate(c);
            printPoint(T, v, r);
            csv.row(std::vector<double>{T, v, r.reachedTarget ? 1.0 : 0.0, r.dryingTime / 3600,
                                        r.electricityJ / 3.6e6, r.specificEnergy / 1e3, r.eta * 100,
                                        r.tProductMax, r.scorched ? 1.0 : 0.0});
            best.consider(T, v, r);
        }
        csv.row(std::vector<std::string>{});
        csv.row(std::vector<std::string>{});
    }
    csv.close();
    return best;
}

void plot(const Plant& plant, const BatchSpec& b, const std::string& dir)
{
    std::string fractions;
    for (double v : plant.whatifVentedFractions) fractions += formatFixed(v, 3) + " ";
    PlotVariables vars;
    vars.set("csv", dir + "/whatif.csv")
        .set("nblocks", double(plant.whatifVentedFractions.size()))
        .set("fractions", fractions)
        .set("title_text", fmt::format("batch {}, venting {} (red: scorched, product above {:.0f} degC)",
                                       b.id, plant.whatifVenting, plant.base.scorchC));
    plotPng(dir + "/whatif_time.png", texts::plots::whatif,
            PlotVariables(vars).set("ycol", 4).set("ylabel_text", "drying time [h]"));
    plotPng(dir + "/whatif_energy.png", texts::plots::whatif,
            PlotVariables(vars).set("ycol", 6).set("ylabel_text", "specific energy E [kJ/kg water]"));
}

void report(const Plant& plant, const Best& best, const std::string& dir)
{
    fmt::print("\nscorch limit: product temperature {:.1f} degC\n", plant.base.scorchC);
    if (best.lowestEnergy.empty())
        fmt::print("best setting: none reaches the target without scorching\n");
    else
    {
        fmt::print("best setting (lowest E without scorching): {}\n", best.lowestEnergy);
        fmt::print("fastest setting without scorching:         {}\n", best.fastest);
    }
    fmt::print("wrote {}/whatif.csv, whatif_time.png, whatif_energy.png\n", dir);
}

} // namespace

int whatifCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const Plant plant = readPlant(args->plant);
    if (plant.whatifBatch.empty())
        throw InputError(plant.file + ": key 'whatif' is missing (needed by whatif)");
    createOutputDirectory(args->out);
    const BatchSpec& b = plant.batch(plant.whatifBatch);
    const Best best = sweep(plant, b, args->out + "/whatif.csv");
    plot(plant, b, args->out);
    report(plant, best, args->out);
    return 0;
}

} // namespace procsim::dryer
