#pragma once
// PNG plots through gnuplot (Debian's gnuplot-nox): the caller writes the
// data as CSV; the gnuplot script is a file of its own (embedded at build
// time, see cmake/EmbedTexts.cmake) that reads what changes from run to run
// (file names, titles, column numbers) as gnuplot variables.
#include <string>
#include <string_view>

namespace procsim
{

// Variables set before a script runs: `csv = 'out/a.csv'`, `ncurves = 3`.
class PlotVariables
{
public:
    PlotVariables& set(const std::string& name, const std::string& text);
    PlotVariables& set(const std::string& name, const char* text) { return set(name, std::string(text)); }
    PlotVariables& set(const std::string& name, double value);
    const std::string& script() const { return script_; }

private:
    std::string script_;
};

// Every script is preceded by its variables and the settings all procsim
// plots share (CSV input, names printed as they are).  Drawn through
// "<png>.tmp"; inside an OutputBatch the drawing waits until the batch
// commits (the data it plots is in place then) and returns true.  Returns
// false (and prints a warning) if gnuplot is missing or fails; plots are a
// convenience, the CSV is the result.
bool plotPng(const std::string& png, std::string_view script, const PlotVariables& variables, int width = 900,
             int height = 600);

} // namespace procsim
