"""protocols/spoutHeight's reading of a run (spoutlab.protocols.spoutheight):
a made-up case whose fields are known by construction -- a particle
velocity falling linearly with height, a known slip, h lower beside the
plates, slugs through the axis probe -- read back to the numbers written
into it; cells outside the spout and write times before the window hold
wild values that would show if they were read."""
import math
import os
import shutil
import tempfile
import types
import unittest

from spoutlab.protocols import spoutheight as sh

RHO, MU, DP = 1.2, 1.8e-5, 8.0      # gas density, viscosity, particle diameter [mm]


def geometry(dx=11.0, heat=True):
    return types.SimpleNamespace(Wd=55.0, He=95.0, Hd=912.0, dx=dx, heat=heat,
                                 gas={'rho': RHO, 'mu': MU}, particles={'dp': DP})


def write_field(path, values):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    vector = isinstance(values[0], tuple)
    body = '\n'.join('(%r %r %r)' % v if vector else repr(v) for v in values)
    with open(path, 'w') as f:
        f.write('FoamFile { version 2.0; format ascii; class vol%sField; }\n'
                'internalField nonuniform List<%s> %d\n(\n%s\n)\n;\n'
                % ('Vector' if vector else 'Scalar', 'vector' if vector else 'scalar',
                   len(values), body))


def vp(z):
    """The made-up mean particle velocity [m/s] at height z [m]."""
    return 2.0 - 1.0 * z


class MadeUpRun(unittest.TestCase):
    # columns x [mm] (the spout is |x| < 27.5), rows z [mm] (He 95, Hd 912)
    XS = [-33.0, -22.0, -11.0, 0.0, 11.0, 22.0, 33.0]
    ZS = [100.0, 300.0, 500.0, 700.0, 950.0]

    def inside(self, x, z):
        return abs(x) < 27.5 and 95 < z < 912

    def setUp(self):
        self.case = tempfile.mkdtemp()
        self.cells = [(x / 1000, 0.02, z / 1000) for z in self.ZS for x in self.XS]
        write_field(os.path.join(self.case, '0', 'C'), self.cells)
        wild = 1e6
        # spoutFoam's means at the last write time: solid fraction 0.4, so
        # the solid flux is 0.4 vp(z); outside the spout wild
        last = os.path.join(self.case, '2')
        # (the columns beside the plates: 0.2 at 1 m/s on the left and 0.6 at
        # 3 m/s on the right, 2.5 m/s pooled by solid fraction)
        phi = {-0.022: 0.2, 0.022: 0.6}
        write_field(os.path.join(last, 'solidFractionMean'),
                    [phi.get(x, 0.4) for x, _, z in self.cells])
        write_field(os.path.join(last, 'solidFluxMean'), [
            (0.0, 0.0, wild if not self.inside(1000 * x, 1000 * z) else
             {-0.022: 0.2, 0.022: 1.8}.get(x, 0.4 * vp(z))) for x, _, z in self.cells])
        write_field(os.path.join(last, 'UMean'), [(0.0, 0.0, 10.0)] * len(self.cells))
        write_field(os.path.join(last, 'voidfractionMean'), [0.6] * len(self.cells))
        # write times: 0.5 before the window (wild), 1, 1.5 and 2 in it; gas
        # 10 m/s up, particles 4 m/s up at voidage 0.75; h 100 on the axis,
        # 80 off it (60 in the row z = 100 mm); at t = 1 the axis cell at
        # z = 300 mm is empty
        for t in ('0.5', '1', '1.5', '2'):
            early = t == '0.5'
            write_field(os.path.join(self.case, t, 'U'), [(0.0, 0.0, 10.0)] * len(self.cells))
            write_field(os.path.join(self.case, t, 'Us'),
                        [(0.0, 0.0, -wild if early else 4.0)] * len(self.cells))
            write_field(os.path.join(self.case, t, 'voidfraction'), [0.75] * len(self.cells))
            write_field(os.path.join(self.case, t, 'solidFraction'), [
                0.0 if (t == '1' and x == 0 and abs(z - 0.3) < 1e-9) else 0.25
                for x, _, z in self.cells])
            write_field(os.path.join(self.case, t, 'hp'), [
                wild if early else 100.0 if x == 0 else 60.0 if abs(z - 0.1) < 1e-9 else 80.0
                for x, _, z in self.cells])
        probe = os.path.join(self.case, 'postProcessing', 'spoutFlux', '0')
        os.makedirs(probe)
        series = [0.9, 0.8, 0.55, 0.65, 0.58, 0.75, 0.8, 0.5, 0.72, 0.9]
        with open(os.path.join(probe, 'voidfraction'), 'w') as f:
            f.write('# Probe 0 (0 0.02 0.5035)\n#  Probe 0\n#  Time\n')
            f.write('0.5 0.1\n')   # before the window: a slug that must not count
            for k, e in enumerate(series):
                f.write('%g %g\n' % (1.0 + 0.1 * k, e))

    def tearDown(self):
        shutil.rmtree(self.case)

    def test_the_spout_cells_are_between_the_plates_and_below_their_top(self):
        rows = sh.spout_cells(geometry(), self.cells)
        self.assertEqual(sorted(rows), [100.0, 300.0, 500.0, 700.0])
        self.assertEqual([x for x, _ in rows[300.0]], [-22.0, -11.0, 0.0, 11.0, 22.0])

    def test_axis_and_plate_columns_on_odd_and_even_column_counts(self):
        g = geometry()
        self.assertEqual([x for x in self.XS if sh.on_axis(g, x)], [0.0])
        self.assertEqual([x for x in self.XS if abs(x) < 27.5 and sh.by_plate(g, x)],
                         [-22.0, 22.0])
        fine = geometry(dx=5.5)      # ten columns across: two on the axis
        xs = [-24.75 + 5.5 * k for k in range(10)]
        self.assertEqual([x for x in xs if sh.on_axis(fine, x)], [-2.75, 2.75])
        self.assertEqual([x for x in xs if sh.by_plate(fine, x)], [-24.75, 24.75])

    def test_the_profiles_are_read_back(self):
        g = geometry()
        names = sh.window_times(self.case, 1.0)
        self.assertEqual(names, ['1', '1.5', '2'])
        cells = sh.cell_sums(self.case, g, names)
        axis = sh.axis_rows(g, cells)
        self.assertEqual([z for z, _ in axis], [0.1, 0.3, 0.5, 0.7])
        for z, s in axis:
            self.assertAlmostEqual(s.mean('Vp'), vp(z), places=12)
            self.assertAlmostEqual(s.mean('Ug'), 10.0, places=12)
            self.assertAlmostEqual(s.mean('eps'), 0.6, places=12)
            self.assertAlmostEqual(s.mean('Re'), 0.75 * RHO * 6.0 * DP * 1e-3 / MU, places=6)
            self.assertAlmostEqual(s.mean('h'), 100.0, places=9)
            self.assertAlmostEqual(s.mean('Vs'), 4.0, places=12)
        self.assertAlmostEqual(sh.axis_slope(axis, 'Vp', 0.0, 1.0), -1.0, places=10)
        self.assertAlmostEqual(sh.axis_slope(axis, 'h', 0.0, 1.0), 0.0, places=9)
        across = sh.paper_rows(g, cells)
        self.assertEqual(len(across), 8)
        # Fig 4's heights fall on the rows 100, 300 (3 times), 500 (twice) and 700
        # mm (twice); Fig 12's band on 500, 500 and 700, clear of the 60 at 100
        self.assertAlmostEqual(sh.plate_over_axis(g, across, 'h'), 0.775, places=12)
        self.assertAlmostEqual(sh.plate_over_axis(g, across, 'h', (16.927, 22.454)), 0.8,
                               places=12)
        self.assertAlmostEqual(sh.plate_over_axis(g, across, 'Re'), 1.0, places=12)
        for _, cols in across:
            beside = sh.pooled(cols, [x for x in cols if sh.by_plate(g, x)])
            self.assertAlmostEqual(beside.mean('Vp'), 2.5, places=12)

    def test_without_heat_there_is_no_h(self):
        g = geometry(heat=False)
        cells = sh.cell_sums(self.case, g, sh.window_times(self.case, 1.0))
        self.assertTrue(math.isnan(sh.axis_rows(g, cells)[0][1].mean('h')))

    def test_pooled_columns_weight_the_particle_velocity_by_solid_fraction(self):
        a, b = sh.Sums(), sh.Sums()
        a.add('Vp', 1.0, 0.1)
        b.add('Vp', 3.0, 0.3)
        self.assertAlmostEqual(sh.pooled({1: a, 2: b}, [1, 2]).mean('Vp'), 2.5)

    def test_slugs_are_counted_with_the_band(self):
        count, rate, share, mean = sh.slugs(self.case, 0.9)
        self.assertEqual(count, 2)          # 0.55 .. 0.75 and 0.5 .. 0.72
        self.assertAlmostEqual(rate, 2 / 0.9)
        self.assertAlmostEqual(share, 0.4 / 0.9)   # 1.2-1.5 and 1.7-1.8
        self.assertAlmostEqual(mean, sum([0.9, 0.8, 0.55, 0.65, 0.58, 0.75, 0.8, 0.5, 0.72,
                                          0.9]) / 10)


