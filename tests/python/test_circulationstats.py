"""The reader and checks of circulation.json (spoutlab.circulationstats) on
a file written here by hand: one state with visits of 0.2 and 0.4 s, the
checks' numbers worked out in the comments, and files that break the
schema."""
import copy
import json
import math
import os
import tempfile
import unittest

from spoutlab import circulationstats as cs


def distribution(samples=0, mean=0.0, std=0.0, counts=None):
    return {'binWidth': 0.1, 'counts': counts if counts is not None else ([samples] if samples else []),
            'samples': samples, 'mean': mean, 'std': std}


def conditions(holdup=0.0, entries=0, open_start=0.0, open_end=0.0):
    c = {k: 0.0 for k in cs.CONDITION_KEYS}
    c.update(holdup=holdup, entries=entries, entryRate=entries / 2.0, openAtStart=open_start,
             openAtEnd=open_end)
    return c


def made_up():
    """A 2 s window (20 samples of 0.1 s). Spout: visits 0.2 and 0.4 s
    (mean 0.3, std sqrt(0.02) = 0.141421), 4 entries, holdup 0.5:
    occupancy 0.5 x 2 = 1.0 particle s = 0.6 completed + 0.1 + 0.3 open."""
    stats = {
        'format': cs.FORMAT,
        'run': {'case': 'made-up', 'u_s': 2.0, 'particles': 10, 'particleDiameter': 0.008,
                'particleDensity': 1231.0, 'particleMass': 3.3e-4, 'heatTransferModel': 'none',
                'inletTemperature': 0, 'inletHumidityRatio': 0,
                'geometry': {k: 0.1 for k in cs.GEOMETRY_KEYS},
                'timeStart': 0.1, 'timeEnd': 2.0, 'samplingInterval': 0.1, 'window': 2.0},
        'regions': list(cs.REGIONS),
        'residence': {k: distribution() for k in cs.DISTRIBUTIONS},
        'halves': {h: {k: {'samples': 0, 'mean': 0, 'std': 0} for k in cs.DISTRIBUTIONS}
                   for h in ('first', 'second')},
        'conditions': {k: conditions() for k in cs.REGIONS},
        'gas': {'inletMassFlow': 0.04, 'spoutShare': 0.9, 'downcomerShare': 0.1},
        'circulationRate': 0.0,
    }
    stats['residence']['spout'] = distribution(2, 0.3, math.sqrt(0.02), [0, 0, 1, 0, 1])
    stats['conditions']['spout'] = conditions(0.5, 4, 0.1, 0.3)
    return stats


class Reader(unittest.TestCase):
    def write(self, stats):
        path = os.path.join(tempfile.mkdtemp(), 'circulation.json')
        with open(path, 'w') as f:
            json.dump(stats, f)
        return path

    def test_reads_a_whole_file(self):
        self.assertEqual(cs.read(self.write(made_up()))['run']['case'], 'made-up')

    def test_missing_key_named(self):
        stats = made_up()
        del stats['run']['geometry']['Hd']
        with self.assertRaisesRegex(cs.SchemaError, 'run/geometry: missing Hd'):
            cs.read(self.write(stats))

    def test_counts_must_add_up(self):
        stats = made_up()
        stats['residence']['spout']['counts'] = [1]
        with self.assertRaisesRegex(cs.SchemaError, 'residence/spout: counts'):
            cs.read(self.write(stats))

    def test_wrong_format(self):
        stats = made_up()
        stats['format'] = 'spoutlab-circulation 0'
        with self.assertRaisesRegex(cs.SchemaError, 'format'):
            cs.read(self.write(stats))


