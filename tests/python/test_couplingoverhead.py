"""bench/couplingOverhead's bookkeeping, without running anything: the rank
counts it accepts, what it reads from a LIGGGHTS log of a parallel run, the
side-by-side figures of serial and 2-rank runs (ratios and speed-ups worked
out here by hand from made-up times) and when it warns that other programs
spoilt a run. The benchmark's figures themselves are not tested."""
import os
import tempfile
import unittest

from spoutlab.bench import couplingoverhead as co
from spoutlab.bench import weakscaling as weak

REPOSITORY = os.path.abspath(os.environ.get('SPOUTLAB_DIR', '../..'))


def runs(coupled_loop, inside, alone_loop, coupled_wall, alone_wall, others=0.0):
    """One rank count's three runs, as the benchmark keeps them."""
    return {'alone': {'loop': alone_loop, 'wall': alone_wall, 'others': others},
            'chunked': {'loop': alone_loop, 'wall': alone_wall + 0.1, 'others': 0.0},
            'coupled': {'loop_wall': coupled_loop, 'loop': inside,
                        'wall': coupled_wall, 'others': 0.0}}


# made-up times [s]: serial, then 2 ranks
SERIAL = runs(20.0, 8.0, 5.0, 22.0, 6.0)
TWO = runs(12.5, 4.0, 3.2, 14.0, 4.0)


class RankCounts(unittest.TestCase):
    def test_default_is_serial(self):
        self.assertEqual(co.options([]).np, [1])

    def test_a_list_of_rank_counts(self):
        self.assertEqual(co.options(['--np', '1', '2']).np, [1, 2])

    def test_refusals_name_the_option(self):
        for bad in (['0'], ['1', '1'], ['2', '-1']):
            with self.subTest(np=bad):
                with self.assertRaisesRegex(co.BenchError, r'^--np '):
                    co.options(['--np'] + bad)

    def test_launcher(self):
        self.assertEqual(co.launcher(1), [])
        self.assertEqual(co.launcher(2, cores=2), ['mpirun', '-np', '2'])
        self.assertEqual(co.launcher(4, cores=2), ['mpirun', '-np', '4', '--oversubscribe'])


class ParallelLog(unittest.TestCase):
    """Rank 0 prints one 'Loop time' line per run, the loop's wall time."""

    def test_loop_times_and_ranks(self):
        text = ('Step Time Atoms KinEng rke vrms zmax CPU\n'
                '0 0 3000 0.1 0.01 0.02 0.3 0\n'
                'Loop time of 0.25 on 2 procs for 5 steps with 3000 atoms\n'
                'Loop time of 0.5 on 2 procs for 5 steps with 3000 atoms\n')
        with tempfile.NamedTemporaryFile('w', suffix='.log') as f:
            f.write(text)
            f.flush()
            log = co.read_liggghts_log(f.name)
        self.assertEqual((log['loop'], log['steps'], log['runs']), (0.75, 10, 2))
        self.assertEqual((log['procs'], log['atoms']), (2, 3000))
        self.assertEqual(log['rows'][0]['zmax'], 0.3)


class SideBySide(unittest.TestCase):
    def test_ratios_on_each_rank_count(self):
        one, two = co.rank_figures(SERIAL), co.rank_figures(TWO)
        self.assertAlmostEqual(one['per_alone'], 4.0)
        self.assertAlmostEqual(one['per_inside'], 2.5)
        self.assertAlmostEqual(one['per_alone_process'], 22.0 / 6.0)
        self.assertAlmostEqual(two['per_alone'], 3.90625)
        self.assertAlmostEqual(two['per_inside'], 3.125)
        self.assertAlmostEqual(two['per_alone_process'], 3.5)

    def test_speed_ups_are_serial_over_parallel(self):
        up = co.speed_ups({1: co.rank_figures(SERIAL), 2: co.rank_figures(TWO)})
        self.assertAlmostEqual(up[2]['coupled'], 1.6)
        self.assertAlmostEqual(up[2]['inside'], 2.0)
        self.assertAlmostEqual(up[2]['alone'], 1.5625)
        self.assertAlmostEqual(up[1]['coupled'], 1.0)

    def test_no_speed_up_without_a_serial_run(self):
        self.assertIsNone(co.speed_ups({2: co.rank_figures(TWO)}))
        text = co.side_by_side({2: TWO}, cores=2)
        self.assertIn('--np 1', text)

    def test_block_shows_both_rank_counts(self):
        text = co.side_by_side({1: SERIAL, 2: TWO}, cores=2)
        self.assertRegex(text, r'coupled / DEM inside coupled\s+2\.50\s+3\.12')
        self.assertRegex(text, r'coupled time loop\s+1\.00\s+1\.60')


class OtherLoad(unittest.TestCase):
    """Waiting MPI ranks poll: on 2 cores a 2-rank run shares with anything."""

    def test_two_ranks_on_two_cores(self):
        self.assertTrue(co.load_note(2, 0.2, cores=2))
        self.assertFalse(co.load_note(2, 0.1, cores=2))
        self.assertIn('meaningless', ' '.join(co.load_note(2, 0.2, cores=2)))

    def test_more_ranks_than_cores(self):
        self.assertIn('oversubscribed', ' '.join(co.load_note(4, 0.0, cores=2)))

    def test_serial_needs_one_free_core(self):
        self.assertFalse(co.load_note(1, 1.0, cores=2))
        self.assertTrue(co.load_note(1, 1.3, cores=2))

    def test_block_warns_for_the_spoilt_run_only(self):
        busy = runs(12.5, 4.0, 3.2, 14.0, 4.0, others=0.3)
        text = co.side_by_side({1: SERIAL, 2: busy}, cores=2)
        self.assertIn('meaningless', text)
        self.assertNotIn('meaningless', co.side_by_side({1: SERIAL, 2: TWO}, cores=2))


