#pragma once
// One DEM particle as the coupling sees it: position, velocity, radius and,
// with heat transfer, temperature (SI).
//
// With coarse graining (docs/DESIGN.md, "Coarse graining") the DEM particle is
// a parcel of radius r that stands for cg^3 original particles of diameter
// d = 2 r / cg. The parcel's volume is exactly that of its originals, so the
// void fraction is built from the parcel as it is; the exchange laws are
// evaluated at the original's diameter and the parcel receives cg^3 times one
// original's force, heat and water. Its temperature and moisture are those of
// each of its originals. cg = 1 is a plain particle.

#include "Vec3.hpp"

#include <cmath>

namespace spoutlab
{

struct Particle
{
    long id = 0;                 // LIGGGHTS atom id, kept to push forces back to the right atom
    Vec3 x;                      // centre [m]
    Vec3 v;                      // velocity [m/s]
    double radius = 0.0;         // the parcel's [m]
    double temperature = 0.0;    // [K]; 0 when the run has no heat transfer
    double coarseGraining = 1.0; // cg >= 1: the parcel stands for cg^3 original particles

    // The parcel's volume, that of its cg^3 originals.
    double volume() const { return 4.0 / 3.0 * std::acos(-1.0) * radius * radius * radius; }
    // The surface gas and parcel exchange through: its cg^3 originals',
    // cg^3 pi d^2 = cg times the parcel's own surface.
    double surface() const { return 4.0 * std::acos(-1.0) * radius * radius * coarseGraining; }
    // The original particle's diameter d, at which the laws are evaluated.
    double diameter() const { return 2.0 * radius / coarseGraining; }
    // How many original particles the parcel stands for, cg^3.
    double multiplicity() const { return coarseGraining * coarseGraining * coarseGraining; }
};

} // namespace spoutlab
