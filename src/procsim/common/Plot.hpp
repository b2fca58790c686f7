#pragma once
// PNG plots through gnuplot (Debian's gnuplot-nox): the caller writes the
// data as CSV and a gnuplot script body; this adds the terminal and output.
#include <string>

namespace procsim
{

// Drawn through "<png>.tmp"; inside an OutputBatch the drawing waits until the
// batch commits (the data it plots is in place then) and returns true.
// Returns false (and prints a warning) if gnuplot is missing or fails;
// plots are a convenience, the CSV is the result.
bool plotPng(const std::string& png, const std::string& gnuplotScript,
             int width = 900, int height = 600);

} // namespace procsim
