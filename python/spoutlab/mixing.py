#!/usr/bin/env python3
"""The degree of particle mixing of a spouted-bed run (no-draft-plate paper
eq 7, draft-plate paper eqs 17-19), from the particle output.

Particles are labelled A or B by their place in the first particle file
(t = 0), so that the two groups are completely segregated and equal in
number:

  left-right   A = the half with the smaller x (split at the median x)
  lower-upper  A = the half with the smaller z (split at the median z)

The default is left-right.  The vessel and its circulation are symmetric
about the axis, so the two halves mix only where particles cross the axis,
in the spout and the fountain.  A lower-upper split is also changed by the
circulation's overturning alone (the annulus moves down as a packed bed and
the spout lifts its bottom to the top), which moves the index up and down
with the circulation period without any mixing; it is reported beside.

Sampling cells are rectangles dx x dz in the x-z plane (one cell through
the depth, as the gas grid), default 55 x 57 mm (5 x 3 gas cells; a packed
cell holds about 270 particles).  One family of faces passes through the
split line (x = median x for left-right, z = median z for lower-upper; the
other family through x = 0 and z = 0), so at t = 0 every cell holds one
group only and both indices are exactly 0, as the papers state.

With x_c the fraction of A in cell c, n_c its particles, K the cells used
and N the particles in them:

  papers  M = 1 - sigma_p/sigma_0,  sigma_0^2 = xbar (1 - xbar)
  Lacey   M = (sigma_0^2 - sigma_p^2)/(sigma_0^2 - sigma_r^2)

Two weightings of sigma_p^2, both written:

  cells      (the headline, M_papers and M_lacey) the papers' eq 18 as
             written: sigma_p^2 = sum (x_c - xbar)^2 / K, every cell weighs
             one, with xbar the papers' "theoretical average", the fraction
             of A among all labelled particles (1/2 for the halves here),
             and sigma_r^2 = xbar (1 - xbar) mean(1/n_c).  A cell of 12
             particles weighs as much as one of 270, so sparse cells (the
             fountain, slivers at the base and walls) inflate sigma_p.  With
             xbar = 1/2 a segregated bed gives exactly 0 and no bed less.
  particles  (M_particles, M_lacey_particles) sigma_p^2 = sum n_c (x_c -
             xbar)^2 / N with xbar = (A in the cells used)/N, sigma_r^2 =
             xbar (1 - xbar) K/N: the variance seen by a particle picked at
             random; a segregated bed gives exactly 0 for any cells, and a
             sparse cell counts only by what it holds.

Either way, cells with fewer than `min_count` particles (default 10) are
left out.

For a randomly labelled bed (N particles, K cells) Lacey's M has the
expectation N/(N - 1) (about 1), and the papers' M the finite-sample floor
1 - sqrt(2/(N - 1)) Gamma(K/2)/Gamma((K - 1)/2), about 1 - 1/sqrt(n) with n
the particles per cell: 0.94 for the default cell.  The papers' 0.9-1 for a
well-mixed bed therefore needs cells of more than about 100 particles;
with the gas cells (11 x 19 mm, about 18 particles) the papers' form could
not pass 0.77.  The cells weighting has about the same floor,
1 - sqrt(mean(1/n_c)), lower where cells are sparse.

usage: python3 -m spoutlab.mixing CASE [--split {left-right,lower-upper,both}]
           [--cell DX DZ] [--min-count N] [--scan-cells] [--no-vtp] [--no-plot]
writes CASE/postProcessing/mixing.csv and mixing.png; with --scan-cells
mixingCellSize.csv; and postProcessing/mixingParticles/ (see write_labelled).
"""
import math
import os
import sys

from spoutlab import casefiles as sc
from spoutlab import cli

