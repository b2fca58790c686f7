#include "common/Plot.hpp"

#include <cstdio>
#include <iostream>

#include "common/Csv.hpp"
#include "common/Format.hpp"

namespace procsim
{

namespace
{

// gnuplot's single-quoted string: only a quote needs escaping, by doubling it.
std::string quoted(const std::string& text)
{
    std::string q = "'";
    for (char ch : text) q += ch == '\'' ? std::string("''") : std::string(1, ch);
    return q + "'";
}

bool drawPng(const std::string& png, const std::string& script, int width, int height)
{
    FILE* gp = popen("gnuplot 2>/dev/null", "w");
    if (!gp)
    {
        std::cerr << "procsim: warning: gnuplot not available, " << png << " not drawn\n";
        return false;
    }
    const std::string tmp = png + ".tmp";
    std::fprintf(gp, "set terminal pngcairo size %d,%d font 'Sans,11'\nset output %s\n%s\nset output\n",
                 width, height, quoted(tmp).c_str(), script.c_str());
    const int status = pclose(gp);
    if (status != 0 || std::rename(tmp.c_str(), png.c_str()) != 0)
    {
        std::remove(tmp.c_str());
        std::cerr << "procsim: warning: gnuplot failed drawing " << png << '\n';
        return false;
    }
    return true;
}

bool drawWhenCommitted(const std::string& png, const std::string& script, int width, int height)
{
    if (!OutputBatch::open()) return drawPng(png, script, width, height);
    // the data files the script reads are staged too: draw once they are in place
    OutputBatch::defer([=] { drawPng(png, script, width, height); });
    return true;
}

} // namespace

PlotVariables& PlotVariables::set(const std::string& name, const std::string& text)
{
    script_ += name + " = " + quoted(text) + "\n";
    return *this;
}

PlotVariables& PlotVariables::set(const std::string& name, double value)
{
    script_ += name + " = " + formatNumber(value, 17) + "\n";
    return *this;
}

bool plotPng(const std::string& png, std::string_view script, const PlotVariables& variables, int width,
             int height)
{
    // CSV input; underscores in names printed as they are, not as subscripts
    const std::string shared = "set termoption noenhanced\nset datafile separator ','\n";
    return drawWhenCommitted(png, variables.script() + shared + std::string(script), width, height);
}

} // namespace procsim
