#pragma once
// "divided": each particle is cut into N equal-volume pieces (SphereSampling)
// and each piece's volume goes to the cell holding the piece's centroid. The
// papers' cells (11 mm x 19 mm) are barely wider than a particle (8 mm), so
// most particles straddle a face and the centre model would make eps jump.
//
// Parameters (besides voidFractionMin):
//   nShells     equal-volume radial shells (default 3)
//   nRings      bands between the polar caps of each shell (default 2)
//   nAzimuthal  sectors per band (default 4; keep it even for antipodal symmetry)
// N = nShells (2 + nRings nAzimuthal), 30 with the defaults.
//
// Details that make the volume sum exact and the split unbiased:
// - a particle whole inside its centre cell skips sampling (fast path);
// - a piece whose centroid is outside the mesh (particle cut by a wall) is
//   given to the centre cell, so no volume is lost;
// - the pattern is turned to a fixed oblique orientation so that no centroid
//   lies on a plane through the centre parallel to the axes: with antipodal
//   symmetry a particle centred on a face then splits exactly in half.

#include "VoidFractionModel.hpp"

namespace spoutlab
{

class DividedVoidFraction : public VoidFractionModel
{
public:
    explicit DividedVoidFraction(const Parameters& props);
    std::string name() const override { return "divided"; }

    // Centroids of the equal-volume pieces of the unit ball, in the orientation
    // used for sampling (multiply by the radius and add the centre).
    const std::vector<Vec3>& unitSamplePoints() const { return samples_; }

protected:
    double distribute(const CellLocator& mesh, const Particle& p, label centreCell,
                      std::vector<CellWeight>& row) const override;

private:
    std::vector<Vec3> samples_;
};

} // namespace spoutlab
