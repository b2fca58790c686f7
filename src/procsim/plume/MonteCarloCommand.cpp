// procsim plume montecarlo: gamma distributions fitted to historical
// meteorology, synthetic years drawn from them, the Gaussian plume for every
// hour of each; statistics of the 24-h averages over the years.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "common/Checked.hpp"
#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Format.hpp"
#include "common/Plot.hpp"
#include "common/YamlInput.hpp"
#include "plume/Commands.hpp"
#include "plume/GaussianCase.hpp"
#include "plume/MonteCarlo.hpp"
#include "plume/Texts.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

namespace
{

constexpr long maxYears = 100000; // synthetic years: ~10 minutes per 1000 on one thread
constexpr int daysPerYear = 365, hoursPerYear = 8760;

// ---- parse -------------------------------------------------------------------

struct MonteCarloArgs
{
    std::string casePath;
    std::string outDir = "results";
    std::optional<long> years, threads, seed; // none: the case's
};

std::optional<MonteCarloArgs> parse(int argc, char** argv)
{
    MonteCarloArgs a;
    CommandLine cl("plume montecarlo", std::string(texts::help::montecarlo));
    cl.input(a.casePath, "case file");
    cl.text("-o", a.outDir);
    cl.integer("--years", a.years);
    cl.integer("--threads", a.threads);
    cl.integer("--seed", a.seed);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

struct MonteCarloCase
{
    GaussianSetup setup;
    int historyDay = 1; // calendar position of the first history row
    double historyHour = 0;
    long years = 50;
    double w = 0.5; // weight of the previous hour's normal score
    unsigned long long seed = 2001;
    std::vector<double> thresholds = {120, 150}; // ug/m3
    MetSeries history;
    Climate climate;
    unsigned threads = 1;
};

void readHistoryStart(const YamlInput& in, MonteCarloCase& c)
{
    if (!in.has("history_start")) return;
    const YamlInput hs = in.child("history_start");
    hs.rejectUnknown({"day_of_year", "hour"});
    if (hs.has("day_of_year"))
    {
        c.historyDay = static_cast<int>(hs.integer("day_of_year"));
        if (c.historyDay < 1 || c.historyDay > 365) throw hs.error("day_of_year", "1..365");
    }
    c.historyHour = hs.number("hour", 0.0, "h");
    if (c.historyHour < 0 || c.historyHour >= 24) throw hs.error("hour", "0..24 [h]");
}

// years, weighting, seed and thresholds; a command-line option wins over the case
void readSampling(const YamlInput& in, const MonteCarloArgs& a, MonteCarloCase& c)
{
    if (in.has("years")) c.years = in.integer("years", 1, maxYears);
    if (a.years) c.years = *a.years;
    if (c.years > maxYears)
        throw InputError("plume montecarlo: " + std::to_string(c.years) + " synthetic years asked for (limit "
                         + std::to_string(maxYears) + ")");
    c.w = in.number("weighting", 0.5);
    if (!(c.w >= 0 && c.w < 1)) throw in.error("weighting", "a number in [0, 1)");
    if (in.has("seed")) c.seed = static_cast<unsigned long long>(in.integer("seed", 0, 2147483647L));
    if (a.seed) c.seed = static_cast<unsigned long long>(*a.seed);
    if (in.has("thresholds_ug_m3"))
    {
        // one column of summary.csv each: increasing, none twice, all above 0
        c.thresholds = in.increasingNumbers("thresholds_ug_m3", "ug/m3");
        if (!(c.thresholds.front() > 0))
            throw InputError(in.file()
                             + ": key 'thresholds_ug_m3[0]' expected a concentration above 0 [ug/m3], got "
                             + formatNumber(c.thresholds.front()));
    }
}

// The history (at least a year of hours) and the gamma fits to it.
void readHistory(const std::string& path, MonteCarloCase& c)
{
    c.history = readMet(path, true);
    if (c.history.hours.size() < hoursPerYear)
        throw InputError(path + ": " + std::to_string(c.history.hours.size())
                         + " hours of history; expected at least one year (8760 hours)");
    try
    {
        c.climate = fitClimate(c.history, c.historyDay, c.historyHour);
    }
    catch (const InputError& e)
    {
        // fitClimate's messages start "history: "; name the file instead
        throw InputError(path + ": " + std::string(e.what()).substr(9));
    }
}

MonteCarloCase load(const MonteCarloArgs& a)
{
    const YamlInput in = YamlInput::load(a.casePath);
    std::vector<std::string> keys = gaussianSetupKeys();
    keys.insert(keys.end(), {"history", "history_start", "years", "weighting", "seed", "thresholds_ug_m3"});
    in.rejectUnknown(keys);
    MonteCarloCase c;
    c.setup = parseGaussianSetup(in);
    c.setup.options.startDayOfYear = 1; // synthetic years start on 1 January, 0 h
    c.setup.options.startHour = 0;
    readHistoryStart(in, c);
    readSampling(in, a, c);
    readHistory(relativeTo(fs::path(a.casePath).parent_path().string(), in.text("history")), c);
    const std::size_t nr = c.setup.receptors.size();
    checkMemory(
        static_cast<double>(c.years) * daysPerYear * static_cast<double>(nr), sizeof(double), a.casePath,
        std::to_string(c.years) + " synthetic years of daily values at " + std::to_string(nr) + " receptors");
    c.threads =
        static_cast<unsigned>(a.threads ? *a.threads : std::max(1u, std::thread::hardware_concurrency()));
    return c;
}

// ---- run ---------------------------------------------------------------------

using Sectors = std::array<long, 8>; // hours per 45-degree wind-direction sector
using Speeds = std::array<long, 4>;  // hours per wind-speed class 0-2, 2-4, 4-6, > 6 m/s

int sectorOf(const MetHour& h)
{
    return static_cast<int>(h.directionFrom / 45.0) % 8;
}
int speedClassOf(const MetHour& h)
{
    return std::min(3, static_cast<int>(h.speed / 2.0));
}

struct Realisations
{
    std::vector<std::vector<std::vector<double>>> daily; // [year][receptor][day], ug/m3
    std::vector<Sectors> sectors;                        // per year
    std::vector<Speeds> speeds;
    std::vector<MetHour> firstYear; // the met of year 1, as an example
    double wallSeconds = 0;
};

// Year r: its own random stream (seed, r), so the result does not depend on
// which thread draws it.
void simulateYear(long r, const MonteCarloCase& c, const GaussianModel& model, Realisations& out)
{
    Stream rng(c.seed, static_cast<std::uint64_t>(r));
    const auto met = synthesiseYear(c.climate, c.w, rng);
    auto& d = out.daily[r];
    for (int t = 0; t < hoursPerYear; ++t)
    {
        const PlumeHour ph = model.hourConditions(met[t], t);
        for (std::size_t k = 0; k < d.size(); ++k)
            d[k][t / 24] += model.concentration(ph, c.setup.receptors[k]) * 1e9 / 24;
        out.sectors[r][sectorOf(met[t])]++;
        out.speeds[r][speedClassOf(met[t])]++;
    }
    if (r == 0) out.firstYear = met;
}

Realisations run(const MonteCarloCase& c, const GaussianModel& model)
{
    const std::size_t nr = c.setup.receptors.size();
    Realisations out;
    out.daily.assign(c.years, std::vector<std::vector<double>>(nr, std::vector<double>(daysPerYear, 0.0)));
    out.sectors.resize(c.years);
    out.speeds.resize(c.years);
    std::atomic<long> next{0};
    const auto t0 = std::chrono::steady_clock::now();
    auto worker = [&]() {
        for (long r = next++; r < c.years; r = next++) simulateYear(r, c, model, out);
    };
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < std::min<unsigned>(c.threads, static_cast<unsigned>(c.years)); ++i)
        pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

// ---- report ------------------------------------------------------------------

// percentile p (0..100) of sorted values, linear between order statistics
double percentile(const std::vector<double>& sorted, double p)
{
    if (sorted.empty()) return 0;
    const double pos = p / 100 * (sorted.size() - 1);
    const std::size_t i = static_cast<std::size_t>(pos);
    if (i + 1 >= sorted.size()) return sorted.back();
    return sorted[i] + (pos - i) * (sorted[i + 1] - sorted[i]);
}

double fractionAbove(const std::vector<double>& values, double threshold)
{
    return static_cast<double>(
               std::count_if(values.begin(), values.end(), [&](double v) { return v > threshold; }))
           / values.size();
}

double mean(const std::vector<double>& values)
{
    double m = 0;
    for (double v : values) m += v;
    return m / values.size();
}

std::string blockHours(int b)
{
    return std::to_string(6 * b) + "-" + std::to_string(6 * b + 6);
}

void writeFits(const std::string& path, const Climate& climate)
{
    CsvWriter f(path, {"variable", "month", "hours", "shape", "scale", "mean", "n", "method"});
    for (int v = 0; v < kMetVariables; ++v)
        for (int m = 0; m < 12; ++m)
            for (int b = 0; b < 4; ++b)
            {
                const GammaFit& g = climate.fit[v][m][b];
                f.row(std::vector<std::string>{metVariableName(v), std::to_string(m + 1), blockHours(b),
                                               formatNumber(g.shape), formatNumber(g.scale),
                                               formatNumber(g.shape * g.scale), std::to_string(g.n),
                                               g.moments ? "moments" : "max-likelihood"});
            }
    f.close();
}

// Wind-direction sectors of the history against the synthetic years, and
// the synthetic speed classes: the synthesis should keep both.
void reportWind(const std::string& path, const MonteCarloCase& c, const Realisations& rs)
{
    Sectors hist{}, syn{};
    for (const auto& h : c.history.hours) hist[sectorOf(h)]++;
    for (const auto& s : rs.sectors)
        for (int k = 0; k < 8; ++k) syn[k] += s[k];
    const double synHours = static_cast<double>(hoursPerYear) * c.years;
    CsvWriter f(path, {"sector_from_deg", "to_deg", "history_fraction", "synthetic_fraction"});
    fmt::print("  wind from (deg)    history  synthetic\n");
    for (int k = 0; k < 8; ++k)
    {
        const double fh = static_cast<double>(hist[k]) / c.history.hours.size();
        const double fsyn = static_cast<double>(syn[k]) / synHours;
        f.row(std::vector<double>{45.0 * k, 45.0 * (k + 1), fh, fsyn});
        fmt::print("    {:>3}-{:<3}{:>12.3f}{:>11.3f}\n", 45 * k, 45 * (k + 1), fh, fsyn);
    }
    f.close();
    Speeds sp{};
    for (const auto& s : rs.speeds)
        for (int k = 0; k < 4; ++k) sp[k] += s[k];
    fmt::print("  synthetic wind speed: 0-2 m/s {:.3f}, 2-4 {:.3f}, 4-6 {:.3f}, >6 {:.3f}\n",
               sp[0] / synHours, sp[1] / synHours, sp[2] / synHours, sp[3] / synHours);
}

std::vector<std::string> summaryHeader(const std::vector<double>& thresholds)
{
    std::vector<std::string> h = {"receptor",         "mean [ug/m3]",     "p5 24-h [ug/m3]",
                                  "p50 24-h [ug/m3]", "p95 24-h [ug/m3]", "max 24-h [ug/m3]"};
    for (double th : thresholds)
    {
        h.push_back("P(24-h > " + formatNumber(th) + ")");
        h.push_back("P(year with a 24-h > " + formatNumber(th) + ")");
    }
    return h;
}

void printSummaryHeader(const std::vector<double>& thresholds)
{
    fmt::print("\n  receptor      mean     p5    p50    p95    max [ug/m3]");
    for (double th : thresholds) fmt::print("  P(24h>{})", formatNumber(th));
    fmt::print("\n");
}

// One receptor over all years: its summary.csv row, and its line on stdout.
std::vector<std::string> receptorSummary(std::size_t k, const MonteCarloCase& c, const Realisations& rs)
{
    std::vector<double> all; // every simulated day
    all.reserve(static_cast<std::size_t>(c.years) * daysPerYear);
    std::vector<long> yearsOver(c.thresholds.size(), 0);
    for (long r = 0; r < c.years; ++r)
    {
        const auto& days = rs.daily[r][k];
        all.insert(all.end(), days.begin(), days.end());
        const double highest = *std::max_element(days.begin(), days.end());
        for (std::size_t q = 0; q < c.thresholds.size(); ++q) yearsOver[q] += highest > c.thresholds[q];
    }
    std::vector<double> sorted = all;
    std::sort(sorted.begin(), sorted.end());
    const double m = mean(all), p5 = percentile(sorted, 5), p50 = percentile(sorted, 50),
                 p95 = percentile(sorted, 95), top = sorted.back();
    const std::string& name = c.setup.receptors[k].name;
    std::vector<std::string> row = {name,
                                    formatFixed(m, 3),
                                    formatFixed(p5, 3),
                                    formatFixed(p50, 3),
                                    formatFixed(p95, 3),
                                    formatFixed(top, 3)};
    fmt::print("  {:<9}{:>9}{:>7}{:>7}{:>7}{:>7}      ", name, formatFixed(m, 1), formatFixed(p5, 1),
               formatFixed(p50, 1), formatFixed(p95, 1), formatFixed(top, 0));
    for (std::size_t q = 0; q < c.thresholds.size(); ++q)
    {
        const double p = fractionAbove(all, c.thresholds[q]);
        row.push_back(formatFixed(p, 5));
        row.push_back(formatFixed(static_cast<double>(yearsOver[q]) / c.years, 3));
        fmt::print("{:>12}", formatFixed(p, 4));
    }
    fmt::print("\n");
    return row;
}

// The annual trend (the study's Figs 2-3): statistics over the years for each day.
void writeTrend(const std::string& outDir, std::size_t k, const MonteCarloCase& c, const Realisations& rs)
{
    std::vector<std::string> header = {"day", "mean [ug/m3]", "p5 [ug/m3]", "p50 [ug/m3]", "p95 [ug/m3]"};
    std::string thresholds;
    for (double th : c.thresholds)
    {
        header.push_back("P(> " + formatNumber(th) + ")");
        thresholds += (thresholds.empty() ? "" : " ") + formatNumber(th);
    }
    const std::string& name = c.setup.receptors[k].name;
    const std::string csv = (fs::path(outDir) / ("daily_" + name + ".csv")).string();
    CsvWriter d(csv, header);
    for (int day = 0; day < daysPerYear; ++day)
    {
        std::vector<double> v(c.years);
        for (long r = 0; r < c.years; ++r) v[r] = rs.daily[r][k][day];
        const double m = mean(v);
        std::sort(v.begin(), v.end());
        std::vector<double> row = {static_cast<double>(day + 1), m, percentile(v, 5), percentile(v, 50),
                                   percentile(v, 95)};
        for (double th : c.thresholds) row.push_back(fractionAbove(v, th));
        d.row(row);
    }
    d.close();
    const std::string title = "Receptor " + name + ": " + std::to_string(c.years)
                              + " synthetic years (w = " + formatNumber(c.w) + ")";
    plotPng((fs::path(outDir) / ("trend_" + name + ".png")).string(), texts::plots::trend,
            PlotVariables()
                .set("csv", csv)
                .set("title_text", title)
                .set("thresholds", thresholds)
                .set("nthresholds", static_cast<double>(c.thresholds.size())),
            1000, 560);
}

void report(const MonteCarloArgs& a, const MonteCarloCase& c, const Realisations& rs)
{
    const fs::path out(a.outDir);
    writeFits((out / "fits.csv").string(), c.climate);
    writeMet((out / "synthetic_met_year1.csv").string(), rs.firstYear, true);
    reportWind((out / "wind_sectors.csv").string(), c, rs);
    CsvWriter summary((out / "summary.csv").string(), summaryHeader(c.thresholds));
    printSummaryHeader(c.thresholds);
    for (std::size_t k = 0; k < c.setup.receptors.size(); ++k)
    {
        summary.row(receptorSummary(k, c, rs));
        writeTrend(a.outDir, k, c, rs);
    }
    summary.close();
    fmt::print(
        "\n  P(24h>X): fraction of all simulated days; P(year ...) in summary.csv\n  wall time {:.1f} s for "
        "{} years; outputs in {}/\n",
        rs.wallSeconds, c.years, a.outDir);
}

} // namespace

int monteCarloCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const MonteCarloCase c = load(*args);
    const GaussianModel model(c.setup.sources, c.setup.options);
    fmt::print(
        "procsim plume montecarlo: {}\n  history {} h, {} synthetic years, w = {}, seed {}, {} threads, "
        "reduction {} %\n",
        args->casePath, c.history.hours.size(), c.years, formatNumber(c.w), c.seed, c.threads,
        formatNumber(c.setup.options.reduction * 100));
    createOutputDirectory(args->outDir);
    report(*args, c, run(c, model));
    return 0;
}

} // namespace procsim::plume
