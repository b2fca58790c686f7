"""One corn kernel drying in a steady stream of moist air, written out again
from the published equations for the evaluate scripts (not taken from the
solver): the references the drying models are checked against.

Moist air from spoutlab.moistair (ASHRAE Handbook - Fundamentals, ch. 1),
and the thermodynamic wet bulb of ASHRAE's eq (35).
Shelled corn: the modified Henderson isotherm of ASAE D245.5,
1 - a_w = exp(-A (t + C) M^B), and the heat of vaporisation of its water by
Clausius-Clapeyron, h_fg + R_v T^2 (d ln a_w/dT)_X (here by a central
difference).  The kernel, lumped in temperature:

    m_d dX/dt = -m_dot,    m_d (c_d + X c_w) dT/dt = h A (T_g - T) - m_dot L
    m_dot = k_m A (rho_v,s - rho_v,inf)

with rho_v,s = rho_v,sat(T) (free water), RH_g^(f T_g/T) rho_v,sat(T),
f = a exp(-b (X - X_eq)^c) (Chen's reaction engineering approach), or
a_w(X_s, T) rho_v,sat(T) at the surface of Fick's sphere (kernel
diffusion, D = D_0 exp(-E_a/(R T)), solved here on a fine radial grid by
the method of lines).
"""
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from spoutlab import moistair

GAS_CONSTANT = 8.314462618          # J/(mol K), CODATA 2018
HENDERSON = (8.6541e-5, 1.8634, 49.810)   # A, B, C of ASAE D245.5 (corn)


def psychrometric_wet_bulb(T, W, p):
    """The thermodynamic wet-bulb temperature [K] (ASHRAE eq 35, over water)."""
    t = T - 273.15

    def residual(ts):
        ws = moistair.saturation_humidity_ratio(ts + 273.15, p)
        return ((2501 - 2.326 * ts) * ws - 1.006 * (t - ts)) / (2501 + 1.86 * t - 4.186 * ts) - W
    return brentq(residual, 0.0, t, xtol=1e-10) + 273.15


def film_wet_bulb(T, W, p, h, km):
    """The particle temperature [K] where the film laws balance,
    h (T_g - T_p) = k_m h_fg(T_p) (rho_v,sat(T_p) - rho_v,inf)."""
    far = moistair.vapour_density(T, W, p)
    return brentq(lambda Tp: h * (T - Tp) - km * moistair.latent_heat(Tp)
                  * (moistair.saturation_vapour_density(Tp) - far), 273.15, T, xtol=1e-12)


def water_activity(X, T):
    """a_w of shelled corn at moisture X [kg/kg d.b.] and T [K] (modified Henderson)."""
    A, B, C = HENDERSON
    if X <= 0:
        return 0.0
    return -math.expm1(-A * (T - 273.15 + C) * (100 * X) ** B)


def equilibrium_moisture(rh, T):
    A, B, C = HENDERSON
    return 0.01 * (-math.log1p(-rh) / (A * (T - 273.15 + C))) ** (1 / B)


def grain_latent_heat(X, T, dT=1e-3):
    """Heat [J/kg] to evaporate the kernel's water at X and T (Clausius-Clapeyron)."""
    slope = (math.log(water_activity(X, T + dT)) - math.log(water_activity(X, T - dT))) / (2 * dT)
    return moistair.latent_heat(T) + moistair.R_VAPOUR * T * T * slope


def film_coefficients(model, eps, us, d, gas):
    """h [W/m2/K] and k_m [m/s] of a kernel at rest in a stream of superficial
    velocity us: the correlation at Re = eps rho (u_s/eps) d/mu, Sh its Nu with
    Sc = mu/(rho D_v) for Pr; gas: rho, mu, Cp, kappa, Dv."""
    from spoutlab import heatcorrelations as hc
    re = gas['rho'] * us * d / gas['mu']
    h = hc.nusselt(model, re, gas['mu'] * gas['Cp'] / gas['kappa'], eps) * gas['kappa'] / d
    km = hc.nusselt(model, re, gas['mu'] / (gas['rho'] * gas['Dv']), eps) * gas['Dv'] / d
    return h, km


