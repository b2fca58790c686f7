#include "plume/EulerianCase.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "common/YamlInput.hpp"
#include "plume/Texts.hpp"
#include "plume/Vtk.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

namespace
{

constexpr long maxStepsPerHour = 10000000;
constexpr double maxCellUpdates = 1e12;   // ~6 h at ~5e7 cell updates per second
constexpr double bytesPerCell = 400;      // fields, fluxes and the implicit vertical solve

} // namespace

std::unique_ptr<TerrainGrid> EulerianCase::makeGrid() const
{
    const double w = terrain.ncols * terrain.cell, h = terrain.nrows * terrain.cell;
    checkMemory(std::floor(w / cellSize + 1e-9) * std::floor(h / cellSize + 1e-9) * levels, bytesPerCell, file,
                "a grid of " + formatNumber(cellSize, 3) + " m cells with " + std::to_string(levels) + " levels");
    const int nx = std::max(2, static_cast<int>(std::floor(w / cellSize + 1e-9)));
    const int ny = std::max(2, static_cast<int>(std::floor(h / cellSize + 1e-9)));
    const double highest = *std::max_element(terrain.z.begin(), terrain.z.end());
    const EsriGrid& t = terrain;
    return std::make_unique<TerrainGrid>(nx, ny, levels, t.xll, t.yll, cellSize, cellSize,
                                         highest + topAboveHighest, stretching,
                                         [&t](double x, double y) { return t.sample(x, y); });
}

