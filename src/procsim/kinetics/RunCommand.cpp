// procsim kinetics run: one case, or a sweep of it over one or two inputs.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/Checked.hpp"
#include "common/CommandLine.hpp"
#include "common/Format.hpp"
#include "kinetics/Case.hpp"
#include "kinetics/Commands.hpp"
#include "kinetics/Run.hpp"
#include "kinetics/Study.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

struct RunArgs
{
    std::string file;
    std::string output; // empty: <case name>_out
    Overrides set;
    std::vector<SweepDim> sweeps;
    std::string solver; // empty: the case's
    bool noPlots = false, quiet = false, noSweep = false;
};

std::optional<RunArgs> parse(int argc, char** argv)
{
    RunArgs a;
    std::vector<std::string> sweeps, sets;
    CommandLine cl("kinetics run", std::string(texts::help::run) + "\n" + std::string(texts::help::format));
    cl.input(a.file, "case file");
    cl.text("-o,--output", a.output);
    cl.list("--sweep", sweeps);
    cl.list("--set", sets);
    cl.text("--solver", a.solver);
    cl.flag("--no-sweep", a.noSweep);
    cl.flag("--no-plots", a.noPlots);
    cl.flag("-q,--quiet", a.quiet);
    if (!cl.parse(argc, argv)) return std::nullopt;
    if (!a.solver.empty() && a.solver != "expm" && a.solver != "rk4" && a.solver != "cvode")
        throw cl.refuse("--solver", "expm, rk4 or cvode", a.solver);
    for (const auto& s : sweeps) a.sweeps.push_back(parseSweep(s));
    a.set = parseSetOptions(sets, cl.command());
    rejectDuplicates(a.sweeps, &SweepDim::key, "kinetics run", "--sweep key");
    return a;
}

// The one-screen table of a sweep: swept values, then every plotted
// quantity and the TOC half time at the last report time.
void printSweep(const std::vector<SweepRun>& runs, const std::vector<SweepDim>& sweeps)
{
    const Results& r0 = runs.front().results;
    const double tEnd = r0.cas.reportTimes.empty() ? r0.t.back() : r0.cas.reportTimes.back();
    auto names = plotSpecies(r0);
    names.push_back("TOC");
    fmt::print("sweep of {}: values at {} h (mg/L; TOC mg C/L)\n ", r0.cas.title,
               formatNumber(tEnd / 3600.0));
    for (const auto& d : sweeps) fmt::print("{:>16}", shortKey(d.key));
    for (const auto& n : names) fmt::print("{:>10}", n);
    fmt::print("{:>10}\n", "t_1/2 h");
    for (const auto& run : runs)
    {
        fmt::print(" ");
        for (const auto& kv : run.values) fmt::print("{:>16}", formatNumber(kv.second));
        for (const auto& n : names) fmt::print("{:>10}", formatNumber(run.results.value(n, tEnd), 4));
        fmt::print("{:>10}\n", run.eff.halfReached ? formatNumber(run.eff.tHalf / 3600.0, 4) : "-");
    }
}

void runOne(const Case& c, const RunArgs& a, const std::string& dir)
{
    const Results r = runCase(c);
    const Efficiency e = efficiency(r);
    writeRun(r, e, dir, !a.noPlots);
    fmt::print("{}  output: {}/\n", summaryText(r, e), dir);
}

} // namespace

Overrides parseSetOptions(const std::vector<std::string>& words, const std::string& command)
{
    Overrides set;
    for (const auto& w : words)
    {
        const SweepDim d = parseSweep(w); // KEY=VALUE is a sweep of one value
        if (d.values.size() != 1)
            throw InputError(command + ": option --set expected KEY=VALUE (one value), got '" + w + "'");
        set.emplace_back(d.key, d.values[0]);
    }
    rejectDuplicates(set, &Override::first, command, "--set key");
    return set;
}

int runCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const CaseSource src = CaseSource::load(args->file);
    Case c = src.build(args->set);
    const std::string dir =
        args->output.empty() ? std::filesystem::path(src.file()).stem().string() + "_out" : args->output;
    std::vector<SweepDim> sweeps = args->sweeps;
    if (sweeps.empty() && !args->noSweep) sweeps = c.sweep;
    if (!args->solver.empty()) c.solver.method = args->solver;
    if (sweeps.empty())
    {
        runOne(c, *args, dir);
        return 0;
    }
    if (sweeps.size() > 2) throw InputError("kinetics run: at most two --sweep keys");
    const auto runs = runSweep(src, args->set, sweeps, dir, !args->noPlots, args->quiet, args->solver);
    printSweep(runs, sweeps);
    fmt::print("{} runs; table: {}/sweep_summary.csv", runs.size(), dir);
    if (!args->noPlots) fmt::print(", plots: {}/family_*.png, {}/sweep_*.png", dir, dir);
    fmt::print("\n");
    return 0;
}

} // namespace procsim::kinetics
