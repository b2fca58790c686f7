#pragma once
// The `procsim plume eulerian` case: its YAML input, the grid it asks for,
// its sources on that grid (the command is plume/EulerianCommand.cpp).
#include <memory>
#include <string>
#include <vector>

#include "plume/Eulerian.hpp"
#include "plume/Met.hpp"
#include "plume/Sites.hpp"
#include "plume/Terrain.hpp"

namespace procsim::plume
{

struct Scenario
{
    std::string name;
    double kH = 200, kV = 1; // m^2/s
    double reduction = 0;    // fraction of the controlled emissions removed (0.8 = the paper's cut)
};

struct EulerianCase
{
    std::string file; // the YAML
    std::string dir;  // its directory (relative paths start here)
    EsriGrid terrain;
    double cellSize = 0; // m
    int levels = 12;
    double topAboveHighest = 600; // m
    double stretching = 2.0;
    Advection advection = Advection::LimitedQuick;
    bool implicitVertical = true;
    bool trueHorizontal = false; // K_H along the terrain-following surfaces
    double exponent = 0.25, zRef = 10;
    double dt = 0; // s, 0 = automatic
    double cflFraction = 0.9;
    double backgroundUgM3 = 0;
    double standardUgM3 = 120;
    int vtsEveryHours = 6;
    // measured 24-h averages (output.measured_24h): per receptor, (day, value)
    std::vector<std::vector<std::pair<int, double>>> measured24h;
    MetSeries met;
    std::vector<Source> sources;
    std::vector<Receptor> receptors;
    std::vector<Scenario> scenarios;

    std::unique_ptr<TerrainGrid> makeGrid() const;
};

EulerianCase loadEulerianCase(const std::string& path);

// Emission per cell [kg/s]; sources outside the grid or above the lid are
// InputErrors.  Controlled sources are multiplied by (1 - reduction).
std::vector<double> distributeSources(const TerrainGrid& g, const std::vector<Source>& sources,
                                      double reduction);
void checkReceptors(const TerrainGrid& g, const std::vector<Receptor>& receptors);

struct ScenarioResult
{
    std::vector<std::vector<double>> hourly;          // [receptor][hour], 1-h averages [ug/m3]
    std::vector<double> groundMean;                   // run-average of the lowest cell layer [ug/m3]
    double emitted = 0, inDomain = 0, leftDomain = 0; // kg, for the mass balance
    double dtMin = 0, dtMax = 0;
    long steps = 0;
};

} // namespace procsim::plume
