"""The spouted-bed post-processing rules that turn protocol output into the
paper's quantities: u_ms and the hysteresis from the pressure-drop curve
and the spout classifier's verdicts, the step schedule, Ergun's u_mf."""
import math
import os
import unittest

from spoutlab import spoutedbed

from spoutlab import bedmaps

from spoutlab import profilefeatures

from spoutlab import spoutcorrelations

from spoutlab import spoutingloop


class KudraEq12(unittest.TestCase):
    """Eq 12 for the simulated vessel of Table 1 (the case's dictionary) at
    the paper's 0.9 m bed: the paper scales Kudra's measured 1.12 m/s to
    (1.12)(55/50)^0.5(95/100)^0.15(55/50)^0.084 = 1.18 m/s."""
    g = spoutedbed.load(os.path.join(os.path.dirname(__file__), '..', '..',
                                     'openfoam_cases', 'spoutDraftPlates'))

    def test_scaled_as_the_paper_does(self):
        self.assertAlmostEqual(spoutcorrelations.kudra_ums(self.g, 0.9), 1.18, delta=0.005)

    def test_evaluated_directly_for_spheres_agrees_with_the_scaling(self):
        self.assertAlmostEqual(spoutcorrelations.kudra_eq12(self.g, 0.9), 1.18, delta=0.01)

    def test_a_lower_bed_spouts_at_a_higher_velocity(self):
        self.assertGreater(spoutcorrelations.kudra_eq12(self.g, 0.8), spoutcorrelations.kudra_eq12(self.g, 0.9))


class MinimumSpouting(unittest.TestCase):
    # (u_s, dP, spouts by the classifier) on the decreasing branch
    down = [(1.5, 1000, True), (1.4, 1040, True), (1.3, 1070, True), (1.2, 1100, True),
            (1.1, 1500, False), (1.0, 1380, False)]

    def test_u_ms_is_the_last_spouting_step_before_a_collapse(self):
        # the paper's criterion: the point below which dP rises steeply
        self.assertEqual(spoutingloop.minimum_spouting(self.down), (1.2, 1100, 1500))

    def test_a_spout_that_pinches_off_once_and_recovers_is_not_collapsed(self):
        down = [(1.5, 1000, True), (1.4, 1040, False), (1.3, 1070, True), (1.2, 1400, False),
                (1.1, 1500, False)]
        self.assertEqual(spoutingloop.minimum_spouting(down), (1.3, 1070, 1400))

    def test_a_spout_that_never_stops_has_no_u_ms(self):
        self.assertIsNone(spoutingloop.minimum_spouting(self.down[:4]))
        self.assertIsNone(spoutingloop.minimum_spouting(self.down[:1]))
        self.assertIsNone(spoutingloop.minimum_spouting([]))


class SteepestRise(unittest.TestCase):
    """u_ms by the pressure drop alone (the paper's words: the point where
    dP begins to rise steeply on the decreasing branch), for a bed whose
    regime the classifier does not call a spout."""
    down = [(3.0, 1580, False), (2.5, 1640, False), (2.0, 1700, False), (1.9, 1760, False),
            (1.8, 2900, False), (1.7, 3300, False)]

    def test_u_ms_is_the_step_before_the_largest_rise(self):
        self.assertEqual(spoutingloop.steepest_rise(self.down), (1.9, 1760, 2900))

    def test_a_falling_or_flat_curve_has_no_rise(self):
        self.assertIsNone(spoutingloop.steepest_rise([(2.0, 1700, True), (1.9, 1690, True)]))
        self.assertIsNone(spoutingloop.steepest_rise(self.down[:1]))
        self.assertIsNone(spoutingloop.steepest_rise([]))


class SpoutReforms(unittest.TestCase):
    def test_first_step_spouting_again(self):
        up = [(0.9, 1500, False), (1.0, 1560, False), (1.1, 1600, True), (1.2, 1100, True)]
        self.assertEqual(spoutingloop.spout_reforms(up), (1.1, 1600))

    def test_never_reforms(self):
        self.assertIsNone(spoutingloop.spout_reforms([(0.9, 1500, False), (1.0, 1560, False)]))


