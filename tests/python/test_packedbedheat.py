"""The reference of the packed-bed heating case: Schumann's analytic solution
of the two-phase plug-flow model, and the numerical solver for beds whose
voidage and heat-transfer coefficient change from layer to layer."""
import math
import sys
import unittest

import numpy as np
from scipy.integrate import quad
from scipy.special import i0
from scipy.stats import ncx2

from spoutlab import packedbedheat as pb

# the verification case: 8 mm particles with a heat capacity made small so
# that the front crosses the bed in seconds
PROPS = dict(u_s=0.75, d=0.008, rho_s=1231.0, c_s=20.0, rho_g=1.2, c_g=1007.0,
             T0=300.0, Tin=400.0)
DT = PROPS['Tin'] - PROPS['T0']
EPS, H, L = 0.42, 150.0, 0.2          # y(L) = 14.4, theta(10 s) = 45
T_END = 10.0


def schumann(z, t, eps=EPS, h=H, **change):
    return pb.schumann(z, t, eps=eps, h=h, **dict(PROPS, **change))


def series_integral(a, b, terms=200):
    """exp(-a) integral_0^b exp(-xi) I0(2 sqrt(a xi)) dxi from the series of
    I0 integrated term by term: exp(-a) sum_n a^n/n! P(n+1, b), with P the
    regularised lower incomplete gamma function."""
    total, a_term = 0.0, 1.0                 # a^n / n!
    b_term, b_sum = 1.0, 1.0                 # b^m / m!, sum_{m<=n}
    for n in range(terms):
        if n:
            a_term *= a / n
            b_term *= b / n
            b_sum += b_term
        total += a_term * (1.0 - math.exp(-b) * b_sum)
    return math.exp(-a) * total


def energy_balance_of_schumann(t, eps=EPS, h=H, height=L):
    """(stored, entered) in J/m2 by adaptive quadrature of Schumann's solution."""
    p = PROPS
    front = p['u_s'] * t / eps

    def stored(z):
        tg, ts = schumann(z, t, eps, h)
        return (eps * p['rho_g'] * p['c_g'] * (tg - p['T0'])
                + (1 - eps) * p['rho_s'] * p['c_s'] * (ts - p['T0']))

    cuts = [0.0] + ([front] if front < height else []) + [height]
    heat = sum(quad(lambda z: float(stored(z)), a, b, epsabs=0, epsrel=1e-10, limit=200)[0]
               for a, b in zip(cuts[:-1], cuts[1:]))
    transit = eps * height / p['u_s']
    flux = p['rho_g'] * p['c_g'] * p['u_s']
    entered = flux * DT * min(t, transit)
    if t > transit:
        entered += flux * quad(lambda tt: float(p['Tin'] - schumann(height, tt, eps, h)[0]),
                               transit, t, epsabs=0, epsrel=1e-10, limit=200)[0]
    return heat, entered


def max_error(sol, eps=EPS, h=H, height=L):
    z, t = np.meshgrid(np.linspace(0, height, 61), np.linspace(0, T_END, 201))
    tg, ts = schumann(z, t, eps, h)
    return (np.abs(sol.gas(z, t) - tg).max() / DT, np.abs(sol.solid(z, t) - ts).max() / DT)


def rms_error(sol):
    z, t = np.meshgrid(np.linspace(0, L, 61), np.linspace(0, T_END, 201))
    tg, ts = schumann(z, t)
    return math.sqrt(np.mean((sol.gas(z, t) - tg) ** 2 + (sol.solid(z, t) - ts) ** 2)) / DT


