#include "common/Plot.hpp"

#include <cstdio>
#include <iostream>

namespace procsim
{

bool plotPng(const std::string& png, const std::string& script, int width, int height)
{
    FILE* gp = popen("gnuplot 2>/dev/null", "w");
    if (!gp)
    {
        std::cerr << "procsim: warning: gnuplot not available, " << png << " not drawn\n";
        return false;
    }
    std::fprintf(gp, "set terminal pngcairo size %d,%d font 'Sans,11'\nset output '%s'\n%s\n",
                 width, height, png.c_str(), script.c_str());
    const int status = pclose(gp);
    if (status != 0)
    {
        std::cerr << "procsim: warning: gnuplot failed drawing " << png << '\n';
        return false;
    }
    return true;
}

} // namespace procsim
