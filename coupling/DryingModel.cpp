#include "DryingModel.hpp"

#include "Psychrometrics.hpp"

#include <cmath>
#include <stdexcept>

namespace spoutlab
{

double surfaceArea(const Kernel& kernel)
{
    return M_PI * kernel.diameter * kernel.diameter;
}

DryingModel::DryingModel(std::unique_ptr<SorptionIsotherm> isotherm) : isotherm_(std::move(isotherm)) {}

DryingModel::~DryingModel() = default;

bool DryingModel::needsGas(const double*) const
{
    return true;
}

double DryingModel::release(double, double&, double*, double&) const
{
    throw std::logic_error("dryingModel " + name() + ": every step needs the gas (no release without it)");
}

int DryingModel::stateSize() const
{
    return 0;
}

void DryingModel::initialise(double, double*) const {}

double DryingModel::latentHeat(const Kernel& kernel, double moisture, const double*) const
{
    return isotherm().latentHeat(moisture, kernel.temperature);
}

double DryingModel::advanceWithLatentHeat(const Kernel& kernel, double& moisture, double* state,
                                          const MoistAir& air, double massTransferCoefficient, double dt,
                                          double& latentHeat) const
{
    latentHeat = this->latentHeat(kernel, moisture, state);
    return advance(kernel, moisture, state, air, massTransferCoefficient, dt);
}

std::unique_ptr<SorptionIsotherm> DryingModel::isothermOf(const Parameters& props)
{
    return SorptionIsotherm::New(props.getWord("isotherm", "modifiedHenderson"), props);
}

void DryingModel::checkStep(double moisture, double massTransferCoefficient, double dt) const
{
    const bool ok = moisture >= 0.0 && std::isfinite(moisture) && massTransferCoefficient >= 0.0
                    && std::isfinite(massTransferCoefficient) && dt >= 0.0 && std::isfinite(dt);
    if (ok) return;
    throw std::domain_error("dryingModel " + name()
                            + ": expected moisture >= 0, k_m >= 0 and dt >= 0, got X = "
                            + std::to_string(moisture) + ", k_m = " + std::to_string(massTransferCoefficient)
                            + ", dt = " + std::to_string(dt));
}

// Built on first use, before any model's registration object adds to it.
ModelRegistry<DryingModel>& DryingModel::registry()
{
    static ModelRegistry<DryingModel> models("dryingModel");
    return models;
}

std::unique_ptr<DryingModel> DryingModel::New(const std::string& typeName, const Parameters& props)
{
    return registry().create(typeName, props);
}

std::vector<std::string> DryingModel::available()
{
    return registry().names();
}

} // namespace spoutlab
