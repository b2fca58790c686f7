"""The circulation rate's standard error (spoutlab.circulationrate) and the
weighted slope of log10 W_s against the friction coefficient
(spoutlab.profilefeatures.weighted_slope), on series and points whose
answers are known by construction; the series read back from a
made-up downcomerFlux output; and the particles a run deleted, set and
counted by the protocols."""
import contextlib
import io
import json
import math
import os
import random
import shutil
import tempfile
import types
import unittest

from spoutlab import circulationrate as cr
from spoutlab import profilefeatures as pf

DT = 3e-4


class BlockStandardError(unittest.TestCase):
    def test_blocks_of_known_means(self):
        # each 1 s block constant at a known value; before the window and a
        # last half block hold wild values that must stay out of the error
        means = [1.0, 3.0, 2.0, 6.0]
        t, y = [], []
        for k in range(5500):                      # samples of 1 ms, mid-step
            ti = (k + 0.5) * 1e-3
            t.append(ti)
            s = ti - 1.0                           # into the window
            y.append(1e3 if s < 0 else means[int(s)] if s < 4.0 else 50.0)
        mean, error, blocks = cr.block_standard_error(t, y, 1.0)
        m = sum(means) / 4
        sd = math.sqrt(sum((x - m) ** 2 for x in means) / 3)
        self.assertEqual(blocks, 4)
        self.assertAlmostEqual(error, sd / 2, places=9)
        # the mean takes the half block too, not the samples before the window
        self.assertAlmostEqual(mean, (m * 4000 + 50.0 * 500) / 4500, places=9)

    def test_window_starts_at_its_first_step(self):
        # OpenFOAM's fieldAverage takes the step at timeStart itself
        mean, _, _ = cr.block_standard_error([0.9, 1.0, 1.5], [100.0, 5.0, 1.0], 1.0)
        self.assertEqual(mean, 3.0)

    def test_white_noise(self):
        # independent samples: the block error estimates sigma / sqrt(n)
        rng = random.Random(7)
        t = [(k + 1) * DT for k in range(int(round(40.2 / DT)))]
        y = [0.3 + rng.gauss(0, 0.1) for _ in t]
        mean, error, blocks = cr.block_standard_error(t, y, 0.0)
        expected = 0.1 / math.sqrt(len(t))
        self.assertEqual(blocks, 40)
        # 40 blocks: the estimate's own relative spread is 1/sqrt(78), 11 %
        self.assertLess(abs(error / expected - 1), 0.35)
        self.assertLess(abs(mean - 0.3), 4 * expected)

    def test_correlated_series(self):
        # AR(1) with a correlation time of 0.1 s: the naive sigma/sqrt(n)
        # is far too small, the blocks get the error of the mean
        rng = random.Random(11)
        tau, sigma = 0.1, 0.05
        a = math.exp(-DT / tau)
        x, t, y = 0.0, [], []
        for k in range(int(round(60 / DT))):
            x = a * x + math.sqrt(1 - a * a) * sigma * rng.gauss(0, 1)
            t.append((k + 1) * DT)
            y.append(0.2 + x)
        mean, error, blocks = cr.block_standard_error(t, y, 0.0)
        n = len(y)
        exact = sigma * math.sqrt((1 + a) / (1 - a) / n)   # the AR(1) mean's error
        naive = sigma / math.sqrt(n)
        self.assertGreater(exact / naive, 10)
        self.assertLess(abs(error / exact - 1), 0.4)        # 60 blocks: 13 % spread

    def test_too_short_a_window(self):
        t = [(k + 1) * DT for k in range(int(round(1.5 / DT)))]
        mean, error, blocks = cr.block_standard_error(t, [2.0] * len(t), 0.0)
        self.assertEqual((mean, error, blocks), (2.0, None, 1))
        self.assertEqual(cr.block_standard_error(t, [2.0] * len(t), 5.0), (None, None, 0))


