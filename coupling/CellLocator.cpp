#include "CellLocator.hpp"

#include <algorithm>

namespace spoutlab
{

CellLocator::~CellLocator() = default;

void CellLocator::findCells(const Vec3& centre, double radius, const std::vector<Vec3>& units,
                            label centreCell, std::vector<label>& cells) const
{
    cells.resize(units.size());
    for (std::size_t k = 0; k < units.size(); ++k)
    {
        cells[k] = findCell(centre + units[k] * radius, centreCell);
    }
}

double CellLocator::clearance(const Vec3&, label) const
{
    return 0.0;
}

double CellLocator::clearance(const Vec3& centre, double radius, const std::vector<Vec3>& units,
                              const std::vector<label>& cells) const
{
    double smallest = 1e300;
    for (std::size_t k = 0; k < units.size() && smallest > 0; ++k)
    {
        smallest = std::min(smallest, clearance(centre + units[k] * radius, cells[k]));
    }
    return smallest;
}

void CellLocator::complete(std::vector<double>&, int) const {}

void completeVectors(const CellLocator& mesh, std::vector<Vec3>& values)
{
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three doubles");
    std::vector<double> flat(3 * values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        flat[3 * i] = values[i].x;
        flat[3 * i + 1] = values[i].y;
        flat[3 * i + 2] = values[i].z;
    }
    mesh.complete(flat, 3);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        values[i] = Vec3{flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
    }
}

} // namespace spoutlab
