// procsim plume eulerian: the scenarios of a case over terrain, one thread
// each; per scenario the receptors' 1-h, 24-h and weekly averages, the
// ground-level mean as a map and the concentration field as a .pvd series;
// the paper's Table 1 over all of them.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
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
#include "plume/Commands.hpp"
#include "plume/EulerianCase.hpp"
#include "plume/Texts.hpp"
#include "plume/Vtk.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

namespace
{

constexpr long maxStepsPerHour = 10000000;
constexpr double maxCellUpdates = 1e12; // ~6 h at ~5e7 cell updates per second

// ---- parse -------------------------------------------------------------------

struct EulerianArgs
{
    std::string casePath;
    std::string outDir = "results";
    std::optional<long> hours; // none: all the meteorology
    unsigned threads = 1;
};

std::optional<EulerianArgs> parse(int argc, char** argv)
{
    EulerianArgs a;
    std::optional<long> threads;
    CommandLine cl("plume eulerian", std::string(texts::help::eulerian));
    cl.input(a.casePath, "case file");
    cl.text("-o", a.outDir);
    cl.integer("--hours", a.hours);
    cl.integer("--threads", threads);
    if (!cl.parse(argc, argv)) return std::nullopt;
    a.threads = threads ? static_cast<unsigned>(*threads) : std::max(1u, std::thread::hardware_concurrency());
    return a;
}

// ---- plan: what the run needs, refused before any work -----------------------

int runHours(const EulerianCase& cs, const EulerianArgs& a)
{
    const int metHours = static_cast<int>(cs.met.hours.size());
    if (a.hours && *a.hours > metHours)
        throw InputError("plume eulerian: option --hours " + std::to_string(*a.hours)
                         + " asks for more than the " + std::to_string(metHours) + " hours of meteorology of "
                         + cs.file);
    return a.hours ? static_cast<int>(*a.hours) : metHours;
}

// The smallest stable step over all hours and scenarios, and where it occurs.
struct StabilityLimit
{
    double dt = 1e300; // s
    int hour = 0;
    std::string scenario;
    double topFlux = 0; // largest flux left through the lid by the wind adjustment [m3/s]
};

StabilityLimit stabilityLimit(const EulerianCase& cs, const TerrainGrid& g, const WindModel& wind, int hours)
{
    StabilityLimit s;
    for (const auto& sc : cs.scenarios)
    {
        Transport t(g, sc.kH, sc.kV, cs.advection, cs.trueHorizontal);
        t.setImplicitVertical(cs.implicitVertical);
        for (int h = 0; h < hours; ++h)
        {
            const Flow f = wind.flow(cs.met.hours[h].speed, cs.met.hours[h].directionFrom);
            s.topFlux = std::max(s.topFlux, f.maxTopFlux);
            t.setFlow(f);
            const double l = t.stableDt();
            if (l < s.dt) s = {l, cs.met.firstHour + h, sc.name, s.topFlux};
        }
    }
    return s;
}

// An explicit dt must be stable in every hour.
void checkTimeStep(const EulerianCase& cs, const StabilityLimit& s)
{
    if (cs.dt <= s.dt) return;
    throw InputError(cs.file + ": key 'time.dt_s' = " + formatNumber(cs.dt)
                     + " s exceeds the stability limit " + formatNumber(s.dt, 3) + " s (scenario '"
                     + s.scenario + "', hour " + std::to_string(s.hour)
                     + "; Adams-Bashforth needs dt <= 1/(4 sum K/dx^2 + sum|F|/V)"
                     + (cs.implicitVertical ? ", vertical diffusion implicit)" : ")"));
}

long stepsPerHour(const EulerianCase& cs, double dt)
{
    return stepCount(3600.0, dt, maxStepsPerHour, cs.file + ": key 'time.dt_s'",
                     "an hour in steps of " + formatNumber(dt, 3) + " s", "use a larger dt_s or 'auto'");
}

// Refuse a run that would not finish in reasonable time.
void checkWork(const EulerianCase& cs, const TerrainGrid& g, const StabilityLimit& s, int hours)
{
    const long perHour = stepsPerHour(cs, cs.dt > 0 ? cs.dt : cs.cflFraction * s.dt);
    const double updates = static_cast<double>(g.nx) * g.ny * g.nz * perHour * hours * cs.scenarios.size();
    if (updates <= maxCellUpdates) return;
    throw InputError(cs.file + ": the run needs about " + formatFixed(updates, 2) + " cell updates (grid "
                     + std::to_string(g.nx) + " x " + std::to_string(g.ny) + " x " + std::to_string(g.nz)
                     + ", " + std::to_string(perHour) + " steps per hour, " + std::to_string(hours) + " h, "
                     + std::to_string(cs.scenarios.size()) + " scenarios; limit "
                     + formatFixed(maxCellUpdates, 2)
                     + "); use a coarser grid.cell_size_m, fewer --hours or a larger dt_s");
}

// ---- run: one scenario -------------------------------------------------------

// What a scenario run shares with the others: the case, grid, wind, length.
struct RunContext
{
    const EulerianCase& cs;
    const TerrainGrid& g;
    const WindModel& wind;
    std::string outDir;
    int hours;
    std::mutex& printLock;
};

// q: the emission per cell [kg/s]
Transport startTransport(const RunContext& rc, const Scenario& sc, const std::vector<double>& q)
{
    Transport t(rc.g, sc.kH, sc.kV, rc.cs.advection, rc.cs.trueHorizontal);
    t.setImplicitVertical(rc.cs.implicitVertical);
    t.setBackground(rc.cs.backgroundUgM3 * 1e-9);
    for (auto& v : t.c) v = rc.cs.backgroundUgM3 * 1e-9; // the run starts from the background
    t.setSources(q);
    return t;
}

// Time integral of the lowest cell layer, for the run-mean ground map.
struct GroundIntegral
{
    std::vector<double> sum; // per column [kg s/m3]
    double time = 0;         // s
};

// One hour of meteorology in whole steps of at most the stable dt: the
// receptors' 1-h average [ug/m3] into res.hourly[.][h].
void runHour(const RunContext& rc, Transport& t, int h, ScenarioResult& res, GroundIntegral& ground)
{
    const MetHour& m = rc.cs.met.hours[h];
    t.setFlow(rc.wind.flow(m.speed, m.directionFrom));
    const long n = stepsPerHour(rc.cs, rc.cs.dt > 0 ? rc.cs.dt : rc.cs.cflFraction * t.stableDt());
    const double dt = 3600.0 / n;
    res.dtMin = std::min(res.dtMin, dt);
    res.dtMax = std::max(res.dtMax, dt);
    const auto& receptors = rc.cs.receptors;
    for (long s = 0; s < n; ++s)
    {
        t.step(dt);
        for (std::size_t r = 0; r < receptors.size(); ++r)
            res.hourly[r][h] += t.sample(receptors[r].x, receptors[r].y, receptors[r].height);
        for (std::size_t col = 0; col < ground.sum.size(); ++col) ground.sum[col] += t.c[col] * dt;
        ground.time += dt;
    }
    res.steps += n;
    for (std::size_t r = 0; r < receptors.size(); ++r) res.hourly[r][h] *= 1e9 / n; // kg/m3 -> ug/m3
}

// The field after hour h as dir/vts/C_<h>h.vts, listed in the .pvd entries.
void writeFrame(const std::string& dir, const TerrainGrid& g, const Transport& t, int h,
                std::vector<std::pair<double, std::string>>& pvd)
{
    std::vector<double> ug(t.c.size());
    for (std::size_t k = 0; k < ug.size(); ++k) ug[k] = t.c[k] * 1e9;
    const std::string name = "vts/C_" + std::to_string(h + 1) + "h.vts";
    writeVts((fs::path(dir) / name).string(), g, "PM10_ug_m3", ug);
    pvd.emplace_back((h + 1) * 3600.0, name);
}

void printProgress(const RunContext& rc, const Scenario& sc, int h, const ScenarioResult& res,
                   std::chrono::steady_clock::time_point start)
{
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::lock_guard<std::mutex> lock(rc.printLock);
    fmt::print("  [{}] hour {}/{}, {} steps, {:.1f} s\n", sc.name, h + 1, rc.hours, res.steps, wall);
    std::fflush(stdout);
}

ScenarioResult runScenario(const RunContext& rc, const Scenario& sc)
{
    const std::string dir = (fs::path(rc.outDir) / sc.name).string();
    createOutputDirectory((fs::path(dir) / "vts").string());
    const std::vector<double> q = distributeSources(rc.g, rc.cs.sources, sc.reduction);
    Transport t = startTransport(rc, sc, q);
    const double m0 = t.mass();
    ScenarioResult res;
    res.hourly.assign(rc.cs.receptors.size(), std::vector<double>(rc.hours, 0.0));
    res.dtMin = 1e300;
    GroundIntegral ground{std::vector<double>(static_cast<std::size_t>(rc.g.nx) * rc.g.ny, 0.0)};
    std::vector<std::pair<double, std::string>> pvd;
    const auto start = std::chrono::steady_clock::now();
    for (int h = 0; h < rc.hours; ++h)
    {
        runHour(rc, t, h, res, ground);
        if (rc.cs.vtsEveryHours > 0 && (h + 1) % rc.cs.vtsEveryHours == 0) writeFrame(dir, rc.g, t, h, pvd);
        if ((h + 1) % 24 == 0 || h + 1 == rc.hours) printProgress(rc, sc, h, res, start);
    }
    if (!pvd.empty()) writePvd((fs::path(dir) / "C.pvd").string(), pvd);
    res.groundMean.resize(ground.sum.size());
    for (std::size_t col = 0; col < ground.sum.size(); ++col)
        res.groundMean[col] = ground.sum[col] / ground.time * 1e9;
    double qTotal = 0; // kg/s
    for (double v : q) qTotal += v;
    res.emitted = qTotal * t.time();
    res.inDomain = t.mass() - m0;
    res.leftDomain = t.boundaryOutflow();
    return res;
}

// Every scenario, each on one of `threads` threads; the first failure is rethrown.
std::vector<ScenarioResult> runScenarios(const RunContext& rc, unsigned threads)
{
    const auto& scenarios = rc.cs.scenarios;
    std::vector<ScenarioResult> results(scenarios.size());
    std::vector<std::exception_ptr> errors(scenarios.size());
    std::size_t next = 0;
    std::mutex nextLock;
    auto worker = [&]() {
        while (true)
        {
            std::size_t k;
            {
                std::lock_guard<std::mutex> l(nextLock);
                if (next >= scenarios.size()) return;
                k = next++;
            }
            try
            {
                results[k] = runScenario(rc, scenarios[k]);
            }
            catch (...)
            {
                errors[k] = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < std::min<unsigned>(threads, static_cast<unsigned>(scenarios.size())); ++i)
        pool.emplace_back(worker);
    for (auto& th : pool) th.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
    return results;
}

// ---- report: one scenario ----------------------------------------------------

std::vector<std::string> receptorColumns(const std::string& first, const std::vector<Receptor>& receptors)
{
    std::vector<std::string> header = {first};
    for (const auto& r : receptors) header.push_back(r.name + " [ug/m3]");
    return header;
}

double blockMean(const std::vector<double>& hourly, int first, int len)
{
    double s = 0;
    for (int h = first; h < first + len; ++h) s += hourly[h];
    return s / len;
}

void writeHourly(const std::string& dir, const EulerianCase& cs, const ScenarioResult& res, int hours)
{
    CsvWriter w(dir + "/receptors_hourly.csv", receptorColumns("hour", cs.receptors));
    for (int h = 0; h < hours; ++h)
    {
        std::vector<double> row = {static_cast<double>(cs.met.firstHour + h + 1)};
        for (const auto& r : res.hourly) row.push_back(r[h]);
        w.row(row);
    }
    w.close();
}

// Averages over whole blocks of `len` hours (days, weeks), one row per block.
void writeBlocks(const std::string& path, const std::string& first, int len, const EulerianCase& cs,
                 const ScenarioResult& res, int hours)
{
    CsvWriter w(path, receptorColumns(first, cs.receptors));
    for (int b = 0; (b + 1) * len <= hours; ++b)
    {
        std::vector<double> row = {static_cast<double>(b + 1)};
        for (const auto& r : res.hourly) row.push_back(blockMean(r, b * len, len));
        w.row(row);
    }
    w.close();
}

void writeGroundMean(const std::string& dir, const TerrainGrid& g, const ScenarioResult& res)
{
    CsvWriter w(dir + "/ground_mean.csv", {"x_m", "y_m", "terrain_m", "PM10_ug_m3"});
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
            w.row(std::vector<double>{g.xc(i), g.yc(j), g.hc[g.col(i, j)], res.groundMean[g.col(i, j)]});
    w.close();
}

// The map's inputs as gnuplot grids (a blank line after each row of cells).
void writeMapData(const std::string& dir, const EulerianCase& cs, const TerrainGrid& g,
                  const ScenarioResult& res)
{
    OutputFile ground(dir + "/map_ground.dat"), sources(dir + "/map_sources.dat"),
        receptors(dir + "/map_receptors.dat");
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
            ground.out() << fmt::format("{} {} {} {}\n", formatNumber(g.xc(i)), formatNumber(g.yc(j)),
                                        formatNumber(g.hc[g.col(i, j)]),
                                        formatNumber(res.groundMean[g.col(i, j)]));
        ground.out() << '\n';
    }
    for (const auto& s : cs.sources) // half sizes, at least an eighth of a cell to stay visible
        sources.out() << fmt::format("{} {} {} {} {}\n", formatNumber(s.x), formatNumber(s.y),
                                     formatNumber(std::max(0.5 * s.lx, 0.5 * g.dx / 4)),
                                     formatNumber(std::max(0.5 * s.ly, 0.5 * g.dy / 4)), s.name);
    for (const auto& r : cs.receptors)
        receptors.out() << fmt::format("{} {} {}\n", formatNumber(r.x), formatNumber(r.y), r.name);
    ground.close();
    sources.close();
    receptors.close();
}

void plotMap(const std::string& dir, const Scenario& sc, const TerrainGrid& g, int hours)
{
    plotPng(dir + "/ground_mean.png", texts::plots::ground_map,
            PlotVariables()
                .set("ground", dir + "/map_ground.dat")
                .set("contours", dir + "/map_contours.dat")
                .set("sources", dir + "/map_sources.dat")
                .set("receptors", dir + "/map_receptors.dat")
                .set("title_text", "Scenario " + sc.name + ": ground-level PM10, mean over "
                                       + std::to_string(hours) + " h [ug/m3]; dashed: terrain contours")
                .set("x0", g.x0)
                .set("x1", g.x0 + g.nx * g.dx)
                .set("y0", g.y0)
                .set("y1", g.y0 + g.ny * g.dy),
            900, 800);
}

void plot24h(const std::string& dir, const EulerianCase& cs, const Scenario& sc)
{
    plotPng(dir + "/receptors_24h.png", texts::plots::receptors_24h,
            PlotVariables()
                .set("csv", dir + "/receptors_24h.csv")
                .set("nreceptors", static_cast<double>(cs.receptors.size()))
                .set("title_text", "Scenario " + sc.name + ": 24-h averages at the receptors")
                .set("standard", cs.standardUgM3));
}

// Measured against predicted 24-h averages at receptor r (the paper's Fig 2).
void reportMeasured(const std::string& dir, const EulerianCase& cs, const Scenario& sc,
                    const ScenarioResult& res, std::size_t r, int hours)
{
    const std::string name = cs.receptors[r].name;
    const std::string file = dir + "/measured_" + name + ".csv";
    CsvWriter w(file, {"day", "measured [ug/m3]", "predicted [ug/m3]"});
    double sm = 0, sp = 0;
    int n = 0;
    for (const auto& [day, value] : cs.measured24h[r])
    {
        if (day < 1 || day * 24 > hours) continue; // outside the run
        double predicted = 0;
        for (int h = (day - 1) * 24; h < day * 24; ++h) predicted += res.hourly[r][h] / 24;
        w.row(std::vector<double>{static_cast<double>(day), value, predicted});
        sm += value;
        sp += predicted;
        ++n;
    }
    w.close();
    if (n == 0) return;
    fmt::print("  [{}] {}: {} measured days, mean measured {}, predicted {} ug/m3 (ratio {})\n", sc.name,
               name, n, formatFixed(sm / n, 2), formatFixed(sp / n, 2), formatFixed(sp / sm, 3));
    plotPng(dir + "/measured_" + name + ".png", texts::plots::measured,
            PlotVariables()
                .set("csv", file)
                .set("title_text", "Scenario " + sc.name + ", receptor " + name + ": predicted and measured")
                .set("standard", cs.standardUgM3));
}

void reportScenario(const EulerianCase& cs, const TerrainGrid& g, const Scenario& sc,
                    const ScenarioResult& res, const std::string& outDir, int hours)
{
    const std::string dir = (fs::path(outDir) / sc.name).string();
    writeHourly(dir, cs, res, hours);
    writeBlocks(dir + "/receptors_24h.csv", "day", 24, cs, res, hours);
    writeBlocks(dir + "/receptors_weekly.csv", "week", 168, cs, res, hours);
    writeGroundMean(dir, g, res);
    writeMapData(dir, cs, g, res);
    plotMap(dir, sc, g, hours);
    if (hours >= 24) plot24h(dir, cs, sc);
    for (std::size_t r = 0; r < cs.receptors.size(); ++r)
        if (!cs.measured24h[r].empty() && hours >= 24) reportMeasured(dir, cs, sc, res, r, hours);
}

// ---- report: all scenarios ---------------------------------------------------

// Table 1 of the paper: run mean and highest 24-h average per receptor and
// scenario, as table.csv and on stdout (* above the 24-h standard).
void reportTable(const EulerianCase& cs, const std::vector<ScenarioResult>& results,
                 const std::string& outDir, int hours)
{
    std::vector<std::string> header = {"receptor", "name"};
    for (const auto& sc : cs.scenarios)
        header.insert(header.end(), {sc.name + " mean [ug/m3]", sc.name + " max 24-h [ug/m3]"});
    CsvWriter table((fs::path(outDir) / "table.csv").string(), header);
    fmt::print("\n  {:<14}", "receptor");
    for (const auto& sc : cs.scenarios) fmt::print("{:>34}", sc.name + " mean / max 24-h");
    fmt::print("   [ug/m3]\n");
    for (std::size_t r = 0; r < cs.receptors.size(); ++r)
    {
        std::vector<std::string> row = {std::to_string(r + 1), cs.receptors[r].name};
        fmt::print("  {:<14}", cs.receptors[r].name);
        for (const auto& res : results)
        {
            const auto& hs = res.hourly[r];
            double mean = 0;
            for (double v : hs) mean += v;
            mean /= hours;
            double max24 = 0;
            for (int b = 0; (b + 1) * 24 <= hours; ++b) max24 = std::max(max24, blockMean(hs, b * 24, 24));
            row.push_back(formatFixed(mean, 4));
            row.push_back(hours >= 24 ? formatFixed(max24, 4) : "");
            fmt::print("{:>34}{}", formatFixed(mean, 2) + " / " + (hours >= 24 ? formatFixed(max24, 2) : "-"),
                       max24 > cs.standardUgM3 ? "*" : " ");
        }
        fmt::print("\n");
        table.row(row);
    }
    table.close();
    fmt::print("  (* = a 24-h average above the standard {} ug/m3)\n\n", formatNumber(cs.standardUgM3));
}

// Per scenario its settings, steps and mass balance.
void printBalances(const EulerianCase& cs, const std::vector<ScenarioResult>& results)
{
    for (std::size_t k = 0; k < cs.scenarios.size(); ++k)
    {
        const Scenario& sc = cs.scenarios[k];
        const ScenarioResult& r = results[k];
        const double imbalance = (r.emitted - r.inDomain - r.leftDomain) / std::max(r.emitted, 1e-300);
        fmt::print(
            "  [{}] K_H {}, K_V {} m2/s, reduction {} %: {} steps (dt {}..{} s); emitted {} kg, in domain {} "
            "kg, left {} kg, relative imbalance {}\n",
            sc.name, formatNumber(sc.kH), formatNumber(sc.kV), formatNumber(sc.reduction * 100), r.steps,
            formatFixed(r.dtMin, 2), formatFixed(r.dtMax, 2), formatFixed(r.emitted, 1),
            formatFixed(r.inDomain, 1), formatFixed(r.leftDomain, 1), formatScientific(imbalance, 2));
    }
}

} // namespace

int eulerianCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const EulerianCase cs = loadEulerianCase(args->casePath);
    const auto grid = cs.makeGrid();
    const TerrainGrid& g = *grid;
    checkReceptors(g, cs.receptors);
    for (const auto& sc : cs.scenarios) distributeSources(g, cs.sources, sc.reduction); // validates
    const int hours = runHours(cs, *args);
    const WindModel wind(g, cs.exponent, cs.zRef);
    const StabilityLimit limit = stabilityLimit(cs, g, wind, hours);
    checkTimeStep(cs, limit);
    checkWork(cs, g, limit, hours);

    fmt::print("procsim plume eulerian: {}\n  grid {} x {} x {} cells ({} m, lid at {} m a.s.l.), {} h of "
               "meteorology, {} scenario(s), stability limit {} s\n",
               args->casePath, g.nx, g.ny, g.nz, formatNumber(g.dx), formatNumber(g.zTop), hours,
               cs.scenarios.size(), formatFixed(limit.dt, 2));
    createOutputDirectory(args->outDir);
    std::mutex printLock;
    const auto t0 = std::chrono::steady_clock::now();
    const auto results = runScenarios({cs, g, wind, args->outDir, hours, printLock}, args->threads);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (std::size_t k = 0; k < cs.scenarios.size(); ++k)
        reportScenario(cs, g, cs.scenarios[k], results[k], args->outDir, hours);
    reportTable(cs, results, args->outDir, hours);
    printBalances(cs, results);
    fmt::print(
        "  wind: largest flux through the lid after adjustment {} m3/s\n  wall time {:.1f} s; outputs in {}/ "
        "(table.csv; per scenario receptors_*.csv, ground_mean.png, C.pvd)\n",
        formatNumber(limit.topFlux, 3), wall, args->outDir);
    return 0;
}

} // namespace procsim::plume