class SchumannFunction(unittest.TestCase):
    """The dimensionless solution Tg* = J(theta, y), Ts* = 1 - J(y, theta)."""
    y, theta = np.meshgrid([0.0, 0.3, 1.0, 4.0, 14.0, 30.0, 50.0],
                           [0.0, 0.2, 1.0, 5.0, 14.0, 45.0, 60.0])

    def test_equals_the_term_by_term_series(self):
        for a, b in [(1.0, 1.0), (0.3, 4.0), (5.0, 2.0), (14.0, 14.0), (20.0, 30.0)]:
            self.assertAlmostEqual(float(pb.schumann_integral(a, b)), series_integral(a, b),
                                   places=12, msg=(a, b))

    def test_solid_is_the_noncentral_chi_squared_distribution(self):
        gas, solid = pb.schumann_dimensionless(self.y, self.theta)
        np.testing.assert_allclose(solid, ncx2.cdf(2 * self.theta, 2, 2 * self.y), atol=1e-12)
        np.testing.assert_allclose(gas, ncx2.sf(2 * self.y, 2, 2 * self.theta), atol=1e-12)

    def test_gas_minus_solid_is_the_exchange_kernel(self):
        # Tg* - Ts* = exp(-y - theta) I0(2 sqrt(y theta)); at y = theta = 1:
        # exp(-2) I0(2) = 0.135335 * 2.279585 = 0.308508
        gas, solid = pb.schumann_dimensionless(1.0, 1.0)
        self.assertAlmostEqual(float(gas - solid), 0.308508, places=6)
        y, th = self.y[:4, :4], self.theta[:4, :4]
        gas, solid = pb.schumann_dimensionless(y, th)
        np.testing.assert_allclose(gas - solid, np.exp(-y - th) * i0(2 * np.sqrt(y * th)),
                                   atol=1e-13)

    def test_inlet_solid_heats_as_one_minus_exp(self):
        theta = np.linspace(0, 20, 41)
        gas, solid = pb.schumann_dimensionless(0.0, theta)
        np.testing.assert_allclose(solid, 1 - np.exp(-theta), atol=1e-13)
        np.testing.assert_allclose(gas, 1.0, atol=1e-13)

    def test_front_gas_cools_as_exp_minus_y_on_a_cold_bed(self):
        y = np.linspace(0, 50, 51)
        gas, solid = pb.schumann_dimensionless(y, 0.0)
        np.testing.assert_allclose(gas, np.exp(-y), atol=1e-14)
        np.testing.assert_allclose(solid, 0.0, atol=1e-14)

    def test_no_overflow_far_into_the_bed_and_late(self):
        gas, solid = pb.schumann_dimensionless(self.y, self.theta)
        self.assertTrue(np.all(np.isfinite(gas)) and np.all(np.isfinite(solid)))
        self.assertTrue(np.all((solid >= -1e-15) & (solid <= gas + 1e-15) & (gas <= 1 + 1e-15)))
        gas, solid = pb.schumann_dimensionless(400.0, 400.0)
        self.assertTrue(np.isfinite(gas) and np.isfinite(solid) and 0 < solid < gas < 1)


class SchumannBed(unittest.TestCase):
    """The dimensional solution for the case's bed."""

    def test_satisfies_the_model_equations(self):
        p = PROPS
        a = 6 * (1 - EPS) / p['d']
        z, t = np.meshgrid(np.linspace(0.01, 0.19, 10), np.linspace(0.5, 8.0, 16))
        dz, dt = 1e-5, 1e-5
        tg, ts = schumann(z, t)
        dtg_dt = (schumann(z, t + dt)[0] - schumann(z, t - dt)[0]) / (2 * dt)
        dts_dt = (schumann(z, t + dt)[1] - schumann(z, t - dt)[1]) / (2 * dt)
        dtg_dz = (schumann(z + dz, t)[0] - schumann(z - dz, t)[0]) / (2 * dz)
        gas = (EPS * p['rho_g'] * p['c_g'] * dtg_dt + p['rho_g'] * p['c_g'] * p['u_s'] * dtg_dz
               - H * a * (ts - tg))
        solid = (1 - EPS) * p['rho_s'] * p['c_s'] * dts_dt - H * a * (tg - ts)
        scale = H * a * DT
        self.assertLess(np.abs(gas).max() / scale, 1e-6)
        self.assertLess(np.abs(solid).max() / scale, 1e-6)

    def test_inlet_gas_is_hot_once_it_flows(self):
        np.testing.assert_allclose(schumann(0.0, np.linspace(1e-3, T_END, 30))[0], PROPS['Tin'])

    def test_cold_ahead_of_the_gas_front(self):
        z = np.linspace(0.01, L, 20)
        tg, ts = schumann(z, 0.999 * EPS * z / PROPS['u_s'])
        np.testing.assert_allclose(tg, PROPS['T0'])
        np.testing.assert_allclose(ts, PROPS['T0'])

    def test_whole_bed_reaches_the_inlet_temperature(self):
        # at 10 s the top is still 1.3e-5 (Tin - T0) short (y = 14.4, theta = 45)
        tg, ts = schumann(np.linspace(0, L, 21), 3 * T_END)
        np.testing.assert_allclose(tg, PROPS['Tin'], atol=1e-9 * DT)
        np.testing.assert_allclose(ts, PROPS['Tin'], atol=1e-9 * DT)

    def test_heat_stored_is_the_enthalpy_brought_in(self):
        # t = 0.05 s: the gas front is inside the bed (transit 0.112 s)
        for t in [0.05, 0.5, 2.0, 5.0]:
            stored, entered = energy_balance_of_schumann(t)
            self.assertLess(abs(stored / entered - 1), 0.005, msg=t)
            self.assertLess(abs(stored / entered - 1), 1e-6, msg=t)   # what it really is

    def test_layer_mean_of_a_linear_profile_is_its_midpoint(self):
        self.assertAlmostEqual(pb.mean_solid_temperature(lambda z, t: 3 * z + t, 0.1, 0.3, 2.0),
                               0.6 + 2.0, places=13)

    def test_layer_mean_of_the_solid(self):
        z0, z1, t = 0.05, 0.1, 1.0
        mean = pb.schumann_mean_solid(z0, z1, t, eps=EPS, h=H, **PROPS)
        exact = quad(lambda z: float(schumann(z, t)[1]), z0, z1, epsrel=1e-12)[0] / (z1 - z0)
        self.assertAlmostEqual(mean, exact, delta=1e-9 * DT)
        self.assertTrue(schumann(z1, t)[1] < mean < schumann(z0, t)[1])


