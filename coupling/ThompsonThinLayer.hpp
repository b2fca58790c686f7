#pragma once
// The thin-layer drying equation of shelled corn of Thompson, Peart and Foster
// (1968), "Mathematical simulation of corn drying - a new model", Trans. ASAE
// 11(4) 582-586, fitted to thin layers of corn in heated air:
//   t = A ln MR + B (ln MR)^2,   A = -1.862 + 0.00488 T,   B = 427.4 exp(-0.033 T)
// t the drying time in hours, T the air temperature in degF and
// MR = (X - X_eq)/(X_0 - X_eq) the moisture ratio; solved for MR,
//   ln MR = (-A - sqrt(A^2 + 4 B t)) / (2 B).
// The measured curves a thin-layer validation case compares with; SI here.

namespace spoutlab::thompson
{

// Time [s] for a thin layer in air at T [K] to reach moisture ratio MR in (0, 1].
double dryingTime(double moistureRatio, double airTemperature);

// Moisture ratio after t >= 0 [s] in air at T [K].
double moistureRatio(double time, double airTemperature);

} // namespace spoutlab::thompson
