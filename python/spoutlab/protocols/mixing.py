"""The degree of mixing against time: the draft-plate paper's Fig 10 (no
plates, 26 000 particles at 2.2-3.0 m/s and 10 000 at velocities from
u_ms), the no-draft paper's Figs 5-6 (both bed heights, Fig 6 at 2.0 m/s),
and the draft-plate bed at 2.0 m/s, which neither paper gives.

Each point is one run in runs/mix_<vessel>_n<N>_u<u>/ made like a point of
`circulation` (protocols/circulation run_point): a copy of the case, the
settled bed labelled A/B at t = 0 (spoutlab.mixing: left-right halves
by default, lower-upper beside), gas at u_s from t = 0 as in the papers (no
spin-up: M oscillates while the spout forms), particle files every --write
seconds.  Runs of one vessel and particle count share one settled bed;
finished runs are kept, so running the command again after an interruption
continues, and several invocations on different points may run side by
side.

M is computed as spoutlab.mixing does, both weightings: M_papers sums
over the sampling cells as the papers' eq 18 does (N = the number of cells,
every cell weighs one; the headline), M_particles weights each cell by its
particles; at the default 55 x 57 mm cells and, with the other sizes of
--scan-cells, at the papers' 11 x 19 mm grid (a run whose mixing.csv lacks
either is evaluated again from its particle files).  Each run's W_s (its
circulation.csv, the last 1.8 s) gives the bed's turnover time m_bed/W_s,
and the first time M reaches 0.9 of its random-mixing value at 55 x 57 mm
(the papers' Fig 10b after 2 s on their scale, where random mixing gives 1;
our cells cannot give more than about 0.88-0.92) is noted.

With --candidates the protocol asks instead whether anything in the model
moves the circulation, and so the mixing, toward the papers': the
10 000-particle bed without plates at 2.5 m/s once as the case stands and
once per candidate (CANDIDATES), each changing one thing, none tuned, in
runs/mix_noplates_n10000_u2.5_<candidate>/ (a candidate that changes the
contacts settles its own bed); results in candidates.txt and
mixingCandidates.json (for protocols/results --mixingCandidates) and
mixingcand_M.png (M against time, every run).

Results: mixing.txt (every finished run; mixing.json, its numbers for
protocols/results), mixing.csv (M against time), mixingCellSize.csv (M_final
against the sampling-cell size), and two figures per bed,
mixing_<vessel>_n<N>.png (M_papers and M_particles, left-right, against
time) and mixing_cellsize_<vessel>_n<N>.png (M_final against the cell size
beside the random-mixing level); snapshots like the draft-plate paper's
Figs 8-9 per run, snapshot_<run>_t<t>_{velocity,label}.png: the particles
coloured by their vertical velocity and by their A/B label at 1 s and at
the end.  The labelled particle files for ParaView are in each run's
postProcessing/mixingParticles/particles.pvd (arrays label_left-right,
label_lower-upper).
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import re
import sys

from spoutlab import casefiles as sc
from spoutlab import cli
from spoutlab import mixing
from spoutlab import spoutedbed
from spoutlab import bedmaps
from spoutlab import spoutregime
from spoutlab.protocols import circulation

# draft-plate paper Fig 10a/b and no-draft paper Fig 6 (26 000 at 2.0 m/s),
# the draft-plate bed at 2.0; the results' keys first
POINTS = [('no-plates', 10000, 2.0), ('no-plates', 26000, 2.5), ('no-plates', 26000, 3.0),
          ('plates', 26000, 2.0), ('no-plates', 26000, 2.2), ('no-plates', 26000, 2.7),
          ('no-plates', 10000, 2.5), ('no-plates', 10000, 3.0), ('no-plates', 26000, 2.0)]

DEFAULT_TIME = 4.0   # simulated seconds per run

# Whether anything in the model moves W_s toward the circulation the
# papers' mixing needs (issue 25 item 3): one run per candidate, each
# changing one thing from the reference, none tuned.  name, what changes,
# spoutedBedDict overrides, entries (file, key, value) of other dictionaries.
CANDIDATE_POINT = ('no-plates', 10000, 2.5)
CANDIDATES = [
    ('reference', "nothing: the papers' mu 0.3 and e 0.9 for every contact, Gidaspow's "
     'drag, 11 x 19 mm gas cells', [], []),
    ('mu0.1', 'friction 0.1 for 0.3, particles and walls', ['mu=0.1'], []),
    ('e0.5', 'restitution 0.5 for 0.9, every contact: maize kernels on steel as measured '
     '(maize on maize 0.32; Agriculture, Sep 2024, contact parameters of maize-kernel DEM '
     'models)', ['e=0.5'], []),
    ('muWall0', "frictionless walls for 0.3: the 40 mm slab's front and back (most wall "
     'contacts), the sides and the base', ['muWall=0'], []),
    ('DiFelice', "Di Felice's drag for Gidaspow's (Ergun / Wen-Yu)", [],
     [('constant/couplingProperties', 'dragModel', 'DiFelice')]),
    ('refine2', 'gas cells 5.5 x 9.5 mm for 11 x 19 mm, and the time step halved to 1.5e-4 s '
     '(on the finer cells the slot jet reaches Courant 3 at 3e-4 s)',
     ['refine=2', 'dtDem=1.5e-4'], [('system/controlDict', 'deltaT', '1.5e-4')]),
]


def point(text):
    try:
        vessel, n, u = text.split(':')
        if vessel not in ('plates', 'no-plates') or int(n) < 1 or float(u) <= 0:
            raise ValueError
        return vessel, int(n), float(u)
    except ValueError:
        raise argparse.ArgumentTypeError('expected VESSEL:N:U with VESSEL plates or '
                                         'no-plates, N > 0 and U > 0 m/s, got %r' % text)


def parse(argv):
    p = cli.parser('mixing', __doc__)
    p.add_argument('--points', type=lambda s: [point(t) for t in s.split(',')],
                   default=POINTS, metavar='VESSEL:N:U,...',
                   help='runs as vessel (plates or no-plates), particles and superficial '
                        'velocity [m/s] (default: the papers\' points, see POINTS)')
    p.add_argument('--time', type=float, default=DEFAULT_TIME, metavar='T',
                   help='simulated time per run [s] (default %(default)s)')
    p.add_argument('--write', type=float, default=0.1, metavar='DT',
                   help='particle output interval [s] (default %(default)s; sets this '
                        'copy\'s system/controlDict writeInterval)')
    p.add_argument('--final', type=float, default=1.0, metavar='T',
                   help='M_final is the mean over the last T seconds (default %(default)s)')
    p.add_argument('-np', type=int, default=1, metavar='RANKS', help='MPI ranks per run')
    p.add_argument('-j', '--jobs', type=int, default=1, metavar='JOBS',
                   help='runs side by side (default %(default)s)')
    p.add_argument('--candidates', action='store_true',
                   help='run the candidates that might move the circulation (CANDIDATES: '
                        'the 10 000-particle bed without plates at 2.5 m/s, one change '
                        'each) instead of --points')
    cli.add_overrides(p, 'system/spoutedBedDict for every run')
    a = cli.parse(p, argv)
    if not 0 < a.final <= a.time or not 0 < a.write <= a.time:
        p.error('--final and --write must lie in (0, --time]')
    return a


def label(vessel, n, u):
    return 'mix_%s_n%d_u%g' % (vessel.replace('-', ''), n, u)


SPLITS = (mixing.DEFAULT_SPLIT, 'lower-upper')
# the M columns of a run's mixing.csv: cells-weighted (the papers' eq 18),
# then weighted by particles
COLUMNS = mixing.column_names(SPLITS)
# the papers' M after 2 s of the 10 000-particle bed (Fig 10b), where random
# mixing gives 1
LEVEL = 0.9


def evaluate(work):
    """The run's postProcessing/mixing.csv with both weightings and
    mixingCellSize.csv with the cell sizes, computed again from its particle
    files unless the case's evaluate already wrote them so."""
    post = os.path.join(work, 'postProcessing')
    path = os.path.join(post, 'mixing.csv')
    head = open(path).readline().strip().split(',') if os.path.isfile(path) else []
    if head[1:1 + len(COLUMNS)] != COLUMNS or not os.path.isfile(
            os.path.join(post, 'mixingCellSize.csv')):
        cell = mixing.DEFAULT_CELL_MM
        mixing.evaluate_case(work, SPLITS, (cell[0] / 1000, cell[1] / 1000), write_vtp=False,
                             scan=True)


