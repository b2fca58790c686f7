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

Results: mixing.txt (every finished run; mixing.json, its numbers for
protocols/results), mixing.csv, and a figure per bed,
mixing_<vessel>_n<N>.png (M_papers and M_Lacey, left-right, against time);
snapshots like the draft-plate paper's Figs 8-9 per run,
snapshot_<run>_t<t>_{velocity,label}.png: the particles coloured by their
vertical velocity and by their A/B label at 1 s and at the end.  The
labelled particle files for ParaView are in each run's
postProcessing/mixingParticles/particles.pvd (arrays label_left-right,
label_lower-upper).
"""
import argparse
import json
import os
import re
import sys

from spoutlab import casefiles as sc
from spoutlab import cli
from spoutlab import mixing
from spoutlab import spoutedbed
from spoutlab import bedmaps
from spoutlab.protocols import circulation

# draft-plate paper Fig 10a/b and no-draft paper Fig 6 (26 000 at 2.0 m/s),
# the draft-plate bed at 2.0; the results' keys first
POINTS = [('no-plates', 10000, 2.0), ('no-plates', 26000, 2.5), ('no-plates', 26000, 3.0),
          ('plates', 26000, 2.0), ('no-plates', 26000, 2.2), ('no-plates', 26000, 2.7),
          ('no-plates', 10000, 2.5), ('no-plates', 10000, 3.0), ('no-plates', 26000, 2.0)]

DEFAULT_TIME = 4.0   # simulated seconds per run


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
    cli.add_overrides(p, 'system/spoutedBedDict for every run')
    a = cli.parse(p, argv)
    if not 0 < a.final <= a.time or not 0 < a.write <= a.time:
        p.error('--final and --write must lie in (0, --time]')
    return a


def label(vessel, n, u):
    return 'mix_%s_n%d_u%g' % (vessel.replace('-', ''), n, u)


class Run:
    """A finished run: M against time from its postProcessing/mixing.csv."""

    def __init__(self, vessel, n, u, final):
        self.vessel, self.n, self.u = vessel, n, u
        self.label = label(vessel, n, u)
        self.work = os.path.join('runs', self.label)
        head, *rows = [r.strip().split(',') for r in
                       open(os.path.join(self.work, 'postProcessing', 'mixing.csv'))]
        col = {name: k for k, name in enumerate(head)}
        self.t = [float(r[0]) for r in rows]
        self.series = {name: [float(r[col[name]]) for r in rows] for name in head[1:5]}
        end = self.t[-1]
        self.final = {name: mean([m for t, m in zip(self.t, v) if t >= end - final - 1e-6])
                      for name, v in self.series.items()}
        self.cells = int(rows[-1][col['sampling cells']])
        self.per_cell = float(rows[-1][col['particles per cell']])

    def summary(self):
        f = self.final
        return ('%s: %s, %d particles, u_s = %g m/s, %.3g s: M_final %.3f (papers, left-right), '
                'Lacey %.3f; lower-upper %.3f, Lacey %.3f; %d sampling cells of %.0f particles'
                % (self.label, 'no draft plates' if self.vessel == 'no-plates' else
                   'draft plates', self.n, self.u, self.t[-1], f['M_papers left-right'],
                   f['M_lacey left-right'], f['M_papers lower-upper'], f['M_lacey lower-upper'],
                   self.cells, self.per_cell))


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
             'M_final is the mean over the last %g s; sampling cells 55 x 57 mm' % a.final]
    shown = [r.snapshots() for r in runs]
    lines += ['%s; snapshots: %s' % (r.summary(), ' '.join(s)) for r, s in zip(runs, shown)]
    text = '\n'.join(lines) + '\n'
    open('mixing.txt', 'w').write(text)
    sys.stdout.write(text)
    # the numbers as mixing.txt prints them, for protocols/results
    with open('mixing.json', 'w') as f:
        json.dump({'settings': lines[0].lstrip('# '), 'runs': [dict(
            label=r.label, vessel=r.vessel, particles=r.n, u_m_s=float('%g' % r.u),
            time_s=float('%.3g' % r.t[-1]), snapshots=s,
            **{k.replace(' ', '_').replace('-', '_'): float('%.3f' % r.final[k])
               for k in ('M_papers left-right', 'M_lacey left-right', 'M_papers lower-upper',
                         'M_lacey lower-upper')}) for r, s in zip(runs, shown)]}, f, indent=1)
        f.write('\n')
    with open('mixing.csv', 'w') as f:
        f.write('run,vessel,particles,superficial velocity [m/s],time [s],M_papers left-right,'
                'M_lacey left-right,M_papers lower-upper,M_lacey lower-upper\n')
        for r in runs:
            for k, t in enumerate(r.t):
                f.write('%s,%s,%d,%g,%.6g,%s\n' % (r.label, r.vessel, r.n, r.u, t, ','.join(
                    '%.6g' % r.series[name][k] for name in (
                        'M_papers left-right', 'M_lacey left-right', 'M_papers lower-upper',
                        'M_lacey lower-upper'))))
    for vessel, n in sorted({(r.vessel, r.n) for r in runs}):
        bed = [r for r in runs if (r.vessel, r.n) == (vessel, n)]
        curves = []
        for r in sorted(bed, key=lambda r: r.u):
            data = os.path.join(r.work, 'postProcessing', 'mixing.csv')
            curves += ['"%s" skip 1 using 1:2 with linespoints title "%g m/s, papers"'
                       % (data, r.u),
                       '"%s" skip 1 using 1:3 with lines dt 2 title "%g m/s, Lacey"'
                       % (data, r.u)]
        sc.plot('mixing_%s_n%d.png' % (vessel.replace('-', ''), n),
                'set datafile separator ","\nset grid\nset key top left\n'
                'set title "Degree of mixing, %s, %d particles (left-right halves)"\n'
                'set xlabel "time [s]"\nset ylabel "M"\nset yrange [-0.1:1.1]\nplot %s\n'
                % ('no draft plates' if vessel == 'no-plates' else 'draft plates', n,
                   ', \\\n     '.join(curves)))


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
    points = [(label(v, n, u), u, ['plates=%s' % ('yes' if v == 'plates' else 'no'),
                                   'nParticles=%d' % n], None, None) for v, n, u in a.points]
    circulation.run_all(o, points)
    report(a)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
