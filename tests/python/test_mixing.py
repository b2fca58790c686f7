"""The degree of mixing (spoutlab.mixing) against answers known
without the code: a completely segregated bed, a hand-computed three-cell
field, and the expectation of both forms for a randomly labelled bed.

Random labelling (exactly N/2 particles A, every labelling equally likely):
the number of A in a cell of n is hypergeometric, so
E[(x_c - 1/2)^2] = (1/4)(N - n)/(n (N - 1)), and Lacey's index, linear in
sigma_p^2, has the expectation N/(N - 1) for any cell sizes and either
weighting.  The papers' form takes a square root: N sigma_p^2/sigma_0^2 is
Pearson's X^2 of the 2 x K table (labels x cells), chi-square with K - 1
degrees of freedom, mean (K - 1) N/(N - 1), so
E[M_papers] = 1 - sqrt(2/(N - 1)) Gamma(K/2)/Gamma((K - 1)/2): 0.87695 for
K = 6 cells of 50, where 1 - sqrt(E sigma_p^2)/sigma_0 would give 0.87068 and
1 - 1/sqrt(n) 0.85858.  The averages over R labellings scatter by
SD/sqrt(R) (SD 0.040 and 0.011 for the two forms at N = 300); the bounds are
4 of those, below the 0.006 that separates the proper expectation from the
square root of the mean."""
import math
import os
import random
import shutil
import tempfile
import unittest

from spoutlab import mixing
from spoutlab import casefiles as sc

CELL = (0.055, 0.057)


def lattice(columns, rows, spacing=0.011, x_first=None, z_first=0.0055):
    """Particle centres (x, 0.02, z) on a columns x rows lattice symmetric
    about x = 0, ids from 1."""
    x_first = -(columns - 1) * spacing / 2 if x_first is None else x_first
    points = [(x_first + i * spacing, 0.02, z_first + k * spacing)
              for k in range(rows) for i in range(columns)]
    return list(range(1, len(points) + 1)), points


def chi_expectation(n_particles, n_cells):
    """1 - sqrt(2/(N-1)) Gamma(K/2)/Gamma((K-1)/2), written out here with
    math.gamma so the test does not lean on the module's own helper."""
    k = n_cells
    return 1 - math.sqrt(2.0 / (n_particles - 1)) * math.gamma(k / 2) / math.gamma((k - 1) / 2)


