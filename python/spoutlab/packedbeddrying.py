"""Drying of a fixed packed bed of wet kernels by warm air from below: the
two-phase plug-flow model with heat and water exchange, as the reference of
the CFD-DEM verification case (openfoam_cases/packedBedDrying).  The
heat-only model and its retarded-time method are spoutlab.packedbedheat's;
this module adds the water.

Model
-----
z points up; the bed fills 0 <= z <= L in layers of voidage eps, with the
heat- and mass-transfer coefficients h and k_m of each layer; the gas
enters at z = 0 with T_in and vapour mass fraction Y_in at the superficial
velocity u_s (incompressible at density rho_g; the evaporated water's mass
is not added to the flow, as in spoutFoam).  Per unit bed volume, with the
specific surface a = 6 (1 - eps)/d and the free-water (constant-rate)
drying law r = k_m (rho_v,sat(T_p) - rho_v(T_g, W)) per unit particle
surface (zero once the kernel has no water left, unless vapour condenses):

  vapour:  rho_g [eps dY/dt + u_s dY/dz]                   = a r
  energy:  rho_g [eps d(c_p T_g)/dt + u_s d(c_p T_g)/dz]   = h a (T_p - T_g)
                                                             + c_pv T_p a r
  water:   rho_d dX/dt                                     = -(6/d) r
  kernel:  rho_d (c_d + X c_w) dT_p/dt                     = (6/d) (h (T_g - T_p)
                                                                    - L(T_p) r)

c_p = (1 - Y) c_p,a + Y c_pv is the humid gas's (per kg of gas), rho_d the
kernel's dry mass per volume, c_d the dry solid's heat capacity, L free
water's heat of vaporisation, rho_v the vapour density of the gas at T_g and
its humidity ratio W = Y/(1 - Y) (spoutlab.moistair).  These are spoutFoam's
equations (docs/DESIGN.md §3.8) for a bed one cell across, without axial
conduction and diffusion (Peclet numbers of thousands).

Method
------
In the retarded time s = t - tau(z), tau(z) = integral_0^z eps/u_s dz', both
gas equations lose their time derivative exactly (packedbedheat), leaving
ordinary equations in z at fixed s for the gas and in s at fixed z for the
kernels.  The gas starts in equilibrium with the bed (saturated at the
bed's temperature), so nothing happens before the inlet gas arrives: the
state for s < 0 is the initial one.  The grid is the box scheme of
packedbedheat.solve, gas on the faces z_j and kernels in the cells, both at
s_n, second order:

    G[c+1] - G[c] = dz f(Gbar, S)                        (midpoint in z)
    S[n+1] - S[n] = ds/2 (g(S[n], Gbar[n]) + g(S[n+1], Gbar[n+1]))   (trapezoid)

nonlinear here, solved by fixed-point iteration.  Cell c at s_n needs only
cell c - 1 at s_n and cell c at s_(n-1), so each anti-diagonal c + n of the
grid is one vector step.  A kernel that dries out within a step loses
exactly its water (the step's latent heat scaled with it).

resolution: grid steps per unit of the shortest exchange length of the gas
and of the shortest time constant of the kernels (the wet kernel's,
including the evaporative cooling k_m L d rho_v,sat/dT at the kernels'
wet-bulb temperature); the error falls as 1/resolution^2.

Layers are given as a list of (thickness, eps, h, k_m) from the bottom up.
"""
import math

import numpy as np

from spoutlab import moistair as ma

ITERATIONS = 3     # fixed-point passes per grid node (contraction ~ 1/resolution)


def film_wet_bulb(T_gas, Y_gas, h, km, p=ma.ATMOSPHERE):
    """The temperature [K] at which a free-water kernel in gas of T_gas and
    Y_gas neither heats nor cools: h (T_g - T_p) = k_m L(T_p)
    (rho_v,sat(T_p) - rho_v,inf), by bisection."""
    rho_v = ma.vapour_density(T_gas, ma.ratio_of_mass_fraction(Y_gas), p)
    lo, hi = ma.KELVIN + 1e-6, T_gas
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        excess = h * (T_gas - mid) - km * ma.latent_heat(mid) * (
            ma.saturation_vapour_density(mid) - rho_v)
        if excess > 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