def first_reach(t, m, level):
    """The first time M reaches level, linear between the samples (None if
    it never does)."""
    for k in range(1, len(t)):
        if m[k] >= level > m[k - 1]:
            return t[k - 1] + (level - m[k - 1]) / (m[k] - m[k - 1]) * (t[k] - t[k - 1])
    return None


def interpolate(t, m, when):
    """M at time when, linear between the samples (None outside them)."""
    for k in range(1, len(t)):
        if t[k - 1] <= when <= t[k]:
            return m[k - 1] + (when - t[k - 1]) / (t[k] - t[k - 1]) * (m[k] - m[k - 1])
    return None


class Run:
    """A finished run: M against time from its postProcessing/mixing.csv,
    M_final against the sampling-cell size from mixingCellSize.csv, W_s from
    its circulation.csv."""

    def __init__(self, vessel, n, u, final, run=None):
        self.vessel, self.n, self.u = vessel, n, u
        self.label = run or label(vessel, n, u)
        self.work = os.path.join('runs', self.label)
        evaluate(self.work)
        head, *rows = [r.strip().split(',') for r in
                       open(os.path.join(self.work, 'postProcessing', 'mixing.csv'))]
        col = {name: k for k, name in enumerate(head)}
        self.t = [float(r[0]) for r in rows]
        self.series = {name: [float(r[col[name]]) for r in rows] for name in COLUMNS}
        end = self.t[-1]
        self.final = {name: mean([m for t, m in zip(self.t, v) if t >= end - final - 1e-6])
                      for name, v in self.series.items()}
        self.cells = int(rows[-1][col['sampling cells']])
        self.per_cell = float(rows[-1][col['particles per cell']])
        # M_final of the left-right split at every cell size, both weightings
        by_size = {}
        for r in list(csv.DictReader(open(os.path.join(
                self.work, 'postProcessing', 'mixingCellSize.csv')))):
            if r['split'] != mixing.DEFAULT_SPLIT or float(r['time [s]']) < end - final - 1e-6:
                continue
            by_size.setdefault((float(r['cell dx [mm]']), float(r['cell dz [mm]'])), []).append(r)
        self.sizes = [dict(dx_mm=dx, dz_mm=dz, **{
            k.replace(' ', '_').replace('-', '_'): float('%.4g' % mean([float(r[k]) for r in rs]))
            for k in ('sampling cells', 'particles per cell', 'M_papers', 'M_particles',
                      'random-mixing M_papers', 'random-mixing M_particles')})
            for (dx, dz), rs in sorted(by_size.items())]
        self.papers_grid = [s for s in self.sizes
                            if (s['dx_mm'], s['dz_mm']) == mixing.PAPERS_CELL_MM][0]
        # the circulation: turnover m_bed/W_s, and when M first reaches LEVEL
        g = spoutedbed.load(self.work)
        self.bed_mass = n * g.particles['rhop'] * math.pi * (g.particles['dp'] / 1000) ** 3 / 6
        self.w_s = circulation.w_s(self.work)
        self.turnover = self.bed_mass / self.w_s if self.w_s > 0 else float('nan')
        # the papers' 0.9 on their scale, where random mixing gives 1, is
        # LEVEL times the random-mixing M of these cells on ours
        default = [z for z in self.sizes if (z['dx_mm'], z['dz_mm']) == mixing.DEFAULT_CELL_MM][0]
        self.level = {w: LEVEL * default['random_mixing_' + name]
                      for w, name in (('cells', 'M_papers'), ('particles', 'M_particles'))}
        self.reach = {w: first_reach(self.t, self.series['%s %s' % (name, mixing.DEFAULT_SPLIT)],
                                     self.level[w])
                      for w, name in (('cells', 'M_papers'), ('particles', 'M_particles'))}
        # M at half a turnover and at one: alike in every run if M follows
        # the turnovers
        self.at_turnover = [interpolate(self.t, self.series['M_papers ' + mixing.DEFAULT_SPLIT],
                                        f * self.turnover) for f in (0.5, 1.0)]

    def summary(self):
        f, lr, lu = self.final, mixing.DEFAULT_SPLIT, 'lower-upper'
        return ('%s: %s, %d particles, u_s = %g m/s, %.3g s: M_final %.3f (papers, cells '
                'weighted as eq 18, left-right), weighted by particles %.3f, Lacey %.3f (by '
                'particles %.3f); lower-upper %.3f (by particles %.3f), Lacey %.3f; %d sampling '
                'cells of %.0f particles; at the papers\' 11 x 19 mm cells %.3f (by particles '
                '%.3f, random mixing about %.3f); W_s %.3f kg/s, turnover m_bed/W_s %.2f s'
                % (self.label, 'no draft plates' if self.vessel == 'no-plates' else
                   'draft plates', self.n, self.u, self.t[-1], f['M_papers ' + lr],
                   f['M_particles ' + lr], f['M_lacey ' + lr], f['M_lacey_particles ' + lr],
                   f['M_papers ' + lu], f['M_particles ' + lu], f['M_lacey ' + lu],
                   self.cells, self.per_cell, self.papers_grid['M_papers'],
                   self.papers_grid['M_particles'], self.papers_grid['random_mixing_M_papers'],
                   self.w_s, self.turnover))

    def snapshots(self):
        """Figs 8-9: the labelled particles at 1 s and at the end, coloured
        by vertical velocity and by the left-right label (made once)."""
        g = spoutedbed.load(self.work)
        labelled = os.path.join(self.work, mixing.LABELLED_DIR)
        files = [(t, os.path.join(labelled, os.path.basename(path)))
                 for t, path in sc.particle_files(self.work)]
        names = []
        shown = {min(files, key=lambda f: abs(f[0] - want)) for want in (1.0, self.t[-1])}
        for t, vtp in sorted(shown):
            for field in ('velocity', 'label'):
                name = 'snapshot_%s_t%g_%s.png' % (self.label, round(t, 1), field)
                names.append(name)
                if os.path.isfile(name):
                    continue
                title = '%s, %d particles, u_s = %g m/s, t = %.1f s' % (
                    'no draft plates' if self.vessel == 'no-plates' else 'draft plates', self.n,
                    self.u, t)
                if field == 'velocity':
                    bedmaps.snapshot(g, vtp, name, title)
                else:
                    bedmaps.snapshot(g, vtp, name, title, field='label_left-right', vmin=0,
                                        vmax=1, label='label: A (1, left at t = 0), B (0)')
        return names