class Segregated(unittest.TestCase):
    """A bed labelled by either split, at t = 0: every cell holds one group."""

    def setUp(self):
        # 20 columns x 30 rows, 11 mm apart, across |x| < 0.11 m
        self.ids, self.points = lattice(20, 30)

    def test_halves_are_equal_and_on_either_side_of_the_median(self):
        for split, axis in (('left-right', 0), ('lower-upper', 2)):
            labels, line = mixing.segregated_labels(self.ids, self.points, split)
            a = [p[axis] for i, p in zip(self.ids, self.points) if labels[i] == 1]
            b = [p[axis] for i, p in zip(self.ids, self.points) if labels[i] == 0]
            self.assertEqual(len(a), len(b))
            self.assertLess(max(a), line)
            self.assertGreater(min(b), line)
        self.assertAlmostEqual(mixing.segregated_labels(self.ids, self.points,
                                                        'left-right')[1], 0.0)

    def test_a_segregated_bed_has_zero_mixing_in_both_forms(self):
        for split in mixing.SPLITS:
            labels, line = mixing.segregated_labels(self.ids, self.points, split)
            for weighting in ('particles', 'cells'):
                grid = mixing.SamplingGrid.for_split(CELL[0], CELL[1], split, line)
                m = mixing.mixing_index(self.ids, self.points, labels, grid,
                                        weighting=weighting)
                self.assertGreater(m.cells, 4)
                self.assertAlmostEqual(m.papers, 0.0, delta=1e-12, msg=split + weighting)
                self.assertAlmostEqual(m.lacey, 0.0, delta=1e-12, msg=split + weighting)

    def test_an_odd_number_splits_into_n_over_2_and_the_rest(self):
        ids, points = self.ids[:-1], self.points[:-1]
        labels, _ = mixing.segregated_labels(ids, points, 'lower-upper')
        self.assertEqual(sum(labels.values()), len(ids) // 2)

    def test_ties_are_broken_by_id(self):
        ids, points = [5, 3, 9, 1], [(0.0, 0.0, 0.0)] * 4
        labels, _ = mixing.segregated_labels(ids, points, 'left-right')
        self.assertEqual(labels, {1: 1, 3: 1, 5: 0, 9: 0})


class HandComputed(unittest.TestCase):
    """Three cells (particles, A): (10, 10), (10, 0), (4, 2); xbar = 1/2."""
    counts = {(0, 0): (10, 10), (1, 0): (10, 0), (2, 0): (4, 2)}

    def test_count_weighted(self):
        m = mixing.MixingIndex(self.counts, min_count=1, weighting='particles')
        # sigma^2 = (10/4 + 10/4 + 0)/24, sigma_r^2 = (1/4) 3/24
        self.assertAlmostEqual(m.sigma_sq, 5 / 24)
        self.assertAlmostEqual(m.papers, 1 - math.sqrt((5 / 24) / 0.25))
        self.assertAlmostEqual(m.lacey, (0.25 - 5 / 24) / (0.25 - 0.25 * 3 / 24))

    def test_cell_weighted_as_the_papers_write_it(self):
        m = mixing.MixingIndex(self.counts, min_count=1, weighting='cells')
        # sigma^2 = (1/4 + 1/4 + 0)/3, sigma_r^2 = (1/4)(1/10 + 1/10 + 1/4)/3
        self.assertAlmostEqual(m.papers, 1 - math.sqrt((1 / 6) / 0.25))
        self.assertAlmostEqual(m.lacey, (0.25 - 1 / 6) / (0.25 - 0.25 * 0.45 / 3))

    def test_the_cells_weighting_is_the_default(self):
        m = mixing.MixingIndex(self.counts, min_count=1)
        self.assertAlmostEqual(m.papers, 1 - math.sqrt((1 / 6) / 0.25))

    def test_cells_below_the_minimum_are_left_out(self):
        for weighting in ('particles', 'cells'):
            m = mixing.MixingIndex(self.counts, min_count=5, weighting=weighting)
            self.assertEqual((m.cells, m.particles, m.skipped), (2, 20, 4))
            self.assertAlmostEqual(m.papers, 0.0, msg=weighting)
            self.assertAlmostEqual(m.lacey, 0.0, msg=weighting)


class TwoCellsUnequal(unittest.TestCase):
    """Two cells (particles, A): (30, 20) and (10, 0); 20 of the 40 are A,
    xbar = 1/2 either way, sigma_0^2 = 1/4.

    cells (eq 18 over N = 2 cells): x = 2/3 and 0, sigma_p^2 =
    ((1/6)^2 + (1/2)^2)/2 = (1/36 + 9/36)/2 = 5/36, sigma_p/sigma_0 =
    sqrt(20/36) = sqrt(5)/3, M = 1 - sqrt(5)/3 = 0.254644; sigma_r^2 =
    (1/4)(1/30 + 1/10)/2 = 1/60, Lacey (1/4 - 5/36)/(1/4 - 1/60) =
    (4/36)/(14/60) = 10/21.
    particles: sigma_p^2 = (30 (1/36) + 10 (9/36))/40 = (120/36)/40 = 1/12,
    sigma_p/sigma_0 = sqrt(1/3), M = 1 - 1/sqrt(3) = 0.422650; sigma_r^2 =
    (1/4)(2/40) = 1/80, Lacey (1/4 - 1/12)/(1/4 - 1/80) = (1/6)/(19/80) =
    40/57."""
    counts = {(0, 0): (30, 20), (1, 0): (10, 0)}

    def test_cells(self):
        m = mixing.MixingIndex(self.counts, min_count=1, weighting='cells')
        self.assertAlmostEqual(m.papers, 0.2546440075, places=9)
        self.assertAlmostEqual(m.lacey, 10 / 21)

    def test_particles(self):
        m = mixing.MixingIndex(self.counts, min_count=1, weighting='particles')
        self.assertAlmostEqual(m.papers, 0.4226497308, places=9)
        self.assertAlmostEqual(m.lacey, 40 / 57)

    def test_the_front_end_writes_both_columns(self):
        # the same two cells as particle files: the t = 0 bed puts the 20
        # left-most particles (A) left of x = 0; at t = 1 s 20 A and 10 B
        # sit in the cell x in [-55, 0) mm and 10 B in [0, 55) mm
        case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, case)
        os.mkdir(os.path.join(case, 'particles'))
        ids = list(range(1, 41))
        left = [(-0.050 + 0.001 * k, 0.02, 0.010) for k in range(30)]
        right = [(0.005 + 0.001 * k, 0.02, 0.010) for k in range(10)]
        # t = 0: ids 1-20 left (A), 21-40 right (B)
        t0 = [(-0.050 + 0.002 * k, 0.02, 0.010) for k in range(20)] + \
             [(0.005 + 0.002 * k, 0.02, 0.010) for k in range(20)]
        write_vtp(os.path.join(case, 'particles', 'particles_0.vtp'), ids, t0)
        # t = 1: ids 1-30 left (20 A + 10 B), ids 31-40 right (B)
        write_vtp(os.path.join(case, 'particles', 'particles_1.vtp'), ids, left + right)
        mixing.main([case, '--no-plot', '--no-vtp', '--split', 'left-right', '--min-count', '1'])
        with open(os.path.join(case, 'postProcessing', 'mixing.csv')) as f:
            head, _, t1 = [line.split(',') for line in f.read().splitlines()]
        row = dict(zip(head, t1))
        self.assertAlmostEqual(float(row['M_papers left-right']), 0.254644, places=5)
        self.assertAlmostEqual(float(row['M_lacey left-right']), 10 / 21, places=5)
        self.assertAlmostEqual(float(row['M_particles left-right']), 0.422650, places=5)
        self.assertAlmostEqual(float(row['M_lacey_particles left-right']), 40 / 57, places=5)
        self.assertEqual(int(row['sampling cells']), 2)

    def test_one_label_only_is_undefined(self):
        m = mixing.MixingIndex({(0, 0): (10, 10), (1, 0): (12, 12)})
        self.assertTrue(math.isnan(m.papers) and math.isnan(m.lacey))


