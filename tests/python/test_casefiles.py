"""What the case layer does with a picture it cannot draw (spoutlab.casefiles
plot, Plot, plots_text): the summary names it and says why, instead of
leaving it out of the list; the spouted bed's heat-transfer picture
without a particle in its band is one of them.  And how it joins the rows
of a run killed and restarted: the restart's rows replace the killed run's
from the same instant, though the two write it a few units in the last
place apart."""
import contextlib
import io
import os
import shutil
import tempfile
import unittest

from spoutlab import casefiles as sc
from spoutlab import spoutheat


class InDirectory(unittest.TestCase):
    def setUp(self):
        self.here = os.getcwd()
        self.dir = tempfile.mkdtemp()
        os.chdir(self.dir)

    def tearDown(self):
        os.chdir(self.here)
        shutil.rmtree(self.dir)

    def quietly(self, f, *args):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            result = f(*args)
        return result, out.getvalue()


class Pictures(InDirectory):
    def test_the_summary_lists_each_picture_drawn_or_why_not(self):
        drawn, missing = sc.Plot('a.png'), sc.Plot('b.png', 'gnuplot: x range is invalid')
        self.assertTrue(drawn)
        self.assertFalse(missing)
        self.assertEqual(sc.plots_text([drawn, missing, sc.Plot('c.png')]),
                         'a.png c.png; b.png not drawn (gnuplot: x range is invalid)')
        self.assertEqual(sc.plots_text([missing]), 'b.png not drawn (gnuplot: x range is invalid)')
        self.assertEqual(sc.plots_text([]), 'none')

    @unittest.skipUnless(shutil.which('gnuplot'), 'gnuplot not installed')
    def test_gnuplot_failing_gives_its_reason_and_no_file(self):
        with open('empty.csv', 'w') as f:
            f.write('x,y\n')
        result, said = self.quietly(sc.plot, 'empty.png',
                                    'set datafile separator ","\nplot "empty.csv" skip 1 using 1:2\n')
        self.assertFalse(result)
        self.assertTrue(result.why.startswith('gnuplot: '), result.why)
        self.assertEqual(said, 'plot empty.png not drawn: %s\n' % result.why)
        self.assertFalse(os.path.exists('empty.png'))
        with open('line.csv', 'w') as f:
            f.write('x,y\n0,0\n1,1\n')
        result, said = self.quietly(sc.plot, 'line.png',
                                    'set datafile separator ","\nplot "line.csv" skip 1 using 1:2\n')
        self.assertTrue(result)
        self.assertEqual(str(result), 'line.png')
        self.assertTrue(os.path.getsize('line.png') > 0)

    def test_no_particle_in_the_heat_transfer_band(self):
        result, said = self.quietly(spoutheat.plot_profiles, [], 'heatTransfer.png')
        self.assertFalse(result)
        self.assertEqual(str(result), 'heatTransfer.png not drawn (no particle in z/R_d '
                         '16.927-22.454 over the averaging window)')
        self.assertEqual(len(said.splitlines()), 1)
        self.assertFalse(os.path.exists('heatTransfer.png'))
        with open('heatProfiles.csv') as f:
            self.assertEqual(f.read(), 'x/R_d,h [W/m2/K],Re,samples\n')


class RestartedRows(InDirectory):
    # a probe row the killed run wrote at 7.5 ms, and the restart's same row:
    # the restart adds its steps to the written 0.006, the killed run to 0
    killed = ['0.0059999999999999993 18163.0', '0.0074999999999999989 15115.1']
    restarted = ['0.0074999999999999997 15115.1', '0.0089999999999999993 12956.5']

    def write(self, path, lines):
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'w') as f:
            f.write('# Probe 0 (0 0.02 0.011)\n# Time\n' + '\n'.join(lines) + '\n')

    def test_a_probe_row_is_not_counted_twice(self):
        self.write('postProcessing/probe/0/p', self.killed)
        self.write('postProcessing/probe/0.006/p', self.restarted)
        _, rows = sc.read_function_object('.', 'probe', 'p')
        self.assertEqual([r[1] for r in rows], [18163.0, 15115.1, 12956.5])

    def test_a_coupling_row_is_not_counted_twice(self):
        os.makedirs('postProcessing')
        with open('postProcessing/coupling.csv', 'w') as f:
            f.write('time [s],x\n' + '\n'.join(r.replace(' ', ',')
                                                for r in self.killed + self.restarted) + '\n')
        self.assertEqual([r['x'] for r in sc.read_coupling_log('.')], [18163.0, 15115.1, 12956.5])

    def test_rows_a_short_step_apart_are_both_kept(self):
        # 1e-7 s, far below any time step the cases take, is not rounding
        self.write('postProcessing/probe/0/p', ['0.0074999 1.0'])
        self.write('postProcessing/probe/0.0075/p', ['0.0075 2.0'])
        self.assertEqual(len(sc.read_function_object('.', 'probe', 'p')[1]), 2)


if __name__ == '__main__':
    unittest.main()