class NumericalUniformBed(unittest.TestCase):
    """solve() on one layer against Schumann's solution."""

    def test_agrees_with_schumann(self):
        # second order; measured max errors at resolution 20: gas 9e-5, solid
        # 3e-4 of (Tin - T0), so 0.1 % leaves a margin of 3 and stays an order
        # of magnitude below what the CFD-DEM comparison can resolve
        gas, solid = max_error(pb.solve([(L, EPS, H)], T_END, resolution=20, **PROPS))
        self.assertLess(max(gas, solid), 1e-3)

    def test_agrees_over_the_range_of_the_case(self):
        for eps, h, u_s, height in [(0.40, 200.0, 0.5, 0.12), (0.45, 100.0, 1.0, 0.3),
                                    (0.40, 200.0, 0.5, 0.3)]:       # y(L) = 45
            p = dict(PROPS, u_s=u_s)
            sol = pb.solve([(height, eps, h)], T_END, resolution=20, **p)
            z, t = np.meshgrid(np.linspace(0, height, 31), np.linspace(0, T_END, 101))
            tg, ts = pb.schumann(z, t, eps=eps, h=h, **p)
            err = max(np.abs(sol.gas(z, t) - tg).max(), np.abs(sol.solid(z, t) - ts).max())
            self.assertLess(err / DT, 1e-3, msg=(eps, h, u_s, height))

    def test_error_falls_as_the_square_of_the_grid_step(self):
        errors = [rms_error(pb.solve([(L, EPS, H)], T_END, resolution=r, **PROPS))
                  for r in (10, 20, 40)]
        orders = [math.log2(coarse / fine) for coarse, fine in zip(errors, errors[1:])]
        print('\n  solve vs Schumann, rms error at resolution 10, 20, 40: '
              + ', '.join('%.2e' % e for e in errors)
              + '; observed order ' + ', '.join('%.2f' % o for o in orders), file=sys.stderr)
        for order in orders:
            self.assertGreater(order, 1.7)

    def test_outlet_follows_schumann(self):
        sol = pb.solve([(L, EPS, H)], T_END, resolution=20, **PROPS)
        t = np.linspace(0, T_END, 401)
        np.testing.assert_allclose(sol.outlet(t), schumann(L, t)[0], atol=1e-3 * DT)

    def test_pure_advection_is_exact(self):
        sol = pb.solve([(L, EPS, 0.0)], 1.0, **PROPS)
        z = np.linspace(0, L, 41)
        arrival = EPS * z / PROPS['u_s']
        np.testing.assert_array_equal(sol.gas(z, arrival + 1e-9), PROPS['Tin'])
        np.testing.assert_array_equal(sol.gas(z[1:], arrival[1:] - 1e-9), PROPS['T0'])
        np.testing.assert_array_equal(sol.solid(z, 1.0), PROPS['T0'])

    def test_energy_is_conserved(self):
        sol = pb.solve([(L, EPS, H)], T_END, resolution=20, **PROPS)
        for t in [0.05, 0.5, 2.0, 5.0, T_END]:
            stored, entered = sol.energy_balance(t)
            self.assertLess(abs(stored / entered - 1), 1e-3, msg=t)

    def test_layer_means_agree_with_schumann(self):
        sol = pb.solve([(L, EPS, H)], T_END, resolution=20, **PROPS)
        for z0, z1 in [(0.0, 0.04), (0.08, 0.12), (0.16, 0.2)]:
            for t in [0.5, 1.5, 3.0]:
                self.assertAlmostEqual(
                    sol.mean_solid(z0, z1, t),
                    pb.schumann_mean_solid(z0, z1, t, eps=EPS, h=H, **PROPS),
                    delta=1e-3 * DT, msg=(z0, z1, t))