class DryingBedSolution:
    """The solution on the grid of solve(): gas T_g, Y on the cell faces
    z[j], kernels T_p, X in the cells, at the retarded times s[n]."""

    def __init__(self, z, s, tau, Tg, Yg, Tp, X, initial, props):
        self.z, self.s, self.tau = z, s, tau
        self.Tg, self.Yg, self.Tp, self.X = Tg, Yg, Tp, X
        self.initial = initial           # (T0, Y0, X0)
        self.props = props
        self.height = z[-1]

    def _at(self, table, j, s, before):
        """table[j, :] at retarded times s (linear in s), `before` for s < 0."""
        ds = self.s[1] - self.s[0]
        if np.any(s > self.s[-1] * (1 + 1e-12)):
            raise ValueError('time beyond the end of the solution')
        f = np.maximum(s, 0.0) / ds
        n = np.clip(np.floor(f).astype(int), 0, len(self.s) - 2)
        w = f - n
        value = (1 - w) * table[j, n] + w * table[j, n + 1]
        return np.where(s >= 0, value, before)

    def outlet(self, t):
        """(T_g, Y) leaving the top of the bed at times t."""
        t = np.asarray(t, float)
        s = t - self.tau[-1]
        j = np.full(t.shape, len(self.z) - 1)
        return (self._at(self.Tg, j, s, self.initial[0]),
                self._at(self.Yg, j, s, self.initial[1]))

    def _cells(self, t):
        centres = 0.5 * (self.z[:-1] + self.z[1:])
        s = t - 0.5 * (self.tau[:-1] + self.tau[1:])
        return centres, s, np.arange(len(centres))

    def kernel_profile(self, which, t):
        """(cell centres, the kernels' X ('X') or T_p ('Tp') there) at time t."""
        centres, s, cells = self._cells(t)
        table, before = (self.X, self.initial[2]) if which == 'X' else (self.Tp, self.initial[0])
        return centres, self._at(table, cells, s, before)

    def layer_mean(self, which, z0, z1, t):
        """Mean of the kernels' X ('X') or T_p ('Tp') over z0 <= z <= z1 at
        time t (scalar): the cells weighted by their overlap with the layer."""
        _, values = self.kernel_profile(which, t)
        overlap = np.clip(np.minimum(self.z[1:], z1) - np.maximum(self.z[:-1], z0), 0, None)
        return float(overlap @ values / (z1 - z0))

    def water_balance(self, t):
        """(water the kernels lost, vapour the gas carried out less what it
        brought in plus the change of its holdup) per unit cross-section
        [kg/m2] by time t (scalar): equal to the grid's accuracy."""
        p = self.props
        dz = np.diff(self.z)
        eps = p['eps_cells']
        _, s, cells = self._cells(t)
        X = self._at(self.X, cells, s, self.initial[2])
        lost = float(np.sum((1 - eps) * p['rho_d'] * dz * (self.initial[2] - X)))
        Y = self._at(self.Yg, np.arange(len(self.z)), t - self.tau, self.initial[1])
        holdup = float(np.sum(eps * p['rho_g'] * dz * (0.5 * (Y[:-1] + Y[1:]) - self.initial[1])))
        # what left through the top: the initial gas until the inlet's
        # arrives (tau(L)), then the grid's outlet, trapezoids in s
        transit = self.tau[-1]
        out = (self.initial[1] - p['Yin']) * min(t, transit)
        if t > transit:
            s_end = t - transit
            s = np.append(self.s[self.s < s_end], s_end)
            top = np.interp(s, self.s, self.Yg[-1]) - p['Yin']
            out += float(np.sum(0.5 * (top[:-1] + top[1:]) * np.diff(s)))
        return lost, p['rho_g'] * p['u_s'] * out + holdup


def check_initial_gas(T0, Y0, X0, p):
    """The initial gas saturated at T0 for wet kernels, at most saturated
    for dry ones (else nothing starts in equilibrium)."""
    rho_w0 = ma.saturation_vapour_density(T0)
    rho_v0 = ma.vapour_density(T0, ma.ratio_of_mass_fraction(Y0), p)
    if (X0 > 0 and abs(rho_w0 - rho_v0) > 1e-9 * rho_w0) or rho_v0 > rho_w0 * (1 + 1e-9):
        raise ValueError('packedbeddrying.solve: the initial gas must be saturated at T0 '
                         '(at most, for dry kernels), got a relative humidity of %.9f'
                         % (rho_v0 / rho_w0))


