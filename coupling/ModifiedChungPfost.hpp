#pragma once
// The modified Chung-Pfost equation for the desorption isotherm of shelled
// (yellow dent) corn, in the form of ASAE D245.4 and Brooker, Bakker-Arkema
// and Hall (Drying and storage of grains and oilseeds, 1992), X decimal dry
// basis and t in degC:
//   X_eq = E - F ln[-(t + C) ln a_w],   E = 0.33872, F = 0.058970, C = 30.205
// so that
//   a_w = exp(-exp((E - X)/F) / (t + C))
//   (d ln a_w/dt)_X = -ln a_w / (t + C)
// (ASAE D245.5 writes it as a_w = exp(-A/(t + C) exp(-B M)) with
// A = exp(E/F) = 312.3 and B = 1/F per decimal moisture.) Below the a_w where
// the formula turns negative the equilibrium moisture is taken as 0.
// No parameters.

#include "SorptionIsotherm.hpp"

namespace spoutlab
{

class ModifiedChungPfost : public SorptionIsotherm
{
public:
    explicit ModifiedChungPfost(const Parameters& props);

    double equilibriumMoisture(double waterActivity, double temperature) const override;
    double waterActivity(double moisture, double temperature) const override;
    double waterActivityDerivative(double moisture, double temperature) const override;
    double lnWaterActivitySlope(double moisture, double temperature) const override;
    Activity activity(double moisture, double temperature) const override;
    std::string name() const override { return "modifiedChungPfost"; }
};

} // namespace spoutlab