EulerianCase loadEulerianCase(const std::string& path)
{
    const YamlInput in = YamlInput::load(path);
    in.rejectUnknown({"terrain", "grid", "dispersion", "wind", "time", "meteorology", "sources",
                      "receptors", "scenarios", "output"});
    EulerianCase c;
    c.file = path;
    c.dir = fs::path(path).parent_path().string();
    c.terrain = readEsriGrid(relativeTo(c.dir, in.text("terrain")));
    c.cellSize = c.terrain.cell;
    if (in.has("grid"))
    {
        const YamlInput g = in.child("grid");
        g.rejectUnknown({"cell_size_m", "levels", "top_above_highest_m", "stretching"});
        c.cellSize = g.has("cell_size_m") ? g.positive("cell_size_m", "m") : c.cellSize;
        if (g.has("levels"))
        {
            c.levels = static_cast<int>(g.integer("levels", 1, 1000));
        }
        if (g.has("top_above_highest_m")) c.topAboveHighest = g.positive("top_above_highest_m", "m");
        c.stretching = g.number("stretching", c.stretching);
    }
    if (c.cellSize * 2 > std::min(c.terrain.ncols, c.terrain.nrows) * c.terrain.cell)
        throw InputError(path + ": key 'grid.cell_size_m' expected at most half the terrain extent");
    double kH = 200, kV = 1;
    if (in.has("dispersion"))
    {
        const YamlInput d = in.child("dispersion");
        d.rejectUnknown({"K_H_m2_s", "K_V_m2_s", "advection", "vertical_diffusion", "horizontal_diffusion"});
        const std::string hd = d.text("horizontal_diffusion", "along_terrain");
        if (hd == "along_terrain") c.trueHorizontal = false;
        else if (hd == "true_horizontal") c.trueHorizontal = true;
        else throw d.error("horizontal_diffusion", "along_terrain or true_horizontal");
        const std::string v = d.text("vertical_diffusion", "implicit");
        if (v == "implicit") c.implicitVertical = true;
        else if (v == "explicit") c.implicitVertical = false;
        else throw d.error("vertical_diffusion", "implicit (Crank-Nicolson) or explicit (AB2)");
        if (c.trueHorizontal && c.implicitVertical)
            throw d.error("horizontal_diffusion",
                          "along_terrain when vertical_diffusion is implicit (true_horizontal needs "
                          "vertical_diffusion: explicit: its metric cross terms are explicit)");
        if (d.has("K_H_m2_s")) kH = d.nonNegative("K_H_m2_s", "m2/s");
        if (d.has("K_V_m2_s")) kV = d.nonNegative("K_V_m2_s", "m2/s");
        const std::string a = d.text("advection", "limited_quick");
        if (a == "limited_quick") c.advection = Advection::LimitedQuick;
        else if (a == "quick") c.advection = Advection::Quick;
        else if (a == "upwind") c.advection = Advection::Upwind;
        else throw d.error("advection", "one of limited_quick, quick, upwind");
    }
    if (in.has("wind"))
    {
        const YamlInput w = in.child("wind");
        w.rejectUnknown({"exponent", "reference_height_m"});
        c.exponent = w.number("exponent", c.exponent);
        if (c.exponent < 0 || c.exponent > 1) throw w.error("exponent", "a number in 0..1");
        if (w.has("reference_height_m")) c.zRef = w.positive("reference_height_m", "m");
    }
    if (in.has("time"))
    {
        const YamlInput t = in.child("time");
        t.rejectUnknown({"dt_s", "cfl_fraction"});
        if (t.has("dt_s") && t.text("dt_s") != "auto") c.dt = t.positive("dt_s", "s");
        if (t.has("cfl_fraction"))
        {
            c.cflFraction = t.positive("cfl_fraction");
            if (c.cflFraction > 1) throw t.error("cfl_fraction", "a number in (0, 1]");
        }
    }
    if (in.has("output"))
    {
        const YamlInput o = in.child("output");
        o.rejectUnknown({"vts_every_h", "background_ug_m3", "standard_24h_ug_m3", "measured_24h"});
        if (o.has("vts_every_h"))
        {
            c.vtsEveryHours = static_cast<int>(o.integer("vts_every_h", 0, 1000000));   // 0 = none
        }
        c.backgroundUgM3 = o.has("background_ug_m3") ? o.nonNegative("background_ug_m3", "ug/m3") : 0.0;
        if (o.has("standard_24h_ug_m3")) c.standardUgM3 = o.positive("standard_24h_ug_m3", "ug/m3");
    }
    c.met = readMet(relativeTo(c.dir, in.text("meteorology")), false);
    c.sources = parseSources(in.child("sources"));
    c.receptors = parseReceptors(in.child("receptors"));
    c.measured24h.assign(c.receptors.size(), {});
    if (in.has("output") && in.child("output").has("measured_24h"))
    {
        const std::string mpath = relativeTo(c.dir, in.child("output").text("measured_24h"));
        const CsvTable t = readCsv(mpath);
        const std::size_t cd = t.column("day", mpath);
        for (std::size_t col = 0; col < t.header.size(); ++col)
        {
            if (col == cd) continue;
            std::size_t r = 0;
            while (r < c.receptors.size() && t.header[col] != c.receptors[r].name + " [ug/m3]") ++r;
            if (r == c.receptors.size())
                throw InputError(mpath + ": column '" + t.header[col]
                                 + "' names no receptor (expected '<receptor> [ug/m3]')");
            for (const auto& row : t.rows)
                if (row[col] >= 0) c.measured24h[r].emplace_back(static_cast<int>(std::lround(row[cd])), row[col]);
        }
    }
    if (in.has("scenarios"))
    {
        for (const auto& s : in.child("scenarios").items())
        {
            s.rejectUnknown({"name", "K_H_m2_s", "K_V_m2_s", "reduction"});
            Scenario sc;
            sc.name = s.text("name");
            if (sc.name.empty()) throw s.error("name", "a non-empty name (it names a directory)");
            for (char ch : sc.name)
                if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-'))
                    throw s.error("name", "letters, digits, '_' or '-' (it names a directory)");
            sc.kH = s.has("K_H_m2_s") ? s.nonNegative("K_H_m2_s", "m2/s") : kH;
            sc.kV = s.has("K_V_m2_s") ? s.nonNegative("K_V_m2_s", "m2/s") : kV;
            sc.reduction = s.number("reduction", 0.0);
            if (sc.reduction < 0 || sc.reduction > 1) throw s.error("reduction", "a fraction 0..1");
            c.scenarios.push_back(sc);
        }
    }
    if (c.scenarios.empty()) c.scenarios.push_back({"base", kH, kV, 0.0});
    rejectDuplicates(c.scenarios, &Scenario::name, path + ": key 'scenarios'", "scenario name");
    return c;
}