class PackedBranch(unittest.TestCase):
    """Fig 2's increasing branch from the settled bed: dP rises to a peak,
    the spout breaks through and dP falls."""
    packed = [(1.0, 1500, False), (1.1, 1700, False), (1.2, 1900, False), (1.3, 1450, True),
              (1.4, 1400, True)]
    down = [(1.3, 1380, True), (1.2, 1300, True), (1.1, 1250, True), (1.0, 1600, False)]

    def test_peak_and_break_through(self):
        self.assertEqual(spoutingloop.break_through(self.packed), (1.2, 1900, 1.3, 1450))

    def test_a_bed_that_never_spouts_has_a_peak_but_no_break_through(self):
        self.assertEqual(spoutingloop.break_through(self.packed[:3]), (1.2, 1900, None, None))
        self.assertIsNone(spoutingloop.break_through([]))

    def test_the_peak_is_taken_before_the_break_through_only(self):
        # a later, higher reading (a slug) above the break-through is not the peak
        packed = self.packed[:4] + [(1.4, 2500, True)]
        self.assertEqual(spoutingloop.break_through(packed)[:2], (1.2, 1900))

    def test_hysteresis_is_the_peak_minus_the_decreasing_branch_at_its_velocity(self):
        self.assertAlmostEqual(spoutingloop.hysteresis(self.packed, self.down), 1900 - 1300)

    def test_hysteresis_interpolates_between_decreasing_steps(self):
        down = [(1.3, 1380, True), (1.1, 1250, True), (1.0, 1600, False)]
        self.assertAlmostEqual(spoutingloop.hysteresis(self.packed, down), 1900 - 1315)

    def test_no_hysteresis_outside_the_decreasing_branch(self):
        self.assertIsNone(spoutingloop.hysteresis(self.packed, self.down[:1]))
        self.assertIsNone(spoutingloop.hysteresis(self.packed, []))


class ErgunMinimumFluidisation(unittest.TestCase):
    """u_mf from the Ergun equation for the papers' particles in air at 20 C."""
    d, rho_p, rho_g, mu = 8e-3, 1231.0, 1.205, 1.81e-5

    def test_wen_yu_form_gives_the_papers_value(self):
        # the no-draft paper quotes 1.746 m/s 'irregardless of the bed height'
        u = spoutcorrelations.ergun_umf(self.d, self.rho_p, self.rho_g, self.mu)
        self.assertAlmostEqual(u, 1.746, delta=0.002)

    def test_at_a_given_voidage_by_hand(self):
        # Ar = 150 (1-e)/e^3 Re + 1.75/e^3 Re^2 at e = 0.4, solved by hand:
        # Ar = d^3 rho_g (rho_p - rho_g) g / mu^2 = 2.2718e7, Re = 886.4
        u = spoutcorrelations.ergun_umf(self.d, self.rho_p, self.rho_g, self.mu, eps_mf=0.4)
        Ar = self.d**3 * self.rho_g * (self.rho_p - self.rho_g) * 9.81 / self.mu**2
        a, b = 1.75 / 0.4**3, 150 * 0.6 / 0.4**3
        re = (-b + (b * b + 4 * a * Ar) ** 0.5) / (2 * a)
        self.assertAlmostEqual(u, re * self.mu / (self.rho_g * self.d), places=6)
        self.assertAlmostEqual(u, 1.664, delta=0.002)

    def test_a_looser_bed_fluidises_later(self):
        u = [spoutcorrelations.ergun_umf(self.d, self.rho_p, self.rho_g, self.mu, eps_mf=e)
             for e in (0.38, 0.42, 0.46)]
        self.assertTrue(u[0] < u[1] < u[2])