class Series(unittest.TestCase):
    def test_read_back(self):
        # two time directories (a restart at 0.6 s that repeats 0.6): the
        # later one's rows replace the earlier's from its first time
        case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, case)
        g = types.SimpleNamespace(dx=11.0, Lb=40.0, particles={'rhop': 1231.0})
        area = 11e-3 * 40e-3
        for start, rows in (('0', [(0.3, -1e-3), (0.6, 9.0), (0.9, 9.0)]),
                            ('0.6', [(0.6, -2e-3), (0.9, -4e-3)])):
            d = os.path.join(case, 'postProcessing', cr.FUNCTION_OBJECT, start)
            os.makedirs(d)
            with open(os.path.join(d, 'volFieldValue.dat'), 'w') as f:
                f.write('# Region type : cellZone downcomerBase\n# Time\tsum(solidFlux)\n')
                for ti, fz in rows:
                    f.write('%g\t(0.5 0.1 %r)\n' % (ti, fz))
        t, ws = cr.series(case, g)
        self.assertEqual(t, [0.3, 0.6, 0.9])
        for got, fz in zip(ws, (-1e-3, -2e-3, -4e-3)):
            self.assertAlmostEqual(got, -1231.0 * area * fz, places=12)

    def test_no_output(self):
        case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, case)
        g = types.SimpleNamespace(dx=11.0, Lb=40.0, particles={'rhop': 1231.0})
        self.assertIsNone(cr.series(case, g))


class WeightedSlope(unittest.TestCase):
    def test_exact_line(self):
        xs = [0.02, 0.063, 0.1, 0.2, 0.3]
        ys = [-0.194 - 3.25 * x for x in xs]
        sig = [0.02, 0.01, 0.02, 0.03, 0.04]
        b, error, chi2 = pf.weighted_slope(xs, ys, sig)
        self.assertAlmostEqual(b, -3.25, places=10)
        w = [1 / s ** 2 for s in sig]
        mx = sum(wi * x for wi, x in zip(w, xs)) / sum(w)
        self.assertAlmostEqual(error, 1 / math.sqrt(sum(wi * (x - mx) ** 2
                                                        for wi, x in zip(w, xs))), places=12)
        self.assertAlmostEqual(chi2, 0.0, places=12)

    def test_weights_pull_the_line(self):
        # a point known a hundred times better than the others sets the line
        # through it: the slope of two precise points wins
        xs, ys = [0.0, 1.0, 2.0], [0.0, 1.0, 5.0]
        b, _, _ = pf.weighted_slope(xs, ys, [0.001, 0.001, 1.0])
        self.assertAlmostEqual(b, 1.0, places=4)
        self.assertAlmostEqual(pf.slope(xs, ys), 2.5, places=12)

    def test_scatter_widens_the_error(self):
        # points off the line by about 3 sigma: chi-square above 1, and the
        # error grows by its root
        xs, sig = [0.0, 1.0, 2.0, 3.0], [0.1] * 4
        ys = [0.3, 0.7, 2.3, 2.7]
        b, error, chi2 = pf.weighted_slope(xs, ys, sig)
        bare = 0.1 / math.sqrt(sum((x - 1.5) ** 2 for x in xs))
        self.assertGreater(chi2, 1)
        self.assertAlmostEqual(error, bare * math.sqrt(chi2), places=12)
        self.assertAlmostEqual(b, pf.slope(xs, ys), places=12)   # equal weights



