#include "SorptionIsotherm.hpp"

#include "MoistAir.hpp"
#include "Psychrometrics.hpp"

namespace spoutlab
{

SorptionIsotherm::~SorptionIsotherm() = default;

SorptionIsotherm::Activity SorptionIsotherm::activity(double moisture, double temperature) const
{
    return {waterActivity(moisture, temperature), waterActivityDerivative(moisture, temperature),
            lnWaterActivitySlope(moisture, temperature)};
}

double SorptionIsotherm::latentHeat(double moisture, double temperature) const
{
    return latentHeat(temperature, Activity{0.0, 0.0, lnWaterActivitySlope(moisture, temperature)});
}

double SorptionIsotherm::latentHeat(double temperature, const Activity& activity)
{
    const double freeWater = psy::latentHeat(temperature - 273.15);
    return freeWater + waterVapourGasConstant() * temperature * temperature * activity.lnSlope;
}

// Built on first use, before any isotherm's registration object adds to it.
ModelRegistry<SorptionIsotherm>& SorptionIsotherm::registry()
{
    static ModelRegistry<SorptionIsotherm> isotherms("isotherm");
    return isotherms;
}

std::unique_ptr<SorptionIsotherm> SorptionIsotherm::New(const std::string& typeName, const Parameters& props)
{
    return registry().create(typeName, props);
}

std::vector<StatedRange> SorptionIsotherm::statedRanges() const
{
    return {};
}

} // namespace spoutlab
