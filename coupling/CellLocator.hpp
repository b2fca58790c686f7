#pragma once
// What the coupling needs to know about the gas mesh, and nothing more. The
// OpenFOAM solver implements it on its polyMesh; the unit tests use
// CartesianMesh. Keeping it this small is what lets the physics core be
// tested without OpenFOAM.

#include "Vec3.hpp"

#include <vector>

namespace spoutlab
{

using label = long;

class CellLocator
{
public:
    virtual ~CellLocator();

    virtual label nCells() const = 0;
    virtual double cellVolume(label cell) const = 0;

    // The cell containing p, or -1 if p is outside the mesh. hint is a nearby
    // cell (or -1): meshes that search by walking start there.
    virtual label findCell(const Vec3& p, label hint) const = 0;

    // True if the whole sphere lies inside this cell. Lets the void-fraction
    // models skip sampling for the common case of a particle well inside a cell;
    // a conservative "false" is always allowed.
    virtual bool sphereInsideCell(label cell, const Vec3& centre, double radius) const = 0;

    // The cells of the points centre + radius * units[k], each as findCell
    // with the centre's cell as hint (the sample points of a divided
    // particle). Meshes may skip the search for points that cannot have left
    // the centre's cell; the answers must be findCell's.
    virtual void findCells(const Vec3& centre, double radius, const std::vector<Vec3>& units,
                           label centreCell, std::vector<label>& cells) const;

    // How far p may move, in any direction, before findCell with cell as
    // hint could answer other than cell, findCell's answer for p (-1, outside
    // the mesh, included). Lets a particle keep last step's cells while it has
    // moved less; 0, the default, is always allowed and means "look again".
    virtual double clearance(const Vec3& p, label cell) const;

    // The smallest clearance of the points centre + radius * units[k] in
    // their cells[k] (findCells' answer), 0 as soon as one of them has none:
    // how far a divided particle may move and keep its cells. The default
    // asks clearance() point by point.
    virtual double clearance(const Vec3& centre, double radius, const std::vector<Vec3>& units,
                             const std::vector<label>& cells) const;

    // Parallel runs. The cells of neighbouring ranks that this rank's
    // particles reach (halo cells) are numbered after its own, and nCells()
    // counts both; findCell() and cellVolume() know them. complete() takes a
    // per-cell sum over this rank's particles (width values per cell), adds
    // each halo cell's share into its owner's entry and copies the owners'
    // totals back, so every cell the rank sees holds the sum over all ranks'
    // particles. A mesh without a halo (serial) has nothing to do.
    virtual void complete(std::vector<double>& values, int width) const;
};

// complete() for a per-cell vector field
void completeVectors(const CellLocator& mesh, std::vector<Vec3>& values);

} // namespace spoutlab