class Checks(unittest.TestCase):
    def test_boundary_terms(self):
        occupied, visits = cs.boundary_terms(made_up(), 'spout')
        self.assertAlmostEqual(occupied, 1.0, places=12)
        self.assertAlmostEqual(visits, 0.6 + 0.1 + 0.3, places=12)

    def test_littles_law(self):
        # rate 4/2 = 2 per s, W 0.3: 1 - 2 x 0.3/0.5 = -0.2; bias
        # var/(W T) = 0.02/(0.3 x 2) = 0.0333; sigma from
        # std/(W sqrt 2) = 0.333 and sqrt(2/0.5) (0.02 + 0.09)/(2 0.3 2) = 0.18333
        residual, bias, sigma = cs.littles_law(made_up(), 'spout')
        self.assertAlmostEqual(residual, -0.2, places=12)
        self.assertAlmostEqual(bias, 0.02 / 0.6, places=12)
        self.assertAlmostEqual(sigma, math.hypot(math.sqrt(0.02) / (0.3 * math.sqrt(2)), 0.11 / 0.6),
                               places=12)
        self.assertIsNone(cs.littles_law(made_up(), 'fountain'))

    def test_halves(self):
        stats = made_up()
        stats['halves']['first']['spout'] = {'samples': 4, 'mean': 1.0, 'std': 0.4}
        stats['halves']['second']['spout'] = {'samples': 9, 'mean': 1.5, 'std': 0.6}
        diff, error, how = cs.halves_agreement(stats, 'spout')
        self.assertAlmostEqual(diff, -0.5, places=12)
        self.assertAlmostEqual(error, math.sqrt(0.16 / 4 + 0.36 / 9), places=12)
        self.assertEqual(how, 'visits')
        self.assertIsNone(cs.halves_agreement(stats, 'cycle'))

    def test_halves_by_batch_means(self):
        """The first half's batches scatter about its mean 1.0 by -0.4, 0,
        +0.4, 0 (sums less mean x samples), the second's not at all: the
        error is sqrt(4/3 x 0.32) / 4 from the first half alone."""
        stats = made_up()
        stats['halves']['first']['spout'] = {'samples': 4, 'mean': 1.0, 'std': 0.4}
        stats['halves']['second']['spout'] = {'samples': 9, 'mean': 1.5, 'std': 0.6}
        stats['batches'] = {h: {k: {'samples': [0] * 4, 'sum': [0] * 4} for k in cs.DISTRIBUTIONS}
                            for h in ('first', 'second')}
        stats['batches']['first']['spout'] = {'samples': [1, 1, 1, 1], 'sum': [0.6, 1.0, 1.4, 1.0]}
        stats['batches']['second']['spout'] = {'samples': [2, 3, 2, 2], 'sum': [3, 4.5, 3, 3]}
        cs.check_schema(stats, 'made-up')
        diff, error, how = cs.halves_agreement(stats, 'spout')
        self.assertAlmostEqual(diff, -0.5, places=12)
        self.assertAlmostEqual(error, math.sqrt(4 / 3 * 0.32) / 4, places=12)
        self.assertEqual(how, 'batches')
        # visits in one batch only give no error
        stats['batches']['first']['spout'] = {'samples': [0, 4, 0, 0], 'sum': [0, 4, 0, 0]}
        self.assertIsNone(cs.halves_agreement(stats, 'spout'))
        stats['batches']['first']['spout'] = {'samples': [1, 1, 1], 'sum': [1, 1, 1]}
        with self.assertRaisesRegex(cs.SchemaError, 'batches/first/spout'):
            cs.check_schema(stats, 'made-up')

    def test_cycle_vs_ws(self):
        stats = copy.deepcopy(made_up())
        stats['residence']['cycle'] = distribution(5, 11.0, 1.0, [0] * 110 + [5])
        stats['residence']['downcomer'] = distribution(5, 6.0, 1.0, [0] * 60 + [5])
        stats['conditions']['downcomer'] = conditions(holdup=2000, entries=600)
        # bed 3.3 kg, W_s 0.3 kg/s: 11 s; completed cycles 11 s (0 %),
        # Kaplan-Meier the same bin's midpoint 11.05 s; by Little's law
        # (0.5 + 2000) / (4 / 2 s) = 1000.25 s.  Downcomer: 2000 x 3.3e-4 /
        # 0.3 = 2.2 s against completed 6 s, Kaplan-Meier 6.05 s, Little
        # 2000 / (600 / 2 s) = 6.667 s
        c = cs.cycle_vs_ws(stats, 3.3, 0.3)
        self.assertAlmostEqual(c['cycle']['completed'], 0.0, places=12)
        self.assertAlmostEqual(c['cycle']['km'], 11.05 / 11 - 1, places=12)
        self.assertAlmostEqual(c['cycle']['little'], 1000.25 / 11 - 1, places=12)
        self.assertAlmostEqual(c['downcomer']['completed'], 6.0 / 2.2 - 1, places=12)
        self.assertAlmostEqual(c['downcomer']['km'], 6.05 / 2.2 - 1, places=12)
        self.assertAlmostEqual(c['downcomer']['little'], (2000 / 300) / 2.2 - 1, places=12)
        # more than 1 % of the cycles open beyond the window: no Kaplan-Meier mean
        stats['residence']['cycle']['censored'] = {'counts': [0] * 120 + [1], 'samples': 1}
        self.assertTrue(math.isnan(cs.cycle_vs_ws(stats, 3.3, 0.3)['cycle']['km']))


