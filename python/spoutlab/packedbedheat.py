"""Heating of a fixed packed bed by hot gas from below: the two-phase
plug-flow model (Schumann 1929), as the reference of the CFD-DEM
verification case.

Model
-----
z points up; the bed fills 0 <= z <= L; gas enters at z = 0 with T_in; gas
and solid start at T_0.  With the superficial velocity u_s (constant, the
gas is incompressible), the specific surface a = 6 (1 - eps) / d and the
gas-to-particle heat-transfer coefficient h:

    gas:    eps rho_g c_g dTg/dt + rho_g c_g u_s dTg/dz = h a (Ts - Tg)
    solid:  (1 - eps) rho_s c_s dTs/dt                  = h a (Tg - Ts)

eps(z) and h(z) may change from layer to layer; rho_g, c_g, rho_s, c_s, d
and u_s are the same everywhere.

Retarded time
-------------
The gas moves at the interstitial velocity u_s/eps, so a gas parcel needs
tau(z) = integral_0^z eps/u_s dz' to reach z.  In the coordinates (z, s)
with s = t - tau(z) the gas accumulation term is absorbed exactly:

    rho_g c_g u_s dTg/dz|_s = h a (Ts - Tg),
    (1 - eps) rho_s c_s dTs/ds|_z = h a (Tg - Ts).

For s < 0 (the first hot gas has not yet arrived) gas and solid are at T_0.
Along s = 0 the solid is still at T_0 and the front gas cools as
exp(-y).  Pure advection (h = 0) is therefore exact in these coordinates.

Dimensionless variables
-----------------------
    y     = h a z / (rho_g c_g u_s)                            (gas: length)
    theta = h a (t - eps z / u_s) / ((1 - eps) rho_s c_s)      (solid: time)
    T*    = (T - T_0) / (T_in - T_0)

which turn the model into dTg*/dy = Ts* - Tg*, dTs*/dtheta = Tg* - Ts*,
with Tg*(0, theta) = 1 and Ts*(y, 0) = 0.

Schumann's solution
-------------------
With Anzelius's J-function

    J(a, b) = 1 - exp(-a) integral_0^b exp(-xi) I0(2 sqrt(a xi)) dxi

the gas and solid temperatures are (the arguments are swapped between the
phases):

    Tg* = J(theta, y)           (gas)
    Ts* = 1 - J(y, theta)       (solid)

(Laplace transform in theta: Ts^ = Tg^/(p + 1), Tg^ = exp(-y p/(p+1))/p.)
Checks: Tg* - Ts* = exp(-y - theta) I0(2 sqrt(y theta)); at y = 0 the
solid heats as 1 - exp(-theta); at theta = 0 the gas is exp(-y).  In terms
of the non-central chi-squared distribution, Ts* = P(2 theta; k=2, nc=2 y).

The integral is evaluated as exp(-(u - sqrt(a))^2) i0e(2 u sqrt(a)) 2u du
with xi = u^2, so no exponential can overflow for large y and theta.

If h is the same in all layers (eps may differ), h a / ((1 - eps) rho_s c_s)
= 6 h / (d rho_s c_s) is uniform, and the solution is Schumann's with y
and tau accumulated layer by layer (schumann_layered).  For general layers
solve() integrates the model numerically.

Layers are given as a list of (thickness, eps, h) from the bottom up.
"""
import math

import numpy as np
from scipy.signal import lfilter
from scipy.special import i0e


# --- Schumann's analytic solution --------------------------------------------

_GL_NODES, _GL_WEIGHTS = np.polynomial.legendre.leggauss(10)


def schumann_integral(a, b):
    """exp(-a) integral_0^b exp(-xi) I0(2 sqrt(a xi)) dxi = 1 - J(a, b),
    for a, b >= 0 (arrays broadcast).  Composite Gauss-Legendre in
    u = sqrt(xi) with panels no wider than 0.5, where the integrand
    2u exp(-(u - sqrt(a))^2) i0e(2u sqrt(a)) is smooth and bounded."""
    a, b = np.broadcast_arrays(np.asarray(a, float), np.asarray(b, float))
    upper = np.sqrt(np.maximum(b, 0.0))
    panels = max(4, int(math.ceil(upper.max(initial=0.0) / 0.5)))
    # nodes and weights of the composite rule on [0, 1]
    left = np.arange(panels) / panels
    x = (left[:, None] + (_GL_NODES[None, :] + 1.0) / (2 * panels)).ravel()
    w = np.tile(_GL_WEIGHTS / (2 * panels), panels)
    u = upper[..., None] * x
    root_a = np.sqrt(np.maximum(a, 0.0))[..., None]
    integrand = 2 * u * np.exp(-(u - root_a) ** 2) * i0e(2 * u * root_a)
    return upper * (integrand @ w)


