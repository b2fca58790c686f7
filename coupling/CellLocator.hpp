#pragma once
// What the coupling needs to know about the gas mesh, and nothing more. The
// OpenFOAM solver implements it on its polyMesh; the unit tests use
// CartesianMesh. Keeping it this small is what lets the physics core be
// tested without OpenFOAM.

#include "Vec3.hpp"

namespace spoutlab {

using label = long;

class CellLocator {
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
};

}  // namespace spoutlab
