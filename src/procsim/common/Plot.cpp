#include "common/Plot.hpp"

#include <cstdio>
#include <iostream>

#include "common/Csv.hpp"

namespace procsim
{

namespace
{

bool drawPng(const std::string& png, const std::string& script, int width, int height)
{
    FILE* gp = popen("gnuplot 2>/dev/null", "w");
    if (!gp)
    {
        std::cerr << "procsim: warning: gnuplot not available, " << png << " not drawn\n";
        return false;
    }
    const std::string tmp = png + ".tmp";
    std::fprintf(gp, "set terminal pngcairo size %d,%d font 'Sans,11'\nset output '%s'\n%s\nset output\n",
                 width, height, tmp.c_str(), script.c_str());
    const int status = pclose(gp);
    if (status != 0 || std::rename(tmp.c_str(), png.c_str()) != 0)
    {
        std::remove(tmp.c_str());
        std::cerr << "procsim: warning: gnuplot failed drawing " << png << '\n';
        return false;
    }
    return true;
}

} // namespace

bool plotPng(const std::string& png, const std::string& script, int width, int height)
{
    if (!OutputBatch::open()) return drawPng(png, script, width, height);
    // the data files the script reads are staged too: draw once they are in place
    OutputBatch::defer([=] { drawPng(png, script, width, height); });
    return true;
}

} // namespace procsim
