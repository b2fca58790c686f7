"""The no-draft paper's Figs 3 and 4: time-averaged gas velocity U_z and
particle velocity V_z over the bed without draft plates, at u_s = 2.0 m/s
(10 000 particles) and 2.2 m/s (26 000), as maps and as profiles across the
width at selected heights, with the features the paper reports checked.

Each point is one run in runs/noplates_n<N>_u<u>/ made like a point of
`circulation` (protocols/circulation run_point: a copy of the case, the
bed broken through at --kick, then u_s to --time; averages over the last
--average seconds); finished runs are kept, so running the command again
after an interruption continues.

Results: maps.txt (and maps.json, its numbers for protocols/results),
maps_<label>_{gasVelocity,particleVelocity}.png (maps),
maps_<label>_profiles.png and maps_<label>_profiles.csv (profiles across the
width every 5 gas cells, 95 mm, of height up to the settled bed).
"""
import argparse
import concurrent.futures
import json
import math
import os
import sys

from spoutlab import casefiles as sc
from spoutlab import cli

from spoutlab import foamfile
from spoutlab import spoutedbed
from spoutlab import bedmaps
from spoutlab import profilefeatures
from spoutlab.protocols import circulation as circ

# a cell holds particles in the time average when its mean solid fraction
# is above this (a fiftieth of a packed bed's): V_z is drawn there only
SOLID_PRESENT = 0.01
SYMMETRIC = 0.2     # mean |U_z(x) - U_z(-x)| below this fraction of mean |U_z|



def points(text):
    """'10000:2.0,26000:2.2' -> [(10000, 2.0), (26000, 2.2)]."""
    try:
        return [(int(p.split(':')[0]), float(p.split(':')[1])) for p in text.split(',')]
    except (IndexError, ValueError):
        raise argparse.ArgumentTypeError('expected N:U,N:U (particles:velocity), got %r' % text)


def parse(argv):
    p = cli.parser('velocityMaps', __doc__)
    p.add_argument('--points', type=points, default=[(10000, 2.0), (26000, 2.2)],
                   metavar='N:U,...', help='runs as particles:superficial velocity '
                                           '(default 10000:2.0,26000:2.2)')
    circ.run_options(p, kick='2.5,1.0', particles=False)
    o = vars(cli.parse(p, argv))
    o['n'] = None
    return o


class Fields:
    """The time-averaged cell fields of a finished run."""

    def __init__(self, work):
        time = foamfile.latest_time(work)
        self.g = spoutedbed.load(work)
        self.centres = foamfile.read_field(os.path.join(work, '0', 'C'))
        U = foamfile.read_field(os.path.join(work, time, 'UMean'))
        flux = foamfile.read_field(os.path.join(work, time, 'solidFluxMean'))
        phi = foamfile.read_field(os.path.join(work, time, 'solidFractionMean'))
        self.Uz = [u[2] for u in U]
        self.Vz = [f[2] / p if p > SOLID_PRESENT else float('nan') for f, p in zip(flux, phi)]
        self.bed, _ = spoutedbed.settled_bed(self.g, os.path.join(work, 'particles',
                                                                  'particles_0.vtp'))

    def rows(self):
        """Cell indices by row (z in mm rounded), each row ordered by x."""
        rows = {}
        for i, c in enumerate(self.centres):
            rows.setdefault(round(c[2] * 1000, 3), []).append(i)
        return {z: sorted(r, key=lambda i: self.centres[i][0]) for z, r in sorted(rows.items())}

    def profile_heights(self):
        """Rows every 5 cells (95 mm) from the fifth, up to the settled bed."""
        heights = sorted(self.rows())
        return [z for k, z in enumerate(heights) if k % 5 == 4 and z <= self.bed * 1000]


def features(f):
    """The paper's features of Figs 3-4 as (statement, measured, holds)."""
    g, c, rows = f.g, f.centres, f.rows()
    in_bed = [i for i in range(len(c)) if c[i][2] <= f.bed]
    top = max(in_bed, key=lambda i: f.Uz[i])
    x_top, z_top = round(c[top][0] * 1000, 1) + 0.0, c[top][2] * 1000   # no '-0'
    out = [('highest U_z just above the inlet', '%.1f m/s at x = %.0f mm, z = %.0f mm'
            % (f.Uz[top], x_top, z_top),
            abs(x_top) <= g.Wi / 2 and z_top <= 0.25 * f.bed * 1000)]
    # symmetry: each cell against its mirror cell in the same row
    diff, size = [], []
    for z, row in rows.items():
        if z > f.bed * 1000:
            continue
        by_x = {round(c[i][0] * 1000, 3): i for i in row}
        for x, i in by_x.items():
            if x > 0 and -x in by_x:
                diff.append(abs(f.Uz[i] - f.Uz[by_x[-x]]))
                size.append(0.5 * (abs(f.Uz[i]) + abs(f.Uz[by_x[-x]])))
    asym = sum(diff) / max(sum(size), 1e-30)
    out.append(('U_z symmetric about the axis', 'mean |U_z(x) - U_z(-x)| = %.2f of mean |U_z|'
                % asym, asym < SYMMETRIC))
    # particles: on the axis (over the slot), falling with height
    heights = f.profile_heights()

    def mean(values):
        values = [v for v in values if not math.isnan(v)]
        return sum(values) / len(values) if values else float('nan')

    axis, off, edge = [], [], []
    for z in heights:
        row = rows[z]
        axis.append(mean([f.Vz[i] for i in row if abs(c[i][0]) * 1000 <= g.Wi / 2]))
        off.append(mean([f.Vz[i] for i in row if abs(c[i][0]) * 1000 > g.Wi / 2]))
        edge.append(mean([f.Vz[i] for i in (row[0], row[-1])]))
    falls = len(heights) > 1 and profilefeatures.slope(heights, axis) < 0
    out.append(('V_z on the axis falls with height', ', '.join(
        '%.0f mm: %.2f' % hv for hv in zip(heights, axis)) + ' m/s', falls))
    out.append(('V_z falls with the distance from the axis', 'axis %s against the rest %s m/s'
                % ('/'.join('%.2f' % v for v in axis), '/'.join('%.2f' % v for v in off)),
                bool(heights) and all(a > b for a, b in zip(axis, off))))
    out.append(('V_z negative next to the walls and the base', 'outermost cells %s m/s'
                % '/'.join('%.3f' % v for v in edge),
                any(not math.isnan(v) for v in edge)
                and all(v < 0 for v in edge if not math.isnan(v))))
    return out


