#include "plume/Vtk.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStructuredGrid.h>

#include "VtkXmlFile.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "plume/Eulerian.hpp"

namespace procsim::plume
{

namespace
{

// Terrain at the column corners: the mean of the columns that share the corner
std::vector<double> cornerTerrain(const TerrainGrid& g)
{
    std::vector<double> h(static_cast<std::size_t>(g.nx + 1) * (g.ny + 1));
    for (int j = 0; j <= g.ny; ++j)
        for (int i = 0; i <= g.nx; ++i)
        {
            double sum = 0;
            int n = 0;
            for (int jj = std::max(j - 1, 0); jj <= std::min(j, g.ny - 1); ++jj)
                for (int ii = std::max(i - 1, 0); ii <= std::min(i, g.nx - 1); ++ii)
                {
                    sum += g.hc[g.col(ii, jj)];
                    ++n;
                }
            h[static_cast<std::size_t>(j) * (g.nx + 1) + i] = sum / n;
        }
    return h;
}

// The terrain-following cell corners: level k sits at the fraction fFace[k]
// of the way from the ground to the lid
vtkSmartPointer<vtkPoints> cornerPoints(const TerrainGrid& g)
{
    const std::vector<double> h = cornerTerrain(g);
    auto xyz = spoutlab::vtkxml::doubleArray("", 3, h.size() * (g.nz + 1));
    vtkIdType n = 0;
    for (int k = 0; k <= g.nz; ++k)
        for (int j = 0; j <= g.ny; ++j)
            for (int i = 0; i <= g.nx; ++i)
            {
                const double hij = h[static_cast<std::size_t>(j) * (g.nx + 1) + i];
                xyz->SetTuple3(n++, g.x0 + i * g.dx, g.y0 + j * g.dy, hij + (g.zTop - hij) * g.fFace[k]);
            }
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(xyz);
    return points;
}

} // namespace

void writeVts(const std::string& path, const TerrainGrid& g, const std::string& fieldName,
              const std::vector<double>& v)
{
    if (v.size() != g.size())
        throw std::logic_error(path + ": " + std::to_string(v.size()) + " cell values for a grid of "
                               + std::to_string(g.size()) + " cells");
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(g.nx + 1, g.ny + 1, g.nz + 1);
    grid->SetPoints(cornerPoints(g));
    // VTK's cell order (i fastest, then j, then k) is the grid's own idx(i, j, k)
    auto field = spoutlab::vtkxml::floatArray(fieldName, 1, v.size());
    for (std::size_t n = 0; n < v.size(); ++n) field->SetValue(static_cast<vtkIdType>(n), float(v[n]));
    grid->GetCellData()->SetScalars(field);
    // staged like every procsim output: in place only when the command succeeds
    const std::string tmp = path + ".tmp";
    try
    {
        spoutlab::vtkxml::write(grid, tmp);
    }
    catch (const std::runtime_error&)
    {
        std::remove(tmp.c_str());
        throw InputError(path + ": cannot be written");
    }
    OutputBatch::stage(tmp, path);
}

void writePvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries)
{
    writeTextFile(path, spoutlab::vtkxml::collection(entries));
}

} // namespace procsim::plume
