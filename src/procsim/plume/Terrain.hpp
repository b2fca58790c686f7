#pragma once
// Terrain elevations on a regular grid, read from an ESRI ASCII grid (.asc).
#include <string>
#include <vector>

namespace procsim::plume
{

struct EsriGrid
{
    int ncols = 0;
    int nrows = 0;
    double xll = 0;        // x of the lower-left corner of the lower-left cell [m]
    double yll = 0;        // y of that corner [m]
    double cell = 0;       // cell size [m]
    std::vector<double> z; // elevations [m], row 0 = southernmost, column fastest

    double at(int col, int row) const { return z[static_cast<std::size_t>(row) * ncols + col]; }
    double xmax() const { return xll + ncols * cell; }
    double ymax() const { return yll + nrows * cell; }
    // Bilinear interpolation between cell centres (clamped at the edges).
    double sample(double x, double y) const;
};

// Reads an ESRI ASCII grid; any defect is a one-line InputError naming the
// file, the line and what was expected.
EsriGrid readEsriGrid(const std::string& path);
void writeEsriGrid(const std::string& path, const EsriGrid& grid);

} // namespace procsim::plume
