#include "kinetics/Run.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double ts)
{
    if (ts <= t.front()) return v.front();
    if (ts >= t.back()) return v.back();
    const auto it = std::upper_bound(t.begin(), t.end(), ts);
    const std::size_t i = static_cast<std::size_t>(it - t.begin());
    const double w = (ts - t[i - 1]) / (t[i] - t[i - 1]);
    return v[i - 1] + w * (v[i] - v[i - 1]);
}

std::string num(double v, int prec = 4)
{
    return formatNumber(v, prec);
}

} // namespace

double Results::tocNoDischarge(std::size_t i) const
{
    double organicFed = 0; // mol C fed as organic species
    const auto feed = cas.feedRate();
    for (std::size_t s = 0; s < feed.size(); ++s)
        if (cas.mech.species[s].organic)
            organicFed += feed[s] * cas.mech.species[s].carbon * cas.volume * t[i];
    return toc.front() + organicFed / cas.volume * carbonMolarMass * 1000.0;
}

std::vector<double> Results::series(const std::string& q) const
{
    std::vector<double> out(t.size());
    if (q == "TOC") return toc;
    const std::size_t s = cas.mech.index(q, "output");
    for (std::size_t i = 0; i < t.size(); ++i)
        out[i] = c[i][static_cast<Eigen::Index>(s)] * cas.mech.species[s].molarMass * 1000.0;
    return out;
}

double Results::value(const std::string& q, double ts) const
{
    return interpolate(t, series(q), ts);
}

Results analyse(const Model& model, const Trajectory& tr)
{
    Results r;
    r.cas = model.caseData();
    r.t = tr.t;
    r.steps = tr.steps;
    const auto& sp = r.cas.mech.species;
    const auto feed = r.cas.feedRate();
    double feedCarbon = 0; // mol C / s into the liquid
    for (std::size_t s = 0; s < sp.size(); ++s) feedCarbon += feed[s] * sp[s].carbon * r.cas.volume;
    for (std::size_t i = 0; i < tr.t.size(); ++i)
    {
        if (!tr.y[i].allFinite())
        {
            throw std::runtime_error("the solution is not finite at t = " + std::to_string(tr.t[i] / 3600.0)
                                     + " h (rk4 step too large for a stiff mechanism? use solver cvode)");
        }
        const Eigen::VectorXd c = model.allSpecies(tr.y[i]);
        double organic = 0, inorganic = 0;
        for (std::size_t s = 0; s < sp.size(); ++s)
        {
            const double molC = c[static_cast<Eigen::Index>(s)] * sp[s].carbon * r.cas.volume;
            (sp[s].organic ? organic : inorganic) += molC;
        }
        r.c.push_back(c);
        r.toc.push_back(organic / r.cas.volume * carbonMolarMass * 1000.0);
        r.inorganicCarbon.push_back(inorganic);
        r.carbonFed.push_back(feedCarbon * tr.t[i]);
        if (i == 0)
            r.carbonInitial.push_back(organic + inorganic);
        else
            r.carbonInitial.push_back(r.carbonInitial.front());
        const double in = r.carbonInitial.back() + r.carbonFed.back();
        const double out = organic + inorganic;
        r.carbonError.push_back(in > 0 ? std::fabs(in - out) / in : std::fabs(out));
    }
    return r;
}

Results runCase(const Case& c)
{
    const Model model(c);
    const auto times = outputTimes(c.duration, c.outputInterval);
    return analyse(model, solve(model, times, c.solver));
}

double maxCarbonError(const Results& r)
{
    return *std::max_element(r.carbonError.begin(), r.carbonError.end());
}

