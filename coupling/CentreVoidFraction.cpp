#include "CentreVoidFraction.hpp"

namespace spoutlab
{

// selected by "voidFractionModel centre;"
const Registration<VoidFractionModel, CentreVoidFraction> registeredCentreVoidFraction("centre");

CentreVoidFraction::CentreVoidFraction(const Parameters& props) : VoidFractionModel(props) {}

double CentreVoidFraction::distribute(const CellLocator& mesh, const Particle& p, label centreCell,
                                      std::vector<CellWeight>& row) const
{
    row.push_back({centreCell, 1.0});
    return mesh.clearance(p.x, centreCell); // the row lasts while the centre stays in its cell
}

} // namespace spoutlab
