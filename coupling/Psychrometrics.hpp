#pragma once
// Psychrometrics of moist air at a given total pressure, valid for dry-bulb
// temperatures from -100 to 200 degC (saturation over ice below 0 degC, over
// liquid water from 0 to 200 degC). The one implementation of the project:
// procsim's tray dryer and the spouted bed's drying models both use it.
//
// Formulation: ASHRAE Handbook - Fundamentals, chapter 1 (Psychrometrics):
//   saturation pressure     Hyland & Wexler (1983), ASHRAE eqs (5) and (6);
//   humidity ratio          W = 0.621945 pw / (p - pw)  (ideal mixing, no
//                           enhancement factor: tables that include it differ
//                           by about 0.4 %);
//   enthalpy                h = 1.006 t + W (2501 + 1.86 t)   [kJ/kg dry air];
//   thermodynamic wet bulb  ASHRAE eq (35) (over water) and (37) (over ice);
//   specific volume/density ideal gas, Ra = 287.042 J/(kg K).
// Units: temperatures in degC, pressures in Pa, W in kg water / kg dry air,
// enthalpy in J/kg dry air, relative humidity as a fraction 0..1.
//
// Every inverse (dew point, wet bulb, temperature from enthalpy) is solved by
// bracketed bisection on a monotone function, so it always converges.
namespace spoutlab::psy
{

constexpr double kMolarRatio = 0.621945; // M_water / M_dry air
constexpr double kRa = 287.042;          // J/(kg K), dry air
constexpr double kCpAir = 1006.0;        // J/(kg K), dry air
constexpr double kCpVapour = 1860.0;     // J/(kg K), water vapour
constexpr double kCpWater = 4186.0;      // J/(kg K), liquid water
constexpr double kHfg0 = 2501.0e3;       // J/kg, vaporisation at 0 degC
constexpr double kAtm = 101325.0;        // Pa

// Saturation pressure of water vapour [Pa]; over ice below 0 degC.
// Valid -100..200 degC; throws std::domain_error outside.
double saturationPressure(double tC);

// Temperature [degC] at which saturationPressure(t) == pw (dew/frost point).
double saturationTemperature(double pw);

double humidityRatioFromPw(double pw, double p);
double pwFromHumidityRatio(double W, double p);
// Saturation humidity ratio; +infinity when p_ws(t) >= p (boiling).
double saturationHumidityRatio(double tC, double p);

double relativeHumidity(double tC, double W, double p);     // 0..1 (can exceed 1 if supersaturated)
double humidityRatioFromRH(double tC, double rh, double p); // throws if pw >= p

double enthalpy(double tC, double W);                 // J/kg dry air
double temperatureFromEnthalpy(double h, double W);   // degC
double dewPoint(double W, double p);                  // degC
double specificVolume(double tC, double W, double p); // m^3/kg dry air
double density(double tC, double W, double p);        // kg moist air / m^3

// Thermodynamic wet-bulb temperature [degC] for dry-bulb tC and humidity W.
// Bisection between the dew point and min(tC, boiling point at p).
double wetBulb(double tC, double W, double p);
// W from dry bulb and thermodynamic wet bulb (ASHRAE eq 35 / 37).
double humidityRatioFromWetBulb(double tC, double twb, double p);

// Latent heat of vaporisation of water [J/kg] at t (0..200 degC), from the
// ideal-gas vapour and liquid enthalpies used above: 2501e3 + (1860 - 4186) t.
double latentHeat(double tC);

} // namespace spoutlab::psy
