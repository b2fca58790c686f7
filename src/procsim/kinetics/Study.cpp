#include "kinetics/Study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "common/Checked.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"

namespace procsim::kinetics
{

namespace
{


std::string num(double v) { return formatNumber(v); }

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

std::vector<SweepRun> runSweep(const CaseSource& src, const Overrides& set, const std::vector<SweepDim>& dims, const std::string& dir,
                               bool plots, bool quiet, const std::string& solver)
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

    // summary table: swept values, outputs at report times, efficiencies
    const Results& first = runs.front().results;
    std::vector<double> times = first.cas.reportTimes;
    if (times.empty() || times.back() < first.t.back()) times.push_back(first.t.back());
    auto names = plotSpecies(first);
    names.push_back("TOC");
    std::vector<std::string> header;
    for (const auto& d : dims) header.push_back(shortKey(d.key));
    for (double ts : times)
        for (const auto& n : names)
            header.push_back(n + "_at_" + num(ts / 3600.0) + "h_" + (n == "TOC" ? "mgC_per_L" : "mg_per_L"));
    header.push_back("TOC_half_time_h");
    header.push_back("J_TOC_mol_per_J");
    std::filesystem::create_directories(dir);
    {
        CsvWriter csv(dir + "/sweep_summary.csv", header);
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
    if (!plots) return runs;

    // family plots: each quantity vs time, one curve per run
    const auto& sp = first.cas.mech.species;
    for (const auto& n : names)
    {
        const std::size_t col = n == "TOC" ? 3 + 2 * sp.size() : 3 + first.cas.mech.index(n, "plot");
        std::ostringstream gp;
        gp << "set termoption noenhanced\nset datafile separator ','\nset grid\nset key outside right\nset xlabel 'time (h)'\nset ylabel '" << n
           << (n == "TOC" ? " (mg C/L)" : " (mg/L)") << "'\nset title '" << first.cas.title << ": " << n << "'\nplot ";
        for (std::size_t k = 0; k < runs.size(); ++k)
            gp << (k ? ", " : "") << "'" << dir << "/" << runs[k].label << "/timeseries.csv' using 1:" << col
               << " with lines lw 2 title '" << runs[k].label << "'";
        gp << '\n';
        plotPng(dir + "/family_" + n + ".png", gp.str());
    }
    // values at report times against the last swept key (one curve per value of the first)
    const std::size_t nd = dims.size();
    const std::size_t xCol = nd;   // 1-based column of the last swept key
    for (std::size_t it = 0; it < times.size(); ++it)
        for (std::size_t q = 0; q < names.size(); ++q)
        {
            const std::size_t col = nd + 1 + it * names.size() + q;
            std::ostringstream gp;
            gp << "set termoption noenhanced\nset datafile separator ','\nset grid\nset key outside right\nset xlabel '" << shortKey(dims.back().key)
               << "'\nset ylabel '" << names[q] << " at " << num(times[it] / 3600.0) << " h'\nset title '" << first.cas.title
               << "'\n";
            if (nd == 1)
                gp << "plot '" << dir << "/sweep_summary.csv' using " << xCol << ":" << col << " with linespoints lw 2 pt 7 notitle\n";
            else
            {
                gp << "plot ";
                const auto& d0 = dims.front();
                for (std::size_t k = 0; k < d0.values.size(); ++k)
                    gp << (k ? ", " : "") << "'" << dir << "/sweep_summary.csv' using ($1==" << num(d0.values[k]) << "?$" << xCol
                       << ":1/0):" << col << " with linespoints lw 2 pt 7 title '" << shortKey(d0.key) << "=" << num(d0.values[k]) << "'";
                gp << '\n';
            }
            plotPng(dir + "/sweep_" + names[q] + "_at_" + num(times[it] / 3600.0) + "h.png", gp.str());
        }
    return runs;
}

std::vector<SensitivityRow> sensitivity(const CaseSource& src, const Overrides& set, std::vector<std::string> parameters,
                                        std::vector<std::string> outputs, double time, double change)
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
        if (ri == std::string::npos) throw InputError(base.mech.file + ": no reaction with id '" + p + "' (sensitivity parameter)");
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
                    if (std::fabs(s0[i]) < 1e-3 * peak) continue;   // skip near-zero values
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
    std::ostringstream os;
    os << "deviation (%) of each output when one rate constant changes (at the chosen time; [largest over the run])\n";
    os << std::setw(8) << "param" << std::setw(8) << "change";
    std::vector<std::string> outs;
    for (const auto& r : rows)
    {
        if (std::find(outs.begin(), outs.end(), r.output) != outs.end()) break;
        outs.push_back(r.output);
    }
    for (const auto& o : outs) os << std::setw(20) << o;
    os << '\n';
    for (std::size_t i = 0; i < rows.size(); i += outs.size())
    {
        os << std::setw(8) << rows[i].parameter << std::setw(7) << std::showpos << std::setprecision(3)
           << rows[i].change * 100 << "%" << std::noshowpos;
        for (std::size_t k = 0; k < outs.size(); ++k)
        {
            std::ostringstream cell;
            cell << std::fixed << std::setprecision(2) << rows[i + k].deviation * 100 << " [" << rows[i + k].maxDeviation * 100
                 << "]";
            os << std::setw(20) << cell.str();
        }
        os << '\n';
    }
    return os.str();
}

void writeSensitivity(const std::vector<SensitivityRow>& rows, const std::string& dir)
{
    std::filesystem::create_directories(dir);
    CsvWriter csv(dir + "/sensitivity.csv", {"parameter", "change_percent", "output", "base_value", "perturbed_value",
                                             "deviation_percent", "max_deviation_percent", "max_deviation_time_h"});
    for (const auto& r : rows)
        csv.row(std::vector<std::string>{r.parameter, num(r.change * 100), r.output, num(r.base), num(r.perturbed),
                                         num(r.deviation * 100), num(r.maxDeviation * 100), num(r.maxDeviationTime / 3600.0)});
    csv.close();
}

} // namespace procsim::kinetics
