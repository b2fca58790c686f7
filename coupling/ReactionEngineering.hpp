#pragma once
// Chen's reaction engineering approach (REA; Chen and Xie 1997, Trans IChemE
// 75C 213-222; Chen 2008, Drying Technol. 26 627-639): evaporation as an
// activated process whose activation energy grows as the kernel dries,
//   rho_v,s = exp(-dE_v/(R T_p)) rho_v,sat(T_p)
//   dE_v = f(X - X_eq) dE_v,inf,   dE_v,inf = -R T_g ln RH_g
//   f(x) = a exp(-b x^c)            (the relative activation energy)
//   m_dot = k_m A (rho_v,s - rho_v,inf)
// X_eq is the isotherm's equilibrium moisture in the drying air (RH_g, T_g).
// At X = X_eq and T_p = T_g with a = 1 the surface is in equilibrium with the
// air and nothing moves; as RH_g -> 1, dE_v,inf -> 0 and the kernel dries as
// free water; in bone-dry air (RH_g = 0) the law gives rho_v,s = 0, no drying.
// Written as rho_v,s = RH_g^(f T_g/T_p) rho_v,sat(T_p), which needs no R.
//
// The advance is backward Euler in X, solved to round-off: stable and
// monotone for any dt (X moves towards the rate's zero and never past it);
// a step is cut into sub-steps of at most 2 % of the kernel's drying time
// constant (at most 1000), so that long steps stay within about 1 % of the
// change; water never leaves a kernel that has none (X >= 0).
//
// Parameters: a, b, c of f (required: a > 0, b >= 0, c > 0). No fit for
// shelled corn could be found in a source at hand, so there are no defaults:
// take them from a published REA fit (e.g. Azmir, Hou and Yu 2018, Powder
// Technol. 323 238-249, for corn) and cite it beside the case.
// isotherm: modifiedHenderson (default) | modifiedChungPfost, for X_eq and
// the latent heat.

#include "DryingModel.hpp"

namespace spoutlab
{

class ReactionEngineering : public DryingModel
{
public:
    explicit ReactionEngineering(const Parameters& props);

    double rate(const Kernel& kernel, double moisture, const double* state, const MoistAir& air,
                double massTransferCoefficient) const override;
    double advance(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                   double massTransferCoefficient, double dt) const override;
    std::string name() const override { return "reactionEngineering"; }

    // f(X - X_eq), the relative activation energy dE_v/dE_v,inf.
    double relativeActivationEnergy(double moisture, double equilibriumMoisture) const;

    // What a step holds fixed: RH_g and X_eq, T_g/T_p, the saturated vapour
    // at T_p, the far-field vapour and k_m A.
    struct Surroundings
    {
        double relativeHumidity;
        double equilibriumMoisture;
        double temperatureRatio; // T_g/T_p
        double saturatedVapour;  // rho_v,sat(T_p) [kg/m^3]
        double farVapour;        // rho_v,inf [kg/m^3]
        double conductance;      // k_m A [m^3/s]
    };

private:
    // m_dot [kg/s] at moisture X, not limited by the water present
    double filmRate(const Surroundings& s, double moisture) const;
    // one backward-Euler step, dt/m_d = perMass
    double implicitStep(const Surroundings& s, double moisture, double perMass) const;

    double a_;
    double b_;
    double c_;
};

} // namespace spoutlab