class WeakScaling(unittest.TestCase):
    """bench/weakScaling: the widened column and what it reads from the
    solver's log."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.mesh = os.path.join(self.tmp.name, 'blockMeshDict')
        with open(os.path.join(REPOSITORY, 'openfoam_cases', 'minFluidisation', 'system',
                               'blockMeshDict')) as f:
            self.original = f.read()
        with open(self.mesh, 'w') as f:
            f.write(self.original)

    def tearDown(self):
        self.tmp.cleanup()

    def test_widening_keeps_the_cell_size(self):
        width, depth = co.widen_mesh(self.mesh, 64)
        self.assertAlmostEqual(width, 64 * 0.12, places=12)
        self.assertAlmostEqual(depth, 0.04, places=12)
        text = open(self.mesh).read()
        self.assertRegex(text, r'(?m)^W\s+7\.68;')
        self.assertRegex(text, r'(?m)^nx\s+384;')
        # everything but the two entries as it was
        strip = lambda t: [l for l in t.splitlines() if not l.startswith(('W ', 'nx '))]
        self.assertEqual(strip(text), strip(self.original))

    def test_widening_in_x_and_y(self):
        width, depth = co.widen_mesh(self.mesh, 8, 4)
        self.assertAlmostEqual(width, 0.96, places=12)
        self.assertAlmostEqual(depth, 0.16, places=12)
        text = open(self.mesh).read()
        for entry, value in (('W', '0.96'), ('nx', '48'), ('L', '0.16'), ('ny', '8')):
            self.assertRegex(text, r'(?m)^%s\s+%s;' % (entry, value.replace('.', r'\.')))

    def test_widening_without_writing(self):
        self.assertAlmostEqual(co.widen_mesh(self.mesh, 4, 2, write=False)[0], 0.48, places=12)
        self.assertEqual(open(self.mesh).read(), self.original)

    def test_grids_of_ranks(self):
        self.assertEqual([weak.rank_grid(p, grid=True) for p in (1, 2, 4, 8, 16, 32, 64)],
                         [(1, 1), (2, 1), (2, 2), (4, 2), (4, 4), (8, 4), (8, 8)])
        self.assertEqual(weak.rank_grid(12, grid=True), (4, 3))
        self.assertEqual(weak.rank_grid(7, grid=True), (7, 1))     # a prime: one row
        self.assertEqual(weak.rank_grid(16), (16, 1))              # without --grid: x-slabs

    def test_interior_ranks(self):
        self.assertEqual(weak.interior_ranks((4, 1)), [1, 2])
        self.assertEqual(weak.interior_ranks((4, 4)), [5, 6, 9, 10])   # x fastest
        self.assertEqual(weak.interior_ranks((4, 2)), [])
        self.assertEqual(weak.interior_ranks((2, 1)), [])
        self.assertEqual(len(weak.interior_ranks((8, 8))), 36)

    def test_widening_needs_the_entries(self):
        with open(self.mesh, 'w') as f:
            f.write(self.original.replace('nx  6;', 'cellsX 6;'))
        with self.assertRaisesRegex(co.BenchError, 'entry nx'):
            co.widen_mesh(self.mesh, 2)

    def test_halo_figures_from_the_log(self):
        log = os.path.join(self.tmp.name, 'log.spoutFoam')
        with open(log, 'w') as f:
            f.write('Parallel coupling: 4 x-slabs cut at 0.12 0.24 0.36 m; halo cells per rank '
                    '(reach 0.006 m): 80 160 160 80\n'
                    'Time = 0.0015\n'
                    'Halo exchange per step, by rank (messages, kB): (7.2, 13.5) (14.4, 27) '
                    '(14.6, 27.5) (7, 1.5e+01)\n')
        cells, traffic = weak.exchange(log)
        self.assertEqual(cells, [80, 160, 160, 80])
        self.assertEqual(traffic, [(7.2, 13.5), (14.4, 27.0), (14.6, 27.5), (7.0, 15.0)])
        row = weak.summary((4, 1), cells, traffic)
        self.assertEqual(row['halo_cells_max'], 160)
        self.assertAlmostEqual(row['messages_interior'], 14.5)   # ranks 1 and 2
        self.assertAlmostEqual(row['kB_interior'], 27.25)
        self.assertAlmostEqual(row['kB_max'], 27.5)
        self.assertAlmostEqual(row['messages_max'], 14.6)

    def test_serial_run_has_no_halo(self):
        log = os.path.join(self.tmp.name, 'log.spoutFoam')
        with open(log, 'w') as f:
            f.write('Time = 0.0015\nEnd\n')
        row = weak.summary((1, 1), *weak.exchange(log))
        self.assertEqual((row['halo_cells_max'], row['messages_max'], row['kB_max']),
                         (0, 0.0, 0.0))
        self.assertIsNone(row['messages_interior'])

    def test_interior_of_a_grid(self):
        # 3 x 3 boxes: rank 4 alone has all eight neighbours
        traffic = [(19.8, 55.7), (33.0, 74.2), (19.8, 55.7), (33.0, 99.0), (52.8, 123.8),
                   (33.0, 99.0), (19.8, 55.7), (33.0, 74.2), (19.8, 55.7)]
        row = weak.summary((3, 3), [360, 480, 360, 640, 800, 640, 360, 480, 360], traffic)
        self.assertEqual(row['halo_cells_max'], 800)
        self.assertEqual((row['messages_interior'], row['kB_interior']), (52.8, 123.8))
        self.assertIsNone(weak.summary((2, 2), [360] * 4, traffic[:4])['kB_interior'])


if __name__ == '__main__':
    unittest.main()
