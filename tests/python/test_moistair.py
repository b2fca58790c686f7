"""The drying references' psychrometrics (spoutlab.moistair) against the
steam tables and by hand."""
import math
import unittest

import numpy as np

from spoutlab import moistair as ma


class SaturationPressure(unittest.TestCase):
    def test_steam_tables(self):
        # saturation pressure of water [Pa] (steam tables), to Hyland-Wexler's 1e-3
        for t, p in ((0.01, 611.66), (20, 2339.2), (40, 7384.9), (60, 19946.0), (80, 47416.0),
                     (100, 101418.0), (150, 476160.0), (200, 1554900.0)):
            self.assertAlmostEqual(ma.saturation_pressure(t + ma.KELVIN) / p, 1.0,
                                   delta=3e-3 if t > 100 else 2e-3, msg='t = %g C' % t)

    def test_slope_is_the_derivative(self):
        for T in (280.0, 305.0, 353.15, 450.0):
            fd = (ma.saturation_pressure(T + 1e-3) - ma.saturation_pressure(T - 1e-3)) / 2e-3
            self.assertAlmostEqual(ma.saturation_pressure_slope(T) / fd, 1.0, places=8)
            fd = (ma.saturation_vapour_density(T + 1e-3)
                  - ma.saturation_vapour_density(T - 1e-3)) / 2e-3
            self.assertAlmostEqual(ma.saturation_vapour_density_slope(T) / fd, 1.0, places=8)

    def test_range_and_arrays(self):
        with self.assertRaises(ValueError):
            ma.saturation_pressure(260.0)
        values = ma.saturation_pressure(np.array([293.15, 333.15]))
        self.assertEqual(values.shape, (2,))
        self.assertEqual(values[1], ma.saturation_pressure(333.15))


class Humidity(unittest.TestCase):
    def test_by_hand(self):
        # p_w = 2000 Pa at 1 atm: W = 0.621945 x 2000/99325 = 0.0125234
        self.assertAlmostEqual(ma.humidity_ratio(2000.0), 0.621945 * 2000 / 99325, places=15)
        self.assertAlmostEqual(ma.vapour_pressure(ma.humidity_ratio(2000.0)), 2000.0, places=9)
        # rho_v = p_w/(R_v T), R_v = 287.042/0.621945 = 461.5231
        self.assertAlmostEqual(ma.R_VAPOUR, 461.5231, places=4)
        self.assertAlmostEqual(ma.vapour_density(300.0, ma.humidity_ratio(2000.0)),
                               2000.0 / (461.52313 * 300.0), places=8)
        self.assertAlmostEqual(ma.relative_humidity(333.15, ma.saturation_humidity_ratio(333.15)),
                               1.0, places=14)

    def test_mass_fraction(self):
        self.assertAlmostEqual(ma.mass_fraction(0.01), 0.01 / 1.01, places=16)
        self.assertAlmostEqual(ma.ratio_of_mass_fraction(ma.mass_fraction(0.03)), 0.03, places=16)
        self.assertAlmostEqual(ma.humid_heat_capacity(0.02, 1007.0), 0.98 * 1007 + 0.02 * 1860,
                               places=10)


class Properties(unittest.TestCase):
    def test_latent_heat(self):
        self.assertEqual(ma.latent_heat(ma.KELVIN), 2501e3)
        # 2501 - 2.326 x 60 = 2361.44 kJ/kg (steam tables 2357.7)
        self.assertAlmostEqual(ma.latent_heat(333.15), 2361.44e3, places=6)

    def test_vapour_diffusivity(self):
        self.assertAlmostEqual(ma.vapour_diffusivity(ma.KELVIN), 0.2178e-4, places=15)
        self.assertAlmostEqual(ma.vapour_diffusivity(2 * ma.KELVIN, 2 * ma.ATMOSPHERE),
                               0.2178e-4 * 2 ** 1.81 / 2, places=15)
        self.assertTrue(math.isclose(ma.vapour_diffusivity(338.75), 3.2155e-5, rel_tol=1e-4))


if __name__ == '__main__':
    unittest.main()
