#pragma once
// Gas-side formulas of the dry corona papers:
//  toluene paper eq 1: E(r) = V / (r ln(R/R0)) in a wire-cylinder reactor;
//  eq 2: area-mean <E/N> = 2 V / (N (R + R0) ln(R/R0)), N = p / (k_B T);
//  eq 4: J = (q_in - q_out) / (I V), molar flows of the target gas;
//  acetaldehyde paper eq 1: psi = (C_out,0mA - C_out,I) / C_out,0mA;
//  eq 2: psi' = psi * theta(25 C) / theta(T), theta = V/Q with Q ~ T at fixed molar flow and p.
#include <string>

namespace procsim::kinetics::corona
{

constexpr double boltzmann = 1.380649e-23; // J/K
constexpr double townsend = 1e-21;         // V m^2

double numberDensity(double pressurePa, double temperatureK);                       // 1/m^3
double field(double voltage, double r, double anodeRadius, double wireRadius);      // V/m (eq 1)
double meanEOverN(double voltage, double anodeRadius, double wireRadius, double n); // V m^2 (eq 2)
double removalEfficiency(double outletNoDischarge, double outletDischarge);         // eq 1 (acetaldehyde)
double residenceCorrected(double psi, double temperatureK, double referenceK);      // eq 2 (acetaldehyde)
double energeticEfficiency(double molarFlowIn, double molarFlowOut, double currentA,
                           double voltageV); // mol/J

} // namespace procsim::kinetics::corona
