#pragma once
// Division of the unit ball into equal-volume pieces for the "divided"
// void-fraction model. Each piece is a sector of a spherical shell,
//   rInner <= r <= rOuter, zLow <= cos(theta) <= zHigh, phiLow <= phi <= phiHigh,
// whose volume (r^3 range/3) * (z range) * (phi range) is exact because area
// on the unit sphere is dz dphi (Archimedes). The shells have equal volume and
// each shell is split the same way into equal solid angles:
//   a polar cap at each pole (full circle) + nRings bands of nAzimuthal sectors,
// M = 2 + nRings nAzimuthal pieces per shell, each of solid angle 4 pi/M.
// Odd shells are turned by half a sector so their points fill the gaps of the
// even ones. With nAzimuthal even, every piece has a mirror piece through the
// centre (antipodal symmetry).

#include "Vec3.hpp"

#include <vector>

namespace spoutlab
{

struct BallSector
{
    double rInner, rOuter;
    double zLow, zHigh;
    double phiLow, phiHigh;

    double volume() const;
    // Exact centroid: the radial first moment times the mean direction of the
    // solid-angle patch.
    Vec3 centroid() const;
};

// Throws InputError unless all counts are >= 1.
std::vector<BallSector> equalVolumeSectors(int nShells, int nRings, int nAzimuthal);

} // namespace spoutlab
