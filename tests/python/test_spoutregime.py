"""The spout classifier (spoutlab.spoutregime) on particle fields built
here whose regime is known by construction: a spouting bed (a dilute,
rising column through the bed and a fountain over it, the annulus sliding
down), a packed bed at rest, and a bubbling bed whose voids rise through
the centre, erupt at the surface now and then and, once in six write times,
line up into an open channel.  Each field is built in the vessel with the
draft plates and without them (plates no), in the case's own geometry."""
import math
import os
import random
import unittest

from spoutlab import spoutedbed
from spoutlab import spoutregime as sr

CASE = os.path.join(os.path.dirname(__file__), '..', '..', 'openfoam_cases', 'spoutDraftPlates')
R = 0.004                      # particle radius [m]
SPACING = 0.0084               # lattice spacing in x and z; 8 mm through the depth
DEPTHS = (0.004, 0.012, 0.020, 0.028, 0.036)


def vessel(plates):
    return spoutedbed.load(CASE, ['plates=%s' % ('yes' if plates else 'no')])


def free(g, x, z):
    """A particle centre at (x, z) [m] clear of walls, base and plates."""
    mm = 1e-3
    if abs(x) > g.W / 2 * mm - R or z < g.base_height(abs(x) / mm + R / mm) * mm + 2 * R:
        return False
    if g.plates and g.He * mm - R <= z <= g.Hd * mm + R \
            and g.Wd / 2 * mm - R <= abs(x) <= (g.Wd / 2 + g.t) * mm + R:
        return False
    return True