namespace
{

using Weights = std::vector<std::pair<int, double>>;

// Linear weights of a coordinate f (in cell units, cell n centred at n) over
// the cell centres either side; beyond the outermost centres all of it goes
// to the edge cell, so the weights always add up to one.
Weights linearWeights(double f, int n)
{
    if (n < 2 || f <= 0) return {{0, 1.0}};
    if (f >= n - 1) return {{n - 1, 1.0}};
    const int i = static_cast<int>(f);
    return {{i, 1 - (f - i)}, {i + 1, f - i}};
}

// Columns around a point (x, y) with bilinear weights.
std::vector<std::pair<std::size_t, double>> pointColumns(const TerrainGrid& g, double x, double y)
{
    std::vector<std::pair<std::size_t, double>> cols;
    for (const auto& [i, wx] : linearWeights((x - g.x0) / g.dx - 0.5, g.nx))
        for (const auto& [j, wy] : linearWeights((y - g.y0) / g.dy - 0.5, g.ny))
            cols.emplace_back(g.col(i, j), wx * wy);
    return cols;
}

// Layers of column (i, j) around a height above ground: linear between the
// cell centres; below the lowest centre all in the lowest cell (the no-flux
// ground reflects what would lie below it), likewise at the lid.
Weights layersAround(const TerrainGrid& g, int i, int j, double height)
{
    const double d = g.depth(i, j);
    if (g.nz < 2 || height <= d * g.fCell[0]) return {{0, 1.0}};
    int k = 0;
    while (k + 1 < g.nz && d * g.fCell[k + 1] <= height) ++k;
    if (k == g.nz - 1) return {{k, 1.0}};
    const double t = (height - d * g.fCell[k]) / (d * (g.fCell[k + 1] - g.fCell[k]));
    return {{k, 1 - t}, {k + 1, t}};
}

} // namespace

// A point source is spread over the (up to) eight cells around it by
// trilinear weights, and an area source's release height over the two
// layers around it: placing either in the cell that contains it would move
// it by up to half a cell wherever a face passes near it.  The weights add up
// to one, and inside the grid they keep the source's position (first moment).
std::vector<double> distributeSources(const TerrainGrid& g, const std::vector<Source>& sources,
                                      double reduction)
{
    std::vector<double> q(g.size(), 0.0);
    const double X1 = g.x0 + g.nx * g.dx, Y1 = g.y0 + g.ny * g.dy;
    for (const auto& s : sources)
    {
        const double rate = s.rate * (s.controlled ? 1.0 - reduction : 1.0);
        const double ax = s.x - 0.5 * s.lx, bx = s.x + 0.5 * s.lx;
        const double ay = s.y - 0.5 * s.ly, by = s.y + 0.5 * s.ly;
        if (ax < g.x0 || bx > X1 || ay < g.y0 || by > Y1)
        {
            std::ostringstream os;
            os << s.where << ": source '" << s.name << "' (x " << ax << ".." << bx << ", y " << ay
               << ".." << by << " m) lies outside the domain (x " << g.x0 << ".." << X1 << ", y "
               << g.y0 << ".." << Y1 << " m)";
            throw InputError(os.str());
        }
        // columns and their horizontal weights
        std::vector<std::pair<std::size_t, double>> cols;
        if (s.type == Source::Type::Point)
        {
            cols = pointColumns(g, s.x, s.y);
        }
        else
        {
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                {
                    const double ox = std::min(bx, g.x0 + (i + 1) * g.dx) - std::max(ax, g.x0 + i * g.dx);
                    const double oy = std::min(by, g.y0 + (j + 1) * g.dy) - std::max(ay, g.y0 + j * g.dy);
                    if (ox > 0 && oy > 0) cols.emplace_back(g.col(i, j), ox * oy / (s.lx * s.ly));
                }
        }
        for (const auto& [col, w] : cols)
        {
            if (w <= 0) continue;
            const int i = static_cast<int>(col % g.nx), j = static_cast<int>(col / g.nx);
            const double d = g.depth(i, j);
            if (s.type == Source::Type::Volume)
            {
                if (s.top > d)
                    throw InputError(s.where + ": source '" + s.name + "' reaches above the model lid");
                for (int k = 0; k < g.nz; ++k)
                {
                    const double lo = std::max(s.bottom, d * g.fFace[k]);
                    const double hi = std::min(s.top, d * g.fFace[k + 1]);
                    if (hi > lo) q[g.idx(i, j, k)] += rate * w * (hi - lo) / (s.top - s.bottom);
                }
            }
            else
            {
                if (s.height >= d)
                    throw InputError(s.where + ": source '" + s.name + "' is above the model lid");
                for (const auto& [k, wz] : layersAround(g, i, j, s.height)) q[g.idx(i, j, k)] += rate * w * wz;
            }
        }
    }
    return q;
}

