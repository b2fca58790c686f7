#pragma once
// "centre": the whole particle volume goes to the cell holding its centre.
// Cheap, but eps jumps as particles cross faces; fine when cells are several
// particle diameters wide.

#include "VoidFractionModel.hpp"

namespace spoutlab
{

class CentreVoidFraction : public VoidFractionModel
{
public:
    explicit CentreVoidFraction(const Parameters& props);
    std::string name() const override { return "centre"; }

protected:
    double distribute(const CellLocator& mesh, const Particle& p, label centreCell,
                      std::vector<CellWeight>& row) const override;
};

} // namespace spoutlab
