#pragma once
// Free water (the constant-rate period): the kernel's surface is wet, its
// vapour saturated at the kernel temperature,
//   m_dot = k_m A (rho_v,sat(T_p) - rho_v,inf)
// independent of X. A kernel held by its heat balance
// h (T_g - T_p) = m_dot h_fg settles at the wet-bulb temperature of the
// gas-film laws (the psychrometric wet bulb when k_m rho c_p = h, Lewis
// number 1). The rate is constant over a step at constant T_p, so the advance
// is exact: X falls linearly until the water is gone (X never below 0);
// condensation (rho_v,inf above saturation at T_p) adds water.
// Latent heat: free water's, Psychrometrics latentHeat(T_p).
// No parameters.

#include "DryingModel.hpp"

namespace spoutlab
{

class FreeWater : public DryingModel
{
public:
    explicit FreeWater(const Parameters& props);

    double rate(const Kernel& kernel, double moisture, const double* state, const MoistAir& air,
                double massTransferCoefficient) const override;
    double advance(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                   double massTransferCoefficient, double dt) const override;
    double latentHeat(const Kernel& kernel, double moisture, const double* state) const override;
    std::string name() const override { return "freeWater"; }
};

} // namespace spoutlab