class Kernel:
    """The kernel and its stream: d [m], dry mass [kg], c_d, X0, T0 [K];
    the air T_g [K], W, p [Pa]; h [W/m2/K] and k_m [m/s] of the stream."""

    def __init__(self, d, dry_mass, cd, X0, T0, Tg, W, p, h, km):
        self.d, self.dry_mass, self.cd, self.X0, self.T0 = d, dry_mass, cd, X0, T0
        self.Tg, self.W, self.p, self.h, self.km = Tg, W, p, h, km
        self.area = math.pi * d * d
        self.far = moistair.vapour_density(Tg, W, p)
        self.rh = moistair.relative_humidity(Tg, W, p)
        self.Xeq = equilibrium_moisture(self.rh, Tg)

    def heating(self, X, T, mdot, latent):
        """dT/dt of the lumped kernel."""
        return (self.h * self.area * (self.Tg - T) - mdot * latent) / (self.dry_mass * (self.cd + X * moistair.CP_WATER))

    def free_water(self, t_end, times):
        def rhs(t, y):
            X, T = y
            mdot = self.km * self.area * (moistair.saturation_vapour_density(T) - self.far) if X > 0 else 0.0
            return [-mdot / self.dry_mass, self.heating(X, T, mdot, moistair.latent_heat(T))]
        return self._integrate(rhs, [self.X0, self.T0], t_end, times)

    def reaction_engineering(self, a, b, c, t_end, times):
        def rhs(t, y):
            X, T = y
            f = a * math.exp(-b * max(0.0, X - self.Xeq) ** c)
            surface = self.rh ** (f * self.Tg / T) * moistair.saturation_vapour_density(T)
            mdot = self.km * self.area * (surface - self.far)
            return [-mdot / self.dry_mass, self.heating(X, T, mdot, grain_latent_heat(X, T))]
        return self._integrate(rhs, [self.X0, self.T0], t_end, times)

    def kernel_diffusion(self, D0, Ea, t_end, times, nodes=200):
        """Fick's sphere on `nodes` equal radial cells (finite volumes, the
        surface moisture from the film condition on the outer half cell)."""
        R = 0.5 * self.d
        dr = R / nodes
        faces = np.arange(nodes + 1) * dr
        volumes = (faces[1:] ** 3 - faces[:-1] ** 3) / R ** 3      # fractions of the sphere
        areas = 3 * faces ** 2 / R ** 3                             # 4 pi r^2 / (4/3 pi R^3)
        rho_d = self.dry_mass / (math.pi * self.d ** 3 / 6)

        def surface_moisture(Xn, T, D):
            g = rho_d * D / (0.5 * dr)          # kg/m2/s per unit of X through the half cell
            rho_sat = moistair.saturation_vapour_density(T)
            film = lambda Xs: self.km * (water_activity(Xs, T) * rho_sat - self.far) - g * (Xn - Xs)
            if film(0.0) >= 0:
                return 0.0
            return brentq(film, 0.0, Xn + self.km * self.far / g + 1e-12, xtol=1e-14)

        def rhs(t, y):
            X, T = y[:-1], y[-1]
            D = D0 * math.exp(-Ea / (GAS_CONSTANT * T))
            Xs = surface_moisture(X[-1], T, D)
            flux = np.zeros(nodes + 1)                      # D dX/dr at the faces
            flux[1:-1] = D * (X[1:] - X[:-1]) / dr
            flux[-1] = D * (Xs - X[-1]) / (0.5 * dr)
            dX = (areas[1:] * flux[1:] - areas[:-1] * flux[:-1]) / volumes
            mdot = -self.dry_mass * areas[-1] * flux[-1]
            mean = float(np.dot(volumes, X))
            return np.append(dX, self.heating(mean, T, mdot, grain_latent_heat(Xs, T)))

        sparsity = np.zeros((nodes + 1, nodes + 1))
        for i in range(nodes):
            sparsity[i, max(0, i - 1):i + 2] = 1
        sparsity[:, -1] = sparsity[-1, :] = 1
        sol = solve_ivp(rhs, (0.0, t_end), np.append(np.full(nodes, self.X0), self.T0),
                        method='BDF', t_eval=times, rtol=1e-8, atol=1e-10, jac_sparsity=sparsity)
        if not sol.success:
            raise RuntimeError('kernel diffusion reference: ' + sol.message)
        return np.dot(volumes, sol.y[:-1]), sol.y[-1]

    @staticmethod
    def _integrate(rhs, y0, t_end, times):
        sol = solve_ivp(rhs, (0.0, t_end), y0, method='LSODA', t_eval=times,
                        rtol=1e-10, atol=1e-13, max_step=5.0)
        if not sol.success:
            raise RuntimeError('kernel reference: ' + sol.message)
        return sol.y[0], sol.y[1]
