"""The command lines of the spouted bed's scripts and protocols, and of the
package's modules and the particle picture: each command answers --help,
stops on a bad option with one line naming it and nothing else on stderr
(status 2), and reads its options with the defaults its documentation
gave before the front ends were argparse (the values below are those of
the usage texts, not read from the code)."""
import contextlib
import io
import json
import os
import shutil
import signal
import subprocess
import tempfile
import unittest

from spoutlab.protocols import circulation, drying, dryingtime, heattransfer, minimumspouting
from spoutlab.protocols import coarsespeedup, mixing, profiles, results, spoutheight
from spoutlab.protocols import velocitymaps

REPOSITORY = os.path.abspath(os.environ.get('SPOUTLAB_DIR', '../..'))
COMMANDS = ['generate', 'inletVelocity', 'evaluate'] + [
    os.path.join('protocols', p) for p in ('minimumSpouting', 'circulation', 'profiles',
                                          'velocityMaps', 'heatTransfer', 'drying', 'results',
                                          'mixing', 'dryingTime', 'coarseSpeedup',
                                          'spoutHeight')]
CASE = None


def setUpModule():
    """The commands run in a copy of the case: a front end that let a bad
    option through would start its protocol there, not in the repository."""
    global CASE
    CASE = os.path.join(tempfile.mkdtemp(), 'spoutDraftPlates')
    shutil.copytree(os.path.join(REPOSITORY, 'openfoam_cases', 'spoutDraftPlates'), CASE)


def tearDownModule():
    shutil.rmtree(os.path.dirname(CASE))


def run(command, *args):
    """Run a command of the case copy; one that is still running after a
    minute (a protocol started) is stopped with all it started."""
    proc = subprocess.Popen([os.path.join(CASE, command)] + list(args), cwd=CASE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ, SPOUTLAB_DIR=REPOSITORY),
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise AssertionError('%s %s ran on instead of stopping at its options'
                             % (command, ' '.join(args)))
    return subprocess.CompletedProcess(proc.args, proc.returncode, out, err)


class Commands(unittest.TestCase):
    def test_help_and_a_bad_option(self):
        for command in COMMANDS:
            name = os.path.basename(command)
            with self.subTest(command=name):
                shown = run(command, '--help')
                self.assertEqual(shown.returncode, 0, shown.stderr)
                self.assertTrue(shown.stdout.startswith('usage: %s ' % name), shown.stdout)
                # the required arguments given, so that the option is what is wrong
                needs = {'inletVelocity': ['2'], 'circulation': ['velocity']}.get(name, [])
                bad = run(command, *(needs + ['--bogus']))
                self.assertEqual(bad.returncode, 2)
                self.assertEqual(bad.stderr.splitlines(),
                                 ['%s: unrecognized arguments: --bogus (%s --help lists the '
                                  'options)' % (name, name)])

    def test_a_bad_value_names_its_option(self):
        for command, args, option in (
                ('protocols/minimumSpouting', ['--hold', 'long'], 'argument --hold'),
                ('protocols/circulation', ['velocity', '--u', '1.4;1.6'], 'argument --u'),
                ('protocols/circulation', ['velocity', '--kick', '2'], 'argument --kick'),
                ('protocols/velocityMaps', ['--points', '3000'], 'argument --points'),
                ('protocols/spoutHeight', ['--runs', 'u1.4,u9'], 'argument --runs'),
                ('inletVelocity', ['fast'], 'argument NUMBER'),
                ('generate', ['He'], 'argument key=value')):
            with self.subTest(command=command, args=args):
                bad = run(command, *args)
                self.assertEqual(bad.returncode, 2)
                lines = bad.stderr.splitlines()
                self.assertEqual(len(lines), 1, bad.stderr)
                self.assertTrue(lines[0].startswith('%s: %s: '
                                                    % (os.path.basename(command), option)),
                                lines[0])

    def test_the_modules_and_the_particle_picture(self):
        env = dict(os.environ, PYTHONPATH=os.path.join(REPOSITORY, 'python'))
        for name, command in (
                ('mixing', ['-m', 'spoutlab.mixing', CASE]),
                ('decomposition', ['-m', 'spoutlab.decomposition', CASE, '2']),
                ('spoutregime', ['-m', 'spoutlab.spoutregime', CASE]),
                ('particles.py', [os.path.join(REPOSITORY, 'etc', 'paraview', 'particles.py'),
                                  CASE])):
            with self.subTest(command=name):
                if name == 'particles.py' and subprocess.run(
                        ['/usr/bin/python3', '-c', 'import vtkmodules'],
                        capture_output=True).returncode != 0:
                    continue   # VTK's Python absent: the picture cannot be tried
                bad = subprocess.run(['/usr/bin/python3'] + command + ['--bogus'],
                                     capture_output=True, text=True, env=env, timeout=60)
                self.assertEqual(bad.returncode, 2, bad.stderr)
                self.assertEqual(bad.stderr.splitlines(),
                                 ['%s: unrecognized arguments: --bogus (%s --help lists the '
                                  'options)' % (name, name)])


