#include "FreeWater.hpp"

#include "Psychrometrics.hpp"

#include <algorithm>

namespace spoutlab
{

// selected by "dryingModel freeWater;"
const Registration<DryingModel, FreeWater> registeredFreeWater("freeWater");

namespace
{

double filmRate(const Kernel& kernel, const MoistAir& air, double massTransferCoefficient)
{
    return massTransferCoefficient * surfaceArea(kernel)
           * (saturationVapourDensity(kernel.temperature) - vapourDensity(air));
}

} // namespace

FreeWater::FreeWater(const Parameters&) : DryingModel(nullptr) {}

double FreeWater::rate(const Kernel& kernel, double moisture, const double*, const MoistAir& air,
                       double massTransferCoefficient) const
{
    const double mdot = filmRate(kernel, air, massTransferCoefficient);
    return mdot > 0.0 && !(moisture > 0.0) ? 0.0 : mdot;
}

double FreeWater::advance(const Kernel& kernel, double& moisture, double*, const MoistAir& air,
                          double massTransferCoefficient, double dt) const
{
    checkStep(moisture, massTransferCoefficient, dt);
    const double old = moisture;
    const double change = filmRate(kernel, air, massTransferCoefficient) * dt / kernel.dryMass;
    moisture = std::max(0.0, old - change);
    return kernel.dryMass * (old - moisture);
}

double FreeWater::latentHeat(const Kernel& kernel, double, const double*) const
{
    return psy::latentHeat(kernel.temperature - 273.15);
}

} // namespace spoutlab