class RandomLabelling(unittest.TestCase):
    R = 2000

    def averages(self, sizes, weighting):
        rng = random.Random(20240607)
        n_total = sum(sizes)
        labels = [1] * (n_total // 2) + [0] * (n_total - n_total // 2)
        papers = lacey = 0.0
        for _ in range(self.R):
            rng.shuffle(labels)
            counts, start = {}, 0
            for c, n in enumerate(sizes):
                counts[(c, 0)] = (n, sum(labels[start:start + n]))
                start += n
            m = mixing.MixingIndex(counts, min_count=1, weighting=weighting)
            papers += m.papers
            lacey += m.lacey
        return papers / self.R, lacey / self.R

    def test_equal_cells(self):
        papers, lacey = self.averages([50] * 6, 'particles')
        self.assertAlmostEqual(papers, chi_expectation(300, 6), delta=4 * 0.040 / math.sqrt(self.R))
        self.assertAlmostEqual(lacey, 300 / 299, delta=4 * 0.011 / math.sqrt(self.R))

    def test_unequal_cells_either_weighting_gives_lacey_n_over_n_minus_1(self):
        sizes = [30, 40, 50, 60, 70, 50]
        for weighting in ('particles', 'cells'):
            _, lacey = self.averages(sizes, weighting)
            self.assertAlmostEqual(lacey, 300 / 299, delta=4 * 0.013 / math.sqrt(self.R),
                                   msg=weighting)
        papers, _ = self.averages(sizes, 'particles')
        self.assertAlmostEqual(papers, chi_expectation(300, 6), delta=4 * 0.040 / math.sqrt(self.R))

    def test_the_front_end_floor_is_the_chi_expectation(self):
        self.assertAlmostEqual(mixing.random_papers_expectation(300, 6), chi_expectation(300, 6))


def write_vtp(path, ids, points):
    """A particle file in the layout spoutFoam writes (points, id, radius)."""
    with open(path, 'w') as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1">\n  <PolyData>\n'
                '    <Piece NumberOfPoints="%d" NumberOfVerts="0">\n      <Points>\n'
                '        <DataArray type="Float64" Name="position" NumberOfComponents="3" '
                'format="ascii">\n' % len(ids))
        f.write(''.join(' %.9g %.9g %.9g\n' % p for p in points))
        f.write('        </DataArray>\n      </Points>\n      <PointData>\n'
                '        <DataArray type="Int64" Name="id" format="ascii">\n')
        f.write(''.join(' %d\n' % i for i in ids))
        f.write('        </DataArray>\n        <DataArray type="Float64" Name="radius" '
                'format="ascii">\n' + ' 0.004\n' * len(ids) + '        </DataArray>\n'
                '      </PointData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n')


