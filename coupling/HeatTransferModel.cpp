#include "HeatTransferModel.hpp"

namespace spoutlab
{

double heatTransferReynolds(const HeatTransferCell& cell, const GasThermalProperties& gas)
{
    return cell.voidFraction * gas.rho * cell.slip * cell.diameter / gas.mu;
}

HeatTransferModel::~HeatTransferModel() = default;

// The multiplication and division are those each correlation's h() did before
// it became nusselt(): the same operations in the same order, so h is the same
// to the bit (spoutFoam's heat-transfer results do not move).
double HeatTransferModel::h(const HeatTransferCell& cell, const GasThermalProperties& gas) const
{
    return nusselt(cell, heatTransferReynolds(cell, gas), gas.prandtl()) * gas.kappa / cell.diameter;
}

double HeatTransferModel::massTransferCoefficient(const HeatTransferCell& cell,
                                                  const GasThermalProperties& gas,
                                                  double vapourDiffusivity) const
{
    const double schmidt = gas.mu / (gas.rho * vapourDiffusivity);
    return nusselt(cell, heatTransferReynolds(cell, gas), schmidt) * vapourDiffusivity / cell.diameter;
}

int HeatTransferModel::region(const HeatTransferCell&) const
{
    return -1;
}

std::vector<const HeatTransferModel*> HeatTransferModel::correlations() const
{
    return {this};
}

int HeatTransferModel::correlationIndex(const HeatTransferCell&) const
{
    return 0;
}

std::vector<StatedRange> HeatTransferModel::statedRanges() const
{
    return {};
}

// Built on first use, before any correlation's registration object adds to it.
ModelRegistry<HeatTransferModel>& HeatTransferModel::registry()
{
    static ModelRegistry<HeatTransferModel> correlations("heatTransferModel");
    return correlations;
}

std::vector<std::string> HeatTransferModel::available()
{
    return registry().names();
}

std::unique_ptr<HeatTransferModel> HeatTransferModel::New(const std::string& typeName,
                                                          const Parameters& props)
{
    return registry().create(typeName, props);
}

} // namespace spoutlab