def anzelius_j(a, b):
    """J(a, b) = 1 - exp(-a) integral_0^b exp(-xi) I0(2 sqrt(a xi)) dxi."""
    return 1.0 - schumann_integral(a, b)


def schumann_dimensionless(y, theta):
    """(Tg*, Ts*) at distance y and retarded time theta; (0, 0) before the
    gas front arrives (theta < 0)."""
    y, theta = np.broadcast_arrays(np.asarray(y, float), np.asarray(theta, float))
    arrived = theta >= 0
    th = np.where(arrived, theta, 0.0)
    gas = np.where(arrived, anzelius_j(th, y), 0.0)
    solid = np.where(arrived, 1.0 - anzelius_j(y, th), 0.0)
    return gas, solid


def exchange_per_length(eps, h, *, u_s, d, rho_g, c_g, **_):
    """dy/dz = h a / (rho_g c_g u_s), 1/m."""
    return h * 6 * (1 - eps) / d / (rho_g * c_g * u_s)


def exchange_per_time(eps, h, *, d, rho_s, c_s, **_):
    """dtheta/dt = h a / ((1 - eps) rho_s c_s) = 6 h / (d rho_s c_s), 1/s."""
    return h * 6 * (1 - eps) / d / ((1 - eps) * rho_s * c_s)


def schumann(z, t, *, eps, h, u_s, d, rho_s, c_s, rho_g, c_g, T0, Tin):
    """Gas and solid temperatures (Tg, Ts) of a uniform bed at heights z and
    times t (arrays broadcast), Schumann's solution.  Both are T0 before the
    gas front eps z / u_s arrives."""
    return schumann_layered(z, t, [(np.inf, eps, h)], u_s=u_s, d=d, rho_s=rho_s,
                            c_s=c_s, rho_g=rho_g, c_g=c_g, T0=T0, Tin=Tin)


def schumann_layered(z, t, layers, *, u_s, d, rho_s, c_s, rho_g, c_g, T0, Tin):
    """Schumann's solution for layers of different eps but one h: y and the
    gas transit time are accumulated layer by layer; theta advances at the
    same rate 6 h / (d rho_s c_s) everywhere, so the dimensionless problem
    is Schumann's.  Raises ValueError if h differs between layers."""
    props = dict(u_s=u_s, d=d, rho_s=rho_s, c_s=c_s, rho_g=rho_g, c_g=c_g)
    if len({h for _, _, h in layers}) != 1:
        raise ValueError('schumann_layered needs the same h in every layer')
    z, t = np.broadcast_arrays(np.asarray(z, float), np.asarray(t, float))
    y = np.zeros_like(z)
    tau = np.zeros_like(z)
    bottom = 0.0
    for thickness, eps, h in layers:
        inside = np.clip(z - bottom, 0.0, thickness)
        y += exchange_per_length(eps, h, **props) * inside
        tau += eps / u_s * inside
        bottom += thickness
    theta = exchange_per_time(layers[0][1], layers[0][2], **props) * (t - tau)
    gas, solid = schumann_dimensionless(y, theta)
    return T0 + (Tin - T0) * gas, T0 + (Tin - T0) * solid


def mean_solid_temperature(solid, z0, z1, t, kinks=(), panels=8):
    """Mean of solid(z, t) over the layer z0 <= z <= z1 at time t (scalar),
    by composite Gauss-Legendre split at the given kinks (e.g. the gas
    front), where the profile is not smooth."""
    cuts = sorted({z0, z1, *[k for k in kinks if z0 < k < z1]})
    total = 0.0
    for a, b in zip(cuts[:-1], cuts[1:]):
        edges = np.linspace(a, b, panels + 1)
        mid = 0.5 * (edges[:-1] + edges[1:])[:, None]
        half = 0.5 * (b - a) / panels
        zq = (mid + half * _GL_NODES[None, :]).ravel()
        wq = np.tile(half * _GL_WEIGHTS, panels)
        total += wq @ np.asarray(solid(zq, np.full_like(zq, t)), float)
    return total / (z1 - z0)


def schumann_mean_solid(z0, z1, t, *, eps, u_s, **params):
    """Layer-averaged solid temperature of Schumann's solution."""
    front = u_s * t / eps
    return mean_solid_temperature(
        lambda z, tt: schumann(z, tt, eps=eps, u_s=u_s, **params)[1],
        z0, z1, t, kinks=[front])


# --- Numerical solution for piecewise layers ---------------------------------