class InsertionSeed(unittest.TestCase):
    """LIGGGHTS takes only primes above 10 000 as seeds."""

    def test_primes_above_ten_thousand_are_taken(self):
        for seed in (10007, 15485867, 49979687):
            self.assertEqual(spoutedbed.insertion_seed(str(seed), 'dict'), seed)

    def test_others_stop_naming_the_key(self):
        for text in ('49979685', '10001', '9973', '1e5', 'seven'):   # 5 x, 73 x 137, < 10 000
            with self.assertRaises(SystemExit) as stop:
                spoutedbed.insertion_seed(text, 'system/spoutedBedDict')
            self.assertIn("system/spoutedBedDict: key 'insertionSeed' expected a prime",
                          str(stop.exception.code))


class WallFriction(unittest.TestCase):
    """The particle-wall friction: the particles' mu unless set (the papers
    give one coefficient), which a friction series that sets mu must keep."""

    def test_same_follows_the_particles_mu(self):
        self.assertEqual(spoutedbed.wall_friction('same', 0.063, 'dict'), 0.063)

    def test_a_number_of_zero_or_more_is_taken(self):
        for text, mu in (('0', 0.0), ('0.5', 0.5)):
            self.assertEqual(spoutedbed.wall_friction(text, 0.3, 'dict'), mu)

    def test_the_case_overridden_as_a_friction_series_does(self):
        case = os.path.join(os.path.dirname(__file__), '..', '..', 'openfoam_cases',
                            'spoutDraftPlates')
        g = spoutedbed.Geometry(spoutedbed.read_dict(os.path.join(case, 'system',
                                                                  'spoutedBedDict'),
                                                     ['mu=0.063']), 'dict')
        self.assertEqual((g.particles['mu'], g.particles['muWall']), (0.063, 0.063))

    def test_others_stop_naming_the_key(self):
        for text in ('-0.1', 'nan', 'inf', 'wall'):
            with self.assertRaises(SystemExit) as stop:
                spoutedbed.wall_friction(text, 0.3, 'system/spoutedBedDict')
            self.assertIn("system/spoutedBedDict: key 'muWall' expected same (as mu) or a "
                          "friction coefficient >= 0", str(stop.exception.code))


class CoarseGraining(unittest.TestCase):
    """The coarse-graining factor: 1 (the dictionary's), or any cg >= 1."""

    def test_factors_of_one_and_above_are_taken(self):
        for text, cg in (('1', 1.0), ('2', 2.0), ('2.5', 2.5)):
            self.assertEqual(spoutedbed.coarse_graining(text, 'dict'), cg)

    def test_others_stop_naming_the_key(self):
        for text in ('0.5', '0', '-2', 'nan', 'inf', 'two'):
            with self.assertRaises(SystemExit) as stop:
                spoutedbed.coarse_graining(text, 'system/spoutedBedDict')
            self.assertIn("system/spoutedBedDict: key 'coarseGraining' expected a factor >= 1",
                          str(stop.exception.code))


class VesselVolume(unittest.TestCase):
    """The vessel below a height, for the settled bed's voidage: the slanted
    part is a trapezoid, the rest a rectangle, less the plates."""
    case = os.path.join(os.path.dirname(__file__), '..', '..', 'openfoam_cases',
                        'spoutDraftPlates')

    def test_below_the_top_of_the_base_a_trapezoid(self):
        g = spoutedbed.load(self.case, ['plates=no'])
        h = 0.3
        top = 0.033 + 2 * h / math.tan(math.radians(60))
        self.assertAlmostEqual(spoutedbed.vessel_volume(g, h), (0.033 + top) / 2 * h * 0.04,
                               places=12)

    def test_above_it_the_full_width_and_the_plates_taken_out(self):
        g = spoutedbed.load(self.case, ['plates=no'])
        z = 0.231 * math.tan(math.radians(60))           # the base meets the walls
        below = (0.033 + 0.495) / 2 * z * 0.04
        self.assertAlmostEqual(spoutedbed.vessel_volume(g, 0.7), below + 0.495 * (0.7 - z) * 0.04,
                               places=12)
        plated = spoutedbed.load(self.case)
        self.assertAlmostEqual(spoutedbed.vessel_volume(g, 0.7) - spoutedbed.vessel_volume(plated, 0.7),
                               2 * 0.011 * (0.7 - 0.095) * 0.04, places=12)