def lattice(g, top, keep=lambda x, z: True):
    """Sites (x, y, z) of the packed lattice below `top` [m]."""
    sites = []
    nx = int(g.W / 1000 / SPACING)
    for k in range(int(top / SPACING)):
        z = (k + 0.5) * SPACING
        for i in range(-nx // 2, nx // 2 + 1):
            x = i * SPACING
            if free(g, x, z) and keep(x, z):
                sites += [(x, y, z) for y in DEPTHS]
    return sites


class Field:
    def __init__(self):
        self.points, self.vz = [], []

    def add(self, points, velocity):
        for p in points:
            self.points.append(p)
            self.vz.append(velocity(p))

    def measure(self, g, region=None, time=0.0):
        region = region or sr.SpoutRegion.of(g)
        return sr.measure(g, region, self.points, self.vz, [R] * len(self.points), time)


def spouting(g, rng, top=0.40, half=0.0275, fountain=0.15):
    """The annulus packed and sliding down at 2-4 cm/s; the column holds one
    site in fifteen, rising at 0.5-1.5 m/s (faster higher up); the fountain
    above the surface, as dilute, rising in the middle and falling beside."""
    f = Field()
    f.add(lattice(g, top, lambda x, z: abs(x) > half),
          lambda p: -0.02 - 0.02 * rng.random())
    column = [p for p in lattice(g, top + fountain, lambda x, z: abs(x) <= half)
              if rng.random() < 1 / 15]
    f.add(column, lambda p: (0.5 + 2.5 * min(p[2], top)) * (1 if abs(p[0]) < half / 2
                                                               or p[2] < top else -0.5)
          + 0.1 * rng.uniform(-1, 1))
    return f


def slugging(g, rng, step, top=0.40):
    """The spouting bed with a packed plug filling the column 60 mm high
    from 0.12 + 0.045 step [m], rising at 1 m/s."""
    f = spouting(g, rng, top)
    z0 = 0.12 + 0.045 * step
    f.add(lattice(g, top, lambda x, z: abs(x) <= 0.0275 and z0 <= z < z0 + 0.06),
          lambda p: 1.0)
    return f


def packed(g, top=0.40):
    f = Field()
    f.add(lattice(g, top), lambda p: 0.0)
    return f


def bubbling(g, rng, step, top=0.40):
    """Write time `step` of six: one void of 45 mm radius rises through the
    centre, which rises with it at 0.25 m/s (the bubbles' gulf stream)
    while the sides sink, everything jostling; at step 3 it erupts, throwing a burst of particles over the surface; at
    step 5 a chain of voids happens to open the whole centre."""
    voids = {0: [0.15], 1: [0.22], 2: [0.29], 3: [top - 0.01], 4: [0.18], 5: None}[step]
    radius = 0.045

    def in_void(x, z):
        if voids is None:                 # the open channel of step 5
            return abs(x) < 0.028 and z > 0.09
        return any(math.hypot(x, z - zv) < radius for zv in voids)

    f = Field()
    f.add(lattice(g, top, lambda x, z: not in_void(x, z)),
          lambda p: (0.25 if abs(p[0]) < 0.03 else -0.02) + 0.05 * rng.uniform(-1, 1))
    if step in (3, 5):
        burst = [(rng.uniform(-0.025, 0.025), rng.choice(DEPTHS), top + rng.uniform(0.01, 0.12))
                 for _ in range(40)]
        f.add(burst, lambda p: 1.0 + 0.3 * rng.uniform(-1, 1))
    if step == 5:
        f.add([(rng.uniform(-0.02, 0.02), rng.choice(DEPTHS), rng.uniform(0.1, top))
               for _ in range(30)], lambda p: 0.8)
    return f


class Snapshots(unittest.TestCase):
    def setUp(self):
        self.rng = random.Random(12)

    def test_a_spout_is_dilute_rising_and_has_a_fountain(self):
        for plates in (True, False):
            g = vessel(plates)
            s = spouting(g, self.rng).measure(g)
            self.assertAlmostEqual(s.surface, 0.40, delta=0.02, msg=plates)
            # the lattice fills (pi/6 d^3)/(8 mm x 8.4 mm x 8.4 mm) = 0.475
            # of the bulk; beside the base, walls and plates it leaves a
            # strip of about 2R empty, and the annulus here lies on the base
            self.assertTrue(0.36 < s.annulus_fraction < 0.475, (plates, s.annulus_fraction))
            self.assertLess(s.densest_core_ratio(), 0.25)
            self.assertTrue(s.open_core and s.upward and s.has_fountain and s.spouts, plates)

    def test_a_packed_bed_has_a_dense_core_at_rest_and_no_fountain(self):
        for plates in (True, False):
            g = vessel(plates)
            s = packed(g).measure(g)
            self.assertGreater(s.densest_core_ratio(), 0.8)
            self.assertEqual((s.open_core, s.upward, s.has_fountain, s.spouts),
                             (False, False, False, False))

    def test_an_erupting_bubble_rises_and_throws_a_fountain_but_leaves_the_core_closed(self):
        g = vessel(False)
        s = bubbling(g, self.rng, 3).measure(g)
        self.assertTrue(s.has_fountain and s.upward)
        self.assertFalse(s.open_core)
        self.assertFalse(s.spouts)

    def test_the_bed_surface_ignores_the_fountain(self):
        g = vessel(True)
        f = spouting(g, self.rng, fountain=0.6)
        self.assertAlmostEqual(f.measure(g).surface, 0.40, delta=0.02)


class Verdicts(unittest.TestCase):
    """Six write times of each bed, as the averaging window would hold."""

    def setUp(self):
        self.rng = random.Random(5)

    def verdict(self, g, fields, region=None):
        return sr.Verdict([f.measure(g, region, time=0.3 * k) for k, f in enumerate(fields)])

    def test_spouting_bed_spouts_with_and_without_plates(self):
        for plates in (True, False):
            g = vessel(plates)
            v = self.verdict(g, [spouting(g, self.rng) for _ in range(6)])
            self.assertTrue(v.spouts, v.describe())
            self.assertEqual(v.fraction, 1.0)

    def test_packed_bed_does_not_spout(self):
        for plates in (True, False):
            g = vessel(plates)
            self.assertFalse(self.verdict(g, [packed(g)] * 6).spouts)

    def test_bubbling_bed_does_not_spout_though_it_opens_once(self):
        g = vessel(False)
        v = self.verdict(g, [bubbling(g, self.rng, k) for k in range(6)])
        self.assertEqual([s.spouts for s in v.snapshots], [False] * 5 + [True])
        self.assertFalse(v.spouts, v.describe())
        # the core alone says no: dense most of the time at every height
        self.assertFalse(v.open_core, v.describe())
        self.assertGreater(v.core_ratio, 0.7)
        self.assertIn('1 of 6 write times open', v.describe())

    def test_a_spout_carrying_a_slug_spouts_though_no_write_time_is_open(self):
        # the draft-plate paper's spout at u_ms carries slugs: a packed plug
        # 60 mm tall rises through the open channel, a different height at
        # each write time; every snapshot has a dense layer, the window's
        # mean core does not
        for plates in (True, False):
            g = vessel(plates)
            fields = [slugging(g, self.rng, k) for k in range(6)]
            v = self.verdict(g, fields)
            self.assertEqual([s.open_core for s in v.snapshots], [False] * 6)
            self.assertTrue(v.spouts, v.describe())
            self.assertLess(v.core_ratio, 0.5)

    def test_a_spout_pinched_off_at_one_write_time_of_six_still_spouts(self):
        g = vessel(True)
        fields = [spouting(g, self.rng) for _ in range(5)] + [packed(g)]
        self.assertTrue(self.verdict(g, fields).spouts)

    def test_the_region_is_a_parameter(self):
        # a narrow spout (16.5 mm half width, the slot's) without plates: in
        # the default 27.5-mm column its layers carry dense annulus at the
        # sides (5 of 7 lattice columns dense), in a region of its own width not
        g = vessel(False)
        fields = [spouting(g, self.rng, half=0.0165) for _ in range(6)]
        self.assertFalse(self.verdict(g, fields).spouts)
        narrow = sr.SpoutRegion(0.0165, 0.095)
        self.assertTrue(self.verdict(g, fields, narrow).spouts)

    def test_a_bad_region_is_refused(self):
        with self.assertRaises(ValueError):
            sr.SpoutRegion(0.0, 0.095)
        with self.assertRaises(SystemExit):
            sr.region_from_text('27.5', vessel(True), 'evaluate')


if __name__ == '__main__':
    unittest.main()