class PackedBedSolution:
    """The numerical solution on the grid of solve(): gas G on the cell
    faces z[j], solid S in the cells, both at the retarded times s[n] and
    both dimensionless (T - T0)/(Tin - T0)."""

    def __init__(self, layers, z, s, G, S, cell_layer, tau, props, T0, Tin):
        self.layers, self.z, self.s, self.G, self.S = layers, z, s, G, S
        self.cell_layer, self.tau, self.props = cell_layer, tau, props
        self.T0, self.Tin = T0, Tin
        self.height = z[-1]
        self.first_cell = np.searchsorted(cell_layer, np.arange(len(layers)))
        self.cells_in_layer = np.bincount(cell_layer, minlength=len(layers))

    def _dimensional(self, value):
        return self.T0 + (self.Tin - self.T0) * value

    def _time_weights(self, s):
        ds = self.s[1] - self.s[0]
        n = np.clip(np.floor(s / ds).astype(int), 0, len(self.s) - 2)
        return n, s / ds - n

    def _cell_of(self, z):
        """Cell holding z; a face between two layers belongs to the upper."""
        return np.clip(np.searchsorted(self.z, z, side='right') - 1, 0, len(self.z) - 2)

    def retarded_time(self, z, t):
        return t - np.interp(z, self.z, self.tau)

    def _check_time(self, s):
        if np.any(s > self.s[-1] * (1 + 1e-12)):
            raise ValueError('time beyond the end of the solution')

    def gas(self, z, t):
        """Gas temperature at heights z and times t (arrays broadcast)."""
        z, t = np.broadcast_arrays(np.asarray(z, float), np.asarray(t, float))
        s = self.retarded_time(z, t)
        self._check_time(s)
        j = self._cell_of(z)
        lam = (z - self.z[j]) / (self.z[j + 1] - self.z[j])
        n, w = self._time_weights(np.maximum(s, 0.0))
        G = self.G
        low = (1 - w) * G[j, n] + w * G[j, n + 1]
        high = (1 - w) * G[j + 1, n] + w * G[j + 1, n + 1]
        return self._dimensional(np.where(s >= 0, (1 - lam) * low + lam * high, 0.0))

    def solid(self, z, t):
        """Solid temperature at heights z and times t, linear between the
        cell centres of one layer (extrapolated in the half cells at its
        faces: the solid temperature jumps where eps or h changes)."""
        z, t = np.broadcast_arrays(np.asarray(z, float), np.asarray(t, float))
        s = self.retarded_time(z, t)
        self._check_time(s)
        layer = self.cell_layer[self._cell_of(z)]
        first, count = self.first_cell[layer], self.cells_in_layer[layer]
        bottom = self.z[first]
        dz = (self.z[first + count] - bottom) / count
        f = (z - bottom) / dz - 0.5
        k = np.clip(np.floor(f).astype(int), 0, np.maximum(count - 2, 0))
        mu = np.where(count > 1, f - k, 0.0)
        c0 = first + k
        c1 = np.minimum(c0 + 1, first + count - 1)
        n, w = self._time_weights(np.maximum(s, 0.0))
        S = self.S
        at0 = (1 - w) * S[c0, n] + w * S[c0, n + 1]
        at1 = (1 - w) * S[c1, n] + w * S[c1, n + 1]
        return self._dimensional(np.where(s >= 0, (1 - mu) * at0 + mu * at1, 0.0))

    def outlet(self, t):
        """Gas temperature leaving the top of the bed at times t."""
        t = np.asarray(t, float)
        return self.gas(np.full_like(t, self.height), t)

    def _cell_values(self, t):
        centres = 0.5 * (self.z[:-1] + self.z[1:])
        s = self.retarded_time(centres, t)
        self._check_time(s)
        n, w = self._time_weights(np.maximum(s, 0.0))
        cells = np.arange(len(centres))
        value = (1 - w) * self.S[cells, n] + w * self.S[cells, n + 1]
        return np.where(s >= 0, value, 0.0)

    def mean_solid(self, z0, z1, t):
        """Mean solid temperature over z0 <= z <= z1 at time t (scalar): the
        cell values weighted by their overlap with the layer."""
        overlap = np.clip(np.minimum(self.z[1:], z1) - np.maximum(self.z[:-1], z0), 0, None)
        return self._dimensional(overlap @ self._cell_values(t) / (z1 - z0))

    def energy_balance(self, t):
        """(heat stored in gas and solid, net enthalpy brought in by the gas)
        per unit cross-section, J/m2, at time t (scalar)."""
        p = self.props
        dT = self.Tin - self.T0
        eps = np.array([layer[1] for layer in self.layers])[self.cell_layer]
        dz = np.diff(self.z)
        solid = np.sum((1 - eps) * p['rho_s'] * p['c_s'] * dz * self._cell_values(t))
        # gas: trapezoids per cell, cut at the front if it is inside the bed
        front = np.interp(t, self.tau, self.z, right=np.inf)
        g = (self.gas(self.z, t) - self.T0) / dT
        behind = self.z[1:] <= front
        gas_cells = np.where(behind, 0.5 * (g[:-1] + g[1:]) * dz, 0.0)
        j = np.searchsorted(self.z, front, side='right') - 1
        if 0 <= j < len(dz):
            front_gas = np.interp(front, self.z, self.G[:, 0])
            gas_cells[j] = 0.5 * (g[j] + front_gas) * (front - self.z[j])
        gas = np.sum(eps * p['rho_g'] * p['c_g'] * gas_cells)
        # in minus out: the outlet stays at T0 until tau(L), then G(L, s)
        transit = self.tau[-1]
        s_end = t - transit
        flux = p['rho_g'] * p['c_g'] * p['u_s']
        if s_end <= 0:
            entered = flux * t
        else:
            s = np.append(self.s[self.s < s_end], s_end)
            out = np.interp(s, self.s, self.G[-1])
            cold = 1.0 - out
            entered = flux * (transit + np.sum(0.5 * (cold[:-1] + cold[1:]) * np.diff(s)))
        return (solid + gas) * dT, entered * dT


