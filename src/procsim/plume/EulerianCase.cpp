#include "plume/EulerianCase.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "common/Format.hpp"
#include "common/YamlInput.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

namespace
{

constexpr double bytesPerCell = 400; // fields, fluxes and the implicit vertical solve

} // namespace

std::unique_ptr<TerrainGrid> EulerianCase::makeGrid() const
{
    const double w = terrain.ncols * terrain.cell, h = terrain.nrows * terrain.cell;
    checkMemory(
        std::floor(w / cellSize + 1e-9) * std::floor(h / cellSize + 1e-9) * levels, bytesPerCell, file,
        "a grid of " + formatNumber(cellSize, 3) + " m cells with " + std::to_string(levels) + " levels");
    const int nx = std::max(2, static_cast<int>(std::floor(w / cellSize + 1e-9)));
    const int ny = std::max(2, static_cast<int>(std::floor(h / cellSize + 1e-9)));
    const double highest = *std::max_element(terrain.z.begin(), terrain.z.end());
    const EsriGrid& t = terrain;
    return std::make_unique<TerrainGrid>(nx, ny, levels, t.xll, t.yll, cellSize, cellSize,
                                         highest + topAboveHighest, stretching,
                                         [&t](double x, double y) { return t.sample(x, y); });
}

namespace
{

void readGrid(const YamlInput& in, EulerianCase& c)
{
    c.cellSize = c.terrain.cell; // default: the terrain's own cells
    if (in.has("grid"))
    {
        const YamlInput g = in.child("grid");
        g.rejectUnknown({"cell_size_m", "levels", "top_above_highest_m", "stretching"});
        if (g.has("cell_size_m")) c.cellSize = g.positive("cell_size_m", "m");
        if (g.has("levels")) c.levels = static_cast<int>(g.integer("levels", 1, 1000));
        if (g.has("top_above_highest_m")) c.topAboveHighest = g.positive("top_above_highest_m", "m");
        c.stretching = g.number("stretching", c.stretching);
    }
    if (c.cellSize * 2 > std::min(c.terrain.ncols, c.terrain.nrows) * c.terrain.cell)
        throw InputError(c.file + ": key 'grid.cell_size_m' expected at most half the terrain extent");
}

// The schemes, and the diffusivities that scenarios without their own take.
void readDispersion(const YamlInput& in, EulerianCase& c, double& kH, double& kV)
{
    if (!in.has("dispersion")) return;
    const YamlInput d = in.child("dispersion");
    d.rejectUnknown({"K_H_m2_s", "K_V_m2_s", "advection", "vertical_diffusion", "horizontal_diffusion"});
    const std::string hd = d.text("horizontal_diffusion", "along_terrain");
    if (hd == "along_terrain")
        c.trueHorizontal = false;
    else if (hd == "true_horizontal")
        c.trueHorizontal = true;
    else
        throw d.error("horizontal_diffusion", "along_terrain or true_horizontal");
    const std::string v = d.text("vertical_diffusion", "implicit");
    if (v == "implicit")
        c.implicitVertical = true;
    else if (v == "explicit")
        c.implicitVertical = false;
    else
        throw d.error("vertical_diffusion", "implicit (Crank-Nicolson) or explicit (AB2)");
    if (c.trueHorizontal && c.implicitVertical)
        throw d.error("horizontal_diffusion",
                      "along_terrain when vertical_diffusion is implicit (true_horizontal needs "
                      "vertical_diffusion: explicit: its metric cross terms are explicit)");
    if (d.has("K_H_m2_s")) kH = d.nonNegative("K_H_m2_s", "m2/s");
    if (d.has("K_V_m2_s")) kV = d.nonNegative("K_V_m2_s", "m2/s");
    const std::string a = d.text("advection", "limited_quick");
    if (a == "limited_quick")
        c.advection = Advection::LimitedQuick;
    else if (a == "quick")
        c.advection = Advection::Quick;
    else if (a == "upwind")
        c.advection = Advection::Upwind;
    else
        throw d.error("advection", "one of limited_quick, quick, upwind");
}

void readWindAndTime(const YamlInput& in, EulerianCase& c)
{
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
}

void readOutput(const YamlInput& in, EulerianCase& c)
{
    if (!in.has("output")) return;
    const YamlInput o = in.child("output");
    o.rejectUnknown({"vts_every_h", "background_ug_m3", "standard_24h_ug_m3", "measured_24h"});
    if (o.has("vts_every_h"))
        c.vtsEveryHours = static_cast<int>(o.integer("vts_every_h", 0, 1000000)); // 0 = none
    c.backgroundUgM3 = o.has("background_ug_m3") ? o.nonNegative("background_ug_m3", "ug/m3") : 0.0;
    if (o.has("standard_24h_ug_m3")) c.standardUgM3 = o.positive("standard_24h_ug_m3", "ug/m3");
}

// The days of the measured series: whole days from 1, each after the one before.
void checkMeasuredDays(const CsvTable& t, std::size_t cd, const std::string& path)
{
    constexpr double maxDay = 1e6;
    for (std::size_t r = 0; r < t.rows.size(); ++r)
    {
        const double day = t.rows[r][cd];
        const std::string where = path + ": line " + std::to_string(t.lines[r]) + ": column 'day'";
        if (!(day >= 1 && day <= maxDay && day == std::floor(day)))
            throw InputError(where + " expected a whole day from 1 to " + formatNumber(maxDay) + ", got "
                             + formatNumber(day));
        if (r > 0 && !(day > t.rows[r - 1][cd]))
            throw InputError(where + " expected days in increasing order, got " + formatNumber(day)
                             + " after " + formatNumber(t.rows[r - 1][cd]));
    }
}

// output.measured_24h: a CSV of day and one column "<receptor> [ug/m3]" per
// measured receptor; negative values are days without a measurement.
void readMeasured(const std::string& path, EulerianCase& c)
{
    const CsvTable t = readCsv(path);
    if (t.rows.empty()) throw InputError(path + ": no data rows under the header (expected one row per day)");
    const std::size_t cd = t.column("day", path);
    checkMeasuredDays(t, cd, path);
    for (std::size_t col = 0; col < t.header.size(); ++col)
    {
        if (col == cd) continue;
        std::size_t r = 0;
        while (r < c.receptors.size() && t.header[col] != c.receptors[r].name + " [ug/m3]") ++r;
        if (r == c.receptors.size())
            throw InputError(path + ": column '" + t.header[col]
                             + "' names no receptor (expected '<receptor> [ug/m3]')");
        for (const auto& row : t.rows)
            if (row[col] >= 0)
                c.measured24h[r].emplace_back(static_cast<int>(std::lround(row[cd])), row[col]);
    }
}

Scenario readScenario(const YamlInput& s, double kH, double kV)
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
    return sc;
}

} // namespace