class FrontEnd(unittest.TestCase):
    """A case with two particle files: the bed at t = 0, and at t = 1 s the
    same places taken by the particles in a random order."""

    def setUp(self):
        self.case = tempfile.mkdtemp()
        os.mkdir(os.path.join(self.case, 'particles'))
        self.ids, self.points = lattice(20, 30)
        write_vtp(os.path.join(self.case, 'particles', 'particles_0.vtp'), self.ids, self.points)
        shuffled = list(self.ids)
        random.Random(7).shuffle(shuffled)
        self.shuffled = shuffled
        write_vtp(os.path.join(self.case, 'particles', 'particles_1.vtp'), shuffled, self.points)

    def tearDown(self):
        shutil.rmtree(self.case)

    def test_csv_labels_and_collection(self):
        mixing.main([self.case, '--no-plot'])
        with open(os.path.join(self.case, 'postProcessing', 'mixing.csv')) as f:
            lines = f.read().splitlines()
        head = lines[0].split(',')
        self.assertEqual(head, ['time [s]', 'M_papers left-right', 'M_lacey left-right',
                                'M_papers lower-upper', 'M_lacey lower-upper',
                                'M_particles left-right', 'M_lacey_particles left-right',
                                'M_particles lower-upper', 'M_lacey_particles lower-upper',
                                'sampling cells', 'particles per cell'])
        t0, t1 = ([float(v) for v in line.split(',')] for line in lines[1:])
        self.assertEqual(t0[1:9], [0.0] * 8)
        # one labelling of 600 particles in ~16 cells: within 4 SD of random
        for papers, lacey in ((1, 2), (5, 6)):
            self.assertAlmostEqual(t1[lacey], 1.0, delta=4 * 0.011)
            self.assertAlmostEqual(t1[papers], 1 - 1 / math.sqrt(t1[10]), delta=4 * 0.040)
        # the labelled copy of t = 1 carries each particle's t = 0 label
        folder = os.path.join(self.case, mixing.LABELLED_DIR)
        copy = os.path.join(folder, 'particles_1.vtp')
        label = sc.read_vtp_array(copy, 'label_left-right')
        ids = [int(v) for v in sc.read_vtp_array(copy, 'id')]
        self.assertEqual(ids, self.shuffled)
        x0 = {i: p[0] for i, p in zip(self.ids, self.points)}
        self.assertEqual([int(v) for v in label], [1 if x0[i] < 0 else 0 for i in ids])
        self.assertEqual(sc.read_vtp_points(copy), sc.read_vtp_points(
            os.path.join(self.case, 'particles', 'particles_1.vtp')))
        with open(os.path.join(folder, 'particles.pvd')) as f:
            pvd = f.read()
        self.assertIn('timestep="0" group="" part="0" file="particles_0.vtp"', pvd)
        self.assertIn('timestep="1" group="" part="0" file="particles_1.vtp"', pvd)

    def test_cell_size_scan(self):
        mixing.main([self.case, '--no-plot', '--no-vtp', '--scan-cells', '--split', 'lower-upper'])
        with open(os.path.join(self.case, 'postProcessing', 'mixingCellSize.csv')) as f:
            rows = f.read().splitlines()[1:]
        self.assertEqual(len(rows), 2 * len(mixing.SCAN_CELLS_MM))
        at_zero = [r.split(',') for r in rows if r.startswith('0,')]
        # the lattice is one particle deep, 11 mm apart: cells of 11 x 19 mm
        # (1-2 particles) and 22 x 38 mm (2 x 3-4) hold fewer than min-count,
        # so they keep no cell; 33 x 38 mm holds 9 or 12; all kept are 0
        used = [r for r in at_zero if int(r[4]) > 0]
        self.assertEqual([(float(r[2]), float(r[3])) for r in used],
                         [s for s in mixing.SCAN_CELLS_MM if s[0] >= 33])
        self.assertEqual([float(r[k]) for r in used for k in (6, 8)], [0.0] * 2 * len(used))

    def test_bad_cell_size_is_one_line(self):
        with self.assertRaises(SystemExit):
            mixing.main([self.case, '--cell', '0', '57'])


