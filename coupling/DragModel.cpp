#include "DragModel.hpp"

namespace spoutlab
{

double particleReynolds(const DragState& s, const GasProperties& gas)
{
    return s.voidFraction * gas.rho * s.slip * s.diameter / gas.mu;
}

DragModel::~DragModel() = default;

// Built on first use, so it exists before any law's registration object
// (in another translation unit) adds to it.
ModelRegistry<DragModel>& DragModel::registry()
{
    static ModelRegistry<DragModel> laws("dragModel");
    return laws;
}

std::vector<std::string> DragModel::available()
{
    return registry().names();
}

std::unique_ptr<DragModel> DragModel::New(const std::string& typeName, const Parameters& props)
{
    return registry().create(typeName, props);
}

} // namespace spoutlab