EulerianCase loadEulerianCase(const std::string& path)
{
    const YamlInput in = YamlInput::load(path);
    in.rejectUnknown({"terrain", "grid", "dispersion", "wind", "time", "meteorology", "sources", "receptors",
                      "scenarios", "output"});
    EulerianCase c;
    c.file = path;
    c.dir = fs::path(path).parent_path().string();
    c.terrain = readEsriGrid(relativeTo(c.dir, in.text("terrain")));
    readGrid(in, c);
    double kH = 200, kV = 1;
    readDispersion(in, c, kH, kV);
    readWindAndTime(in, c);
    readOutput(in, c);
    c.met = readMet(relativeTo(c.dir, in.text("meteorology")), false);
    c.sources = parseSources(in.child("sources"));
    c.receptors = parseReceptors(in.child("receptors"));
    c.measured24h.assign(c.receptors.size(), {});
    if (in.has("output") && in.child("output").has("measured_24h"))
        readMeasured(relativeTo(c.dir, in.child("output").text("measured_24h")), c);
    if (in.has("scenarios"))
        for (const auto& s : in.child("scenarios").items()) c.scenarios.push_back(readScenario(s, kH, kV));
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
            throw InputError(s.where + ": source '" + s.name + "' (x " + formatNumber(ax) + ".."
                             + formatNumber(bx) + ", y " + formatNumber(ay) + ".." + formatNumber(by)
                             + " m) lies outside the domain (x " + formatNumber(g.x0) + ".."
                             + formatNumber(X1) + ", y " + formatNumber(g.y0) + ".." + formatNumber(Y1)
                             + " m)");
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
                for (const auto& [k, wz] : layersAround(g, i, j, s.height))
                    q[g.idx(i, j, k)] += rate * w * wz;
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
            throw InputError(r.where + ": receptor '" + r.name + "' at (" + formatNumber(r.x) + ", "
                             + formatNumber(r.y) + ") m lies outside the domain (x " + formatNumber(g.x0)
                             + ".." + formatNumber(g.x0 + g.nx * g.dx) + ", y " + formatNumber(g.y0) + ".."
                             + formatNumber(g.y0 + g.ny * g.dy) + " m)");
    }
}

} // namespace procsim::plume
