#include "HeatTransferModel.hpp"

namespace spoutlab
{

double heatTransferReynolds(const HeatTransferCell& cell, const GasThermalProperties& gas)
{
    return cell.voidFraction * gas.rho * cell.slip * cell.diameter / gas.mu;
}

HeatTransferModel::~HeatTransferModel() = default;

int HeatTransferModel::region(const HeatTransferCell&) const
{
    return -1;
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
