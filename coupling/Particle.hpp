#pragma once
// One DEM particle as the coupling sees it: position, velocity, radius and,
// with heat transfer, temperature (SI).

#include "Vec3.hpp"

#include <cmath>

namespace spoutlab
{

struct Particle
{
    long id = 0;              // LIGGGHTS atom id, kept to push forces back to the right atom
    Vec3 x;                   // centre [m]
    Vec3 v;                   // velocity [m/s]
    double radius = 0.0;      // [m]
    double temperature = 0.0; // [K]; 0 when the run has no heat transfer

    double volume() const { return 4.0 / 3.0 * std::acos(-1.0) * radius * radius * radius; }
    double surface() const { return 4.0 * std::acos(-1.0) * radius * radius; }
};

} // namespace spoutlab