def solve(layers, t_end, *, u_s, d, rho_s, c_s, rho_g, c_g, T0, Tin, resolution=20):
    """Numerical solution of the two-phase model for layers [(thickness,
    eps, h), ...] from the bottom up, up to time t_end.

    The model is integrated in the retarded time s = t - tau(z) (see the
    module notes), which carries the gas along its characteristics exactly.
    On a grid with every layer face on a cell face, the box scheme
    (Keller/Preissmann, second order) couples the gas on the cell faces to
    the solid in the cells:

        G[j+1] - G[j] = alpha dz (S - (G[j] + G[j+1])/2)          at s[n+1]
        S[n+1] - S[n] = beta ds (Gbar - S) averaged over s[n], s[n+1]

    with alpha = dy/dz, beta = dtheta/dt of the cell's layer and Gbar the
    cell mean of the gas.  The gas is eliminated cell by cell, which leaves
    a linear recurrence in time for the solid of each cell.

    resolution: grid steps per unit of y and per unit of theta (the
    exchange length and the solid's time constant), in the layer where
    they are shortest; the error falls as 1/resolution^2."""
    props = dict(u_s=u_s, d=d, rho_s=rho_s, c_s=c_s, rho_g=rho_g, c_g=c_g)
    alphas = [exchange_per_length(eps, h, **props) for _, eps, h in layers]
    betas = [exchange_per_time(eps, h, **props) for _, eps, h in layers]

    faces, tau, cell_layer = [0.0], [0.0], []
    for i, (thickness, eps, _) in enumerate(layers):
        cells = max(4, int(math.ceil(resolution * alphas[i] * thickness)))
        bottom, tau_bottom = faces[-1], tau[-1]
        for k in range(1, cells + 1):
            faces.append(bottom + thickness * k / cells)
            tau.append(tau_bottom + eps / u_s * thickness * k / cells)
            cell_layer.append(i)
    z = np.array(faces)
    tau = np.array(tau)
    cell_layer = np.array(cell_layer)

    steps = max(4, int(math.ceil(resolution * max(betas) * t_end)))
    s = np.linspace(0.0, t_end, steps + 1)
    ds = s[1] - s[0]

    G = np.empty((len(z), len(s)))
    S = np.empty((len(z) - 1, len(s)))
    G[0] = 1.0                        # hot gas at the inlet from s = 0 on
    for c in range(len(z) - 1):
        A = alphas[cell_layer[c]] * (z[c + 1] - z[c])
        B = betas[cell_layer[c]] * ds
        r = 1.0 / (1.0 + A / 2)
        p, q = (1.0 - A / 2) * r, A * r     # G[c+1] = p G[c] + q S
        k = B * r / 2
        forcing = np.zeros(len(s))
        forcing[1:] = k / (1 + k) * (G[c, :-1] + G[c, 1:])
        S[c] = lfilter([1.0], [1.0, -(1 - k) / (1 + k)], forcing)   # S[c, 0] = 0
        G[c + 1] = p * G[c] + q * S[c]
    return PackedBedSolution(layers, z, s, G, S, cell_layer, tau, props, T0, Tin)