SPLITS = ('left-right', 'lower-upper')
DEFAULT_SPLIT = 'left-right'
DEFAULT_CELL_MM = (55.0, 57.0)
DEFAULT_MIN_COUNT = 10
# the cell sizes of --scan-cells [mm]: 1 x 1 (the papers' grid), 2 x 2, 3 x 2,
# 5 x 3 (the default), 7 x 4 and 9 x 6 gas cells of 11 x 19 mm
PAPERS_CELL_MM = (11.0, 19.0)
SCAN_CELLS_MM = (PAPERS_CELL_MM, (22.0, 38.0), (33.0, 38.0), DEFAULT_CELL_MM, (77.0, 76.0),
                 (99.0, 114.0))
WEIGHTINGS = ('cells', 'particles')


def segregated_labels(ids, points, split):
    """{id: 1 for A, 0 for B}: A is the half of the particles with the
    smaller coordinate (x for left-right, z for lower-upper), ties broken by
    id, so A has N//2 particles and B the rest.  Returns (labels, the split
    coordinate: midway between the last A and the first B)."""
    axis = {'left-right': 0, 'lower-upper': 2}[split]
    order = sorted(range(len(ids)), key=lambda i: (points[i][axis], ids[i]))
    half = len(order) // 2
    labels = {ids[i]: (1 if k < half else 0) for k, i in enumerate(order)}
    if 0 < half < len(order):
        line = 0.5 * (points[order[half - 1]][axis] + points[order[half]][axis])
    else:
        line = 0.0
    return labels, line


class SamplingGrid:
    """Rectangular sampling cells dx x dz [m] in the x-z plane with faces at
    x = x0 + i dx and z = z0 + k dz."""

    def __init__(self, dx, dz, x0=0.0, z0=0.0):
        if not (dx > 0 and dz > 0):
            raise ValueError('sampling cells must have positive sizes, got %g x %g m'
                             % (dx, dz))
        self.dx, self.dz, self.x0, self.z0 = dx, dz, x0, z0

    def cell(self, x, z):
        return (math.floor((x - self.x0) / self.dx), math.floor((z - self.z0) / self.dz))

    @classmethod
    def for_split(cls, dx, dz, split, line):
        """The grid whose faces pass through the split line."""
        if split == 'left-right':
            return cls(dx, dz, x0=line)
        return cls(dx, dz, z0=line)


class MixingIndex:
    """Both forms of the index for one labelled particle field.

    counts: {cell: (particles, particles A)}; weighting cells (the papers'
    eq 18, the default) or particles.  Attributes: cells (K kept),
    particles (N in them), xbar, sigma0_sq, sigma_sq, sigmar_sq, papers,
    lacey (nan when undefined: no cell kept, or one label only)."""

    def __init__(self, counts, min_count=DEFAULT_MIN_COUNT, weighting='cells'):
        if weighting not in ('particles', 'cells'):
            raise ValueError('weighting must be particles or cells, got %r' % weighting)
        kept = [(n, a) for n, a in counts.values() if n >= min_count]
        self.cells = len(kept)
        self.particles = sum(n for n, _ in kept)
        self.skipped = sum(n for n, _ in counts.values()) - self.particles
        self.papers = self.lacey = float('nan')
        self.xbar = self.sigma0_sq = self.sigma_sq = self.sigmar_sq = float('nan')
        if not kept:
            return
        if weighting == 'particles':
            xbar = sum(a for _, a in kept) / self.particles
        else:
            xbar = (sum(a for _, a in counts.values())
                    / sum(n for n, _ in counts.values()))
        sigma0_sq = xbar * (1 - xbar)
        if weighting == 'particles':
            sigma_sq = sum(n * (a / n - xbar) ** 2 for n, a in kept) / self.particles
            sigmar_sq = sigma0_sq * self.cells / self.particles
        else:
            sigma_sq = sum((a / n - xbar) ** 2 for n, a in kept) / self.cells
            sigmar_sq = sigma0_sq * sum(1.0 / n for n, _ in kept) / self.cells
        self.xbar, self.sigma0_sq, self.sigma_sq, self.sigmar_sq = (
            xbar, sigma0_sq, sigma_sq, sigmar_sq)
        if sigma0_sq > 0:
            self.papers = 1 - math.sqrt(sigma_sq / sigma0_sq)
            if sigma0_sq > sigmar_sq:
                self.lacey = (sigma0_sq - sigma_sq) / (sigma0_sq - sigmar_sq)

    @property
    def random_level(self):
        """1 - sigma_r/sigma_0: about the papers' M of a randomly labelled
        bed with these cells (a little below its expectation, which takes
        the mean of the square root)."""
        if not self.sigma0_sq > 0:
            return float('nan')
        return 1 - math.sqrt(self.sigmar_sq / self.sigma0_sq)

    @property
    def mean_count(self):
        return self.particles / self.cells if self.cells else float('nan')


