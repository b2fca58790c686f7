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
        diff, error = cs.halves_agreement(stats, 'spout')
        self.assertAlmostEqual(diff, -0.5, places=12)
        self.assertAlmostEqual(error, math.sqrt(0.16 / 4 + 0.36 / 9), places=12)
        self.assertIsNone(cs.halves_agreement(stats, 'cycle'))

    def test_cycle_vs_ws(self):
        stats = copy.deepcopy(made_up())
        stats['residence']['cycle'] = distribution(5, 11.0, 1.0)
        stats['residence']['downcomer'] = distribution(5, 6.0, 1.0)
        stats['conditions']['downcomer'] = conditions(holdup=2000)
        # bed 3.3 kg, W_s 0.3 kg/s: 11 s against 11 s; downcomer 2000 x
        # 3.3e-4 / 0.3 = 2.2 s against 6 s
        rel, rel_down = cs.cycle_vs_ws(stats, 3.3, 0.3)
        self.assertAlmostEqual(rel, 0.0, places=12)
        self.assertAlmostEqual(rel_down, 6.0 / 2.2 - 1, places=12)


if __name__ == '__main__':
    unittest.main()