def mean(values):
    return sum(values) / len(values) if values else float('nan')


def finished_runs(final):
    """Every run under runs/ with a mixing.csv, in the order of POINTS then
    the others."""
    runs = []
    if os.path.isdir('runs'):
        for name in sorted(os.listdir('runs')):
            parts = name.split('_')
            if len(parts) != 4 or parts[0] != 'mix' or not os.path.isfile(
                    os.path.join('runs', name, 'postProcessing', 'mixing.csv')):
                continue
            vessel = 'no-plates' if parts[1] == 'noplates' else 'plates'
            runs.append(Run(vessel, int(parts[2][1:]), float(parts[3][1:]), final))
    order = {p: k for k, p in enumerate(POINTS)}
    return sorted(runs, key=lambda r: (order.get((r.vessel, r.n, r.u), len(order)),
                                       r.vessel, r.n, r.u))


def report(a):
    runs = finished_runs(a.final)
    lines = ['# degree of mixing: gas at u_s from the settled, segregated bed (t = 0); '
             'M_final is the mean over the last %g s; sampling cells 55 x 57 mm and the '
             'papers\' 11 x 19 mm; M_papers sums over the cells as eq 18 does (weighting '
             'cells), M_particles weights each cell by its particles' % a.final]
    shown = [r.snapshots() for r in runs]
    lines += ['%s; snapshots: %s' % (r.summary(), ' '.join(s)) for r, s in zip(runs, shown)]
    text = '\n'.join(lines) + '\n'
    open('mixing.txt', 'w').write(text)
    sys.stdout.write(text)

    def key(name):
        return name.replace(' ', '_').replace('-', '_')

    def reach(t):
        return None if t is None else float('%.3g' % t)

    # the numbers as mixing.txt prints them, for protocols/results
    with open('mixing.json', 'w') as f:
        json.dump({'settings': lines[0].lstrip('# '), 'level': LEVEL, 'runs': [dict(
            label=r.label, vessel=r.vessel, particles=r.n, u_m_s=float('%g' % r.u),
            time_s=float('%.3g' % r.t[-1]), snapshots=s, cell_sizes=r.sizes,
            W_s_kg_s=float('%.4g' % r.w_s), bed_mass_kg=float('%.4g' % r.bed_mass),
            turnover_s=float('%.4g' % r.turnover),
            level_cells=float('%.3f' % r.level['cells']),
            level_particles=float('%.3f' % r.level['particles']),
            t_reach_cells_s=reach(r.reach['cells']),
            t_reach_particles_s=reach(r.reach['particles']),
            **{name: None if m is None else float('%.3f' % m) for name, m in zip(
                ('M_papers_at_half_turnover', 'M_papers_at_turnover'), r.at_turnover)},
            **{key(k): float('%.3f' % r.final[k]) for k in COLUMNS})
            for r, s in zip(runs, shown)]}, f, indent=1)
        f.write('\n')
    with open('mixing.csv', 'w') as f:
        f.write('run,vessel,particles,superficial velocity [m/s],time [s],%s\n'
                % ','.join(COLUMNS))
        for r in runs:
            for k, t in enumerate(r.t):
                f.write('%s,%s,%d,%g,%.6g,%s\n' % (r.label, r.vessel, r.n, r.u, t, ','.join(
                    '%.6g' % r.series[name][k] for name in COLUMNS)))
    with open('mixingCellSize.csv', 'w') as f:
        f.write('run,vessel,particles,superficial velocity [m/s],cell dx [mm],cell dz [mm],'
                'sampling cells,particles per cell,M_final papers (cells),'
                'M_final particles,random-mixing M_papers,random-mixing M_particles\n')
        for r in runs:
            for z in r.sizes:
                f.write('%s,%s,%d,%g,%g,%g,%g,%g,%g,%g,%g,%g\n' % (
                    r.label, r.vessel, r.n, r.u, z['dx_mm'], z['dz_mm'], z['sampling_cells'],
                    z['particles_per_cell'], z['M_papers'], z['M_particles'],
                    z['random_mixing_M_papers'], z['random_mixing_M_particles']))
    for vessel, n in sorted({(r.vessel, r.n) for r in runs}):
        bed = sorted([r for r in runs if (r.vessel, r.n) == (vessel, n)], key=lambda r: r.u)
        what = 'no draft plates' if vessel == 'no-plates' else 'draft plates'
        curves = []
        for k, r in enumerate(bed):
            data = os.path.join(r.work, 'postProcessing', 'mixing.csv')
            curves += ['"%s" skip 1 using 1:%d with linespoints lc %d title "%g m/s, papers '
                       '(cells)"' % (data, 2 + COLUMNS.index('M_papers left-right'), k + 1, r.u),
                       '"%s" skip 1 using 1:%d with lines dt 2 lc %d title "%g m/s, by '
                       'particles"' % (data, 2 + COLUMNS.index('M_particles left-right'),
                                       k + 1, r.u)]
        tag = '%s_n%d' % (vessel.replace('-', ''), n)
        sc.plot('mixing_%s.png' % tag,
                'set datafile separator ","\nset grid\nset key top left\n'
                'set title "Degree of mixing, %s, %d particles (left-right halves, 55 x 57 mm)"\n'
                'set xlabel "time [s]"\nset ylabel "M"\nset yrange [-0.1:1.1]\nplot %s\n'
                % (what, n, ', \\\n     '.join(curves)))
        # M_final against the cell size (the square root of its area)
        curves = []
        for k, r in enumerate(bed):
            sel = '(strcol(1) eq "%s" ? sqrt($5*$6) : 1/0)' % r.label
            curves += ['"mixingCellSize.csv" skip 1 using %s:9 with linespoints pt 7 lc %d '
                       'title "%g m/s, papers (cells)"' % (sel, k + 1, r.u),
                       '"mixingCellSize.csv" skip 1 using %s:10 with linespoints dt 2 pt 6 '
                       'lc %d title "%g m/s, by particles"' % (sel, k + 1, r.u)]
        sel = '(strcol(1) eq "%s" ? sqrt($5*$6) : 1/0)' % bed[0].label
        curves += ['"mixingCellSize.csv" skip 1 using %s:11 with lines lc rgb "gray" lw 2 '
                   'title "random mixing, cells"' % sel,
                   '"mixingCellSize.csv" skip 1 using %s:12 with lines dt 2 lc rgb "gray" lw 2 '
                   'title "random mixing, particles"' % sel]
        sc.plot('mixing_cellsize_%s.png' % tag,
                'set datafile separator ","\nset grid\nset key bottom right\n'
                'set title "M_{final} against the sampling cell, %s, %d particles"\n'
                'set xlabel "sampling cell size sqrt(dx dz) [mm] (11 x 19 mm: the papers\' '
                'grid)"\nset ylabel "M_{final} (left-right)"\nset yrange [-0.1:1.1]\n'
                'plot %s\n' % (what, n, ', \\\n     '.join(curves)))


