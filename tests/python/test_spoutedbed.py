"""The spouted-bed post-processing rules that turn protocol output into the
paper's quantities (u_ms from the pressure-drop curve)."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'etc', 'python'))
import spoutedbed  # noqa: E402


class MinimumSpouting(unittest.TestCase):
    def test_jump_marks_the_last_spouting_velocity(self):
        # spouting plateau rising slowly, collapse between 1.2 and 1.1,
        # then a packed bed whose dP falls with u
        down = [(1.5, 1000), (1.4, 1040), (1.3, 1070), (1.2, 1100), (1.1, 1500), (1.0, 1380)]
        self.assertEqual(spoutedbed.minimum_spouting(down), (1.2, 1100, 1500 / 1100 - 1))

    def test_scatter_below_the_threshold_is_no_collapse(self):
        down = [(1.5, 1000), (1.4, 1080), (1.3, 1050), (1.2, 1120)]
        self.assertIsNone(spoutedbed.minimum_spouting(down))

    def test_threshold_is_inclusive_and_adjustable(self):
        down = [(1.3, 1000), (1.2, 1100)]
        self.assertIsNotNone(spoutedbed.minimum_spouting(down, rise=0.1 - 1e-12))
        self.assertIsNone(spoutedbed.minimum_spouting(down, rise=0.2))

    def test_single_step_has_no_jump(self):
        self.assertIsNone(spoutedbed.minimum_spouting([(1.3, 1000)]))


class SpoutReforms(unittest.TestCase):
    def test_largest_fall_on_the_way_up(self):
        up = [(0.9, 1500), (1.0, 1560), (1.1, 1600), (1.2, 1100), (1.3, 1080)]
        u, dp, fall = spoutedbed.spout_reforms(up)
        self.assertEqual((u, dp), (1.2, 1100))
        self.assertAlmostEqual(fall, 500 / 1600)

    def test_rising_curve_never_reforms(self):
        self.assertIsNone(spoutedbed.spout_reforms([(0.9, 1500), (1.0, 1560), (1.1, 1600)]))


class ProfileFeatures(unittest.TestCase):
    heights = [5.873, 8.637, 11.400, 14.164, 16.927]

    def spout(self, v):
        return [(h, y, v(h, y), 0.6) for h in self.heights for y in (-0.6, -0.2, 0.2, 0.6)]

    def downcomer(self, v):
        # cells next to the plates at |y| = 1.4, next to the walls at 8.6
        return [(h, y, v(h, y), 0.4) for h in self.heights for y in (-8.6, -5, -1.4, 1.4, 5, 8.6)]

    def test_paper_like_profiles_show_every_feature(self):
        spout = self.spout(lambda h, y: 3.0 - 0.1 * h)
        down = self.downcomer(lambda h, y: 0.05 - 0.002 * h if abs(y) < 2
                              else (0.01 + 0.0005 * h if abs(y) > 8 else 0.03 - 0.001 * h))
        found = spoutedbed.profile_features(spout, down)
        self.assertEqual([f[3] for f in found], [True, True, True, True])
        name, low, high, _ = found[0]
        # spout mean over z/R_d < 12 (5.873, 8.637, 11.4) and above
        self.assertAlmostEqual(low, 3.0 - 0.1 * (5.873 + 8.637 + 11.4) / 3)
        self.assertAlmostEqual(high, 3.0 - 0.1 * (14.164 + 16.927) / 2)

    def test_opposite_trends_are_reported_as_missing(self):
        spout = self.spout(lambda h, y: 1.0 + 0.1 * h)
        down = self.downcomer(lambda h, y: 0.01 + 0.001 * h if abs(y) < 8 else 0.05 - 0.001 * h)
        self.assertEqual([f[3] for f in spoutedbed.profile_features(spout, down)],
                         [False, False, False, False])

    def test_nan_cells_are_skipped(self):
        spout = self.spout(lambda h, y: float('nan') if y > 0.5 else 2.0 - 0.1 * h)
        down = self.downcomer(lambda h, y: 0.05 - 0.001 * h)
        self.assertTrue(spoutedbed.profile_features(spout, down)[0][3])


if __name__ == '__main__':
    unittest.main()