class FrictionResults(unittest.TestCase):
    """protocols/results on a made-up friction study: the slope weighted by
    the points' standard errors, and its error key."""

    def study(self, errors):
        case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, case)
        mus = [0.02, 0.1, 0.3]
        points = [{'label': 'mu%g_u1.25' % mu, 'u_m_s': 1.25,
                   'W_s_kg_s': 10 ** (-0.2 - 3.0 * mu), 'W_s_err_kg_s': err,
                   'correlation_kg_s': 10 ** (-3.25 * mu - 0.194)}
                  for mu, err in zip(mus, errors)]
        with open(os.path.join(case, 'circulation_friction.json'), 'w') as f:
            json.dump({'settings': 'made up', 'points': points}, f)
        open(os.path.join(case, 'circulation_friction.txt'), 'w').write('made up\n')
        return case, mus, points

    def test_weighted_slope_and_its_error(self):
        from spoutlab.protocols import results
        case, mus, points = self.study([0.02, 0.01, 0.005])
        rows, _, slope = results.circulation_rows(case, 'friction')
        self.assertAlmostEqual(slope[0], -3.0, places=3)      # on the line: no scatter
        sig = [p['W_s_err_kg_s'] / (p['W_s_kg_s'] * math.log(10)) for p in points]
        self.assertAlmostEqual(slope[1], pf.weighted_slope(mus, [math.log10(p['W_s_kg_s'])
                                                                 for p in points], sig)[1])
        self.assertIn('+-', rows[-1][1])

    def test_particles_lost_beside_their_point(self):
        from spoutlab.protocols import results
        case, _, points = self.study([0.02, 0.01, 0.005])
        points[1]['particles_lost'] = 1
        points[2]['particles_lost'] = 3
        with open(os.path.join(case, 'circulation_friction.json'), 'w') as f:
            json.dump({'settings': 'made up', 'points': points}, f)
        rows, _, _ = results.circulation_rows(case, 'friction')
        self.assertNotIn('lost', rows[0][1])
        self.assertTrue(rows[1][1].endswith('; 1 particle lost'))
        self.assertTrue(rows[2][1].endswith('; 3 particles lost'))

    def test_friction_section_without_a_ums_copy(self):
        from spoutlab.protocols import results
        case, _, _ = self.study([0.02, 0.01, 0.005])
        out = os.path.join(case, 'docs', 'RESULTS.md')
        os.makedirs(os.path.dirname(out))
        open(out, 'w').write('<!-- section ums -->\n## kept\n<!-- end ums -->\n')
        with open(os.path.join(os.path.dirname(out), 'results.csv'), 'w') as f:
            f.write('key,value,unit,paper_value,note\ndraft.u_ms_m_s,1.2,m/s,1.25,kept\n')
        self.assertEqual(results.main(['--circulation', case, '-o', out]), 0)
        text = open(out).read()
        self.assertIn('## kept', text)
        self.assertIn('d log10 W_s / d mu', text)
        keys = [line.split(',')[0] for line in open(os.path.join(os.path.dirname(out),
                                                                 'results.csv'))]
        self.assertIn('draft.u_ms_m_s', keys)
        self.assertIn('draft.dlogWs_dmu_err', keys)

    def test_without_errors_the_plain_slope(self):
        from spoutlab.protocols import results
        case, _, _ = self.study([None, 0.01, 0.005])
        _, _, slope = results.circulation_rows(case, 'friction')
        self.assertAlmostEqual(slope[0], -3.0, places=3)
        self.assertEqual(slope[1:], (None, None))


class DragVelocityLine(unittest.TestCase):
    def test_from_the_case_copies(self):
        from spoutlab.protocols import results
        root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, root)
        for name, text in (('new', 'dragVelocity      flux;\n#include "heatTransfer"\n'),
                           ('old', 'dragModel Gidaspow;\n'), ('cc', 'dragVelocity cellCentre;\n')):
            os.makedirs(os.path.join(root, name, 'constant'))
            open(os.path.join(root, name, 'constant', 'couplingProperties'), 'w').write(text)
        self.assertEqual(results.drag_velocity(os.path.join(root, 'new')), 'flux')
        self.assertEqual(results.drag_velocity(os.path.join(root, 'old')), 'cellCentre')
        self.assertIsNone(results.drag_velocity(os.path.join(root, 'none')))
        line = results.drag_velocity_line(results.drag_velocities(
            [os.path.join(root, n) for n in ('old', 'cc', 'none')]))
        self.assertIn('cellCentre', line)
        self.assertNotIn('flux`', line)
        self.assertEqual(results.drag_velocity_line([]), '')
        row = results.with_drag({'note': 'eq 16'}, results.drag_velocities(
            [os.path.join(root, 'new')]))
        self.assertEqual(row['note'], 'eq 16; dragVelocity flux')
        self.assertEqual(results.with_drag({'note': 'x'}, [])['note'], 'x')


