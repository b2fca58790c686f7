"""The three-dimensional spouted bed's geometry (spoutlab.spoutedbed3d, the
case's system/spoutedBedDict), Mathur and Gishler's u_ms, the rule of
minimumSpouting3D that reads u_ms off the decreasing branch, and the case's
command lines (--help; a bad option one line, status 2, in a copy)."""
import math
import os
import shutil
import subprocess
import tempfile
import unittest

from spoutlab import spoutedbed3d
from spoutlab.protocols import minimumspouting3d

CASE = os.path.join(os.path.dirname(__file__), '..', '..', 'openfoam_cases', 'spoutedBed3D')


class MathurGishler(unittest.TestCase):
    def test_by_hand(self):
        # d/D_c = 0.05, (D_i/D_c)^(1/3) = 0.5, sqrt(2 g H (rho_p - rho)/rho)
        # = sqrt(2 9.81 0.2 1000) = 62.642
        u = spoutedbed3d.mathur_gishler_ums(0.005, 0.1, 0.0125, 0.2, 1001.0, 1.0)
        self.assertAlmostEqual(u, 0.05 * 0.5 * math.sqrt(3924.0), places=12)

    def test_grows_as_the_root_of_the_depth(self):
        a = spoutedbed3d.mathur_gishler_ums(0.008, 0.15, 0.04, 0.1, 1231.0)
        b = spoutedbed3d.mathur_gishler_ums(0.008, 0.15, 0.04, 0.4, 1231.0)
        self.assertAlmostEqual(b / a, 2.0, places=12)


class CaseGeometry(unittest.TestCase):
    g = spoutedbed3d.load(CASE)

    def test_walls_polygon_has_the_circles_area(self):
        n, rv = self.g.sides, self.g.vertex_radius
        self.assertAlmostEqual(n / 2 * rv ** 2 * math.sin(2 * math.pi / n),
                               math.pi * self.g.R ** 2, places=9)

    def test_inlet_is_the_central_square_at_the_bottom(self):
        # squareRatio 0.5 of Db 75 mm: a 37.5 mm square
        self.assertAlmostEqual(self.g.inlet_area, 0.0375 ** 2, places=15)
        self.assertAlmostEqual(self.g.inlet_diameter, math.sqrt(4 * 0.0375 ** 2 / math.pi),
                               places=15)

    def test_cone_height_and_volume(self):
        # 60 deg included: (75 - 37.5)/tan 30 deg = 64.952 mm; a frustum
        # pi h/3 (r0^2 + r0 r1 + r1^2) and the cylinder above
        h = 37.5 / math.tan(math.radians(30))
        self.assertAlmostEqual(self.g.zCone, h, places=9)
        frustum = math.pi * h / 3 * (37.5 ** 2 + 37.5 * 75 + 75 ** 2) * 1e-9
        self.assertAlmostEqual(self.g.vessel_volume(h / 1000), frustum, places=15)
        self.assertAlmostEqual(self.g.vessel_volume(0.3),
                               frustum + math.pi * 0.075 ** 2 * (0.3 - h / 1000), places=15)


def row(u, branch, spouts):
    return {'u_s': u, 'branch': branch, 'dP_Pa': 1000 * u, 'spouts': spouts}


class MinimumSpoutingRule(unittest.TestCase):
    def test_last_spouting_step_of_the_decreasing_branch(self):
        table = [row(1.6, 'up', False), row(2.8, 'up', True), row(2.4, 'down', True),
                 row(2.0, 'down', True), row(1.8, 'down', False), row(1.6, 'down', True)]
        self.assertEqual(minimumspouting3d.minimum_spouting(table)['u_s'], 2.0)

    def test_none_when_the_peak_does_not_spout(self):
        table = [row(1.6, 'up', False), row(2.8, 'up', False), row(2.4, 'down', True)]
        self.assertIsNone(minimumspouting3d.minimum_spouting(table))

    def test_the_schedule_must_fall_after_its_peak(self):
        with self.assertRaises(SystemExit):
            minimumspouting3d.options(['--schedule', '1.6,2.0,2.4'])


class Commands(unittest.TestCase):
    def test_help_and_a_bad_option(self):
        top = os.path.abspath(os.environ.get('SPOUTLAB_DIR', os.path.join(CASE, '..', '..')))
        with tempfile.TemporaryDirectory() as tmp:
            case = os.path.join(tmp, 'spoutedBed3D')
            shutil.copytree(CASE, case, symlinks=True)
            env = dict(os.environ, SPOUTLAB_DIR=top)
            for command in ('generate', 'inletVelocity', 'evaluate',
                            os.path.join('protocols', 'minimumSpouting3D')):
                name = os.path.basename(command)
                with self.subTest(command=name):
                    shown = subprocess.run([os.path.join(case, command), '--help'], cwd=case,
                                           capture_output=True, text=True, env=env, timeout=60)
                    self.assertEqual(shown.returncode, 0, shown.stderr)
                    self.assertTrue(shown.stdout.startswith('usage: %s ' % name), shown.stdout)
                    needs = ['2'] if name == 'inletVelocity' else []
                    bad = subprocess.run([os.path.join(case, command)] + needs + ['--bogus'],
                                         cwd=case, capture_output=True, text=True, env=env,
                                         timeout=60)
                    self.assertEqual(bad.returncode, 2, bad.stderr)
                    self.assertEqual(bad.stderr.splitlines(),
                                     ['%s: unrecognized arguments: --bogus (%s --help lists '
                                      'the options)' % (name, name)])


if __name__ == '__main__':
    unittest.main()