void checkReceptors(const TerrainGrid& g, const std::vector<Receptor>& receptors)
{
    for (const auto& r : receptors)
    {
        if (!g.containsXY(r.x, r.y))
        {
            std::ostringstream os;
            os << r.where << ": receptor '" << r.name << "' at (" << r.x << ", " << r.y
               << ") m lies outside the domain (x " << g.x0 << ".." << g.x0 + g.nx * g.dx << ", y "
               << g.y0 << ".." << g.y0 + g.ny * g.dy << " m)";
            throw InputError(os.str());
        }
    }
}

namespace
{

struct RunOptions
{
    std::string outDir;
    int hours = 0;
};

std::string fmt(double v, int prec = 2)
{
    std::ostringstream os;
    os << std::fixed << std::setprecision(prec) << v;
    return os.str();
}

ScenarioResult runScenario(const EulerianCase& cs, const TerrainGrid& g, const WindModel& wind,
                           const Scenario& sc, const RunOptions& opt, std::mutex& printLock)
{
    ScenarioResult res;
    const int hours = opt.hours;
    const std::string dir = (fs::path(opt.outDir) / sc.name).string();
    fs::create_directories(fs::path(dir) / "vts");
    Transport t(g, sc.kH, sc.kV, cs.advection, cs.trueHorizontal);
    t.setImplicitVertical(cs.implicitVertical);
    t.setBackground(cs.backgroundUgM3 * 1e-9);
    for (auto& v : t.c) v = cs.backgroundUgM3 * 1e-9;
    const auto q = distributeSources(g, cs.sources, sc.reduction);
    t.setSources(q);
    double qTotal = 0;
    for (double v : q) qTotal += v;
    const double m0 = t.mass();

    const std::size_t nr = cs.receptors.size();
    res.hourly.assign(nr, std::vector<double>(hours, 0.0));
    const std::size_t nxy = static_cast<std::size_t>(g.nx) * g.ny;
    std::vector<double> ground(nxy, 0.0);
    double groundTime = 0;
    std::vector<std::pair<double, std::string>> pvd;
    res.dtMin = 1e300;
    const auto start = std::chrono::steady_clock::now();
    for (int h = 0; h < hours; ++h)
    {
        const MetHour& m = cs.met.hours[h];
        t.setFlow(wind.flow(m.speed, m.directionFrom));
        const double limit = t.stableDt();
        const double dt0 = cs.dt > 0 ? cs.dt : cs.cflFraction * limit;
        const long n = stepCount(3600.0, dt0, maxStepsPerHour, cs.file + ": key 'time.dt_s'",
                                 "an hour in steps of " + formatNumber(dt0, 3) + " s", "use a larger dt_s or 'auto'");
        const double dt = 3600.0 / n;
        res.dtMin = std::min(res.dtMin, dt);
        res.dtMax = std::max(res.dtMax, dt);
        for (long s = 0; s < n; ++s)
        {
            t.step(dt);
            for (std::size_t r = 0; r < nr; ++r)
                res.hourly[r][h] += t.sample(cs.receptors[r].x, cs.receptors[r].y, cs.receptors[r].height);
            for (std::size_t col = 0; col < nxy; ++col) ground[col] += t.c[col] * dt;
            groundTime += dt;
        }
        res.steps += n;
        for (std::size_t r = 0; r < nr; ++r) res.hourly[r][h] *= 1e9 / n;   // kg/m3 -> ug/m3
        if (cs.vtsEveryHours > 0 && (h + 1) % cs.vtsEveryHours == 0)
        {
            std::vector<double> ug(t.c.size());
            for (std::size_t k = 0; k < ug.size(); ++k) ug[k] = t.c[k] * 1e9;
            const std::string name = "vts/C_" + std::to_string(h + 1) + "h.vts";
            writeVts((fs::path(dir) / name).string(), g, "PM10_ug_m3", ug);
            pvd.emplace_back((h + 1) * 3600.0, name);
        }
        if ((h + 1) % 24 == 0 || h + 1 == hours)
        {
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::lock_guard<std::mutex> lock(printLock);
            std::cout << "  [" << sc.name << "] hour " << h + 1 << "/" << hours << ", "
                      << res.steps << " steps, " << fmt(wall, 1) << " s\n" << std::flush;
        }
    }
    if (!pvd.empty()) writePvd((fs::path(dir) / "C.pvd").string(), pvd);
    res.groundMean.resize(nxy);
    for (std::size_t col = 0; col < nxy; ++col) res.groundMean[col] = ground[col] / groundTime * 1e9;
    res.emitted = qTotal * t.time();
    res.inDomain = t.mass() - m0;
    res.leftDomain = t.boundaryOutflow();
    return res;
}

void writeScenarioOutputs(const EulerianCase& cs, const TerrainGrid& g, const Scenario& sc,
                          const ScenarioResult& res, const std::string& outDir, int hours)
{
    const std::string dir = (fs::path(outDir) / sc.name).string();
    const std::size_t nr = cs.receptors.size();
    std::vector<std::string> header = {"hour"};
    for (const auto& r : cs.receptors) header.push_back(r.name + " [ug/m3]");
    {
        CsvWriter w(dir + "/receptors_hourly.csv", header);
        for (int h = 0; h < hours; ++h)
        {
            std::vector<double> row = {static_cast<double>(cs.met.firstHour + h + 1)};
            for (std::size_t r = 0; r < nr; ++r) row.push_back(res.hourly[r][h]);
            w.row(row);
        }
        w.close();
    }
    auto blocks = [&](int len, const std::string& file, const std::string& first) {
        std::vector<std::string> hd = header;
        hd[0] = first;
        CsvWriter w(dir + "/" + file, hd);
        for (int b = 0; (b + 1) * len <= hours; ++b)
        {
            std::vector<double> row = {static_cast<double>(b + 1)};
            for (std::size_t r = 0; r < nr; ++r)
            {
                double s = 0;
                for (int h = b * len; h < (b + 1) * len; ++h) s += res.hourly[r][h];
                row.push_back(s / len);
            }
            w.row(row);
        }
        w.close();
    };
    blocks(24, "receptors_24h.csv", "day");
    blocks(168, "receptors_weekly.csv", "week");
    {
        CsvWriter w(dir + "/ground_mean.csv", {"x_m", "y_m", "terrain_m", "PM10_ug_m3"});
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                w.row(std::vector<double>{g.xc(i), g.yc(j), g.hc[g.col(i, j)], res.groundMean[g.col(i, j)]});
        w.close();
    }
    // gnuplot inputs for the map (blank line after each grid row)
    {
        OutputFile gmFile(dir + "/map_ground.dat"), sfFile(dir + "/map_sources.dat"),
            rfFile(dir + "/map_receptors.dat");
        std::ostream& gm = gmFile.out();
        std::ostream& sf = sfFile.out();
        std::ostream& rf = rfFile.out();
        for (int j = 0; j < g.ny; ++j)
        {
            for (int i = 0; i < g.nx; ++i)
                gm << g.xc(i) << ' ' << g.yc(j) << ' ' << g.hc[g.col(i, j)] << ' '
                   << res.groundMean[g.col(i, j)] << '\n';
            gm << '\n';
        }
        for (const auto& s : cs.sources)
            sf << s.x << ' ' << s.y << ' ' << std::max(0.5 * s.lx, 0.5 * g.dx / 4) << ' '
               << std::max(0.5 * s.ly, 0.5 * g.dy / 4) << ' ' << s.name << '\n';
        for (const auto& r : cs.receptors) rf << r.x << ' ' << r.y << ' ' << r.name << '\n';
        gmFile.close();
        sfFile.close();
        rfFile.close();
    }
    std::ostringstream gp;
    gp << "set termoption noenhanced\nset size ratio -1\nset xlabel 'x (east) [m]'\nset ylabel 'y (north) [m]'\n"
          "set title 'Scenario " << sc.name << ": ground-level PM10, mean over " << hours
       << " h [ug/m3]; dashed: terrain contours'\n"
          "set xrange [" << g.x0 << ":" << g.x0 + g.nx * g.dx << "]\nset yrange [" << g.y0 << ":"
       << g.y0 + g.ny * g.dy << "]\nset palette defined (0 'white', 1 '#ffe680', 2 '#ff8c1a', 3 '#cc0000', 4 '#4d0000')\n"
          "set cbrange [0:*]\nset contour base\nset cntrparam levels 10\nunset surface\nset view map\n"
          "set table '" << dir << "/map_contours.dat'\nsplot '" << dir << "/map_ground.dat' using 1:2:3 with lines\n"
          "unset table\nunset contour\nset key outside bottom horizontal\n"
          "plot '" << dir << "/map_ground.dat' using 1:2:4 with image notitle, "
          "'" << dir << "/map_contours.dat' using 1:2 with lines lc rgb '#555555' dt 2 notitle, "
          "'" << dir << "/map_sources.dat' using 1:2:3:4 with boxxyerror lc rgb 'black' lw 2 title 'sources', "
          "'" << dir << "/map_receptors.dat' using 1:2 with points pt 7 ps 1.2 lc rgb 'blue' title 'receptors', "
          "'" << dir << "/map_receptors.dat' using 1:2:3 with labels offset 1.5,0.8 textcolor rgb 'blue' notitle\n";
    plotPng(dir + "/ground_mean.png", gp.str(), 900, 800);
    if (hours >= 24)
    {
        std::ostringstream p2;
        p2 << "set termoption noenhanced\nset datafile separator ','\nset key outside right\nset xlabel 'day'\nset ylabel "
              "'24-h average PM10 [ug/m3]'\nset title 'Scenario " << sc.name << ": 24-h averages at the receptors'\n"
              "set grid\nplot for [c=2:" << nr + 1 << "] '" << dir
           << "/receptors_24h.csv' using 1:c with linespoints title columnheader(c), "
           << cs.standardUgM3 << " with lines lw 2 lc rgb 'red' title 'standard'\n";
        plotPng(dir + "/receptors_24h.png", p2.str());
    }
    // measured vs predicted 24-h averages (the paper's Fig 2)
    for (std::size_t r = 0; r < nr; ++r)
    {
        const auto& m = cs.measured24h[r];
        if (m.empty() || hours < 24) continue;
        const std::string name = cs.receptors[r].name;
        const std::string file = dir + "/measured_" + name + ".csv";
        CsvWriter w(file, {"day", "measured [ug/m3]", "predicted [ug/m3]"});
        double sm = 0, sp = 0;
        int n = 0;
        for (const auto& [day, value] : m)
        {
            if (day < 1 || day * 24 > hours) continue;
            double pred = 0;
            for (int h = (day - 1) * 24; h < day * 24; ++h) pred += res.hourly[r][h] / 24;
            w.row(std::vector<double>{static_cast<double>(day), value, pred});
            sm += value;
            sp += pred;
            ++n;
        }
        w.close();
        if (n == 0) continue;
        std::cout << "  [" << sc.name << "] " << name << ": " << n << " measured days, mean measured "
                  << fmt(sm / n) << ", predicted " << fmt(sp / n) << " ug/m3 (ratio " << fmt(sp / sm, 3) << ")\n";
        std::ostringstream p3;
        p3 << "set termoption noenhanced\nset datafile separator ','\nset key top left\nset xlabel 'day'\n"
              "set ylabel '24-h average PM10 [ug/m3]'\nset grid\nset yrange [0:*]\n"
              "set title 'Scenario " << sc.name << ", receptor " << name << ": predicted and measured'\n"
              "plot '" << file << "' using 1:3 with linespoints lw 2 pt 7 title 'predicted', "
              "'' using 1:2 with points pt 5 ps 1.3 title 'measured', "
           << cs.standardUgM3 << " with lines lc rgb 'red' title 'standard'\n";
        plotPng(dir + "/measured_" + name + ".png", p3.str());
    }
}

} // namespace

