#pragma once
// Thermal properties of a shelled-corn kernel that the drying coupling needs
// beside the isotherms (SorptionIsotherm) and the drying laws (DryingModel).

#include "Psychrometrics.hpp"

namespace spoutlab::corn
{

// Specific heat of bone-dry shelled corn [J/(kg K)]: the dry intercept of
// c = 1.465 + 3.56 M_wb kJ/(kg K) for shelled corn (ASAE D243, Thermal
// properties of grain and grain products, from Kazarian and Hall 1965).
constexpr double kDrySpecificHeat = 1465.0;

// Specific heat of the kernel's water [J/(kg K)]: liquid water, the value the
// psychrometrics use (ASHRAE Fundamentals ch. 1, 4.186 kJ/(kg K)).
constexpr double kWaterSpecificHeat = psy::kCpWater;

// Heat capacity of a kernel [J/K] from its dry solid and its water,
// m_d (c_d + X c_w).
inline double heatCapacity(double dryMass, double moisture)
{
    return dryMass * (kDrySpecificHeat + moisture * kWaterSpecificHeat);
}

} // namespace spoutlab::corn
