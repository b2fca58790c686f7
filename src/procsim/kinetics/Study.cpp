#include "kinetics/Study.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "common/Checked.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

std::string num(double v)
{
    return formatNumber(v);
}

// Every combination of the swept values (cartesian product, last key fastest).
std::vector<Overrides> combinations(const std::vector<SweepDim>& dims)
{
    std::vector<Overrides> combos = {{}};
    for (const auto& d : dims)
    {
        std::vector<Overrides> next;
        for (const auto& c : combos)
            for (double v : d.values)
            {
                Overrides o = c;
                o.emplace_back(d.key, v);
                next.push_back(o);
            }
        combos = next;
    }
    return combos;
}

// sweep_summary.csv: swept values, outputs at report times, efficiencies.
void writeSweepSummary(const std::vector<SweepRun>& runs, const std::vector<SweepDim>& dims,
                       const std::vector<double>& times, const std::vector<std::string>& names,
                       const std::string& path)
{
    std::vector<std::string> header;
    for (const auto& d : dims) header.push_back(shortKey(d.key));
    for (double ts : times)
        for (const auto& n : names)
            header.push_back(n + "_at_" + num(ts / 3600.0) + "h_" + (n == "TOC" ? "mgC_per_L" : "mg_per_L"));
    header.push_back("TOC_half_time_h");
    header.push_back("J_TOC_mol_per_J");
    CsvWriter csv(path, header);
    for (const auto& run : runs)
    {
        std::vector<double> row;
        for (const auto& kv : run.values) row.push_back(kv.second);
        for (double ts : times)
            for (const auto& n : names) row.push_back(run.results.value(n, ts));
        row.push_back(run.eff.halfReached ? run.eff.tHalf / 3600.0 : NAN);
        row.push_back(run.eff.halfReached ? run.eff.jToc : NAN);
        csv.row(row);
    }
    csv.close();
}

// family_<quantity>.png: each quantity over time, one curve per member.
void plotFamilies(const std::vector<SweepRun>& runs, const std::vector<std::string>& names,
                  const std::string& dir)
{
    const Results& first = runs.front().results;
    std::string labels;
    for (const auto& run : runs) labels += run.label + " ";
    for (const auto& n : names)
    {
        const std::size_t col =
            n == "TOC" ? 3 + 2 * first.cas.mech.species.size() : 3 + first.cas.mech.index(n, "plot");
        plotPng(dir + "/family_" + n + ".png", texts::plots::family,
                PlotVariables()
                    .set("dir", dir)
                    .set("labels", labels)
                    .set("col", double(col))
                    .set("ylabel_text", n + (n == "TOC" ? " (mg C/L)" : " (mg/L)"))
                    .set("title_text", first.cas.title + ": " + n));
    }
}

// sweep_<quantity>_at_<t>h.png: values at report times against the last
// swept key (one curve per value of the first).
void plotSweeps(const std::vector<SweepDim>& dims, const std::vector<double>& times,
                const std::vector<std::string>& names, const std::string& title, const std::string& dir)
{
    const std::size_t nd = dims.size();
    std::string values0;
    if (nd > 1)
        for (double v : dims.front().values) values0 += num(v) + " ";
    for (std::size_t it = 0; it < times.size(); ++it)
        for (std::size_t q = 0; q < names.size(); ++q)
        {
            const std::string at = num(times[it] / 3600.0);
            plotPng(dir + "/sweep_" + names[q] + "_at_" + at + "h.png", texts::plots::sweep,
                    PlotVariables()
                        .set("csv", dir + "/sweep_summary.csv")
                        .set("xcol", double(nd))
                        .set("col", double(nd + 1 + it * names.size() + q))
                        .set("xlabel_text", shortKey(dims.back().key))
                        .set("ylabel_text", names[q] + " at " + at + " h")
                        .set("title_text", title)
                        .set("key0", shortKey(dims.front().key))
                        .set("values0", values0));
        }
}

} // namespace

std::string shortKey(const std::string& key)
{
    const auto p = key.rfind('.');
    const std::string last = p == std::string::npos ? key : key.substr(p + 1);
    // initial_mg_per_L.PH -> PH_mg_per_L reads better than PH
    if (key.rfind("initial_mg_per_L.", 0) == 0) return last + "0_mg_per_L";
    if (key.rfind("gas.inlet_ppm.", 0) == 0) return last + "_in_ppm";
    return last;
}

std::vector<SweepRun> runSweep(const CaseSource& src, const Overrides& set, const std::vector<SweepDim>& dims,
                               const std::string& dir, bool plots, bool quiet, const std::string& solver)
{
    const std::vector<Overrides> combos = combinations(dims);
    // every member is built (validated) and solved before anything is written
    std::vector<SweepRun> runs;
    std::vector<Case> cases;
    std::vector<std::string> labels;
    for (const auto& o : combos)
    {
        SweepRun run;
        run.values = o;
        for (const auto& [k, v] : o) run.label += (run.label.empty() ? "" : "_") + shortKey(k) + "=" + num(v);
        Overrides all = set;
        all.insert(all.end(), o.begin(), o.end());
        cases.push_back(src.build(all));
        if (!solver.empty()) cases.back().solver.method = solver;
        labels.push_back(run.label);
        runs.push_back(std::move(run));
    }
    rejectDuplicates(labels, "kinetics run: sweep", "member");
    for (std::size_t i = 0; i < runs.size(); ++i)
    {
        runs[i].results = runCase(cases[i]);
        runs[i].eff = efficiency(runs[i].results);
    }
    for (const auto& run : runs)
    {
        writeRun(run.results, run.eff, dir + "/" + run.label, false);
        if (!quiet) std::cout << "--- " << run.label << '\n' << summaryText(run.results, run.eff);
    }

    const Results& first = runs.front().results;
    const std::vector<double> times = reportTimes(first);
    auto names = plotSpecies(first);
    names.push_back("TOC");
    createOutputDirectory(dir);
    writeSweepSummary(runs, dims, times, names, dir + "/sweep_summary.csv");
    if (!plots) return runs;
    plotFamilies(runs, names, dir);
    plotSweeps(dims, times, names, first.cas.title, dir);
    return runs;
}