def renewal_window(n, window, shape, scale, bin_width, seed=7):
    """n particles, each in one state whose visits last gamma(shape, scale)
    s, one after another, observed over a window of `window` s from a
    stationary start (the visit open then length-biased, gamma(shape + 1),
    a uniform share of it left): the downcomer's entry of a statistics file
    as spoutFoam would write it, the visits begun in the window by their
    residence (ended) or their time so far at its end (censored)."""
    import random
    rng = random.Random(seed)
    bins = int(window / bin_width) + 1
    ended, censored, entries = [0] * bins, [0] * bins, 0
    for _ in range(n):
        t = rng.random() * rng.gammavariate(shape + 1, scale)
        while t < window:
            tau = rng.gammavariate(shape, scale)
            entries += 1
            if t + tau <= window:
                ended[int(tau / bin_width)] += 1
            else:
                censored[min(int((window - t) / bin_width), bins - 1)] += 1
            t += tau
    done = [x for i, c in enumerate(ended) for x in [(i + 0.5) * bin_width] * c]
    mean = sum(done) / len(done)
    stats = made_up()
    stats['run']['window'] = window
    stats['residence']['downcomer'] = dict(
        distribution(len(done), mean, 0.0, ended), binWidth=bin_width,
        censored={'counts': censored, 'samples': sum(censored)})
    stats['conditions']['downcomer'] = dict(conditions(holdup=n), entryRate=entries / window)
    return stats


def gamma_survival(t, shape, scale):
    """P(residence > t) of gamma(shape, scale) with an integer shape."""
    x = t / scale
    return math.exp(-x) * sum(x ** k / math.factorial(k) for k in range(shape))


class Censored(unittest.TestCase):
    def test_kaplan_meier_by_hand(self):
        # ended in bins 1 and 3, one censored in bin 0 and one in bin 2:
        # at risk 4 (bin 0: 4 - 0.5 exposed, none ended), 3 (bin 1: 1 of 3
        # ended, S 2/3), 2 (bin 2: 1.5 exposed, none), 1 (bin 3: ended, S 0)
        stats = made_up()
        stats['residence']['fountain'] = dict(distribution(2, 0.3, 0.1, [0, 1, 0, 1]),
                                              censored={'counts': [1, 0, 1], 'samples': 2})
        km = cs.kaplan_meier(stats, 'fountain')
        for got, want in zip(km['survival'], [1, 1, 2 / 3, 2 / 3, 0]):
            self.assertAlmostEqual(got, want, places=12)
        self.assertAlmostEqual(km['mean'], 0.1 * (1 + 5 / 6 + 2 / 3 + 1 / 3), places=12)
        self.assertEqual((km['ended'], km['censored'], km['beyond']), (2, 2, 0))
        self.assertIsNone(cs.kaplan_meier(made_up(), 'cycle'))

    def test_window_shorter_than_the_residences(self):
        # visits of gamma(4, 10 s), mean 40 s, seen through a 30 s window,
        # as the full bed's downcomer: the completed visits' mean is far
        # too short, Kaplan-Meier gives the survival up to the window's end
        # (within a few of its standard errors, about 0.005) and Little's
        # law the mean
        stats = renewal_window(20000, 30.0, 4, 10.0, 1.0)
        km = cs.kaplan_meier(stats, 'downcomer')
        for t in (5, 10, 20, 29):
            self.assertAlmostEqual(km['survival'][t], gamma_survival(t, 4, 10.0), delta=0.03)
        restricted = sum(0.5 * (gamma_survival(t, 4, 10.0) + gamma_survival(t + 1, 4, 10.0))
                         for t in range(len(km['survival']) - 1))   # over the same bins
        self.assertAlmostEqual(km['mean'], restricted, delta=0.015 * restricted)
        self.assertGreater(km['beyond'], 0.6)
        self.assertLess(stats['residence']['downcomer']['mean'], 0.5 * 40)
        self.assertAlmostEqual(cs.littles_mean(stats, 'downcomer'), 40.0, delta=0.03 * 40)

    def test_little_cycle_is_all_holdup_over_spout_entries(self):
        stats = made_up()   # spout: holdup 0.5, 4 entries in 2 s
        stats['conditions']['downcomer'] = conditions(holdup=3.5)
        self.assertAlmostEqual(cs.littles_mean(stats, 'cycle'), (0.5 + 3.5) / 2.0, places=12)
        self.assertAlmostEqual(cs.littles_mean(stats, 'spout'), 0.25, places=12)
        self.assertIsNone(cs.littles_mean(stats, 'fountain'))

    def test_censored_counts_must_add_up(self):
        stats = made_up()
        stats['residence']['spout']['censored'] = {'counts': [1, 2], 'samples': 4}
        with self.assertRaisesRegex(cs.SchemaError, 'residence/spout/censored'):
            cs.check_schema(stats)


if __name__ == '__main__':
    unittest.main()
