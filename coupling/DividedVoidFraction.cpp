#include "DividedVoidFraction.hpp"

#include "SphereSampling.hpp"

#include <algorithm>
#include <cmath>

namespace spoutlab
{

// selected by "voidFractionModel divided;"
const Registration<VoidFractionModel, DividedVoidFraction> registeredDividedVoidFraction("divided");

namespace
{

// Rodrigues' rotation of v about the unit axis k by angle theta.
Vec3 rotate(const Vec3& v, const Vec3& k, double theta)
{
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0 - c));
}

// A fixed oblique orientation, picked by scanning simple axes and angles:
// with the default 30 points it keeps every centroid more than 0.05 radius
// from the axis-parallel planes through the centre, and the share of a
// particle on either side of an axis-aligned face stays within 0.07 of the
// exact spherical-cap fraction wherever the face cuts the sphere.
Vec3 obliqueOrientation(const Vec3& v)
{
    const Vec3 axis{3.0, 1.0, 2.0};
    return rotate(v, axis / mag(axis), 1.7);
}

int positiveCount(const Parameters& props, const char* key, long defaultValue)
{
    const long n = props.getInteger(key, defaultValue);
    if (n < 1 || n > 1000) throw props.badValue(key, "an integer from 1 to 1000");
    return static_cast<int>(n);
}

} // namespace

DividedVoidFraction::DividedVoidFraction(const Parameters& props) : VoidFractionModel(props)
{
    const int nShells = positiveCount(props, "nShells", 3);
    const int nRings = positiveCount(props, "nRings", 2);
    const int nAzimuthal = positiveCount(props, "nAzimuthal", 4);
    for (const BallSector& s : equalVolumeSectors(nShells, nRings, nAzimuthal))
    {
        samples_.push_back(obliqueOrientation(s.centroid()));
    }
}

double DividedVoidFraction::distribute(const CellLocator& mesh, const Particle& p, label centreCell,
                                       std::vector<CellWeight>& row) const
{
    // The row lasts while the centre stays in its cell and every piece in
    // the cell it is in now (outside the mesh included): the smallest of
    // their clearances.
    double clearance = mesh.clearance(p.x, centreCell);
    if (mesh.sphereInsideCell(centreCell, p.x, p.radius))
    {
        row.push_back({centreCell, 1.0});
        return std::max(0.0, clearance - p.radius); // and the sphere inside it
    }
    // Count pieces per cell first and divide once, so the weights are exact
    // ratios count/N whose sum is 1 to round-off. A particle touches few cells,
    // so a linear search of row is the fastest lookup.
    thread_local std::vector<label> cells; // reused: one call per particle and step
    mesh.findCells(p.x, p.radius, samples_, centreCell, cells);
    if (clearance > 0) clearance = std::min(clearance, mesh.clearance(p.x, p.radius, samples_, cells));
    for (label cell : cells)
    {
        if (cell < 0) cell = centreCell;
        auto it = row.begin();
        while (it != row.end() && it->cell != cell) ++it;
        if (it == row.end())
        {
            row.push_back({cell, 1.0});
        }
        else
        {
            it->weight += 1.0;
        }
    }
    const double n = static_cast<double>(samples_.size());
    for (CellWeight& cw : row) cw.weight /= n;
    return clearance;
}

} // namespace spoutlab
