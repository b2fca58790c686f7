#pragma once
// The modified Henderson equation for the desorption isotherm of shelled
// (yellow dent) corn, ASAE D245.5 (Moisture relationships of plant-based
// agricultural products, 1995), with M in percent dry basis and t in degC:
//   1 - a_w = exp(-A (t + C) M^B),   A = 8.6541e-5, B = 1.8634, C = 49.810
// so that
//   X_eq = 0.01 [-ln(1 - a_w) / (A (t + C))]^(1/B)
//   (d ln a_w/dt)_X = A M^B (1 - a_w)/a_w   (-> 1/(t + C) as X -> 0)
// These constants reproduce the shelled-corn EMC tables printed from the
// Henderson-Thompson equation (e.g. 17.2 % w.b. at 60 degF and 80 % RH) to
// their last digit. ASAE gives the fits for about 0-50 degC and 10-90 % RH;
// beyond (hot drying air) they are extrapolations, warned once per run
// (StatedRange.hpp).
// No parameters.

#include "SorptionIsotherm.hpp"

namespace spoutlab
{

class ModifiedHenderson : public SorptionIsotherm
{
public:
    explicit ModifiedHenderson(const Parameters& props);

    double equilibriumMoisture(double waterActivity, double temperature) const override;
    double waterActivity(double moisture, double temperature) const override;
    double waterActivityDerivative(double moisture, double temperature) const override;
    double lnWaterActivitySlope(double moisture, double temperature) const override;
    Activity activity(double moisture, double temperature) const override;
    std::vector<StatedRange> statedRanges() const override;
    std::string name() const override { return "modifiedHenderson"; }
};

} // namespace spoutlab
