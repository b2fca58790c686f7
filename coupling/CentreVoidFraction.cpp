#include "CentreVoidFraction.hpp"

namespace spoutlab
{

// selected by "voidFractionModel centre;"
const Registration<VoidFractionModel, CentreVoidFraction> registeredCentreVoidFraction("centre");

CentreVoidFraction::CentreVoidFraction(const Parameters& props) : VoidFractionModel(props) {}

void CentreVoidFraction::distribute(const CellLocator&, const Particle&, label centreCell,
                                    std::vector<CellWeight>& row) const
{
    row.push_back({centreCell, 1.0});
}

} // namespace spoutlab
