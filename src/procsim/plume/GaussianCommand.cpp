// procsim plume gaussian: the ISCST3-style plume for every hour of a
// meteorology series: hourly and 24-h concentrations at the receptors.
#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Format.hpp"
#include "common/Plot.hpp"
#include "common/YamlInput.hpp"
#include "plume/Commands.hpp"
#include "plume/GaussianCase.hpp"
#include "plume/Texts.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

namespace
{

struct GaussianArgs
{
    std::string casePath;
    std::string outDir = "results";
};

std::optional<GaussianArgs> parse(int argc, char** argv)
{
    GaussianArgs a;
    CommandLine cl("plume gaussian", std::string(texts::help::gaussian));
    cl.input(a.casePath, "case file");
    cl.text("-o", a.outDir);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

struct GaussianCase
{
    GaussianSetup setup;
    MetSeries met;
};

GaussianCase load(const std::string& casePath)
{
    const YamlInput in = YamlInput::load(casePath);
    std::vector<std::string> keys = gaussianSetupKeys();
    keys.push_back("meteorology");
    in.rejectUnknown(keys);
    GaussianCase c;
    c.setup = parseGaussianSetup(in);
    const std::string dir = fs::path(casePath).parent_path().string();
    c.met = readMet(relativeTo(dir, in.text("meteorology")), true);
    return c;
}

// Every hour's conditions and the 1-h concentrations they give.
struct GaussianRun
{
    std::vector<PlumeHour> conditions;  // per hour
    std::vector<std::vector<double>> c; // [receptor][hour], ug/m3
    std::array<int, 7> classCount{};    // hours per stability class 1..6

    int hours() const { return static_cast<int>(conditions.size()); }
    int days() const { return hours() / 24; }
    double mean24(std::size_t r, int day) const
    {
        double s = 0;
        for (int h = day * 24; h < (day + 1) * 24; ++h) s += c[r][h];
        return s / 24;
    }
};

GaussianRun run(const GaussianModel& model, const GaussianCase& cs)
{
    const auto& receptors = cs.setup.receptors;
    const int hours = static_cast<int>(cs.met.hours.size());
    GaussianRun r;
    r.c.assign(receptors.size(), std::vector<double>(hours));
    for (int h = 0; h < hours; ++h)
    {
        const PlumeHour ph = model.hourConditions(cs.met.hours[h], h);
        r.conditions.push_back(ph);
        ++r.classCount[ph.cls];
        for (std::size_t k = 0; k < receptors.size(); ++k)
            r.c[k][h] = model.concentration(ph, receptors[k]) * 1e9; // kg/m3 -> ug/m3
    }
    return r;
}

std::vector<std::string> receptorColumns(const std::string& first, const std::vector<Receptor>& receptors)
{
    std::vector<std::string> header = {first};
    for (const auto& r : receptors) header.push_back(r.name + " [ug/m3]");
    return header;
}

void writeHourly(const std::string& path, const GaussianCase& cs, const GaussianRun& r)
{
    std::vector<std::string> header = {"hour", "class", "wind_speed_m_s", "wind_direction_deg",
                                       "mixing_height_m"};
    for (const auto& rc : cs.setup.receptors) header.push_back(rc.name + " [ug/m3]");
    CsvWriter hourly(path, header);
    for (int h = 0; h < r.hours(); ++h)
    {
        const PlumeHour& ph = r.conditions[h];
        std::vector<std::string> row = {std::to_string(cs.met.firstHour + h),
                                        std::string(1, className(ph.cls)), formatNumber(ph.u10),
                                        formatNumber(ph.directionFrom), formatNumber(ph.mixingHeight)};
        for (const auto& ck : r.c) row.push_back(formatNumber(ck[h]));
        hourly.row(row);
    }
    hourly.close();
}

void writeDaily(const std::string& path, const GaussianCase& cs, const GaussianRun& r)
{
    CsvWriter daily(path, receptorColumns("day", cs.setup.receptors));
    for (int d = 0; d < r.days(); ++d)
    {
        std::vector<double> row = {static_cast<double>(d + 1)};
        for (std::size_t k = 0; k < r.c.size(); ++k) row.push_back(r.mean24(k, d));
        daily.row(row);
    }
    daily.close();
}

void printHeader(const GaussianArgs& a, const GaussianModel& model, const GaussianCase& cs,
                 const GaussianRun& r)
{
    const GaussianOptions& o = cs.setup.options;
    fmt::print(
        "procsim plume gaussian: {}\n  {} h, {} sources, {} receptors, reduction {} %, deposition velocity {} "
        "m/s, dispersion {}\n  hours per class:",
        a.casePath, r.hours(), cs.setup.sources.size(), cs.setup.receptors.size(),
        formatNumber(o.reduction * 100), formatNumber(o.depositionVelocity), model.dispersionTitle());
    for (int k = 1; k <= 6; ++k) fmt::print(" {} {}", className(k), r.classCount[k]);
    fmt::print("\n\n  {:<12}{:>12}{:>12}{:>12}   [ug/m3]\n", "receptor", "mean", "max 1-h", "max 24-h");
}

// Per receptor: mean, highest 1-h and highest 24-h average; * above the standard.
void printReceptors(const GaussianCase& cs, const GaussianRun& r)
{
    for (std::size_t k = 0; k < r.c.size(); ++k)
    {
        double mean = 0, max1 = 0, max24 = 0;
        for (double v : r.c[k])
        {
            mean += v / r.hours();
            max1 = std::max(max1, v);
        }
        for (int d = 0; d < r.days(); ++d) max24 = std::max(max24, r.mean24(k, d));
        fmt::print("  {:<12}{:>12.2f}{:>12.2f}{:>12.2f}{}\n", cs.setup.receptors[k].name, mean, max1, max24,
                   max24 > cs.setup.standardUgM3 ? " *" : "");
    }
}

void report(const GaussianArgs& a, const GaussianModel& model, const GaussianCase& cs, const GaussianRun& r)
{
    const std::string daily = (fs::path(a.outDir) / "daily.csv").string();
    writeHourly((fs::path(a.outDir) / "hourly.csv").string(), cs, r);
    writeDaily(daily, cs, r);
    printHeader(a, model, cs, r);
    printReceptors(cs, r);
    if (r.days() > 0)
        plotPng((fs::path(a.outDir) / "daily.png").string(), texts::plots::receptors_24h,
                PlotVariables()
                    .set("csv", daily)
                    .set("nreceptors", static_cast<double>(cs.setup.receptors.size()))
                    .set("title_text", "Gaussian plume: 24-h averages at the receptors")
                    .set("standard", cs.setup.standardUgM3));
    fmt::print("\n  (* = a 24-h average above {} ug/m3); outputs in {}/ (hourly.csv, daily.csv, daily.png)\n",
               formatNumber(cs.setup.standardUgM3), a.outDir);
}

} // namespace

int gaussianCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const GaussianCase cs = load(args->casePath);
    const GaussianModel model(cs.setup.sources, cs.setup.options);
    createOutputDirectory(args->outDir);
    report(*args, model, cs, run(model, cs));
    return 0;
}

} // namespace procsim::plume