def candidate_run(name):
    """A candidate's run under runs/ (the reference's is the point's own)."""
    return label(*CANDIDATE_POINT) + ('' if name == 'reference' else '_' + name)


def run_candidates(o):
    """Every candidate's run, --jobs at a time, those sharing a settled bed
    after the first that makes it; a run that fails is reported, not fatal."""
    vessel, n, u = CANDIDATE_POINT
    point = ['plates=%s' % ('yes' if vessel == 'plates' else 'no'), 'nParticles=%d' % n]
    settled = {}

    def one(c):
        name, _, overrides, entries = c
        try:
            circulation.run_point(o, candidate_run(name), u, point + overrides, settled,
                                  entries)
        except SystemExit as e:
            print('mixing: candidate %s: %s' % (name, e), flush=True)

    first = [c for c in CANDIDATES if not c[2]]
    with concurrent.futures.ThreadPoolExecutor(o['jobs']) as pool:
        for batch in (first[:1], first[1:] + [c for c in CANDIDATES if c[2]]):
            list(pool.map(one, batch))


def report_candidates(a):
    """candidates.txt, mixingCandidates.json and mixingcand_M.png: each
    candidate's W_s, turnover and M_final beside the reference's."""
    vessel, n, u = CANDIDATE_POINT
    runs, failed = [], []
    for name, what, overrides, entries in CANDIDATES:
        r = None
        if os.path.isfile(os.path.join('runs', candidate_run(name), 'postProcessing',
                                       'mixing.csv')):
            r = Run(vessel, n, u, a.final, candidate_run(name))
        (runs if r else failed).append((name, what, overrides, entries, r))
    reference = [r for name, _, _, _, r in runs if name == 'reference']
    if not reference:
        sys.exit('mixing: the reference candidate did not finish (runs/%s): nothing to '
                 'compare with' % candidate_run('reference'))
    ref = reference[0]
    lr = 'M_papers ' + mixing.DEFAULT_SPLIT
    settings = ('%s, %d particles, u_s = %g m/s, gas from the settled bed at t = 0, %g s; '
                'M_final the mean over the last %g s, left-right halves, 55 x 57 mm sampling '
                'cells, weighting cells (eq 18); W_s from the last 1.8 s'
                % ('no draft plates' if vessel == 'no-plates' else 'draft plates', n, u,
                   a.time, a.final))
    records = []
    for name, what, overrides, entries, r in runs:
        # W_s by eq 14 means circulation only where the bed spouts
        regime = spoutregime.bed_spouts(spoutedbed.load(r.work), r.work, r.t[-1] - 1.8, r.t[-1])
        records.append(dict(spouts=regime.spouts, regime=regime.describe(),
            name=name, what=what, changes=overrides + ['%s %s' % e[1:] for e in entries],
            label=r.label, time_s=float('%.3g' % r.t[-1]), W_s_kg_s=float('%.4g' % r.w_s),
            turnover_s=float('%.4g' % r.turnover),
            M_final=float('%.3f' % r.final[lr]),
            M_final_particles=float('%.3f' % r.final['M_particles ' + mixing.DEFAULT_SPLIT]),
            M_final_grid11x19=float('%.3f' % r.papers_grid['M_papers'])))
    lines = ['# candidates: %s' % settings]
    lines += ['%s (%s): W_s %.3f kg/s (%+.1f %% on the reference), turnover %.2f s, '
              'M_final %.3f (by particles %.3f; 11 x 19 mm cells %.3f); the bed %s'
              % (c['name'], c['what'], c['W_s_kg_s'], 100 * (c['W_s_kg_s'] / ref.w_s - 1),
                 c['turnover_s'], c['M_final'], c['M_final_particles'],
                 c['M_final_grid11x19'], c['regime']) for c in records]
    lines += ['%s (%s): no finished run' % (name, what) for name, what, _, _, _ in failed]
    text = '\n'.join(lines) + '\n'
    open('candidates.txt', 'w').write(text)
    sys.stdout.write(text)
    with open('mixingCandidates.json', 'w') as f:
        json.dump({'settings': settings, 'runs': records,
                   'failed': [dict(name=c[0], what=c[1]) for c in failed]}, f, indent=1)
        f.write('\n')
    curves = ['"%s" skip 1 using 1:%d with lines lw 2 title "%s"'
              % (os.path.join(r.work, 'postProcessing', 'mixing.csv'), 2 + COLUMNS.index(lr),
                 name) for name, _, _, _, r in runs]
    sc.plot('mixingcand_M.png',
            'set datafile separator ","\nset grid\nset key top left\n'
            'set title "Degree of mixing, one change each, %d particles, no plates, %g m/s"\n'
            'set xlabel "time [s]"\nset ylabel "M (papers, left-right, 55 x 57 mm)"\n'
            'set yrange [-0.1:1.1]\nplot %s\n' % (n, u, ', \\\n     '.join(curves)))


def set_write_interval(path, dt):
    """The top-level writeInterval of a controlDict, set as text (before any
    OpenFOAM program has run in the case)."""
    text = open(path).read()
    new, n = re.subn(r'^writeInterval\s+[^;]*;', 'writeInterval   %g;' % dt, text, flags=re.M)
    if n != 1:
        sys.exit('mixing: %s: expected one top-level writeInterval entry, found %d' % (path, n))
    open(path, 'w').write(new)


def main(argv):
    a = parse(argv)
    set_write_interval('system/controlDict', a.write)
    o = dict(kick='', time=a.time, average=min(1.8, a.time), np=a.np, n=None,
             overrides=a.overrides, jobs=a.jobs)
    if a.candidates:
        run_candidates(o)
        report_candidates(a)
        return 0
    points = [(label(v, n, u), u, ['plates=%s' % ('yes' if v == 'plates' else 'no'),
                                   'nParticles=%d' % n], None, None) for v, n, u in a.points]
    circulation.run_all(o, points)
    report(a)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