if __name__ == '__main__':
    unittest.main()


class LostParticles(unittest.TestCase):
    """Every protocol point runs with lostParticles delete, and what
    spoutFoam deleted is counted from its log."""

    def case(self):
        case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, case)
        os.makedirs(os.path.join(case, 'constant'))
        os.makedirs(os.path.join(case, '0.orig'))
        open(os.path.join(case, 'constant', 'couplingProperties'), 'w').write(
            'dragModel Gidaspow;\nlostParticles     stop;            // stop | delete\n')
        with open(os.path.join(case, 'Allrun'), 'w') as f:
            f.write('#!/bin/sh\nexit 0\n')
        os.chmod(os.path.join(case, 'Allrun'), 0o755)
        return case

    def test_count_from_the_log(self):
        from spoutlab import caserun
        case = self.case()
        self.assertEqual(caserun.lost_particles(case), 0)          # no log yet
        open(os.path.join(case, 'log.spoutFoam'), 'w').write(
            'Time = 1.0632\n'
            'spoutFoam: deleting 1 particle(s) outside the CFD mesh at t = 1.0632 s (ids 2806)\n'
            'a line that says 7 particle(s) outside the CFD mesh, quoted\n'
            'spoutFoam: 2 particle(s) lost by LIGGGHTS (centre out of its box, ...)\n')
        self.assertEqual(caserun.lost_particles(case), 3)
        self.assertEqual(caserun.lost_text(3), '; 3 particles lost')
        self.assertEqual(caserun.lost_text(0), '')

    def test_wall_time_over_restarts(self):
        # a run killed at 5 s of its clock and continued for 3 s more, and a
        # second run below the case: 5 + 3 + 2 s, whatever log.wallTime says
        from spoutlab import caserun
        case = self.case()
        clock = lambda seconds: ''.join('ExecutionTime = %g s  ClockTime = %d s\n' % (0.9 * s, s)
                                        for s in seconds)
        open(os.path.join(case, 'log.spoutFoam'), 'w').write(
            clock([1, 2, 5]) + 'Time = 0.3\n' + clock([0, 1, 3]))
        os.makedirs(os.path.join(case, 'runs', 'p'))
        open(os.path.join(case, 'runs', 'p', 'log.spoutFoam'), 'w').write(clock([1, 2]))
        open(os.path.join(case, 'log.wallTime'), 'w').write('3\n')
        self.assertEqual(caserun.wall_time(case), 10.0)
        self.assertEqual(caserun.wall_time(os.path.join(case, 'runs', 'p')), 2.0)

    def finished_run(self, case, options):
        work = os.path.join(case, 'runs', 'p')
        os.makedirs(os.path.join(work, 'constant'))
        shutil.copy(os.path.join(case, 'constant', 'couplingProperties'),
                    os.path.join(work, 'constant'))
        with open(os.path.join(work, 'Allrun'), 'w') as f:
            f.write('#!/bin/sh\necho "$@" > called\n')
        os.chmod(os.path.join(work, 'Allrun'), 0o755)
        open(os.path.join(work, 'log.options'), 'w').write(
            '# options\noptions: %s\nevaluate: --window 10.0\n' % options)
        open(os.path.join(work, 'log.spoutFoam'), 'w').write('Time = 12\n')
        open(os.path.join(work, 'circulation.csv'), 'w').write('quantity,h,value\n')
        return work

    def test_finished_points_kept_or_continued(self):
        from spoutlab.protocols import circulation
        case = self.case()
        here = os.getcwd()
        os.chdir(case)
        self.addCleanup(os.chdir, here)
        options = '-u 1.25 -k 2.0,1.0 -t 12.0 -a 10.0 -np 1 mu=0.2'
        work = self.finished_run(case, options)
        o = {'kick': '2.0,1.0', 'time': 12.0, 'average': 10.0, 'np': 1, 'n': None,
             'overrides': []}
        circulation.run_point(o, 'p', 1.25, ['mu=0.2'], {})        # the same: kept
        self.assertFalse(os.path.isfile(os.path.join(work, 'called')))
        circulation.run_point(dict(o, time=30.0, average=28.0), 'p', 1.25, ['mu=0.2'], {})
        self.assertEqual(open(os.path.join(work, 'called')).read().split(),
                         ['-c'] + options.replace('12.0', '30.0').replace('10.0', '28.0').split())

    def test_points_delete_them(self):
        from spoutlab import foamfile
        from spoutlab.protocols import circulation
        case = self.case()
        o = {'kick': '2.0,1.0', 'time': 1.0, 'average': 0.5, 'np': 1, 'n': None,
             'overrides': []}
        here = os.getcwd()
        os.chdir(case)
        self.addCleanup(os.chdir, here)
        work = circulation.run_point(o, 'p', 1.25, [], {},
                                     [('constant/couplingProperties', 'dragModel', 'Ergun')])
        path = os.path.join(work, 'constant', 'couplingProperties')
        self.assertEqual(foamfile.entry(path, 'lostParticles', 'stop'), 'delete')
        self.assertEqual(foamfile.entry(path, 'dragModel', ''), 'Ergun')


