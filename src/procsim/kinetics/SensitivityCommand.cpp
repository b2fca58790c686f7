// procsim kinetics sensitivity: every chosen rate constant changed by
// +-change, the deviation of each output (the paper's Table S1).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Format.hpp"
#include "kinetics/Case.hpp"
#include "kinetics/Commands.hpp"
#include "kinetics/Study.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

struct SensitivityArgs
{
    std::string file;
    std::string output; // empty: <case name>_sensitivity
    Overrides set;
    std::string params, outputs; // comma-separated; empty: the case's or the defaults
    std::optional<double> timeH, changePercent;
};

std::vector<std::string> splitCommas(const std::string& s)
{
    std::vector<std::string> out;
    std::string cur;
    for (char ch : s + ",")
    {
        if (ch != ',')
            cur += ch;
        else if (!cur.empty())
            out.push_back(cur), cur.clear();
    }
    return out;
}

std::optional<SensitivityArgs> parse(int argc, char** argv)
{
    SensitivityArgs a;
    std::vector<std::string> sets;
    CommandLine cl("kinetics sensitivity", std::string(texts::help::sensitivity));
    cl.input(a.file, "case file");
    cl.text("-o,--output", a.output);
    cl.text("--params", a.params);
    cl.text("--outputs", a.outputs);
    cl.number("--time-h", a.timeH);
    cl.number("--change-percent", a.changePercent);
    cl.list("--set", sets);
    if (!cl.parse(argc, argv)) return std::nullopt;
    if (a.timeH && !(*a.timeH > 0)) throw cl.refuse("--time-h", "a time above 0 [h]", formatNumber(*a.timeH));
    if (a.changePercent && !(*a.changePercent > 0 && *a.changePercent < 100))
        throw cl.refuse("--change-percent", "a number above 0 and below 100 [%]",
                        formatNumber(*a.changePercent));
    a.set = parseSetOptions(sets, cl.command());
    return a;
}

} // namespace

int sensitivityCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const CaseSource src = CaseSource::load(args->file);
    // 0: not given, the case's value or the default
    const auto rows = sensitivity(src, args->set, splitCommas(args->params), splitCommas(args->outputs),
                                  args->timeH.value_or(0) * 3600.0, args->changePercent.value_or(0) / 100.0);
    const std::string dir = args->output.empty()
                                ? std::filesystem::path(src.file()).stem().string() + "_sensitivity"
                                : args->output;
    writeSensitivity(rows, dir);
    fmt::print("{}  output: {}/sensitivity.csv\n", sensitivityTable(rows), dir);
    return 0;
}

} // namespace procsim::kinetics