int eulerianMain(int argc, char** argv)
{
    std::string casePath, outDir = "results";
    std::optional<long> hoursOpt, threadsOpt;
    CommandLine cl("plume eulerian", std::string(texts::help::eulerian));
    cl.input(casePath, "case file");
    cl.text("-o", outDir);
    cl.integer("--hours", hoursOpt);
    cl.integer("--threads", threadsOpt);
    if (!cl.parse(argc, argv)) return 0;
    const int hoursLimit = hoursOpt ? static_cast<int>(*hoursOpt) : 0;   // 0: all the meteorology
    const unsigned threads =
        threadsOpt ? static_cast<unsigned>(*threadsOpt) : std::max(1u, std::thread::hardware_concurrency());
    const EulerianCase cs = loadEulerianCase(casePath);
    const auto grid = cs.makeGrid();
    const TerrainGrid& g = *grid;
    checkReceptors(g, cs.receptors);
    for (const auto& sc : cs.scenarios) distributeSources(g, cs.sources, sc.reduction);   // validates
    const int metHours = static_cast<int>(cs.met.hours.size());
    if (hoursLimit > metHours)
    {
        throw InputError("plume eulerian: option --hours " + std::to_string(hoursLimit) + " asks for more than the "
                         + std::to_string(metHours) + " hours of meteorology of " + cs.file);
    }
    const int hours = hoursLimit > 0 ? hoursLimit : metHours;
    const WindModel wind(g, cs.exponent, cs.zRef);

    // stability limit over all hours and scenarios (an explicit dt must satisfy it)
    double limit = 1e300;
    int limitHour = 0;
    std::string limitScenario;
    double topFlux = 0;
    for (const auto& sc : cs.scenarios)
    {
        Transport t(g, sc.kH, sc.kV, cs.advection, cs.trueHorizontal);
        t.setImplicitVertical(cs.implicitVertical);
        for (int h = 0; h < hours; ++h)
        {
            const Flow f = wind.flow(cs.met.hours[h].speed, cs.met.hours[h].directionFrom);
            topFlux = std::max(topFlux, f.maxTopFlux);
            t.setFlow(f);
            const double l = t.stableDt();
            if (l < limit)
            {
                limit = l;
                limitHour = cs.met.firstHour + h;
                limitScenario = sc.name;
            }
        }
    }
    if (cs.dt > limit)
    {
        std::ostringstream os;
        os << cs.file << ": key 'time.dt_s' = " << cs.dt << " s exceeds the stability limit "
           << std::setprecision(3) << limit << " s (scenario '" << limitScenario << "', hour "
           << limitHour << "; Adams-Bashforth needs dt <= 1/(4 sum K/dx^2 + sum|F|/V)"
           << (cs.implicitVertical ? ", vertical diffusion implicit)" : ")");
        throw InputError(os.str());
    }

    // the work the run needs: refuse what would not finish in reasonable time
    const double dtRun = cs.dt > 0 ? cs.dt : cs.cflFraction * limit;
    const long perHour = stepCount(3600.0, dtRun, maxStepsPerHour, cs.file + ": key 'time.dt_s'",
                                   "an hour in steps of " + formatNumber(dtRun, 3) + " s", "use a larger dt_s or 'auto'");
    const double updates = static_cast<double>(g.nx) * g.ny * g.nz * perHour * hours * cs.scenarios.size();
    if (updates > maxCellUpdates)
    {
        throw InputError(cs.file + ": the run needs about " + fmt(updates, 2) + " cell updates (grid "
                         + std::to_string(g.nx) + " x " + std::to_string(g.ny) + " x " + std::to_string(g.nz) + ", "
                         + std::to_string(perHour) + " steps per hour, " + std::to_string(hours) + " h, "
                         + std::to_string(cs.scenarios.size()) + " scenarios; limit " + fmt(maxCellUpdates, 2)
                         + "); use a coarser grid.cell_size_m, fewer --hours or a larger dt_s");
    }

    std::cout << "procsim plume eulerian: " << casePath << "\n  grid " << g.nx << " x " << g.ny
              << " x " << g.nz << " cells (" << g.dx << " m, lid at " << g.zTop
              << " m a.s.l.), " << hours << " h of meteorology, " << cs.scenarios.size()
              << " scenario(s), stability limit " << fmt(limit, 2) << " s\n";
    fs::create_directories(outDir);
    RunOptions opt{outDir, hours};
    std::vector<ScenarioResult> results(cs.scenarios.size());
    std::mutex printLock;
    std::vector<std::exception_ptr> errors(cs.scenarios.size());
    const auto t0 = std::chrono::steady_clock::now();
    std::size_t next = 0;
    std::mutex nextLock;
    auto worker = [&]() {
        while (true)
        {
            std::size_t k;
            {
                std::lock_guard<std::mutex> l(nextLock);
                if (next >= cs.scenarios.size()) return;
                k = next++;
            }
            try
            {
                results[k] = runScenario(cs, g, wind, cs.scenarios[k], opt, printLock);
            }
            catch (...)
            {
                errors[k] = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    const unsigned nt = std::min<unsigned>(threads, static_cast<unsigned>(cs.scenarios.size()));
    for (unsigned i = 0; i < nt; ++i) pool.emplace_back(worker);
    for (auto& th : pool) th.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (std::size_t k = 0; k < cs.scenarios.size(); ++k)
        writeScenarioOutputs(cs, g, cs.scenarios[k], results[k], outDir, hours);

    // Table 1 of the paper: run mean and highest 24-h average per receptor
    std::vector<std::string> header = {"receptor", "name"};
    for (const auto& sc : cs.scenarios)
    {
        header.push_back(sc.name + " mean [ug/m3]");
        header.push_back(sc.name + " max 24-h [ug/m3]");
    }
    CsvWriter table((fs::path(outDir) / "table.csv").string(), header);
    std::cout << "\n  " << std::left << std::setw(14) << "receptor";
    for (const auto& sc : cs.scenarios) std::cout << std::right << std::setw(34) << (sc.name + " mean / max 24-h");
    std::cout << "   [ug/m3]\n";
    for (std::size_t r = 0; r < cs.receptors.size(); ++r)
    {
        std::vector<std::string> row = {std::to_string(r + 1), cs.receptors[r].name};
        std::cout << "  " << std::left << std::setw(14) << cs.receptors[r].name;
        for (std::size_t k = 0; k < cs.scenarios.size(); ++k)
        {
            const auto& hs = results[k].hourly[r];
            double mean = 0;
            for (double v : hs) mean += v;
            mean /= hours;
            double max24 = 0;
            for (int b = 0; (b + 1) * 24 <= hours; ++b)
            {
                double sum = 0;
                for (int h = b * 24; h < (b + 1) * 24; ++h) sum += hs[h];
                max24 = std::max(max24, sum / 24);
            }
            row.push_back(fmt(mean, 4));
            row.push_back(hours >= 24 ? fmt(max24, 4) : "");
            std::cout << std::right << std::setw(34)
                      << (fmt(mean) + " / " + (hours >= 24 ? fmt(max24) : std::string("-")))
                      << (max24 > cs.standardUgM3 ? "*" : " ");
        }
        std::cout << '\n';
        table.row(row);
    }
    table.close();
    std::cout << "  (* = a 24-h average above the standard " << cs.standardUgM3 << " ug/m3)\n\n";
    for (std::size_t k = 0; k < cs.scenarios.size(); ++k)
    {
        const auto& r = results[k];
        const double bal = r.emitted - r.inDomain - r.leftDomain;
        std::cout << "  [" << cs.scenarios[k].name << "] K_H " << cs.scenarios[k].kH << ", K_V "
                  << cs.scenarios[k].kV << " m2/s, reduction " << cs.scenarios[k].reduction * 100
                  << " %: " << r.steps << " steps (dt " << fmt(r.dtMin, 2) << ".." << fmt(r.dtMax, 2)
                  << " s); emitted " << fmt(r.emitted, 1) << " kg, in domain " << fmt(r.inDomain, 1)
                  << " kg, left " << fmt(r.leftDomain, 1) << " kg, relative imbalance "
                  << std::scientific << std::setprecision(2) << bal / std::max(r.emitted, 1e-300)
                  << std::defaultfloat << std::setprecision(6) << "\n";
    }
    std::cout << "  wind: largest flux through the lid after adjustment " << std::setprecision(3)
              << topFlux << " m3/s\n  wall time " << fmt(wall, 1) << " s; outputs in " << outDir
              << "/ (table.csv; per scenario receptors_*.csv, ground_mean.png, C.pvd)\n";
    return 0;
}

} // namespace procsim::plume