std::vector<SensitivityRow> sensitivity(const CaseSource& src, const Overrides& set,
                                        std::vector<std::string> parameters, std::vector<std::string> outputs,
                                        double time, double change)
{
    const Case base = src.build(set);
    if (parameters.empty()) parameters = base.sensParameters;
    if (parameters.empty())
        for (const auto& r : base.mech.reactions) parameters.push_back(r.id);
    if (outputs.empty()) outputs = base.sensOutputs;
    if (time > base.duration * (1 + 1e-12))
    {
        throw InputError("kinetics sensitivity: option --time-h " + formatNumber(time / 3600.0)
                         + " is past the end of the run (" + formatNumber(base.duration / 3600.0) + " h)");
    }
    if (time <= 0) time = base.sensTime > 0 ? base.sensTime : base.duration;
    if (change <= 0) change = base.sensChange;
    const Results r0 = runCase(base);
    if (outputs.empty())
    {
        outputs = plotSpecies(r0);
        outputs.push_back("TOC");
    }
    for (const auto& o : outputs)
        if (o != "TOC") base.mech.index(o, "sensitivity output");
    std::vector<SensitivityRow> rows;
    for (const auto& p : parameters)
    {
        const std::size_t ri = base.mech.reaction(p);
        if (ri == std::string::npos)
            throw InputError(base.mech.file + ": no reaction with id '" + p + "' (sensitivity parameter)");
        for (double sign : {+1.0, -1.0})
        {
            Overrides o = set;
            o.emplace_back("k." + p, base.mech.reactions[ri].k * (1 + sign * change));
            const Results r1 = runCase(src.build(o));
            for (const auto& o : outputs)
            {
                SensitivityRow row;
                row.parameter = p;
                row.change = sign * change;
                row.output = o;
                row.base = r0.value(o, time);
                row.perturbed = r1.value(o, time);
                row.deviation = row.base != 0 ? (row.perturbed - row.base) / row.base : 0.0;
                const auto s0 = r0.series(o), s1 = r1.series(o);
                double peak = 0;
                for (double v : s0) peak = std::max(peak, std::fabs(v));
                row.maxDeviation = 0;
                row.maxDeviationTime = 0;
                for (std::size_t i = 0; i < s0.size() && r0.t[i] <= time * (1 + 1e-12); ++i)
                {
                    if (std::fabs(s0[i]) < 1e-3 * peak) continue; // skip near-zero values
                    const double d = (s1[i] - s0[i]) / s0[i];
                    if (std::fabs(d) > std::fabs(row.maxDeviation))
                    {
                        row.maxDeviation = d;
                        row.maxDeviationTime = r0.t[i];
                    }
                }
                rows.push_back(row);
            }
        }
    }
    return rows;
}

std::string sensitivityTable(const std::vector<SensitivityRow>& rows)
{
    std::string os =
        "deviation (%) of each output when one rate constant changes (at the chosen time; [largest over "
        "the run])\n";
    os += fmt::format("{:>8}{:>8}", "param", "change");
    std::vector<std::string> outs;
    for (const auto& r : rows)
    {
        if (std::find(outs.begin(), outs.end(), r.output) != outs.end()) break;
        outs.push_back(r.output);
    }
    for (const auto& o : outs) os += fmt::format("{:>20}", o);
    os += '\n';
    for (std::size_t i = 0; i < rows.size(); i += outs.size())
    {
        os += fmt::format("{:>8}{:>+7.3g}%", rows[i].parameter, rows[i].change * 100);
        for (std::size_t k = 0; k < outs.size(); ++k)
            os += fmt::format("{:>20}", fmt::format("{:.2f} [{:.2f}]", rows[i + k].deviation * 100,
                                                    rows[i + k].maxDeviation * 100));
        os += '\n';
    }
    return os;
}

void writeSensitivity(const std::vector<SensitivityRow>& rows, const std::string& dir)
{
    createOutputDirectory(dir);
    CsvWriter csv(dir + "/sensitivity.csv",
                  {"parameter", "change_percent", "output", "base_value", "perturbed_value",
                   "deviation_percent", "max_deviation_percent", "max_deviation_time_h"});
    for (const auto& r : rows)
        csv.row(std::vector<std::string>{r.parameter, num(r.change * 100), r.output, num(r.base),
                                         num(r.perturbed), num(r.deviation * 100), num(r.maxDeviation * 100),
                                         num(r.maxDeviationTime / 3600.0)});
    csv.close();
}

} // namespace procsim::kinetics