def retarded_grid(layers, t_end, resolution, *, u_s, d, rho_d, c_d, rho_g, cp_air, T0, Tin,
                  wet_bulb, p):
    """The grid of the characteristics: the faces z and their gas transit
    times tau, cells per layer from the shortest gas exchange length (each
    cell's layer in cells), and the retarded times s, steps from the fastest
    kernel (its heat and, near T_wet, its latent heat)."""
    six_d = 6.0 / d
    flow = rho_g * u_s
    T_wet = max(T0, wet_bulb) + 5.0
    rho_ideal = p / (ma.R_AIR * min(T0, Tin, wet_bulb))
    faces, tau, cells = [0.0], [0.0], []
    kernel_rate = 0.0
    for i, (thickness, eps, h, km) in enumerate(layers):
        per_length = (1 - eps) * six_d * max(km * rho_ideal / flow, h / (flow * cp_air))
        n = max(4, int(math.ceil(resolution * per_length * thickness)))
        bottom, tau_bottom = faces[-1], tau[-1]
        for k in range(1, n + 1):
            faces.append(bottom + thickness * k / n)
            tau.append(tau_bottom + eps / u_s * thickness * k / n)
            cells.append(i)
        if eps < 1:
            kernel_rate = max(kernel_rate, six_d / rho_d * (
                h + km * ma.latent_heat(T_wet) * ma.saturation_vapour_density_slope(T_wet)) / c_d)
    steps = max(4, int(math.ceil(resolution * kernel_rate * t_end)))
    s = np.linspace(0.0, t_end, steps + 1)
    return np.array(faces), np.array(tau), np.array(cells), s


class _CellExchange:
    """The exchange of the grid's cells: the gas across a cell (midpoint
    rule) and the kernels' rates, with the film coefficients of each
    cell's layer."""

    def __init__(self, layers, cells, dz, *, u_s, d, rho_d, c_d, rho_g, cp_air, p):
        six_d = 6.0 / d
        flow = rho_g * u_s
        lay = np.array(layers, float)
        self.eps = lay[cells, 1]
        self.aH = (1 - self.eps) * six_d * lay[cells, 2] / flow * dz   # per cell, x (T_p - T_g)
        self.aY = (1 - self.eps) * six_d * lay[cells, 3] / flow * dz   # x (rho_sat - rho_v)
        self.bH = six_d * lay[cells, 2] / rho_d                        # kernel, per second
        self.bY = six_d * lay[cells, 3] / rho_d
        self.c_d, self.cp_air, self.p = c_d, cp_air, p

    def film(self, Tk, Tgas, Ygas, wet):
        """The free-water rate per unit surface and film coefficient,
        rho_v,sat(T_p) - rho_v(T_g, W); nothing leaves a dry kernel."""
        r = ma.saturation_vapour_density(Tk) - ma.vapour_density(
            Tgas, ma.ratio_of_mass_fraction(Ygas), self.p)
        return np.where(wet | (r < 0), r, 0.0)

    def gas_out(self, c, T_in, Y_in, T_out, Y_out, Tk, wet):
        """The gas leaving cell c (midpoint rule), from its inflow, a guess of
        its outflow and the kernels."""
        cp_air, aH, aY = self.cp_air, self.aH, self.aY
        e_in = ma.humid_heat_capacity(Y_in, cp_air) * T_in
        for _ in range(ITERATIONS):
            Tm, Ym = 0.5 * (T_in + T_out), 0.5 * (Y_in + Y_out)
            r = self.film(Tk, Tm, Ym, wet)
            Y_out = Y_in + aY[c] * r
            e_out = e_in + aH[c] * (Tk - Tm) + ma.CP_VAPOUR * Tk * aY[c] * r
            T_out = e_out / ma.humid_heat_capacity(Y_out, cp_air)
        return T_out, Y_out

    def kernel_rates(self, c, Tk, Xk, wet, Tm, Ym):
        """dT_p/ds without and with only the latent heat, and dX/ds."""
        r = self.film(Tk, Tm, Ym, wet)
        cap = self.c_d + Xk * ma.CP_WATER
        return (self.bH[c] * (Tm - Tk) / cap, -ma.latent_heat(Tk) * self.bY[c] * r / cap,
                -self.bY[c] * r)


