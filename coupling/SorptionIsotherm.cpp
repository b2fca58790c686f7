#include "SorptionIsotherm.hpp"

#include "MoistAir.hpp"
#include "Psychrometrics.hpp"

namespace spoutlab
{

SorptionIsotherm::~SorptionIsotherm() = default;

double SorptionIsotherm::latentHeat(double moisture, double temperature) const
{
    const double freeWater = psy::latentHeat(temperature - 273.15);
    return freeWater
           + waterVapourGasConstant() * temperature * temperature
                 * lnWaterActivitySlope(moisture, temperature);
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

} // namespace spoutlab