class ContinuedRuns(unittest.TestCase):
    """--target-error: the runs above it go on by --step seconds, their
    averaging start kept, until below it or at --longest; a run longer than
    asked with the same start is kept; the table gives each run's end."""

    # a stand-in for the case's Allrun: records its options as startCase
    # and evaluate would and writes a W_s whose standard error falls as
    # 1/(end - start), the averaging window
    ALLRUN = """#!/usr/bin/python3
import sys
args = [a for a in sys.argv[1:] if a != '-c']
value = dict(zip(args, args[1:]))
end, window = float(value['-t']), float(value['-a'])
open('log.options', 'w').write('# options\\noptions: %s\\nevaluate: --window %s\\n'
                               % (' '.join(args), value['-a']))
open('log.spoutFoam', 'a').write('Time = %g\\n' % end)
with open('calls', 'a') as f:
    f.write(' '.join(sys.argv[1:]) + '\\n')
err = 0.9 / window if 'mu=0.3' in args else 0.1 / window
open('circulation.csv', 'w').write('quantity,height [mm],value [kg/s]\\n'
                                   'W_s downward in the downcomers (eq 14),427.5,1.0\\n'
                                   'W_s standard error (1 s blocks),427.5,%r\\n' % err)
"""

    def setUp(self):
        self.case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.case)
        os.makedirs(os.path.join(self.case, 'constant'))
        os.makedirs(os.path.join(self.case, '0.orig'))
        open(os.path.join(self.case, 'constant', 'couplingProperties'), 'w').write(
            'lostParticles     stop;\n')
        with open(os.path.join(self.case, 'Allrun'), 'w') as f:
            f.write(self.ALLRUN)
        os.chmod(os.path.join(self.case, 'Allrun'), 0o755)
        here = os.getcwd()
        os.chdir(self.case)
        self.addCleanup(os.chdir, here)

    def calls(self, label):
        return open(os.path.join('runs', label, 'calls')).read().splitlines()

    def test_window_and_covers(self):
        from spoutlab.protocols import circulation as c
        run = '-u 1.25 -k 2.0,1.0 -t 12.0 -a 10.0 -np 1 mu=0.2'.split()
        self.assertEqual(c.window(run), (12.0, 2.0))
        self.assertEqual(c.window(['-u', '2']), (3.0, 1.2))            # Allrun's defaults
        self.assertTrue(c.covers(run, run))
        self.assertTrue(c.covers('-u 1.25 -k 2.0,1.0 -t 18 -a 16 -np 1 mu=0.2'.split(), run))
        self.assertFalse(c.covers(run, '-u 1.25 -k 2.0,1.0 -t 18 -a 16 -np 1 mu=0.2'.split()))
        self.assertFalse(c.covers('-u 1.25 -k 2.0,1.0 -t 18 -a 15 -np 1 mu=0.2'.split(), run))
        self.assertFalse(c.covers(run, '-u 1.25 -k 2.0,1.0 -t 12.0 -a 10.0 -np 1 mu=0.3'.split()))
        self.assertFalse(c.covers(None, run))

    def test_continued_until_below_the_target(self):
        from spoutlab.protocols import circulation as c
        with contextlib.redirect_stdout(io.StringIO()):
            c.main(['friction', '--mu', '0.2,0.3', '--time', '12', '--average', '10',
                    '--target-error', '0.05', '--step', '6', '--longest', '30'])
        # mu 0.2: 0.1/10 = 1 %, below 5 % at once; mu 0.3: 0.9/10 = 9 %, 0.9/16 = 5.6 %,
        # 0.9/22 = 4.1 %: on to 18 s, then to 24 s, its averages from 2 s each time
        self.assertEqual(len(self.calls('mu0.2_u1.25')), 1)
        asked = []
        for call in self.calls('mu0.3_u1.25'):
            words = call.split()
            value = dict(zip(words, words[1:]))
            asked.append((words[0] == '-c', float(value['-t']), float(value['-a'])))
        self.assertEqual(asked, [(False, 12, 10), (True, 18, 16), (True, 24, 22)])
        table = json.load(open('circulation_friction.json'))
        self.assertEqual([(p['time_s'], p['average_s']) for p in table['points']],
                         [(12.0, 10.0), (24.0, 22.0)])
        self.assertIn("to each run's end (--target-error 0.05)", table['settings'])
        # the same command again: every run covers what it asks, nothing runs
        with contextlib.redirect_stdout(io.StringIO()):
            c.main(['friction', '--mu', '0.2,0.3', '--time', '12', '--average', '10',
                    '--target-error', '0.05'])
        self.assertEqual(len(self.calls('mu0.3_u1.25')), 3)

    def test_an_interrupted_continuation_goes_on_to_its_own_end(self):
        from spoutlab.protocols import circulation as c
        with contextlib.redirect_stdout(io.StringIO()):
            c.main(['friction', '--mu', '0.3', '--time', '12', '--average', '10'])
        work = os.path.join('runs', 'mu0.3_u1.25')
        # killed on its way to 18 s: startCase wrote the options, evaluate did not run
        open(os.path.join(work, 'log.options'), 'w').write(
            '# options\noptions: -u 1.25 -k 2.0,1.0 -t 18.0 -a 16.0 -np 1 mu=0.3\n')
        with contextlib.redirect_stdout(io.StringIO()):
            c.main(['friction', '--mu', '0.3', '--time', '12', '--average', '10'])
        self.assertEqual(self.calls('mu0.3_u1.25')[-1],
                         '-c -u 1.25 -k 2.0,1.0 -t 18.0 -a 16.0 -np 1 mu=0.3')

    def test_longest_stops_it(self):
        from spoutlab.protocols import circulation as c
        with contextlib.redirect_stdout(io.StringIO()):
            c.main(['friction', '--mu', '0.3', '--time', '12', '--average', '10',
                    '--target-error', '0.01', '--step', '6', '--longest', '20'])
        self.assertEqual(len(self.calls('mu0.3_u1.25')), 2)        # 12, then 18; 24 > 20