Efficiency efficiency(const Results& r)
{
    Efficiency e;
    const auto& sp = r.cas.mech.species;
    // time at which TOC falls to half of what it would be without discharge
    for (std::size_t i = 1; i < r.t.size(); ++i)
    {
        const double f0 = r.toc[i - 1] - 0.5 * r.tocNoDischarge(i - 1);
        const double f1 = r.toc[i] - 0.5 * r.tocNoDischarge(i);
        if (f0 > 0 && f1 <= 0)
        {
            e.halfReached = true;
            e.tHalf = r.t[i - 1] + (r.t[i] - r.t[i - 1]) * f0 / (f0 - f1);
            break;
        }
    }
    const double power = r.cas.current * r.cas.voltage; // mA * kV = W
    const auto feed = r.cas.feedRate();
    for (std::size_t s = 0; s < sp.size(); ++s)
    {
        if (feed[s] > 0 && sp[s].organic && power > 0)
            e.jGas.emplace_back(sp[s].name, feed[s] * r.cas.volume / power);
    }
    if (!e.halfReached || power <= 0) return e;
    double carbonInitial = 0, carbonFed = 0;
    for (std::size_t s = 0; s < sp.size(); ++s)
    {
        if (!sp[s].organic) continue;
        carbonInitial += r.cas.initial[s] * sp[s].carbon * r.cas.volume;
        carbonFed += feed[s] * sp[s].carbon * r.cas.volume * e.tHalf;
        if (r.cas.initial[s] > 0)
            e.jLiquid.emplace_back(sp[s].name, r.cas.initial[s] * r.cas.volume / 2.0 / (power * e.tHalf));
    }
    e.jToc = (carbonInitial + carbonFed) / 2.0 / (power * e.tHalf);
    return e;
}

std::vector<std::string> plotSpecies(const Results& r)
{
    if (!r.cas.plotSpecies.empty()) return r.cas.plotSpecies;
    std::vector<std::string> out;
    const auto feed = r.cas.feedRate();
    for (std::size_t s = 0; s < r.cas.mech.species.size(); ++s)
    {
        const auto& sp = r.cas.mech.species[s];
        if (!sp.organic) continue;
        double peak = 0;
        for (const auto& c : r.c) peak = std::max(peak, c[static_cast<Eigen::Index>(s)]);
        if (peak > 0) out.push_back(sp.name);
    }
    return out;
}

std::vector<double> reportTimes(const Results& r)
{
    std::vector<double> times = r.cas.reportTimes;
    if (times.empty() || times.back() < r.t.back()) times.push_back(r.t.back());
    return times;
}

namespace
{

// The plotted species and TOC at every report time.
std::string valuesTable(const Results& r)
{
    const auto names = plotSpecies(r);
    std::string os = "  time_h";
    for (const auto& n : names) os += fmt::format("{:>11}", n);
    os += fmt::format("{:>11}   (mg/L; TOC mg C/L)\n", "TOC");
    for (double ts : reportTimes(r))
    {
        os += fmt::format("  {:>6}", num(ts / 3600.0, 3));
        for (const auto& n : names) os += fmt::format("{:>11}", num(r.value(n, ts)));
        os += fmt::format("{:>11}\n", num(r.value("TOC", ts)));
    }
    return os;
}

// Energetic efficiencies, paper eqs 18-20 (values in 1e-9 mol/J).
std::string efficiencyLine(const Results& r, const Efficiency& e)
{
    std::string os = fmt::format("  energetic efficiency at {} mA, {} kV:", formatNumber(r.cas.current),
                                 formatNumber(r.cas.voltage));
    if (e.halfReached) os += " J_TOC = " + num(e.jToc * 1e9) + "e-9 mol C/J (eq 18)";
    for (const auto& [n, j] : e.jLiquid) os += "; J_" + n + " = " + num(j * 1e9) + "e-9 mol/J (eq 19)";
    for (const auto& [n, j] : e.jGas) os += "; J_" + n + " = " + num(j * 1e9) + "e-9 mol/J (eq 20)";
    return os + "\n";
}

} // namespace

std::string summaryText(const Results& r, const Efficiency& e)
{
    const Case& c = r.cas;
    std::string os = fmt::format("case {} ({}), mechanism {}, solver {} ({} steps)\n", c.title, c.file,
                                 c.mech.name, c.solver.method, r.steps);
    if (c.radicalFixed())
        os += fmt::format(
            "  [{}] = {} mg/L = {} mol/L ({}, I = {} mA)\n", c.mech.radical,
            num(c.radicalConcentration() * 1000.0 * c.mech.species[c.mech.radicalIndex()].molarMass),
            num(c.radicalConcentration()), c.oh.kind, formatNumber(c.current));
    os += valuesTable(r);
    if (e.halfReached)
        os += "  TOC half time (TOC = 1/2 TOC without discharge): " + num(e.tHalf / 3600.0) + " h\n";
    else
        os += "  TOC half time: not reached within " + num(r.t.back() / 3600.0) + " h\n";
    if (c.voltage > 0) os += efficiencyLine(r, e);
    const std::size_t last = r.t.size() - 1;
    os += fmt::format(
        "  carbon: initial {} mmol + fed {} mmol = in solution {} mmol + CO2 {} mmol; max relative "
        "imbalance {}\n",
        num(r.carbonInitial[last] * 1e3, 6), num(r.carbonFed[last] * 1e3, 6),
        num(r.toc[last] / carbonMolarMass / 1000.0 * c.volume * 1e3, 6),
        num(r.inorganicCarbon[last] * 1e3, 6), num(maxCarbonError(r), 3));
    return os;
}