def draw(f, label, title):
    """The two maps and the profiles of one run."""
    g = f.g
    umax = max(abs(v) for v in f.Uz)
    bedmaps.field_map(g, f.centres, f.Uz, 'maps_%s_gasVelocity.png' % label,
                         'Time-averaged gas velocity U_z, %s (Fig 3)' % title,
                         'U_z [m/s]', -umax, umax, zmax=2 * f.bed)
    shown = [(c, v) for c, v in zip(f.centres, f.Vz) if not math.isnan(v)]
    bedmaps.field_map(g, [c for c, _ in shown], [v for _, v in shown],
                         'maps_%s_particleVelocity.png' % label,
                         'Time-averaged particle velocity V_z, %s (Fig 4)' % title,
                         'V_z [m/s]', -0.5, 0.5, zmax=2 * f.bed)
    csv = 'maps_%s_profiles.csv' % label
    rows = f.rows()
    with open(csv, 'w') as out:
        out.write('z [m],x [m],gas U_z [m/s],particle V_z [m/s]\n')
        for z in f.profile_heights():
            for i in rows[z]:
                out.write('%.4f,%.4f,%.5g,%.5g\n' % (z / 1000, f.centres[i][0], f.Uz[i], f.Vz[i]))
    curves = []
    for column, axes in ((3, 'x1y1'), (4, 'x1y2')):
        for z in f.profile_heights():
            curves.append('"%s" skip 1 using ($1 == %.4f ? $2 : 1/0):%d axes %s with linespoints '
                          'title "%s z = %.3f m"' % (csv, z / 1000, column, axes,
                                                     'U_z' if column == 3 else 'V_z', z / 1000))
    sc.plot('maps_%s_profiles.png' % label, '''
set title "Gas U_z (left axis) and particle V_z (right axis) across the width, %s"
set xlabel "x [m]"
set ylabel "gas U_z [m/s]"
set y2label "particle V_z [m/s]"
set ytics nomirror
set y2tics
set grid
set key outside right
set datafile separator ","
plot %s
''' % (title, ', \\\n     '.join(curves)), size=(1100, 600))
    return ['maps_%s_%s.png' % (label, n) for n in ('gasVelocity', 'particleVelocity',
                                                     'profiles')]


def main(argv):
    o = parse(argv)
    points = [('noplates_n%d_u%g' % (n, u), n, u) for n, u in o['points']]
    settled = {}

    def run(point):
        label, n, u = point
        return circ.run_point(dict(o, n=str(n)), label, u, ['plates=no'], settled)
    with concurrent.futures.ThreadPoolExecutor(o['jobs']) as pool:
        works = list(pool.map(run, points))
    lines = ['time-averaged velocities without draft plates (no-draft paper, Figs 3-4): %g s '
             'per run (broken through at %s m/s for %s s), averaged over the last %g s'
             % ((o['time'],) + tuple(o['kick'].split(',')) + (o['average'],))]
    runs = []      # what maps.txt says, for protocols/results (maps.json)
    for (label, n, u), work in zip(points, works):
        f = Fields(work)
        pictures = draw(f, label, '%d particles, u_s = %g m/s' % (n, u))
        lines.append('')
        lines.append('%s: %d particles, u_s = %g m/s, settled bed %.3f m (%s)'
                     % (label, n, u, f.bed, work))
        found = features(f)
        for statement, measured, holds in found:
            lines.append('  %-44s %s: %s' % (statement, 'yes' if holds else 'NO', measured))
        lines.append('  pictures: ' + ' '.join(pictures))
        runs.append({'label': label, 'particles': n, 'u_m_s': float('%g' % u),
                     'bed_height_m': float('%.3f' % f.bed), 'pictures': pictures,
                     'features': [{'feature': statement, 'holds': bool(holds),
                                   'measured': measured} for statement, measured, holds in found]})
    text = '\n'.join(lines) + '\n'
    sys.stdout.write(text)
    open('maps.txt', 'w').write(text)
    with open('maps.json', 'w') as out:
        json.dump({'settings': lines[0], 'runs': runs}, out, indent=1)
        out.write('\n')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
