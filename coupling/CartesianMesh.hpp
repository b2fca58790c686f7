#pragma once
// A structured box mesh from three strictly increasing lists of face
// coordinates (so graded spacing works). Cells are numbered i + nx (j + ny k).
// Ownership of points on faces: intervals are half-open [x_i, x_i+1), so a
// point on an interior face belongs to the cell on the + side; the last face in
// each direction is closed so the whole box, boundary included, is inside.

#include "CellLocator.hpp"

#include <vector>

namespace spoutlab
{

class CartesianMesh : public CellLocator
{
public:
    // Throws InputError unless each list has at least two strictly increasing,
    // finite coordinates.
    CartesianMesh(std::vector<double> xFaces, std::vector<double> yFaces, std::vector<double> zFaces);

    // n equal cells per direction between lo and hi.
    static CartesianMesh uniform(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz);

    label nCells() const override;
    double cellVolume(label cell) const override;
    label findCell(const Vec3& p, label hint) const override;
    bool sphereInsideCell(label cell, const Vec3& centre, double radius) const override;
    using CellLocator::clearance; // and the samples' (from the point's)
    double clearance(const Vec3& p, label cell) const override;

    label nx() const { return static_cast<label>(xf_.size()) - 1; }
    label ny() const { return static_cast<label>(yf_.size()) - 1; }
    label nz() const { return static_cast<label>(zf_.size()) - 1; }
    label cellIndex(label i, label j, label k) const { return i + nx() * (j + ny() * k); }

    Vec3 cellLower(label cell) const;
    Vec3 cellUpper(label cell) const;
    Vec3 cellCentre(label cell) const;

private:
    struct Ijk
    {
        label i, j, k;
    };
    Ijk ijk(label cell) const;

    std::vector<double> xf_, yf_, zf_;
};

} // namespace spoutlab
