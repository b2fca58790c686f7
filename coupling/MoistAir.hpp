#pragma once
// Moist air as the drying models see it: temperature, humidity ratio and
// pressure, with the vapour densities the gas-film mass transfer is written in
// and the diffusivity of water vapour in air. SI units and kelvin throughout
// (coupling/Psychrometrics, which these build on, works in degC).

namespace spoutlab
{

struct MoistAir
{
    double temperature;   // T_g [K]
    double humidityRatio; // W [kg water vapour / kg dry air], >= 0
    double pressure;      // p [Pa], total
};

// Specific gas constant of water vapour R_v = R_a/(M_w/M_a) [J/(kg K)]: the
// psychrometrics' own R_a = 287.042 and M_w/M_a = 0.621945 (ASHRAE Handbook
// Fundamentals ch. 1), 461.52, so that vapour densities and humidity ratios
// here agree with coupling/Psychrometrics exactly.
double waterVapourGasConstant();

// Partial pressure of the vapour p_w = p W/(0.621945 + W) [Pa].
double vapourPressure(const MoistAir& air);

// Relative humidity p_w/p_ws(T_g), 0..1 (above 1 if supersaturated).
double relativeHumidity(const MoistAir& air);

// Vapour density far from the particle, rho_v,inf = p_w/(R_v T_g) [kg/m^3].
double vapourDensity(const MoistAir& air);

// Density of saturated vapour over liquid water at T [K], p_ws(T)/(R_v T)
// [kg/m^3] (Hyland-Wexler p_ws; over ice below 273.15 K).
double saturationVapourDensity(double temperature);

// Binary diffusivity of water vapour in air [m^2/s],
//   D_v = D_0 (p_0/p) (T/T_0)^1.81,  D_0 = 0.2178 cm^2/s at T_0 = 273.15 K,
//   p_0 = 101.325 kPa
// (Massman 1998, "A review of the molecular diffusivities of H2O, CO2, CH4,
// CO, O3, SO2, NH3, N2O, NO, and NO2 in air, O2 and N2 near STP", Atmos.
// Environ. 32(6) 1111-1127: his recommended H2O-air value and exponent).
double vapourDiffusivity(double temperature, double pressure);

} // namespace spoutlab