class CirculationNeeded(unittest.TestCase):
    """The W_s the papers' 2 s would need, from a made-up M(t): M rises
    by 0.1 a second, so it first reaches 0.9 x 0.8 = 0.72 at 7.2 s; with
    W_s = 0.9 kg/s and M a function of the turnovers, reaching it at 2 s
    needs 0.9 x 7.2/2 = 3.24 kg/s, and the particle weighting reaching
    0.9 x 0.9 = 0.81 at 8.1 s needs 0.9 x 8.1/2 = 3.645 kg/s."""

    def run_numbers(self, **changes):
        r = dict(vessel='no-plates', particles=10000, u_m_s=2.5, time_s=12.0,
                 label='mix_noplates_n10000_u2.5', W_s_kg_s=0.9, turnover_s=3.5,
                 M_papers_left_right=0.85, M_papers_at_turnover=0.35, level_cells=0.72,
                 level_particles=0.81, t_reach_cells_s=7.2, t_reach_particles_s=8.1)
        r.update(changes)
        return r

    def test_first_reach_and_interpolation(self):
        from spoutlab.protocols import mixing as protocol
        t = [0.1 * k for k in range(121)]
        m = [0.01 * k for k in range(121)]
        self.assertAlmostEqual(protocol.first_reach(t, m, 0.72), 7.2)
        self.assertIsNone(protocol.first_reach(t, m, 1.5))
        self.assertAlmostEqual(protocol.interpolate(t, m, 3.55), 0.355)
        self.assertIsNone(protocol.interpolate(t, m, 13.0))

    def test_needed_rate(self):
        from spoutlab.protocols import results
        rows, keys = results.mixing_circulation([self.run_numbers()], 0.9)
        values = {k[0]: float(k[1]) for k in keys}
        self.assertAlmostEqual(values['mixing10k.Ws_needed_kg_s'], 3.24)
        self.assertAlmostEqual(values['mixing10k.Ws_needed_kg_s_particles'], 3.645, places=2)
        for k in keys:
            self.assertTrue(k[4].startswith('weighting '), k)
        self.assertIn('3.24 kg/s, 3.6 times', rows[0][1])

    def test_not_reached_gives_no_key(self):
        from spoutlab.protocols import results
        rows, keys = results.mixing_circulation(
            [self.run_numbers(time_s=4.0, t_reach_cells_s=None, t_reach_particles_s=None)], 0.9)
        self.assertEqual(keys, [])
        self.assertIn('not reached', rows[0][1])