def cell_counts(grid, ids, points, labels):
    """{cell: (particles, A)} of the particles that carry a label (a particle
    not in the first file, e.g. inserted later, is ignored)."""
    counts = {}
    for pid, (x, _, z) in zip(ids, points):
        label = labels.get(pid)
        if label is None:
            continue
        c = grid.cell(x, z)
        n, a = counts.get(c, (0, 0))
        counts[c] = (n + 1, a + label)
    return counts


def mixing_index(ids, points, labels, grid, min_count=DEFAULT_MIN_COUNT,
                 weighting='cells'):
    return MixingIndex(cell_counts(grid, ids, points, labels), min_count, weighting)


def both_weightings(ids, points, labels, grid, min_count=DEFAULT_MIN_COUNT):
    """{weighting: MixingIndex} from one count of the cells."""
    counts = cell_counts(grid, ids, points, labels)
    return {w: MixingIndex(counts, min_count, w) for w in WEIGHTINGS}


# the columns of mixing.csv per split: (name, weighting, attribute)
COLUMNS = (('M_papers', 'cells', 'papers'), ('M_lacey', 'cells', 'lacey'),
           ('M_particles', 'particles', 'papers'), ('M_lacey_particles', 'particles', 'lacey'))


def column_names(splits):
    """mixing.csv's M columns: the cells-weighted pair for every split, then
    the particle-weighted pair (so that the first four columns stay M_papers
    and M_lacey of left-right and lower-upper)."""
    return ['%s %s' % (name, s) for weighting in WEIGHTINGS for s in splits
            for name, w, _ in COLUMNS if w == weighting]


def column_values(by_split, splits):
    return [getattr(by_split[s][w], attr) for weighting in WEIGHTINGS for s in splits
            for _, w, attr in COLUMNS if w == weighting]


# --- the particle files of a case ------------------------------------------------

def read_particles(path):
    """(ids, points) of one particle file."""
    ids = [int(v) for v in sc.read_vtp_array(path, 'id')]
    return ids, sc.read_vtp_points(path)


# --- ParaView: the labels beside the particles ------------------------------------

LABELLED_DIR = os.path.join('postProcessing', 'mixingParticles')


def write_labelled(source, target, ids, labels_by_split):
    """A copy of the particle file `source` with one Int8 array per split,
    `label_<split>` (1 = A, 0 = B, -1 = not in the first file), added to its
    point data: colour by it in ParaView."""
    with open(source, 'rb') as f:
        data = f.read()
    arrays = ''
    for split, labels in labels_by_split.items():
        values = '\n'.join(' %d' % labels.get(i, -1) for i in ids)
        arrays += ('        <DataArray type="Int8" Name="label_%s" format="ascii">\n%s\n'
                   '        </DataArray>\n' % (split, values))
    # the arrays go into the XML header; appended binary data after it keeps
    # its offsets, which count from the start of <AppendedData>
    appended = data.find(b'<AppendedData')
    header = data if appended < 0 else data[:appended]
    end = header.rfind(b'</PointData>')
    if end < 0:
        raise ValueError('%s: no <PointData> section' % source)
    with open(target + '.tmp', 'wb') as f:
        f.write(data[:end] + arrays.encode() + data[end:])
    os.replace(target + '.tmp', target)


def write_collection(folder, entries):
    """A ParaView .pvd collection of [(time, file name)]."""
    with open(os.path.join(folder, 'particles.pvd'), 'w') as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" '
                'byte_order="LittleEndian">\n  <Collection>\n')
        for t, name in entries:
            f.write('    <DataSet timestep="%.12g" group="" part="0" file="%s"/>\n' % (t, name))
        f.write('  </Collection>\n</VTKFile>\n')