namespace
{

void writeTimeseries(const Results& r, const std::string& path)
{
    const auto& sp = r.cas.mech.species;
    std::vector<std::string> header = {"time_h", "time_s"};
    for (const auto& s : sp) header.push_back(s.name + "_mg_per_L");
    for (const auto& s : sp) header.push_back(s.name + "_mol_per_L");
    for (const char* h : {"TOC_mgC_per_L", "TOC_no_discharge_mgC_per_L", "CO2_formed_mol", "carbon_fed_mol",
                          "carbon_balance_rel_error"})
        header.push_back(h);
    CsvWriter csv(path, header);
    for (std::size_t i = 0; i < r.t.size(); ++i)
    {
        std::vector<double> row = {r.t[i] / 3600.0, r.t[i]};
        for (std::size_t s = 0; s < sp.size(); ++s)
            row.push_back(r.c[i][static_cast<Eigen::Index>(s)] * sp[s].molarMass * 1000.0);
        for (std::size_t s = 0; s < sp.size(); ++s) row.push_back(r.c[i][static_cast<Eigen::Index>(s)]);
        row.insert(row.end(),
                   {r.toc[i], r.tocNoDischarge(i), r.inorganicCarbon[i], r.carbonFed[i], r.carbonError[i]});
        csv.row(row);
    }
    csv.close();
}

void writeSummaryCsv(const Results& r, const Efficiency& e, const std::string& path)
{
    CsvWriter csv(path, {"quantity", "value", "unit"});
    auto put = [&](const std::string& q, double v, const std::string& u) {
        csv.row(std::vector<std::string>{q, formatNumber(v, 10), u});
    };
    put("current", r.cas.current, "mA");
    put("voltage", r.cas.voltage, "kV");
    if (r.cas.radicalFixed()) put(r.cas.mech.radical, r.cas.radicalConcentration(), "mol/L");
    for (double ts : reportTimes(r))
    {
        for (const auto& n : plotSpecies(r)) put(n + "@" + num(ts / 3600.0) + "h", r.value(n, ts), "mg/L");
        put("TOC@" + num(ts / 3600.0) + "h", r.value("TOC", ts), "mg C/L");
    }
    if (e.halfReached) put("TOC_half_time", e.tHalf / 3600.0, "h");
    if (e.halfReached && r.cas.voltage > 0) put("J_TOC", e.jToc, "mol C/J");
    for (const auto& [n, j] : e.jLiquid) put("J_" + n, j, "mol/J");
    for (const auto& [n, j] : e.jGas) put("J_" + n, j, "mol/J");
    put("carbon_balance_max_rel_error", maxCarbonError(r), "-");
    csv.close();
}

// species.png and toc.png from timeseries.csv: species in mg/L from column 3,
// TOC after the mol/L columns.
void plotRun(const Results& r, const std::string& dir)
{
    const std::string csv = dir + "/timeseries.csv";
    std::string names, columns;
    for (const auto& n : plotSpecies(r))
    {
        names += n + " ";
        columns += std::to_string(3 + r.cas.mech.index(n, "plot")) + " ";
    }
    plotPng(dir + "/species.png", texts::plots::species,
            PlotVariables()
                .set("csv", csv)
                .set("title_text", r.cas.title)
                .set("names", names)
                .set("columns", columns));
    plotPng(dir + "/toc.png", texts::plots::toc,
            PlotVariables()
                .set("csv", csv)
                .set("title_text", r.cas.title)
                .set("toc", double(3 + 2 * r.cas.mech.species.size())));
}

} // namespace

void writeRun(const Results& r, const Efficiency& e, const std::string& dir, bool plots)
{
    createOutputDirectory(dir);
    writeTimeseries(r, dir + "/timeseries.csv");
    writeSummaryCsv(r, e, dir + "/summary.csv");
    writeTextFile(dir + "/summary.txt", summaryText(r, e));
    if (plots) plotRun(r, dir);
}

} // namespace procsim::kinetics