class ResultsSection(unittest.TestCase):
    """protocols/results --spoutHeight: keys spout.<quantity>_<run's key>,
    h only from runs with heat."""

    def test_keys_from_a_made_up_protocol_output(self):
        import json
        from spoutlab.protocols import results
        case = tempfile.mkdtemp()
        try:
            run = {'run': 'u1.4', 'key': '1.4', 'what': 'w', 'u_m_s': 1.4, 'samples': 60,
                   'heat': False, 'dVp_dz': -0.25, 'dVp_dz_halves': [-0.2, -0.3],
                   'dVp_dz_width': -0.22, 'dUg_dz': 0.1, 'deps_dz': 0.01,
                   'dRe_dz': -5.0, 'dh_dz': None, 'Vp_change': -0.2,
                   'h_plate_over_axis': None, 'Re_plate_over_axis': 1.1, 'slugs': 3,
                   'slugs_per_s': 1.0, 'slug_share': 0.1, 'eps_probe': 0.8, 'lost': 0,
                   'wall_s': 600}
            hot = dict(run, run='u2_hot', key='2.0', heat=True, dh_dz=-12.5,
                       h_plate_over_axis=0.85, h_plate_over_axis_all=0.9, lost=4)
            with open(os.path.join(case, 'spoutHeight.json'), 'w') as f:
                json.dump({'time': 5, 'average': 3, 'runs': [run, hot]}, f)
            rows, keys, _ = results.spout_height_section(case)
            values = {k[0]: float(k[1]) for k in keys}
            self.assertEqual(values, {'spout.dVp_dz_1.4': -0.25, 'spout.slugs_per_s_1.4': 1.0,
                                      'spout.dVp_dz_2.0': -0.25, 'spout.slugs_per_s_2.0': 1.0,
                                      'spout.dh_dz_2.0': -12.5,
                                      'spout.h_plate_over_axis_2.0': 0.85})
            self.assertEqual({results.section_of_key(k) for k in values}, {'spoutheight'})
            self.assertIn('4 particles lost', rows[1][1])
            self.assertEqual(len(rows), 3)
        finally:
            shutil.rmtree(case)


if __name__ == '__main__':
    unittest.main()