def march(exchange, Tg, Yg, Tp, X, ds):
    """Fill the tables diagonal by diagonal (k = cell + step): each cell's
    gas from its inflow and its kernels from their previous step (the
    trapezoidal rule, iterated with the gas); the inlet row Tg[0], Yg[0]
    and the kernels' first step Tp[:, 0], X[:, 0] given."""
    nc, steps = Tp.shape[0], Tp.shape[1] - 1
    for k in range(nc + steps):
        c = np.arange(max(0, k - steps), min(nc - 1, k) + 1)
        n = k - c
        first = n == 0                      # the cell starting s = 0 on this diagonal
        old = np.maximum(n - 1, 0)
        T_in, Y_in = Tg[c, n], Yg[c, n]
        # the kernels at s_(n-1) and the gas around them then
        Tk0, Xk0 = Tp[c, old], X[c, old]
        wet0 = Xk0 > 0
        T_out = np.where(first, T_in, Tg[c + 1, old])
        Y_out = np.where(first, Y_in, Yg[c + 1, old])
        Tm0 = 0.5 * (Tg[c, old] + T_out)
        Ym0 = 0.5 * (Yg[c, old] + Y_out)
        h0, l0, x0 = exchange.kernel_rates(c, Tk0, Xk0, wet0, Tm0, Ym0)
        Tk = np.where(first, Tk0, Tk0 + ds * (h0 + l0))
        Xk = np.where(first, Xk0, np.where(wet0, np.maximum(Xk0 + ds * x0, 0.0), Xk0 + ds * x0))
        for _ in range(ITERATIONS):
            T_out, Y_out = exchange.gas_out(c, T_in, Y_in, T_out, Y_out, Tk, Xk > 0)
            Tm, Ym = 0.5 * (T_in + T_out), 0.5 * (Y_in + Y_out)
            h1, l1, x1 = exchange.kernel_rates(c, Tk, Xk, wet0, Tm, Ym)
            loss = -0.5 * ds * (x0 + x1)
            # a kernel drying out within the step loses exactly its water
            out = wet0 & (loss >= Xk0)
            share = np.where(out, Xk0 / np.where(out, loss, 1.0), 1.0)
            Xk = np.where(first, Xk0, np.where(out, 0.0, Xk0 - loss))
            Tk = np.where(first, Tk0, Tk0 + 0.5 * ds * (h0 + h1 + share * (l0 + l1)))
        Tp[c, n], X[c, n] = Tk, Xk
        Tg[c + 1, n], Yg[c + 1, n] = T_out, Y_out


def solve(layers, t_end, *, u_s, d, rho_d, c_d, rho_g, cp_air, T0, Y0, X0, Tin, Yin,
          p=ma.ATMOSPHERE, resolution=20, wet_bulb=None):
    """Numerical solution of the model for layers [(thickness, eps, h, k_m),
    ...] from the bottom up, up to time t_end.  T0, Y0: the gas and kernels
    at the start (Y0 saturated at T0 for wet kernels, else nothing is in
    equilibrium; at most saturated for dry ones); X0 the kernels' moisture;
    Tin, Yin the inlet gas; p the total pressure.
    wet_bulb: the kernels' temperature while they dry, for the step size
    (default: the film wet bulb of the inlet gas in the first layer)."""
    check_initial_gas(T0, Y0, X0, p)
    if wet_bulb is None:
        wet_bulb = film_wet_bulb(Tin, Yin, layers[0][2], layers[0][3], p)
    kernel = dict(u_s=u_s, d=d, rho_d=rho_d, c_d=c_d, rho_g=rho_g, cp_air=cp_air, p=p)
    z, tau, cells, s = retarded_grid(layers, t_end, resolution, T0=T0, Tin=Tin,
                                     wet_bulb=wet_bulb, **kernel)
    exchange = _CellExchange(layers, cells, np.diff(z), **kernel)
    nc, steps = len(cells), len(s) - 1
    Tg = np.empty((nc + 1, steps + 1))
    Yg = np.empty((nc + 1, steps + 1))
    Tp = np.empty((nc, steps + 1))
    X = np.empty((nc, steps + 1))
    Tg[0], Yg[0] = Tin, Yin
    Tp[:, 0], X[:, 0] = T0, X0
    march(exchange, Tg, Yg, Tp, X, s[1] - s[0])
    props = dict(u_s=u_s, d=d, rho_d=rho_d, c_d=c_d, rho_g=rho_g, cp_air=cp_air, p=p,
                 Tin=Tin, Yin=Yin, eps_cells=exchange.eps)
    return DryingBedSolution(z, s, tau, Tg, Yg, Tp, X, (T0, Y0, X0), props)