# --- the front end ----------------------------------------------------------------

def evaluate_case(case, splits, cell, min_count=DEFAULT_MIN_COUNT, write_vtp=True,
                  scan=False, plot=True):
    """Writes mixing.csv (and the rest) for a case; returns the rows
    [(time, {split: {weighting: MixingIndex}})]."""
    files = sc.particle_files(case)
    if not files:
        raise SystemExit('mixing: %s: no particle files particles/particles_<time>.vtp'
                         % os.path.join(case, 'particles'))
    ids0, points0 = read_particles(files[0][1])
    labels, lines = {}, {}
    for split in splits:
        labels[split], lines[split] = segregated_labels(ids0, points0, split)
    grids = {s: SamplingGrid.for_split(cell[0], cell[1], s, lines[s]) for s in splits}
    scan_grids = {(s, size): SamplingGrid.for_split(size[0] / 1000, size[1] / 1000, s, lines[s])
                  for s in splits for size in SCAN_CELLS_MM} if scan else {}
    out = os.path.join(case, 'postProcessing')
    os.makedirs(out, exist_ok=True)
    vtp_dir = os.path.join(case, LABELLED_DIR)
    if write_vtp:
        os.makedirs(vtp_dir, exist_ok=True)
    rows, scan_rows, collection = [], [], []
    for t, path in files:
        ids, points = read_particles(path) if path != files[0][1] else (ids0, points0)
        rows.append((t, {s: both_weightings(ids, points, labels[s], grids[s], min_count)
                         for s in splits}))
        for (s, size), g in scan_grids.items():
            scan_rows.append((t, s, size, both_weightings(ids, points, labels[s], g, min_count)))
        if write_vtp:
            name = os.path.basename(path)
            write_labelled(path, os.path.join(vtp_dir, name), ids, labels)
            collection.append((t, name))
    if write_vtp:
        write_collection(vtp_dir, collection)
    csv = os.path.join(out, 'mixing.csv')
    with open(csv, 'w') as f:
        f.write(','.join(['time [s]'] + column_names(splits)
                         + ['sampling cells', 'particles per cell']) + '\n')
        for t, by_split in rows:
            first = by_split[splits[0]]['cells']
            f.write(','.join(['%.6g' % t] + ['%.6g' % v for v in column_values(by_split, splits)]
                             + ['%d' % first.cells, '%.4g' % first.mean_count]) + '\n')
    if scan:
        with open(os.path.join(out, 'mixingCellSize.csv'), 'w') as f:
            f.write('time [s],split,cell dx [mm],cell dz [mm],sampling cells,'
                    'particles per cell,M_papers,M_lacey,M_particles,M_lacey_particles,'
                    'random-mixing M_papers,random-mixing M_particles\n')
            for t, s, size, m in scan_rows:
                c, p = m['cells'], m['particles']
                f.write('%.6g,%s,%g,%g,%d,%.4g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n'
                        % (t, s, size[0], size[1], c.cells, c.mean_count, c.papers, c.lacey,
                           p.papers, p.lacey, c.random_level,
                           random_papers_expectation(p.particles, p.cells)))
    if plot:
        plot_history(csv, splits, os.path.join(out, 'mixing.png'))
    return rows


def random_papers_expectation(n_particles, n_cells):
    """E[M_papers] of a randomly labelled bed (count-weighted cells): N
    sigma_p^2/sigma_0^2 is Pearson's X^2 of the 2 x K table of labels and
    cells, chi-square with K - 1 degrees of freedom and mean
    (K - 1) N/(N - 1), so E[sigma_p/sigma_0] = sqrt(2/(N - 1))
    Gamma(K/2)/Gamma((K - 1)/2)."""
    if n_cells < 2 or n_particles < 2:
        return float('nan')
    k = n_cells
    return 1 - math.sqrt(2.0 / (n_particles - 1)) * math.exp(
        math.lgamma(k / 2) - math.lgamma((k - 1) / 2))


