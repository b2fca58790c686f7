#pragma once
// The Arrhenius temperature dependence of a rate constant or a diffusivity,
// written about a reference temperature so that its parameter is a value read
// off a measurement at that temperature:
//   k(T) = k_ref exp(-E_a/R (1/T - 1/T_ref))        (T, T_ref in K)
// Used by procsim's tray-dryer kinetics and by the kernel-diffusion drying
// model of the spouted bed.

#include <cmath>

namespace spoutlab
{

// Molar gas constant [J/(mol K)], CODATA 2018 (exact in the 2019 SI,
// 8.314462618... ; the digits kept here are the ones procsim always used).
constexpr double kGasConstant = 8.314462618;

inline double arrhenius(double valueAtReference, double activationEnergy, double temperature,
                        double referenceTemperature)
{
    return valueAtReference
           * std::exp(-activationEnergy / kGasConstant * (1.0 / temperature - 1.0 / referenceTemperature));
}

} // namespace spoutlab
