"""Moist air for the drying cases' references: saturation pressure, humidity
ratio, vapour density, latent heat and the vapour's diffusivity, written out
again from the published formulas (not taken from coupling/), in kelvin and
SI units.  Functions take floats or numpy arrays.

    saturation pressure  Hyland & Wexler (1983) over liquid water, 0..200 C
                         (ASHRAE Handbook - Fundamentals, ch. 1, eq 6)
    humidity ratio       W = 0.621945 p_w / (p - p_w)        (ASHRAE eq 20)
    vapour density       rho_v = p_w / (R_v T),  R_v = R_a / 0.621945,
                         R_a = 287.042 J/(kg K)               (ASHRAE)
    specific heats       dry air 1006, vapour 1860, liquid water 4186 J/(kg K)
    latent heat          h_fg(T) = 2501e3 + (1860 - 4186) t   (t in C; the
                         difference of the ideal-gas vapour and liquid
                         enthalpies ASHRAE writes, eq 30)
    vapour diffusivity   D_v = 0.2178 cm2/s (p0/p)(T/273.15)^1.81
                         (Massman 1998, Atmos. Environ. 32, 1111)

The vapour mass fraction Y of the gas (what spoutFoam's H2O holds) and the
humidity ratio are W = Y/(1 - Y), Y = W/(1 + W).
"""
import numpy as np

KELVIN = 273.15
MOLAR_RATIO = 0.621945       # M_water / M_dry air
R_AIR = 287.042              # J/(kg K)
R_VAPOUR = R_AIR / MOLAR_RATIO
CP_AIR = 1006.0              # J/(kg K)
CP_VAPOUR = 1860.0
CP_WATER = 4186.0
HFG0 = 2501.0e3              # J/kg at 0 C
ATMOSPHERE = 101325.0        # Pa

# Hyland-Wexler over liquid water: ln p_ws = C8/T + C9 + C10 T + C11 T^2
# + C12 T^3 + C13 ln T  (p_ws in Pa, T in K)
_C8, _C9, _C10 = -5.8002206e3, 1.3914993, -4.8640239e-2
_C11, _C12, _C13 = 4.1764768e-5, -1.4452093e-8, 6.5459673


def saturation_pressure(T):
    """p_ws [Pa] over liquid water at T [K] (273.15..473.15 K)."""
    T = np.asarray(T, float)
    if np.any(T < KELVIN - 1e-9) or np.any(T > KELVIN + 200 + 1e-9):
        raise ValueError('saturation_pressure: outside 0..200 C: %s' % T)
    value = np.exp(_C8 / T + _C9 + T * (_C10 + T * (_C11 + T * _C12)) + _C13 * np.log(T))
    return value if value.ndim else float(value)


def saturation_pressure_slope(T):
    """d p_ws / dT [Pa/K]."""
    T = np.asarray(T, float)
    dln = -_C8 / T ** 2 + _C10 + T * (2 * _C11 + 3 * _C12 * T) + _C13 / T
    return saturation_pressure(T) * dln


def humidity_ratio(pw, p=ATMOSPHERE):
    """W [kg vapour / kg dry air] of a vapour partial pressure pw [Pa]."""
    return MOLAR_RATIO * pw / (p - pw)


def vapour_pressure(W, p=ATMOSPHERE):
    """p_w [Pa] of humidity ratio W."""
    return p * W / (MOLAR_RATIO + W)


def vapour_density(T, W, p=ATMOSPHERE):
    """rho_v [kg/m3] of the vapour in air at T [K] and humidity ratio W."""
    return vapour_pressure(W, p) / (R_VAPOUR * T)


def saturation_vapour_density(T):
    """rho_v,sat [kg/m3] at T [K]."""
    return saturation_pressure(T) / (R_VAPOUR * np.asarray(T, float))


def saturation_vapour_density_slope(T):
    """d rho_v,sat / dT [kg/m3/K]."""
    T = np.asarray(T, float)
    return (saturation_pressure_slope(T) - saturation_pressure(T) / T) / (R_VAPOUR * T)


def saturation_humidity_ratio(T, p=ATMOSPHERE):
    return humidity_ratio(saturation_pressure(T), p)


def relative_humidity(T, W, p=ATMOSPHERE):
    return vapour_pressure(W, p) / saturation_pressure(T)


def latent_heat(T):
    """Free water's heat of vaporisation [J/kg] at T [K]."""
    return HFG0 + (CP_VAPOUR - CP_WATER) * (np.asarray(T, float) - KELVIN)


def vapour_diffusivity(T, p=ATMOSPHERE):
    """D_v [m2/s] of water vapour in air (Massman 1998)."""
    return 0.2178e-4 * (ATMOSPHERE / p) * (np.asarray(T, float) / KELVIN) ** 1.81


def mass_fraction(W):
    """Vapour mass fraction Y of humidity ratio W."""
    return W / (1 + W)


def ratio_of_mass_fraction(Y):
    """Humidity ratio W of vapour mass fraction Y."""
    return Y / (1 - Y)


def humid_heat_capacity(Y, cp_air=CP_AIR):
    """c_p [J/(kg K)] of the humid gas of vapour mass fraction Y, per kg of
    gas, as spoutFoam's energy equation has it: (1 - Y) c_p,a + Y c_p,v."""
    return (1 - Y) * cp_air + Y * CP_VAPOUR
