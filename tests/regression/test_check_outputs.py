#!/usr/bin/python3
"""check_outputs.py on a synthetic run directory (no simulation): within
tolerance it passes, a drifted value fails with DRIFT on its line, a number
that cannot be read fails, --update rewrites only the values (sources,
tolerances and notes kept; a second update changes no byte), and a
reference without a tolerance's reason, or a bad command line, is refused
with one line."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'check_outputs.py')

CSV = '''time [s],T [K],dP [Pa]
0,300,10
1,310,20
2,320,30
3,330,
'''

RESULTS = '''demo case

quantity                         SpoutLab
whole-run energy balance residual   1.5e-12
'''


def number(name, source, value, tolerance):
    return {'name': name, 'from': source, 'value': value, 'tolerance': tolerance,
            'why': 'test'}


def numbers():
    return [
        number('T at 1 s', {'csv': 'out.csv', 'column': 'T [K]',
                            'at': {'column': 'time [s]', 'value': 1}}, 310.0, {'absolute': 0.01}),
        number('last T', {'csv': 'out.csv', 'column': 'T [K]', 'row': 'last'}, 330.0,
               {'relative': 1e-4}),
        number('mean dP from 1 s', {'csv': 'out.csv', 'column': 'dP [Pa]', 'reduce': 'mean',
                                    'where': {'column': 'time [s]', 'min': 1}}, 25.0,
               {'relative': 1e-4}),
        number('max dP', {'csv': 'sub/out.csv', 'column': 'dP [Pa]', 'reduce': 'max'}, 30.0,
               {'relative': 1e-4}),
        number('rate', {'json': 'results.json', 'key': 'drying.rate'}, 2.5e-3, {'relative': 1e-4}),
        number('balance', {'text': 'results.txt',
                           'pattern': r'^whole-run energy balance residual\s+(\S+)'}, 1e-12,
               {'absolute': 1e-10}),
    ]


class CheckOutputs(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run_dir = os.path.join(self.tmp.name, 'run')
        os.makedirs(os.path.join(self.run_dir, 'sub'))
        self.write_outputs(CSV, 2.5e-3)
        self.reference = os.path.join(self.tmp.name, 'demo.json')
        self.write_reference(numbers())

    def tearDown(self):
        self.tmp.cleanup()

    def write_outputs(self, table, rate):
        for name in ('out.csv', 'sub/out.csv'):
            with open(os.path.join(self.run_dir, name), 'w') as f:
                f.write(table)
        with open(os.path.join(self.run_dir, 'results.json'), 'w') as f:
            json.dump({'drying': {'rate': rate}}, f)
        with open(os.path.join(self.run_dir, 'results.txt'), 'w') as f:
            f.write(RESULTS)

    def write_reference(self, entries):
        with open(self.reference, 'w') as f:
            json.dump({'test': 'case.demo', 'note': 'synthetic', 'numbers': entries}, f)

    def run_script(self, *extra):
        result = subprocess.run([sys.executable, SCRIPT, *extra, self.reference, self.run_dir],
                                capture_output=True, text=True)
        return result.returncode, result.stdout, result.stderr

    def line(self, out, name):
        return next(line for line in out.splitlines() if line.strip().startswith(name))

    def test_passes_on_its_own_values_and_inside_tolerance(self):
        status, out, _ = self.run_script()
        self.assertEqual(status, 0, out)
        self.assertEqual(sum(line.endswith(' ok') for line in out.splitlines()), 6, out)
        # T at 1 s moves by 0.009 K (tolerance 0.01 K), the rate by 0.9e-4
        self.write_outputs(CSV.replace('1,310,', '1,310.009,'), 2.5e-3 * (1 + 0.9e-4))
        status, out, _ = self.run_script()
        self.assertEqual(status, 0, out)

    def test_fails_on_drift_beyond_tolerance(self):
        # absolute: 0.011 K on a 0.01 K tolerance
        self.write_outputs(CSV.replace('1,310,', '1,310.011,'), 2.5e-3)
        status, out, _ = self.run_script()
        self.assertEqual(status, 1, out)
        self.assertTrue(self.line(out, 'T at 1 s').endswith('DRIFT'), out)
        self.assertTrue(self.line(out, 'rate').endswith('ok'), out)
        # relative: 1.1e-4 on 1e-4
        self.write_outputs(CSV, 2.5e-3 * (1 + 1.1e-4))
        status, out, _ = self.run_script()
        self.assertEqual(status, 1, out)
        self.assertTrue(self.line(out, 'rate').endswith('DRIFT'), out)
        # a NaN is never within tolerance
        self.write_outputs(CSV.replace('2,320,30', '2,320,nan'), 2.5e-3)
        status, out, _ = self.run_script()
        self.assertEqual(status, 1, out)
        self.assertTrue(self.line(out, 'mean dP from 1 s').endswith('DRIFT'), out)

    def test_a_number_that_cannot_be_read_fails(self):
        os.remove(os.path.join(self.run_dir, 'results.json'))
        status, out, _ = self.run_script()
        self.assertEqual(status, 1)
        self.assertIn('results.json: missing', self.line(out, 'rate'))
        entries = numbers()
        entries[0]['from']['at']['value'] = 1.5    # no row at 1.5 s
        self.write_reference(entries)
        status, out, _ = self.run_script()
        self.assertEqual(status, 1)
        self.assertIn('no row with "time [s]" = 1.5', self.line(out, 'T at 1 s'))

    def test_update_rewrites_values_only(self):
        self.write_outputs(CSV.replace('3,330,', '3,331.5,'), 3e-3)
        status, out, _ = self.run_script('--update')
        self.assertEqual(status, 0, out)
        with open(self.reference) as f:
            updated = json.load(f)
        expected = numbers()
        expected[1]['value'] = 331.5
        expected[4]['value'] = 3e-3
        expected[5]['value'] = 1.5e-12     # within tolerance, rewritten all the same
        self.assertEqual(updated['numbers'], expected)
        self.assertEqual(updated['note'], 'synthetic')
        status, out, _ = self.run_script()
        self.assertEqual(status, 0, out)
        # a second update writes the same bytes: no diff without drift
        with open(self.reference, 'rb') as f:
            first = f.read()
        self.run_script('--update')
        with open(self.reference, 'rb') as f:
            self.assertEqual(f.read(), first)
        # one changed value is one changed line of the file
        self.write_outputs(CSV.replace('3,330,', '3,332,'), 3e-3)
        self.run_script('--update')
        with open(self.reference, 'rb') as f:
            second = f.read()
        changed = [a for a, b in zip(first.splitlines(), second.splitlines()) if a != b]
        self.assertEqual(len(first.splitlines()), len(second.splitlines()))
        self.assertEqual(changed, [b'    "value": 331.5,'])

    def test_update_refuses_when_a_number_cannot_be_read(self):
        with open(self.reference, 'rb') as f:
            before = f.read()
        os.remove(os.path.join(self.run_dir, 'out.csv'))
        status, out, _ = self.run_script('--update')
        self.assertEqual(status, 1)
        self.assertIn('not updated', out)
        with open(self.reference, 'rb') as f:
            self.assertEqual(f.read(), before)

    def test_reference_without_reason_is_refused_in_one_line(self):
        entries = numbers()
        del entries[2]['why']
        self.write_reference(entries)
        status, _, err = self.run_script()
        self.assertEqual(status, 2)
        self.assertEqual(len(err.strip().splitlines()), 1, err)
        self.assertIn('"mean dP from 1 s": no "why"', err)
        self.assertIn('demo.json', err)

    def test_bad_command_line_is_one_line(self):
        for args in (['--bogus'], ['only-one-argument']):
            result = subprocess.run([sys.executable, SCRIPT, *args],
                                    capture_output=True, text=True)
            self.assertEqual(result.returncode, 2)
            self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)


if __name__ == '__main__':
    unittest.main()
