#include "CartesianMesh.hpp"

#include "InputError.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace spoutlab
{

namespace
{

void checkFaces(const std::vector<double>& f, const char* direction)
{
    bool ok = f.size() >= 2;
    for (std::size_t n = 0; ok && n < f.size(); ++n)
    {
        ok = std::isfinite(f[n]) && (n == 0 || f[n] > f[n - 1]);
    }
    if (!ok)
    {
        throw InputError(std::string("CartesianMesh: ") + direction
                         + " faces must be at least two strictly increasing numbers");
    }
}

// Interval index of c among the faces f, or -1 outside [f.front(), f.back()].
label interval(const std::vector<double>& f, double c)
{
    if (!(c >= f.front() && c <= f.back())) return -1; // also rejects NaN
    if (c == f.back()) return static_cast<label>(f.size()) - 2;
    // upper_bound gives the first face strictly above c, so a point on an
    // interior face lands in the interval that starts there (+ side owns it).
    return static_cast<label>(std::upper_bound(f.begin(), f.end(), c) - f.begin()) - 1;
}

std::vector<double> evenFaces(double lo, double hi, int n)
{
    std::vector<double> f(n > 0 ? n + 1 : 0);
    for (int i = 0; i <= n && n > 0; ++i) f[i] = lo + (hi - lo) * i / n;
    if (n > 0) f[n] = hi; // exact end, not lo + (hi - lo) * n / n with round-off
    return f;
}

} // namespace

CartesianMesh::CartesianMesh(std::vector<double> xFaces, std::vector<double> yFaces,
                             std::vector<double> zFaces)
    : xf_(std::move(xFaces)), yf_(std::move(yFaces)), zf_(std::move(zFaces))
{
    checkFaces(xf_, "x");
    checkFaces(yf_, "y");
    checkFaces(zf_, "z");
}

CartesianMesh CartesianMesh::uniform(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz)
{
    return CartesianMesh(evenFaces(lo.x, hi.x, nx), evenFaces(lo.y, hi.y, ny), evenFaces(lo.z, hi.z, nz));
}

label CartesianMesh::nCells() const
{
    return nx() * ny() * nz();
}

CartesianMesh::Ijk CartesianMesh::ijk(label cell) const
{
    return {cell % nx(), (cell / nx()) % ny(), cell / (nx() * ny())};
}

Vec3 CartesianMesh::cellLower(label cell) const
{
    const Ijk c = ijk(cell);
    return {xf_[c.i], yf_[c.j], zf_[c.k]};
}

Vec3 CartesianMesh::cellUpper(label cell) const
{
    const Ijk c = ijk(cell);
    return {xf_[c.i + 1], yf_[c.j + 1], zf_[c.k + 1]};
}

Vec3 CartesianMesh::cellCentre(label cell) const
{
    return 0.5 * (cellLower(cell) + cellUpper(cell));
}

double CartesianMesh::cellVolume(label cell) const
{
    const Vec3 size = cellUpper(cell) - cellLower(cell);
    return size.x * size.y * size.z;
}

// Binary search per direction is already O(log n), so the hint is not needed.
label CartesianMesh::findCell(const Vec3& p, label /*hint*/) const
{
    const label i = interval(xf_, p.x);
    const label j = interval(yf_, p.y);
    const label k = interval(zf_, p.z);
    if (i < 0 || j < 0 || k < 0) return -1;
    return cellIndex(i, j, k);
}

bool CartesianMesh::sphereInsideCell(label cell, const Vec3& c, double r) const
{
    const Vec3 lo = cellLower(cell);
    const Vec3 hi = cellUpper(cell);
    return c.x - r >= lo.x && c.x + r <= hi.x && c.y - r >= lo.y && c.y + r <= hi.y && c.z - r >= lo.z
           && c.z + r <= hi.z;
}

// Inside a cell: the distance to its nearest face (a point on a face has
// none: the half-open intervals give it to the + side). Outside the box: the
// largest distance beyond it along one axis, which keeps it outside.
double CartesianMesh::clearance(const Vec3& p, label cell) const
{
    const Vec3 lo{xf_.front(), yf_.front(), zf_.front()};
    const Vec3 hi{xf_.back(), yf_.back(), zf_.back()};
    if (cell < 0)
    {
        const double beyond[3] = {std::max(lo.x - p.x, p.x - hi.x), std::max(lo.y - p.y, p.y - hi.y),
                                  std::max(lo.z - p.z, p.z - hi.z)};
        return std::max(0.0, std::max(beyond[0], std::max(beyond[1], beyond[2])));
    }
    const Vec3 a = cellLower(cell), b = cellUpper(cell);
    return std::max(0.0, std::min({p.x - a.x, b.x - p.x, p.y - a.y, b.y - p.y, p.z - a.z, b.z - p.z}));
}

} // namespace spoutlab