class Candidates(unittest.TestCase):
    """The candidates' section of RESULTS from a made-up
    mixingCandidates.json: the reference at W_s 0.9 kg/s, one candidate at
    1.08 (+20 %), one that did not finish."""

    def setUp(self):
        import json
        self.case = tempfile.mkdtemp()
        record = dict(time_s=4.0, turnover_s=3.5, M_final=0.4, M_final_particles=0.41,
                      M_final_grid11x19=0.35, spouts=True, regime='SPOUTS over 19 write times')
        runs = [dict(record, name='reference', what='nothing', changes=[], W_s_kg_s=0.9,
                     label='mix_noplates_n10000_u2.5'),
                dict(record, name='e0.5', what='restitution 0.5', changes=['e=0.5'],
                     W_s_kg_s=1.08, label='mix_noplates_n10000_u2.5_e0.5'),
                dict(record, name='muWall0', what='frictionless walls', changes=['muWall=0'],
                     W_s_kg_s=0.14, label='mix_noplates_n10000_u2.5_muWall0', spouts=False,
                     regime='does NOT spout over 19 write times')]
        with open(os.path.join(self.case, 'mixingCandidates.json'), 'w') as f:
            json.dump({'settings': 'made up', 'runs': runs,
                       'failed': [dict(name='refine2', what='finer cells')]}, f)

    def tearDown(self):
        shutil.rmtree(self.case)

    def test_keys_and_change_on_the_reference(self):
        from spoutlab.protocols import results
        rows, keys, _ = results.mixing_candidates_section(self.case, '4.3')
        values = {k[0]: float(k[1]) for k in keys}
        self.assertAlmostEqual(values['mixing10k.candidate.e0.5.Ws_rel'], 0.2)
        self.assertAlmostEqual(values['mixing10k.candidate.reference.Ws_rel'], 0.0)
        self.assertAlmostEqual(values['mixing10k.candidate.e0.5.Ws_kg_s'], 1.08)
        self.assertEqual({results.section_of_key(k[0]) for k in keys}, {'mixingcand'})
        self.assertIn('+20.0 %', rows[1][1])
        self.assertNotIn('does not spout', rows[1][1])
        self.assertIn('the bed does not spout (does NOT spout over 19 write times)', rows[2][1])
        self.assertEqual(rows[3][1], 'no finished run')
        self.assertFalse(any(k[0].startswith('mixing10k.candidate.refine2') for k in keys))

    def test_a_candidate_sets_the_drag_law_in_its_copy(self):
        from spoutlab.protocols import circulation
        from spoutlab import draglaws
        path = os.path.join(self.case, 'couplingProperties')
        text = ('FoamFile { version 2.0; format ascii; class dictionary; object '
                'couplingProperties; }\ndragModel         Gidaspow;     // the papers\n'
                'GidaspowProps { switch sharp; }\n')
        open(path, 'w').write(text)
        for _ in range(2):   # a resumed run sets it again
            circulation.set_entries(path, [('dragModel', 'DiFelice')])
        self.assertIsInstance(draglaws.from_coupling_properties(path), draglaws.DiFelice)
        # a key of a sub-dictionary, and not a key of the same name elsewhere
        with open(path, 'a') as f:
            f.write('switch sharp;\n')
        circulation.set_entries(path, [('GidaspowProps/switch', 'smooth')])
        text = open(path).read()
        self.assertIn('GidaspowProps { switch smooth; }', text)
        self.assertIn('\nswitch sharp;\n', text)
        with self.assertRaises(SystemExit) as stop:
            circulation.set_entries(path, [('DiFeliceProps/switch', 'smooth')])
        self.assertIn("expected a top-level sub-dictionary 'DiFeliceProps'",
                      str(stop.exception.code))
        with self.assertRaises(SystemExit) as stop:
            circulation.set_entries(path, [('dragLaw', 'DiFelice')])
        self.assertIn("expected one top-level entry 'dragLaw', found 0", str(stop.exception.code))

    def test_a_point_with_entries_takes_the_bed_settled_for_its_overrides(self):
        """run_point's entries do not change the settled bed: a point that sets
        one starts from the bed another point settled with its overrides
        (the entry's name once took the place of the bed's key)."""
        from unittest import mock
        from spoutlab.protocols import circulation
        here = os.getcwd()
        os.chdir(self.case)
        try:
            os.makedirs('0.orig')
            os.makedirs('constant')
            with open('constant/couplingProperties', 'w') as f:
                f.write('dragModel Gidaspow;\nlostParticles stop;\n')   # the protocols set delete
            os.makedirs('elsewhere')
            with open('elsewhere/settled.restart', 'w') as f:
                f.write('the bed\n')
            o = {'overrides': [], 'n': '1500', 'kick': '2.0,1.0', 'time': 1, 'average': 0.5,
                 'np': 1}
            settled = {circulation.settle_key(o, ['mu=0.1']): 'elsewhere/settled.restart'}
            with mock.patch('subprocess.call', return_value=0):
                work = circulation.run_point(o, 'p', 1.4, ['mu=0.1'], settled,
                                             [('constant/couplingProperties', 'dragModel',
                                               'DiFelice')])
            with open(os.path.join(work, 'DEM', 'settled.restart')) as f:
                self.assertEqual(f.read(), 'the bed\n')
            self.assertEqual(list(settled), [circulation.settle_key(o, ['mu=0.1'])])
        finally:
            os.chdir(here)


if __name__ == '__main__':
    unittest.main()
