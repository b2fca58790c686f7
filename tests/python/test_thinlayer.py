"""The thin-layer references (spoutlab.thinlayer): Thompson's equation by
hand, Crank's series in its limits, and the calibration recovering a known
Arrhenius law from curves made with it."""
import math
import unittest

from spoutlab import thinlayer as tl


class Thompson(unittest.TestCase):
    def test_time_to_half_by_hand(self):
        # 40 C = 104 F: A = -1.862 + 0.00488 104 = -1.35448,
        # B = 427.4 exp(-3.432) = 427.4 x 0.0323222 = 13.8145; ln 0.5 = -0.693147:
        # t = 0.938853 + 13.8145 x 0.480453 = 0.938853 + 6.637218 = 7.5761 h
        self.assertAlmostEqual(tl.thompson_time(0.5, 40.0) / 3600, 7.5761, delta=2e-4)

    def test_ratio_inverts_time(self):
        for T in (40.0, 80.0):
            for mr in (0.9, 0.5, 0.1):
                self.assertAlmostEqual(tl.thompson_ratio(tl.thompson_time(mr, T), T), mr, places=12)


class Crank(unittest.TestCase):
    def test_limits(self):
        self.assertEqual(tl.crank_ratio(0.0), 1.0)
        # late: the first term alone, 6/pi^2 exp(-pi^2 Fo)
        self.assertAlmostEqual(tl.crank_ratio(1.0), 6 / math.pi ** 2 * math.exp(-math.pi ** 2),
                               places=15)
        # early: 1 - 6 sqrt(Fo/pi) + 3 Fo (Crank 6.20, short times)
        fo = 1e-4
        self.assertAlmostEqual(tl.crank_ratio(fo, terms=4000), 1 - 6 * math.sqrt(fo / math.pi) + 3 * fo,
                               places=5)


class Calibration(unittest.TestCase):
    def test_recovers_a_known_arrhenius_law(self):
        d0, ea = 2e-4, 35000.0

        def sphere(mr, T_C):   # the time a sphere of that law needs to reach mr
            from scipy.optimize import brentq
            d = d0 * math.exp(-ea / (tl.GAS_CONSTANT * (T_C + 273.15)))
            fo = brentq(lambda f: tl.crank_ratio(f) - mr, 1e-12, 5.0, xtol=1e-15)
            return fo * tl.RADIUS ** 2 / d
        fit_d0, fit_ea, worst, rms = tl.arrhenius_fit((40.0, 60.0, 80.0), curve=sphere)
        self.assertAlmostEqual(fit_ea / ea, 1.0, places=5)
        self.assertAlmostEqual(fit_d0 / d0, 1.0, places=4)
        self.assertLess(rms, 1e-6)


    def test_kernel_fit_recovers_the_law_of_its_own_model(self):
        """Curves made by the coupled kernel model itself with a known law
        (its heating and film included) give that law back."""
        import numpy as np
        kernels = {T: k for T, k in tl.singlekernel_conditions().items() if T in (40.0, 80.0)}
        d0, ea = 3e-4, 43000.0

        curves = {}
        for T_C, k in kernels.items():
            times = np.linspace(0.0, 3 * tl.thompson_time(0.05, T_C), 2000)
            X, _ = k.kernel_diffusion(d0, ea, times[-1], times, nodes=30)
            curves[T_C] = (-(X - k.Xeq) / (k.X0 - k.Xeq), times)

        def model_curve(mr, T_C):
            return float(np.interp(-mr, *curves[T_C]))
        fit_d0, fit_ea, rms = tl.kernel_fit(kernels, (1.5e-4, 41000.0), points=8, nodes=30,
                                            curve=model_curve)
        self.assertAlmostEqual(fit_ea / ea, 1.0, places=2)
        self.assertAlmostEqual(math.log(fit_d0 / d0), 0.0, places=1)
        self.assertLess(rms, 2e-3)


if __name__ == '__main__':
    unittest.main()
