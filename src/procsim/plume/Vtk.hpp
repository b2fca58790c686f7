#pragma once
// ParaView output of the terrain-following grid: one .vts (XML structured
// grid) per snapshot and a .pvd collection that lists them with their times.
#include <string>
#include <utility>
#include <vector>

namespace procsim::plume
{

class TerrainGrid;

void writeVts(const std::string& path, const TerrainGrid& grid, const std::string& fieldName,
              const std::vector<double>& cellValues);
// entries: (time, file name relative to the .pvd)
void writePvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries);

} // namespace procsim::plume
