#pragma once
// Desorption isotherms of shelled corn: the equilibrium moisture X_eq of the
// grain in air of relative humidity a_w, and its inverse, the water activity
// a_w of grain at moisture X. Moisture X is kg water per kg dry solid
// (decimal, dry basis), temperatures in K; a_w is a fraction 0..1.
//
// The isotherm also gives the heat taken to evaporate the grain's water,
// which exceeds that of free water at low moisture where the water is bound:
// by Clausius-Clapeyron at constant moisture (the net isosteric heat of
// desorption, as Rodriguez-Arias, Hall and Bakker-Arkema 1963, Cereal Chem.
// 40:676, derived it from corn isotherms),
//   h_fg,grain(X, T) = h_fg(T) + R_v T^2 (d ln a_w / dT)_X
// with h_fg of free water (Psychrometrics latentHeat) and R_v of the vapour.
// Computed from the same isotherm as the equilibrium moisture, the heat and the
// surface vapour pressure of a drying model are one consistent description.
//
// Selected by name ("isotherm" in a drying model's settings):
// modifiedHenderson (default) or modifiedChungPfost.

#include "ModelRegistry.hpp"
#include "Parameters.hpp"
#include "StatedRange.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spoutlab
{

class SorptionIsotherm
{
public:
    virtual ~SorptionIsotherm();

    // X_eq [kg/kg d.b.] at water activity a_w (0 for a_w <= 0, +infinity for
    // a_w >= 1) and temperature T [K].
    virtual double equilibriumMoisture(double waterActivity, double temperature) const = 0;

    // a_w of grain at moisture X >= 0 and T [K], in [0, 1).
    virtual double waterActivity(double moisture, double temperature) const = 0;

    // (d a_w / dX) at constant T, >= 0.
    virtual double waterActivityDerivative(double moisture, double temperature) const = 0;

    // (d ln a_w / dT) at constant X [1/K], finite at X -> 0.
    virtual double lnWaterActivitySlope(double moisture, double temperature) const = 0;

    // The three above at one (X, T) from one evaluation of the isotherm, what
    // a drying step asks for several times per particle; exactly the values
    // the three functions return (the default calls them).
    struct Activity
    {
        double value;      // a_w
        double derivative; // d a_w / dX
        double lnSlope;    // (d ln a_w / dT)_X [1/K]
    };
    virtual Activity activity(double moisture, double temperature) const;

    // Heat to evaporate 1 kg of the grain's water at X and T [J/kg] (above).
    double latentHeat(double moisture, double temperature) const;
    // ... with (d ln a_w / dT)_X already known (Activity::lnSlope).
    static double latentHeat(double temperature, const Activity& activity);

    // The ranges of the grain's "temperature" [K] and the air's "relative
    // humidity" [0..1] its source fitted (none unless the isotherm says so).
    virtual std::vector<StatedRange> statedRanges() const;

    virtual std::string name() const = 0;

    // Run-time selection; an isotherm joins the registry from its own .cpp.
    static ModelRegistry<SorptionIsotherm>& registry();
    static std::unique_ptr<SorptionIsotherm> New(const std::string& typeName, const Parameters& props);
};

} // namespace spoutlab