class Defaults(unittest.TestCase):
    """The documented defaults, and overrides wherever they stand."""

    def test_minimum_spouting(self):
        o = minimumspouting.options(['He=152', '--up', '-np', '2', 'mu=0.1', '-n', '1500'])
        expected = dict(vessel='plates', rise_from=1.0, top=3.0, stop=0.9, step=0.1,
                        kick=None, up=True, full_loop=False, report=False, confirm=2,
                        spinup=1.5, hold=2.5, average=1.8, start=2.0, n=1500, np=2)
        self.assertEqual({k: o[k] for k in expected}, expected)
        self.assertEqual(o['overrides'], ['He=152', 'mu=0.1', 'plates=yes', 'nParticles=1500'])
        with self.assertRaises(SystemExit):
            minimumspouting.options(['--hold', '1', '--average', '1.5'])

    def test_circulation(self):
        o = circulation.parse(['velocity'])
        expected = dict(study='velocity', He=[95, 152], u=[1.4, 1.6, 1.8, 2.0, 2.2],
                        time=4.0, average=1.8, kick='2.0,1.0', n=None, np=1, jobs=1,
                        overrides=[])
        self.assertEqual({k: o[k] for k in expected}, expected)
        o = circulation.parse(['friction', 'He=152', '-j', '2', 'e=0.8', '-n', '1500'])
        self.assertEqual((o['u'], o['mu'], o['jobs'], o['n'], o['overrides']),
                         ([1.25], [0.02, 0.063, 0.1, 0.2, 0.3], 2, '1500',
                          ['He=152', 'e=0.8']))
        self.assertIsNone(o['target_error'])
        o = circulation.parse(['friction', '--target-error', '0.05'])
        self.assertEqual((o['target_error'], o['step'], o['longest']), (0.05, 6.0, 60.0))
        for bad in (['--target-error', '5'], ['--target-error', '0.05', '--step', '0']):
            with self.assertRaises(SystemExit), contextlib.redirect_stderr(io.StringIO()):
                circulation.parse(['friction'] + bad)

    def test_spout_height(self):
        o = spoutheight.parse(['--runs', 'u2_hot,u1.4', 'He=152'])
        self.assertEqual((o['runs'], o['time'], o['average'], o['write'], o['kick'],
                          o['overrides']), (['u2_hot', 'u1.4'], 5.0, 3.0, 0.05, '2.0,1.0',
                                            ['He=152']))
        self.assertEqual(spoutheight.parse([])['runs'], [r.name for r in spoutheight.RUNS])

    def test_profiles_and_velocity_maps(self):
        o = profiles.parse([])
        self.assertEqual((o['u'], o['He'][0], o['time'], o['average'], o['kick']),
                         ([1.4, 2.0], 95, 4.0, 1.8, '2.0,1.0'))
        o = velocitymaps.parse(['-j', '2'])
        self.assertEqual((o['points'], o['time'], o['average'], o['kick'], o['np'],
                          o['jobs']), ([(10000, 2.0), (26000, 2.2)], 4.0, 1.8, '2.5,1.0', 1, 2))

    def test_heat_transfer_and_results(self):
        o = heattransfer.options([])
        self.assertEqual((o['u'], o['time'], o['average'], o['write'], o['n'], o['np']),
                         (2.0, 6.0, 1.8, 0.15, None, 1))
        o = drying.options(['dryingModel=freeWater'])
        self.assertEqual((o['u'], o['time'], o['average'], o['write'], o['part'], o['n'], o['np'],
                          o['overrides']), (2.0, 6.0, 1.8, 0.15, 'both', None, 1, ['dryingModel=freeWater']))
        o = dryingtime.options([])
        self.assertEqual((o['u'], o['time'], o['average'], o['write'], o['part'], o['bin']),
                         (2.0, 16.0, 8.0, 1.0, 'statistics', 0.05))
        o = dryingtime.options(['--part', 'study'])
        self.assertEqual((o['temperatures'], o['velocities'], o['ums'], o['hours'],
                          o['samples']), ([60, 80, 100, 150], [1.1, 1.3, 1.6], None, 12, 10000))
        _, a = results.parse(['ums', 'circ', '--heat', 'h', '--noplates', 'a',
                              '--noplates', 'b', '-o', 'out.md', '--mixing', 'm', '--drying', 'd',
                              '--dryingTime', 't', '--coarse', 'c2'])
        self.assertEqual((a.cases, a.heat, a.noplates, a.maps, a.mixing, a.drying, a.dryingTime,
                          a.coarse, a.out),
                         (['ums', 'circ'], 'h', ['a', 'b'], None, ['m'], 'd', ['t'], ['c2'], 'out.md'))
        _, a = results.parse(['--coarse', 'c2', '--coarseCirculation', 'w2', '--coarseHeat',
                              'h2', '--coarseSpeedup', 's'])
        self.assertEqual((a.coarse, a.coarseCirculation, a.coarseHeat, a.coarseSpeedup),
                         (['c2'], ['w2'], ['h2'], ['s']))

    def test_design_study_without_u_ms_and_its_keys(self):
        # no --ums and no ums.json: one line, before any run
        bad = run('protocols/dryingTime', '--part', 'study')
        self.assertEqual(bad.returncode, 1)
        self.assertEqual(len(bad.stderr.splitlines()), 1, bad.stderr)
        self.assertIn('--ums U', bad.stderr)
        self.assertFalse(os.path.isdir(os.path.join(CASE, 'runs')))
        # the keys of two points of a bed of 1500 particles, by hand: one
        # reached the target, one did not (no value, said so)
        point = dict(u_over_ums=1.3, u_s=1.17, particles=1500, ums=0.9, kWh_per_kg=12.34,
                     Tmax_C=79.14, spread=0.0123, statistics_wall_s=360, wall_s=20)
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, 'dryingTime.json'), 'w') as f:
                json.dump({'study': [dict(point, T_in_C=80, reached=1, hours=1.234),
                                     dict(point, T_in_C=60, reached=0, hours=float('nan'))]}, f)
            _, keys, _ = results.drytime_section(d)
        got = {k[0]: k[1:3] for k in keys}
        self.assertEqual(got['drytime.80C_1.3ums_n1500.hours'], ('1.23', 'h'))
        self.assertEqual(got['drytime.80C_1.3ums_n1500.kWh_per_kg'], ('12.3', 'kWh/kg'))
        self.assertEqual(got['drytime.80C_1.3ums_n1500.Tmax_K'], ('352.3', 'K'))
        self.assertEqual(got['drytime.80C_1.3ums_n1500.spread'], ('0.0123', 'kg/kg'))
        self.assertEqual(got['drytime.60C_1.3ums_n1500.hours'], ('', 'h'))
        self.assertIn('not reached', [k for k in keys if k[0] == 'drytime.60C_1.3ums_n1500.hours'][0][4])
        # a call that ran 1.6 u_ms keeps the earlier call's 1.3 (same bed)
        # and replaces its own points; another bed's rows go
        one = lambda k, T, n=1500, hours=1.0: dict(point, u_over_ums=k, T_in_C=T, particles=n,
                                                   hours=hours)
        merged = dryingtime.merged_study(
            [one(1.3, 80), one(1.6, 80, hours=9.0), one(1.3, 60, n=26000)],
            [one(1.6, 80), one(1.6, 60)])
        self.assertEqual([(q['u_over_ums'], q['T_in_C'], q['hours']) for q in merged],
                         [(1.3, 80, 1.0), (1.6, 60, 1.0), (1.6, 80, 1.0)])
        # the reduced bed's study and the full bed's, from two case copies,
        # make one section with the keys and figures of both; the same point
        # from both stops with one line
        with tempfile.TemporaryDirectory() as d:
            for name, n in (('reduced', 1500), ('full', 26000)):
                os.makedirs(os.path.join(d, name))
                with open(os.path.join(d, name, 'dryingTime.json'), 'w') as f:
                    json.dump({'study': [dict(point, T_in_C=80, reached=1, hours=1.0,
                                              particles=n)]}, f)
                open(os.path.join(d, name, 'dryingTime_study.png'), 'w').close()
            figures = os.path.join(d, 'figures')
            dirs = [os.path.join(d, name) for name in ('reduced', 'full')]
            rows, keys, pngs = results.build(None, None, None, figures, drytime=dirs)['drytime'][:3]
            self.assertEqual(sorted(k[0] for k in keys if k[0].endswith('.hours')),
                             ['drytime.80C_1.3ums.hours', 'drytime.80C_1.3ums_n1500.hours'])
            self.assertEqual(sorted(pngs), ['drytime_study.png', 'drytime_study_n1500.png'])
            with self.assertRaises(SystemExit) as twice:
                results.build(None, None, None, figures, drytime=dirs + dirs[:1])
            self.assertRegex(str(twice.exception), r'^results: --dryingTime \S+/reduced: .*'
                             r'drytime.80C_1.3ums_n1500.hours.* also from an earlier --dryingTime')

    def test_coarse_speedup(self):
        o = coarsespeedup.options([])
        self.assertEqual((o['cg'], o['u'], o['spinup'], o['span'], o['overrides']),
                         ([2.0], 2.0, 0.6, 0.9, []))
        o = coarsespeedup.options(['--cg', '2,3', 'mu=0.063'])
        self.assertEqual((o['cg'], o['overrides']), ([2.0, 3.0], ['mu=0.063']))
        for bad in (['--cg', '1'], ['coarseGraining=2'], ['--span', '0']):
            with self.subTest(args=bad), self.assertRaises(SystemExit):
                coarsespeedup.options(bad)

    def test_mixing(self):
        a = mixing.parse(['-j', '2', 'e=0.8'])
        self.assertEqual((a.time, a.write, a.final, a.np, a.jobs, a.overrides),
                         (4.0, 0.1, 1.0, 1, 2, ['e=0.8']))
        self.assertEqual(a.points[:4], [('no-plates', 10000, 2.0), ('no-plates', 26000, 2.5),
                                        ('no-plates', 26000, 3.0), ('plates', 26000, 2.0)])


if __name__ == '__main__':
    unittest.main()
