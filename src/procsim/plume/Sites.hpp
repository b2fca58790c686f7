#pragma once
// Sources and receptors as written in the case YAML (shared by the Eulerian
// and the Gaussian models).
//
// sources:
//   - {name: Q1, type: area,   x_m: 1200, y_m: 800, size_m: [300, 200], height_m: 2, rate_g_s: 15}
//   - {name: Q2, type: volume, x_m: ..., y_m: ..., size_m: [60, 60], bottom_m: 0, top_m: 12, rate_g_s: 4}
//   - {name: S1, type: point,  x_m: ..., y_m: ..., height_m: 20, rate_g_s: 2}
//   optional on each: controlled: false   (the emission reduction does not apply)
// receptors:
//   - {name: P1, x_m: 1500, y_m: 2300, height_m: 10}
#include <string>
#include <vector>

#include "common/YamlInput.hpp"

namespace procsim::plume
{

struct Source
{
    enum class Type
    {
        Point,
        Area,
        Volume
    };
    std::string name;
    Type type = Type::Area;
    double x = 0, y = 0;        // centre [m]
    double lx = 0, ly = 0;      // horizontal size [m] (area, volume)
    double height = 0;          // release height above ground (point, area) [m]
    double bottom = 0, top = 0; // vertical extent above ground (volume) [m]
    double rate = 0;            // emission [kg/s]
    bool controlled = true;     // subject to the scenario's emission reduction
    std::string where;          // "file: sources[2]" for messages
};

struct Receptor
{
    std::string name;
    double x = 0, y = 0, height = 0; // m, height above ground
    std::string where;
};

std::vector<Source> parseSources(const YamlInput& list);
std::vector<Receptor> parseReceptors(const YamlInput& list);

} // namespace procsim::plume