class NumericalLayeredBed(unittest.TestCase):
    """solve() with eps and h changing between the layers of the CFD mesh."""
    two = [(0.06, 0.40, 180.0), (0.14, 0.45, 110.0)]
    three = [(0.05, 0.45, 120.0), (0.08, 0.40, 200.0), (0.07, 0.43, 150.0)]

    def test_energy_is_conserved(self):
        for layers in (self.two, self.three):
            sol = pb.solve(layers, T_END, resolution=20, **PROPS)
            for t in [0.05, 0.3, 1.0, 3.0, T_END]:
                stored, entered = sol.energy_balance(t)
                self.assertLess(abs(stored / entered - 1), 1e-3, msg=(layers, t))

    def test_layers_of_one_h_follow_schumann_in_accumulated_y_and_transit(self):
        # with one h, dtheta/dt = 6 h/(d rho_s c_s) is the same in every layer
        # whatever eps, so the dimensionless problem is Schumann's exactly
        layers = [(0.06, 0.40, 150.0), (0.08, 0.45, 150.0), (0.06, 0.42, 150.0)]
        sol = pb.solve(layers, T_END, resolution=20, **PROPS)
        z, t = np.meshgrid(np.linspace(0, L, 81), np.linspace(0, T_END, 201))
        tg, ts = pb.schumann_layered(z, t, layers, **PROPS)
        self.assertLess(np.abs(sol.gas(z, t) - tg).max() / DT, 1e-3)
        # the solid is compared away from the faces, where it jumps
        inner = np.abs(((z + 1e-9) % 0.02) - 0.01) < 0.009
        self.assertLess(np.abs(sol.solid(z, t) - ts)[inner].max() / DT, 1e-3)
        for (z0, z1) in [(0.0, 0.06), (0.06, 0.14), (0.14, 0.2)]:
            mean = pb.mean_solid_temperature(
                lambda zz, tt: pb.schumann_layered(zz, tt, layers, **PROPS)[1], z0, z1, 1.0,
                kinks=np.linspace(z0, z1, 41))
            self.assertAlmostEqual(sol.mean_solid(z0, z1, 1.0), mean, delta=1e-3 * DT)

    def test_schumann_layered_refuses_layers_of_different_h(self):
        with self.assertRaises(ValueError):
            pb.schumann_layered(0.1, 1.0, self.two, **PROPS)

    def test_bottom_layer_does_not_feel_the_layers_above(self):
        # the gas carries information upwards only, so the bottom layer of
        # any stack is Schumann's bed with its own eps and h
        height, eps, h = self.two[0]
        sol = pb.solve(self.two, T_END, resolution=20, **PROPS)
        z, t = np.meshgrid(np.linspace(0, height * 0.999, 31), np.linspace(0, T_END, 201))
        tg, ts = schumann(z, t, eps, h)
        self.assertLess(np.abs(sol.gas(z, t) - tg).max() / DT, 1e-3)
        self.assertLess(np.abs(sol.solid(z, t) - ts).max() / DT, 1e-3)

    def test_first_gas_cools_with_the_accumulated_exchange(self):
        # on the cold bed the front gas loses heat as exp(-y) with y summed
        # over the layers it crossed, and arrives after the summed transit
        sol = pb.solve(self.two, T_END, resolution=20, **PROPS)
        z = np.linspace(0, L, 21)
        y = np.zeros_like(z)
        tau = np.zeros_like(z)
        bottom = 0.0
        for height, eps, h in self.two:
            inside = np.clip(z - bottom, 0, height)
            y += pb.exchange_per_length(eps, h, **PROPS) * inside
            tau += eps / PROPS['u_s'] * inside
            bottom += height
        np.testing.assert_allclose(sol.gas(z, tau + 1e-12), PROPS['T0'] + DT * np.exp(-y),
                                   atol=1e-3 * DT)
        np.testing.assert_allclose(sol.gas(z[1:], tau[1:] - 1e-6), PROPS['T0'])

    def test_converges_with_refinement(self):
        reference = pb.solve(self.three, T_END, resolution=80, **PROPS)
        z, t = np.meshgrid(np.linspace(0, L, 61), np.linspace(0, T_END, 201))
        worst, errors = [], []
        for r in (10, 20, 40):
            sol = pb.solve(self.three, T_END, resolution=r, **PROPS)
            diff = np.abs(sol.gas(z, t) - reference.gas(z, t)) / DT
            worst.append(diff.max())
            errors.append(math.sqrt(np.mean(diff ** 2)))
        orders = [math.log2(coarse / fine) for coarse, fine in zip(errors, errors[1:])]
        print('\n  three layers, gas against resolution 80 at 10, 20, 40: rms '
              + ', '.join('%.2e' % e for e in errors)
              + ' (max ' + ', '.join('%.2e' % e for e in worst) + ')'
              + '; observed order ' + ', '.join('%.2f' % o for o in orders), file=sys.stderr)
        self.assertLess(worst[1], 1e-3)
        for order in orders:
            self.assertGreater(order, 1.7)


if __name__ == '__main__':
    unittest.main()
