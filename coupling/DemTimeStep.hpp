#pragma once
// Largest stable DEM time step for the linear spring-dashpot contact:
// dt <= pi sqrt(m/k)/5 (draft-plate paper eq 11), a fifth of the half period
// of the contact oscillation, using the lightest particle mass.

#include <cmath>

namespace spoutlab
{

// massMin [kg], stiffness k [N/m] -> time step [s]
inline double demTimeStepLimit(double massMin, double stiffness)
{
    return std::acos(-1.0) * std::sqrt(massMin / stiffness) / 5.0;
}

} // namespace spoutlab
