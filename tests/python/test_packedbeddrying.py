"""The reference of the packed-bed drying case (spoutlab.packedbeddrying):
a dry bed is Schumann's heating problem, a kernel in a layer too thin to
change the gas dries at the film wet bulb and heats up once dry as worked
out by hand, nothing moves before the gas arrives, and the water the
kernels lose is the vapour the gas carries away."""
import math
import unittest

import numpy as np

from spoutlab import moistair as ma
from spoutlab import packedbeddrying as pbd
from spoutlab import packedbedheat as pb

# the verification case's kernels and gas (openfoam_cases/packedBedDrying)
GAS = dict(u_s=0.8, d=0.008, rho_d=1230.0, c_d=10.0, rho_g=1.0416, cp_air=1007.0)
H, KM = 144.0, 0.154
TIN, YIN = 353.15, ma.mass_fraction(0.01)


def saturated(T):
    return ma.mass_fraction(ma.saturation_humidity_ratio(T))


class DryBed(unittest.TestCase):
    """Without water the model is the two-phase heating model."""

    def test_is_schumanns_problem(self):
        layers = [(0.01, 0.4, H, KM), (0.02, 0.45, H, KM)]
        T0, t_end = 300.0, 2.0
        sol = pbd.solve(layers, t_end, T0=T0, Y0=0.0, X0=0.0, Tin=TIN, Yin=0.0, **GAS)
        props = dict(u_s=GAS['u_s'], d=GAS['d'], rho_s=GAS['rho_d'], c_s=GAS['c_d'],
                     rho_g=GAS['rho_g'], c_g=GAS['cp_air'], T0=T0, Tin=TIN)
        heat = [(dz, e, h) for dz, e, h, _ in layers]
        t = np.linspace(0.0, t_end, 81)
        exact, _ = pb.schumann_layered(np.full_like(t, 0.03), t, heat, **props)
        self.assertLess(np.max(np.abs(sol.outlet(t)[0] - exact)) / (TIN - T0), 2e-3)
        for z0, z1 in ((0.0, 0.01), (0.01, 0.02), (0.02, 0.03)):
            zq = np.linspace(z0, z1, 401)
            _, ts = pb.schumann_layered(zq, np.full_like(zq, 1.0), heat, **props)
            mean = float(np.mean(0.5 * (ts[:-1] + ts[1:])))
            self.assertAlmostEqual((sol.layer_mean('Tp', z0, z1, 1.0) - mean) / (TIN - T0), 0.0,
                                   delta=2e-3)
        self.assertTrue(np.all(sol.Yg == 0.0) and np.all(sol.X == 0.0))


class ThinLayer(unittest.TestCase):
    """A kernel that leaves the gas as it found it: starting at the film wet
    bulb T_wb of the inlet gas it stays there while it holds water, loses it
    at the constant rate (6/d) k_m (rho_v,sat(T_wb) - rho_v,in)/rho_d until
    t_d = X0/rate, then heats up as T_in - (T_in - T_wb) exp(-6 h (t - t_d)/(d rho_d c_d))."""

    @classmethod
    def setUpClass(cls):
        cls.Twb = pbd.film_wet_bulb(TIN, YIN, H, KM)
        cls.rate = 6 / GAS['d'] * KM * (ma.saturation_vapour_density(cls.Twb) - ma.vapour_density(
            TIN, ma.ratio_of_mass_fraction(YIN))) / GAS['rho_d']
        cls.X0 = 1e-3
        cls.t_dry = cls.X0 / cls.rate
        cls.sol = pbd.solve([(1e-8, 0.4, H, KM)], 1.5 * cls.t_dry, T0=cls.Twb,
                            Y0=saturated(cls.Twb), X0=cls.X0, Tin=TIN, Yin=YIN, **GAS)

    def test_film_wet_bulb_balance(self):
        T = self.Twb
        loss = KM * ma.latent_heat(T) * (ma.saturation_vapour_density(T)
                                         - ma.vapour_density(TIN, ma.ratio_of_mass_fraction(YIN)))
        self.assertAlmostEqual(H * (TIN - T) / loss, 1.0, places=9)
        self.assertTrue(300 < T < 310)

    def test_constant_rate_at_the_wet_bulb(self):
        for f in (0.2, 0.5, 0.9):
            t = f * self.t_dry
            self.assertAlmostEqual(self.sol.layer_mean('Tp', 0, 1e-8, t), self.Twb, delta=1e-5)
            self.assertAlmostEqual(self.sol.layer_mean('X', 0, 1e-8, t) / self.X0, 1 - f,
                                   delta=1e-6)

    def test_dries_out_and_heats_up(self):
        ds = self.sol.s[1] - self.sol.s[0]
        X = self.sol.X[0]
        self.assertAlmostEqual(self.sol.s[np.argmax(X == 0)], self.t_dry, delta=1.01 * ds)
        self.assertTrue(np.all(X >= 0))
        beta = 6 * H / (GAS['d'] * GAS['rho_d'] * GAS['c_d'])
        for t in (1.1 * self.t_dry, 1.3 * self.t_dry, 1.5 * self.t_dry):
            exact = TIN - (TIN - self.Twb) * math.exp(-beta * (t - self.t_dry))
            self.assertAlmostEqual((self.sol.layer_mean('Tp', 0, 1e-8, t) - exact)
                                   / (TIN - self.Twb), 0.0, delta=1e-2)


class WetBed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.T0 = 304.65
        cls.layers = [(0.01, 0.40, H, KM), (0.01, 0.42, 150.0, 0.16), (0.005, 0.75, 60.0, 0.06)]
        cls.sol = pbd.solve(cls.layers, 2.0, T0=cls.T0, Y0=saturated(cls.T0), X0=2e-4,
                            Tin=TIN, Yin=YIN, **GAS)

    def test_nothing_before_the_gas_arrives(self):
        tau = 0.40 * 0.01 / GAS['u_s'] + 0.42 * 0.01 / GAS['u_s']   # to z = 0.02
        T, Y = self.sol.outlet(np.array([0.5 * tau]))
        self.assertEqual((T[0], Y[0]), (self.T0, saturated(self.T0)))
        self.assertAlmostEqual(self.sol.layer_mean('X', 0.02, 0.025, 0.99 * tau), 2e-4,
                               places=18)
        self.assertAlmostEqual(self.sol.layer_mean('Tp', 0.02, 0.025, 0.99 * tau), self.T0,
                               places=10)

    def test_water_lost_is_carried_away(self):
        # to the grid's accuracy: each kernel drying out within a step puts
        # up to half a step's loss between what it lost and what the gas saw
        # (6e-4 here, 0.07 s of drying per kernel against steps of 1e-3 s)
        for t in (0.5, 1.0, 2.0):
            lost, carried = self.sol.water_balance(t)
            self.assertGreater(lost, 0)
            self.assertAlmostEqual(carried / lost, 1.0, delta=2e-3)

    def test_dries_from_the_bottom(self):
        X = [self.sol.layer_mean('X', a, a + 0.005, 1.0) for a in (0.0, 0.005, 0.01, 0.015)]
        self.assertEqual(X[0], 0.0)
        self.assertTrue(all(a <= b for a, b in zip(X, X[1:])))

    def test_unsaturated_start_refused(self):
        with self.assertRaises(ValueError):
            pbd.solve(self.layers, 1.0, T0=self.T0, Y0=0.99 * saturated(self.T0), X0=2e-4,
                      Tin=TIN, Yin=YIN, **GAS)


if __name__ == '__main__':
    unittest.main()
