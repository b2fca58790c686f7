"""The spouted-bed post-processing rules that turn protocol output into the
paper's quantities (u_ms from the pressure-drop curve)."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'etc', 'python'))
import spoutedbed  # noqa: E402


class KudraEq12(unittest.TestCase):
    """Eq 12 for the simulated vessel of Table 1 (the case's dictionary) at
    the paper's 0.9 m bed: the paper scales Kudra's measured 1.12 m/s to
    (1.12)(55/50)^0.5(95/100)^0.15(55/50)^0.084 = 1.18 m/s."""
    g = spoutedbed.load(os.path.join(os.path.dirname(__file__), '..', '..',
                                     'openfoam_cases', 'spoutDraftPlates'))

    def test_scaled_as_the_paper_does(self):
        self.assertAlmostEqual(spoutedbed.kudra_ums(self.g, 0.9), 1.18, delta=0.005)

    def test_evaluated_directly_for_spheres_agrees_with_the_scaling(self):
        self.assertAlmostEqual(spoutedbed.kudra_eq12(self.g, 0.9), 1.18, delta=0.01)

    def test_a_lower_bed_spouts_at_a_higher_velocity(self):
        self.assertGreater(spoutedbed.kudra_eq12(self.g, 0.8), spoutedbed.kudra_eq12(self.g, 0.9))


class MinimumSpouting(unittest.TestCase):
    # (u_s, dP, upward solid flux on the spout axis)
    down = [(1.5, 1000, 0.050), (1.4, 1040, 0.060), (1.3, 1070, 0.030), (1.2, 1100, 0.006),
            (1.1, 1500, -0.004), (1.0, 1380, 0.003)]

    def test_collapse_is_the_first_step_whose_flux_falls_below_the_threshold(self):
        # 10 % of the first step's 0.05 m/s: 0.006 still spouts, -0.004 does not
        self.assertEqual(spoutedbed.minimum_spouting(self.down, stopped=0.1), (1.2, 1100, 1500))
        # the default, 25 %: 0.006 m/s no longer counts as a spout
        self.assertEqual(spoutedbed.minimum_spouting(self.down), (1.3, 1070, 1100))

    def test_threshold_is_a_fraction_of_the_first_flux(self):
        # The series peaks after its first step (0.060 at 1.4 against 0.050 at 1.5), and at 55 %
        # the references part: of the first flux the threshold is 0.0275, so 1.3 (0.030) still
        # spouts and u_ms = 1.3; of the largest or of the previous step's flux it would be 0.033,
        # 1.3 would count as collapsed and u_ms = 1.4.
        self.assertEqual(spoutedbed.minimum_spouting(self.down, stopped=0.55)[0], 1.3)

    def test_a_spout_that_never_stops_has_no_u_ms(self):
        self.assertIsNone(spoutedbed.minimum_spouting(self.down[:4], stopped=0.1))
        self.assertIsNone(spoutedbed.minimum_spouting(self.down[:1]))


class SpoutReforms(unittest.TestCase):
    def test_first_step_carrying_particles_again(self):
        up = [(0.9, 1500, -0.01), (1.0, 1560, 0.002), (1.1, 1600, 0.02), (1.2, 1100, 0.04)]
        self.assertEqual(spoutedbed.spout_reforms(up, reference=0.05), (1.1, 1600))

    def test_never_reforms(self):
        self.assertIsNone(spoutedbed.spout_reforms([(0.9, 1500, 0.0), (1.0, 1560, 0.001)],
                                                   reference=0.05))


class NextVelocity(unittest.TestCase):
    """The adaptive schedule: from 1.5 m/s down by 0.1 to at most 0.8, and back up."""

    def schedule(self, flux_at, up=True, confirm=2):
        """Run the decision rule against a bed whose spout flux at u_s is
        flux_at(u_s, branch); returns the velocities of the steps."""
        done, u, branch = [], 1.5, 'down'
        while u is not None:
            done.append((u, branch, flux_at(u, branch)))
            u_next = spoutedbed.next_velocity(done, start=1.5, stop=0.8, step=0.1, up=up,
                                              confirm=confirm)
            if u_next is not None:
                branch = 'down' if u_next < u and branch == 'down' else 'up'
            u = u_next
        return [(u, b) for u, b, _ in done]

    @staticmethod
    def bed(u, branch):
        # spouts down to 1.1 m/s, re-forms only at 1.2 on the way up (hysteresis)
        return 0.05 if u >= (1.1 if branch == 'down' else 1.2) else 0.0

    def test_lowers_until_two_collapsed_steps_then_rises_until_two_spouting_steps(self):
        self.assertEqual(self.schedule(self.bed),
                         [(1.5, 'down'), (1.4, 'down'), (1.3, 'down'), (1.2, 'down'),
                          (1.1, 'down'), (1.0, 'down'), (0.9, 'down'),
                          (1.0, 'up'), (1.1, 'up'), (1.2, 'up'), (1.3, 'up')])

    def test_a_spout_that_never_collapses_runs_the_whole_range(self):
        steps = self.schedule(lambda u, b: 0.05)
        self.assertEqual(steps[7], (0.8, 'down'))
        self.assertEqual(steps[8:10], [(0.9, 'up'), (1.0, 'up')])
        self.assertEqual(len(steps), 10)

    def test_without_the_up_branch_it_ends_at_the_confirmed_collapse(self):
        self.assertEqual(self.schedule(self.bed, up=False)[-1], (0.9, 'down'))

    def test_a_large_confirm_runs_the_full_loop(self):
        steps = self.schedule(self.bed, confirm=100)
        self.assertEqual((steps[7], steps[-1], len(steps)), ((0.8, 'down'), (1.5, 'up'), 15))

    def test_the_threshold_is_a_fraction_of_the_first_steps_flux(self):
        # 0.02 m/s is below 25 % of 0.1 m/s: collapsed from 1.3 on
        steps = self.schedule(lambda u, b: 0.1 if u > 1.35 else 0.02, up=False)
        self.assertEqual(steps[-1], (1.2, 'down'))


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

    def test_next_to_the_walls_is_read_at_the_walls_not_at_the_slanting_base(self):
        # the downcomer widens with height up to the wall at 9 (bins to 8.6);
        # low down the outermost bin lies on the base and is fast, while at
        # every y near the wall the velocity rises with height
        def extent(h):
            return min(8.6, 0.62 * h)
        down = [(h, y, 0.001 * h + (0.03 if abs(y) < 5 else 0.0), 0.4)
                for h in self.heights for y in (-8.6, -7, -5, -3, -1.4, 1.4, 3, 5, 7, 8.6)
                if abs(y) <= extent(h)]
        wall = spoutedbed.profile_features(self.spout(lambda h, y: 1.0), down)[3]
        self.assertTrue(wall[3])
        # |y| >= 6.6 is reached from z/R_d = 11.4 up; lower down it is the base
        self.assertAlmostEqual(wall[1], 0.001 * 11.4)
        self.assertAlmostEqual(wall[2], 0.001 * (14.164 + 16.927) / 2)

    def test_a_region_without_cells_decides_nothing(self):
        down = [r for r in self.downcomer(lambda h, y: 0.01 + 0.001 * h if abs(y) > 8 else 0.02)
                if r[0] > 12 or abs(r[1]) < 8]
        self.assertFalse(spoutedbed.profile_features(self.spout(lambda h, y: 1.0), down)[3][3])

    def test_nan_cells_are_skipped(self):
        spout = self.spout(lambda h, y: float('nan') if y > 0.5 else 2.0 - 0.1 * h)
        down = self.downcomer(lambda h, y: 0.05 - 0.001 * h)
        self.assertTrue(spoutedbed.profile_features(spout, down)[0][3])


if __name__ == '__main__':
    unittest.main()