class ClippedOutline(unittest.TestCase):
    def test_segments_end_at_the_top_of_the_map(self):
        segs = [(0, 0, 0, 2), (0, 0, 1, 2), (0, 3, 1, 4), (0, 0.5, 1, 0.5)]
        self.assertEqual(bedmaps.clipped(segs, 1.0),
                         [(0, 0, 0, 1.0), (0, 0, 0.5, 1.0), (0, 0.5, 1, 0.5)])


class NextStep(unittest.TestCase):
    """The adaptive schedule, decided from the classifier's verdicts."""

    def schedule(self, spouts_at, plan):
        """Run the decision rule against a bed that spouts at u_s on a
        branch when spouts_at(u_s, branch); returns (u_s, branch) of the steps."""
        done, step = [], plan.first()
        while step is not None:
            u, branch = step
            done.append((u, branch, spouts_at(u, branch)))
            step = plan.next(done)
        return [(u, b) for u, b, _ in done]

    @staticmethod
    def bed(u, branch):
        # breaks through the packed bed at 1.3, spouts down to 1.1 on the
        # way down, re-forms at 1.2 on the way up (hysteresis)
        return u >= {'packed': 1.3, 'down': 1.1, 'up': 1.2}[branch] - 1e-9

    def test_packed_branch_rises_until_two_spouting_steps_then_falls_to_a_confirmed_collapse(self):
        plan = spoutingloop.Schedule(step=0.1, stop=0.8, rise_from=1.0, top=3.0)
        self.assertEqual(self.schedule(self.bed, plan),
                         [(1.0, 'packed'), (1.1, 'packed'), (1.2, 'packed'), (1.3, 'packed'),
                          (1.4, 'packed'), (1.3, 'down'), (1.2, 'down'), (1.1, 'down'),
                          (1.0, 'down'), (0.9, 'down')])

    def test_with_up_it_rises_again_until_two_spouting_steps(self):
        plan = spoutingloop.Schedule(step=0.1, stop=0.8, rise_from=1.0, top=3.0, up=True)
        self.assertEqual(self.schedule(self.bed, plan)[-4:],
                         [(1.0, 'up'), (1.1, 'up'), (1.2, 'up'), (1.3, 'up')])

    def test_a_bed_that_never_spouts_rises_to_the_top_and_stops(self):
        plan = spoutingloop.Schedule(step=0.2, stop=0.8, rise_from=2.0, top=3.0)
        steps = self.schedule(lambda u, b: False, plan)
        self.assertEqual(steps, [(u, 'packed') for u in (2.0, 2.2, 2.4, 2.6, 2.8, 3.0)])

    def test_a_break_through_at_the_top_still_gets_its_decreasing_branch(self):
        plan = spoutingloop.Schedule(step=0.5, stop=1.0, rise_from=2.0, top=3.0)
        steps = self.schedule(lambda u, b: u >= 3.0 if b == 'packed' else u >= 2.0, plan)
        self.assertEqual(steps, [(2.0, 'packed'), (2.5, 'packed'), (3.0, 'packed'),
                                 (2.5, 'down'), (2.0, 'down'), (1.5, 'down'), (1.0, 'down')])

    def test_the_full_loop_is_the_same_whatever_the_classifier_says(self):
        # the paper's Fig 2 read by dP: up to the top and down to the stop,
        # for a bed that never spouts, always spouts or breaks through early
        expected = [(2.0, 'packed'), (2.5, 'packed'), (3.0, 'packed'),
                    (2.5, 'down'), (2.0, 'down'), (1.5, 'down')]
        for bed in (lambda u, b: False, lambda u, b: True, self.bed):
            plan = spoutingloop.Schedule(step=0.5, stop=1.5, rise_from=2.0, top=3.0,
                                       full_loop=True)
            self.assertEqual(self.schedule(bed, plan), expected)

    def test_an_intermittent_break_through_must_be_confirmed(self):
        # spouts at 1.2 once, not at 1.3: the branch keeps rising
        plan = spoutingloop.Schedule(step=0.1, stop=0.8, rise_from=1.1, top=3.0)
        steps = self.schedule(lambda u, b: u >= 1.4 or abs(u - 1.2) < 1e-9, plan)
        self.assertEqual(steps[:5], [(1.1, 'packed'), (1.2, 'packed'), (1.3, 'packed'),
                                     (1.4, 'packed'), (1.5, 'packed')])
        self.assertEqual(steps[5], (1.4, 'down'))

    def test_spin_up_start_lowers_from_start_as_before(self):
        plan = spoutingloop.Schedule(step=0.1, stop=0.8, start=1.5, up=True)
        self.assertEqual(self.schedule(self.bed, plan),
                         [(1.5, 'down'), (1.4, 'down'), (1.3, 'down'), (1.2, 'down'),
                          (1.1, 'down'), (1.0, 'down'), (0.9, 'down'),
                          (1.0, 'up'), (1.1, 'up'), (1.2, 'up'), (1.3, 'up')])

    def test_a_spout_that_never_collapses_runs_down_to_stop(self):
        plan = spoutingloop.Schedule(step=0.1, stop=0.8, start=1.5)
        self.assertEqual(self.schedule(lambda u, b: True, plan)[-1], (0.8, 'down'))

    def test_a_large_confirm_runs_the_full_loop(self):
        plan = spoutingloop.Schedule(step=0.1, stop=0.8, start=1.5, up=True, confirm=100)
        steps = self.schedule(self.bed, plan)
        self.assertEqual((steps[7], steps[-1], len(steps)), ((0.8, 'down'), (1.5, 'up'), 15))

    def test_a_schedule_needs_one_way_to_begin(self):
        with self.assertRaises(ValueError):
            spoutingloop.Schedule(step=0.1, stop=0.8)
        with self.assertRaises(ValueError):
            spoutingloop.Schedule(step=0.1, stop=0.8, start=1.5, rise_from=1.0, top=2.0)
        with self.assertRaises(ValueError):
            spoutingloop.Schedule(step=0.1, stop=0.8, rise_from=2.0, top=1.5)


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
        found = profilefeatures.profile_features(spout, down)
        self.assertEqual([f[3] for f in found], [True, True, True, True])
        name, low, high, _ = found[0]
        # spout mean over z/R_d < 12 (5.873, 8.637, 11.4) and above
        self.assertAlmostEqual(low, 3.0 - 0.1 * (5.873 + 8.637 + 11.4) / 3)
        self.assertAlmostEqual(high, 3.0 - 0.1 * (14.164 + 16.927) / 2)

    def test_opposite_trends_are_reported_as_missing(self):
        spout = self.spout(lambda h, y: 1.0 + 0.1 * h)
        down = self.downcomer(lambda h, y: 0.01 + 0.001 * h if abs(y) < 8 else 0.05 - 0.001 * h)
        self.assertEqual([f[3] for f in profilefeatures.profile_features(spout, down)],
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
        wall = profilefeatures.profile_features(self.spout(lambda h, y: 1.0), down)[3]
        self.assertTrue(wall[3])
        # |y| >= 6.6 is reached from z/R_d = 11.4 up; lower down it is the base
        self.assertAlmostEqual(wall[1], 0.001 * 11.4)
        self.assertAlmostEqual(wall[2], 0.001 * (14.164 + 16.927) / 2)

    def test_a_region_without_cells_decides_nothing(self):
        down = [r for r in self.downcomer(lambda h, y: 0.01 + 0.001 * h if abs(y) > 8 else 0.02)
                if r[0] > 12 or abs(r[1]) < 8]
        self.assertFalse(profilefeatures.profile_features(self.spout(lambda h, y: 1.0), down)[3][3])

    def test_nan_cells_are_skipped(self):
        spout = self.spout(lambda h, y: float('nan') if y > 0.5 else 2.0 - 0.1 * h)
        down = self.downcomer(lambda h, y: 0.05 - 0.001 * h)
        self.assertTrue(profilefeatures.profile_features(spout, down)[0][3])


if __name__ == '__main__':
    unittest.main()