def plot_history(csv, splits, png):
    names = column_names(splits)
    curves = []
    for s in splits:
        for name, dash, title in (('M_papers', '', 'papers, cells'),
                                  ('M_particles', ' dt 3', 'papers, particles'),
                                  ('M_lacey', ' dt 2', 'Lacey, cells')):
            curves.append('"%s" skip 1 using 1:%d with linespoints%s title "%s, %s"'
                          % (csv, 2 + names.index('%s %s' % (name, s)), dash, title, s))
    sc.plot(png, 'set datafile separator ","\nset grid\nset key bottom right\n'
            'set title "Degree of mixing (eqs 17-19)"\nset xlabel "time [s]"\n'
            'set ylabel "M"\nset yrange [-0.1:1.1]\nplot ' + ', \\\n     '.join(curves) + '\n')


def main(argv=None):
    p = cli.Parser(prog='mixing',
        description='Degree of particle mixing of a spouted-bed case (eqs 17-19 and '
                    'Lacey) from its particle files: M_papers sums over the sampling cells '
                    'as eq 18 does (every cell weighs one), M_particles weights each cell '
                    'by its particles; writes postProcessing/mixing.csv, '
                    'mixing.png and the labelled particles for ParaView '
                    '(postProcessing/mixingParticles/particles.pvd).')
    p.add_argument('case', help='case directory (holding particles/particles_<time>.vtp)')
    p.add_argument('--split', choices=SPLITS + ('both',), default='both',
                   help='how A and B are segregated at t = 0 (default: both, the '
                        'default split %s first)' % DEFAULT_SPLIT)
    p.add_argument('--cell', nargs=2, type=float, metavar=('DX', 'DZ'),
                   default=DEFAULT_CELL_MM,
                   help='sampling cell width and height in mm (default %g %g)'
                        % DEFAULT_CELL_MM)
    p.add_argument('--min-count', type=int, default=DEFAULT_MIN_COUNT,
                   help='cells with fewer particles are left out (default %d)'
                        % DEFAULT_MIN_COUNT)
    p.add_argument('--scan-cells', action='store_true',
                   help='also write postProcessing/mixingCellSize.csv: M for cells of '
                        + ', '.join('%gx%g' % s for s in SCAN_CELLS_MM) + ' mm')
    p.add_argument('--no-vtp', action='store_true', help='no labelled particle files')
    p.add_argument('--no-plot', action='store_true', help='no mixing.png')
    a = p.parse_args(argv)
    if not (a.cell[0] > 0 and a.cell[1] > 0):
        p.error('--cell: expected two positive sizes in mm, got %g %g' % tuple(a.cell))
    if a.min_count < 1:
        p.error('--min-count: expected a whole number >= 1, got %d' % a.min_count)
    splits = (DEFAULT_SPLIT, 'lower-upper') if a.split == 'both' else (a.split,)
    rows = evaluate_case(a.case, splits, (a.cell[0] / 1000, a.cell[1] / 1000), a.min_count,
                         write_vtp=not a.no_vtp, scan=a.scan_cells, plot=not a.no_plot)
    t, last = rows[-1]
    m = last[splits[0]]['cells']
    print('mixing: %d particle files; sampling cells %g x %g mm, %d cells of %.0f particles '
          'on average at t = %g s' % (len(rows), a.cell[0], a.cell[1], m.cells, m.mean_count, t))
    for s in splits:
        c, p = last[s]['cells'], last[s]['particles']
        print('mixing: %-11s M_papers %.3f (cells weighted, eq 18), M_lacey %.3f; weighted by '
              'particles M_particles %.3f, M_lacey_particles %.3f at t = %g s (random mixing: '
              'M_papers about %.3f, M_particles %.3f, M_lacey 1)'
              % (s, c.papers, c.lacey, p.papers, p.lacey, t, c.random_level,
                 random_papers_expectation(p.particles, p.cells)))
    print('mixing: wrote %s' % os.path.join(a.case, 'postProcessing', 'mixing.csv'))
    return 0


if __name__ == '__main__':
    sys.exit(main())
