"""The spout along its height (draft-plate paper section 4.2, Fig 4: the
particle velocity in the spout falls with height, slugging near u_ms;
section 4.7, Fig 12: h in the spout falls with height and is lower next
to the draft plates).

Each run (RUNS, or those --runs names) is one case in runs/height_<name>/,
made as a point of `circulation velocity` (break through at --kick, then
u_s to --time) with the fields written every --write seconds.  Over the
last --average seconds, per gas-cell row in the spout (between the plates'
inner faces, He < z < Hd) and per column across it:
  particle velocity   mean(solid flux) / mean(solid fraction), averaged
                      by spoutFoam every time step (fieldAverage)
  gas velocity        mean interstitial U, every time step
  voidage             mean voidage, every time step
  slip Re             eps rho |U - Us| d / mu from each write time's cell
                      fields, weighted by the cell's solid fraction then
  h                   the heat coupling's cell h, weighted alike (runs
                      with heat only)
and the slugs: the axis probe at mid-plate height (every 5 steps) counts
a slug each time the voidage there falls below SLUG_VOIDAGE and rises
back above it.

Results: spoutHeight.csv (every run, row and column), spoutHeight.txt
(slopes along the height, h beside the plates over h on the axis, slugs),
spoutHeight.png (along the axis, every run), spoutHeight_<run>.png (across
the spout at Fig 4's heights), and spoutHeight.json (read by
protocols/results).
"""
import argparse
import collections
import json
import math
import os
import sys

from spoutlab import casefiles as sc
from spoutlab import caserun
from spoutlab import cli
from spoutlab import foamfile
from spoutlab import profilefeatures
from spoutlab import spoutedbed
from spoutlab import spoutheat
from spoutlab.protocols import circulation

# One run: its name (runs/height_<name>), the suffix of its keys in
# docs/results.csv (spout.dVp_dz_<key>), u_s [m/s], what it is, the
# spoutedBedDict overrides and the entries (file, key, value) set in the
# copy's other dictionaries; each variant changes one thing
Run = collections.namedtuple('Run', 'name key u what overrides entries')
COUPLING = 'constant/couplingProperties'
CELL_CENTRE = [(COUPLING, 'dragVelocity', 'cellCentre')]
RUNS = [
    Run('u1.4', '1.4', 1.4, "Fig 4's point (1.12 u_ms in the paper), isothermal", [], []),
    Run('u1.25', '1.25', 1.25, "the paper's u_ms (1.04 of ours), where it sees slugs", [], []),
    Run('u2_hot', '2.0', 2.0, "Fig 12's point: inlet air at 150 C", ['heat=yes'], []),
    Run('u1.4_cellCentre', '1.4.cellCentre', 1.4,
        'drag from the cell-centre U (dragVelocity cellCentre, the default before flux)', [],
        CELL_CENTRE),
    Run('u2_hot_cellCentre', '2.0.cellCentre', 2.0, "Fig 12's point, drag from the cell-centre U",
        ['heat=yes'], CELL_CENTRE),
    Run('u1.4_smooth', '1.4.smooth', 1.4, "Gidaspow's switch smooth (Huilin-Gidaspow blend)",
        [], [(COUPLING, 'GidaspowProps/switch', 'smooth')]),
    Run('u1.4_refine2', '1.4.refine2', 1.4,
        'gas cells 5.5 x 9.5 mm, the time step halved to 1.5e-4 s',
        ['refine=2', 'dtDem=1.5e-4'], [('system/controlDict', 'deltaT', '1.5e-4')]),
]
SLUG_VOIDAGE = 0.6   # a dense plug on the spout axis: a packed bed is 0.415


def run_names(text):
    names = text.split(',')
    unknown = [n for n in names if n not in [r.name for r in RUNS]]
    if unknown:
        raise argparse.ArgumentTypeError('no run %s (one of %s)' % (
            ', '.join(unknown), ', '.join(r.name for r in RUNS)))
    return names


def parse(argv):
    p = cli.parser('spoutHeight', __doc__)
    p.add_argument('--runs', type=run_names, default=[r.name for r in RUNS], metavar='NAME,...',
                   help='which runs (default all: %s)' % ','.join(r.name for r in RUNS))
    p.add_argument('--write', type=float, default=0.05, metavar='DT',
                   help='field output interval [s] (default %(default)s)')
    circulation.run_options(p)
    p.set_defaults(time=5.0, average=3.0)
    o = vars(cli.parse(p, argv))
    if not 0 < o['average'] < o['time']:
        p.error('--average must be positive and shorter than --time')
    return o


def run_all(o, runs):
    """Every run as a point of circulation's (finished runs are kept), the
    fields written every --write seconds."""
    write = [('system/controlDict', 'writeInterval', '%g' % o['write'])]
    circulation.run_all(o, [('height_' + r.name, r.u, r.overrides, r) for r in runs],
                        lambda p: p[3].entries + write)


def spout_cells(g, centres):
    """{z [mm]: [(x [mm], cell)]} of the gas cells between the plates' inner
    faces with He < z < Hd, each row sorted across."""
    rows = {}
    for i, (x, _, z) in enumerate(centres):
        X, Z = 1000 * x, 1000 * z
        if abs(X) < g.Wd / 2 and g.He < Z < g.Hd:
            rows.setdefault(round(Z, 3), []).append((round(X, 3), i))
    return {z: sorted(cells) for z, cells in sorted(rows.items())}


def on_axis(g, x):
    """The column(s) on the spout axis (x in mm): the centre one, or the two
    either side of the axis on an even number of columns."""
    return abs(x) <= g.dx / 2 + 1e-6


def by_plate(g, x):
    """The spout's outermost columns, beside the plates' inner faces."""
    return abs(x) > g.Wd / 2 - g.dx + 1e-6


def window_times(case, average):
    """Names of the write times (t > 0) in the last `average` seconds."""
    times = foamfile.time_dirs(case)
    end = times[-1][0]
    return [n for t, n in times if t >= end - average - 1e-9 and t > 0]


class Sums:
    """Weighted sums of a cell's (or pooled cells') quantities: particle
    velocity weighted by the mean solid fraction; Vs, the particle velocity
    again but from the write times (to compare parts of the window), slip
    Re and h by each write time's solid fraction; gas velocity and voidage
    unweighted."""
    NAMES = ('Vp', 'Ug', 'eps', 'Re', 'h', 'Vs')

    def __init__(self):
        self.s = dict.fromkeys(self.NAMES, 0.0)
        self.w = dict.fromkeys(self.NAMES, 0.0)

    def add(self, name, value, weight=1.0):
        self.s[name] += weight * value
        self.w[name] += weight

    def pool(self, other):
        for n in self.NAMES:
            self.s[n] += other.s[n]
            self.w[n] += other.w[n]
        return self

    def mean(self, name):
        return self.s[name] / self.w[name] if self.w[name] > 0 else float('nan')


def cell_sums(case, g, names):
    """{(z, x): Sums} of the spout's cells: particle velocity, gas
    velocity and voidage from spoutFoam's time means of every step (written
    at the last of the write times `names`); slip Re, eps rho |U - Us| d /
    mu, h (runs with heat) and Vs from the cell fields at `names`."""
    rows = spout_cells(g, foamfile.read_field(os.path.join(case, '0', 'C')))
    mean = {f: foamfile.read_field(os.path.join(case, names[-1], f + 'Mean'))
            for f in ('solidFlux', 'solidFraction', 'U', 'voidfraction')}
    rho, mu, d = g.gas['rho'], g.gas['mu'], g.particles['dp'] * 1e-3
    cells = {(z, x): (i, Sums()) for z, row in rows.items() for x, i in row}
    for i, s in cells.values():
        phi = mean['solidFraction'][i]
        if phi > 1e-9:
            s.add('Vp', mean['solidFlux'][i][2] / phi, phi)
        s.add('Ug', mean['U'][i][2])
        s.add('eps', mean['voidfraction'][i])
    for name in names:
        def field(f):
            return foamfile.read_field(os.path.join(case, name, f))
        U, Us, eps, phi = field('U'), field('Us'), field('voidfraction'), field('solidFraction')
        hp = field('hp') if g.heat else None
        for i, s in cells.values():
            if phi[i] <= 1e-9:
                continue          # no particle in the cell at this time
            slip = math.sqrt(sum((a - b) ** 2 for a, b in zip(U[i], Us[i])))
            s.add('Re', eps[i] * rho * slip * d / mu, phi[i])
            s.add('Vs', Us[i][2], phi[i])
            if hp is not None:
                s.add('h', hp[i], phi[i])
    return {key: s for key, (_, s) in cells.items()}


def pooled(cells, keys):
    out = Sums()
    for k in keys:
        out.pool(cells[k])
    return out


def axis_rows(g, cells, where=on_axis):
    """[(z [m], Sums)] along the spout axis (or the columns where(g, x)
    picks), bottom to top."""
    return [(z / 1000, pooled(cells, [k for k in cells if k[0] == z and where(g, k[1])]))
            for z in sorted({z for z, _ in cells})]


def paper_rows(g, cells):
    """[(z/R_d, {x [mm]: Sums})] across the spout at the heights of Fig 4,
    each the nearest cell row."""
    heights = sorted({z for z, _ in cells})
    out = []
    for h in profilefeatures.HEIGHTS:
        z = min(heights, key=lambda zz: abs(zz - h * g.Wd / 2))
        out.append((h, {x: s for (zz, x), s in cells.items() if zz == z}))
    return out


def axis_slope(rows, name, lo, hi):
    """Least-squares d(quantity)/dz [per m] along the axis over lo..hi [m]."""
    pts = [(z, s.mean(name)) for z, s in rows if lo <= z <= hi and not math.isnan(s.mean(name))]
    if len(pts) < 2:
        return float('nan')
    return profilefeatures.slope([p[0] for p in pts], [p[1] for p in pts])


def plate_over_axis(g, across, name, band=(0, math.inf)):
    """The quantity in the columns beside the plates over its value on the
    axis, each averaged over the paper's heights within band (z/R_d)."""
    across = [(h, cols) for h, cols in across if band[0] - 1e-6 <= h <= band[1] + 1e-6]
    plate = pooled_columns(g, across, name, lambda x: by_plate(g, x))
    axis = pooled_columns(g, across, name, lambda x: on_axis(g, x))
    return plate / axis if axis else float('nan')


def pooled_columns(g, across, name, which):
    values = [pooled(cols, [x for x in cols if which(x)]).mean(name) for _, cols in across]
    values = [v for v in values if not math.isnan(v)]
    return sum(values) / len(values) if values else float('nan')


def slugs(case, average, dense=SLUG_VOIDAGE, clear=SLUG_VOIDAGE + 0.1):
    """Slugs through the axis probe at mid-plate height over the window: one
    begins when the voidage there falls below `dense` and ends when it rises
    above `clear` (the band keeps a wavering plug one slug).  Returns (count,
    per second, share of the time in a slug, mean voidage)."""
    _, rows = sc.read_function_object(case, 'spoutFlux', 'voidfraction')
    end = rows[-1][0]
    series = [(r[0], r[1]) for r in rows if r[0] >= end - average - 1e-9]
    count, inside, time_in = 0, False, 0.0
    for (t0, e0), (t1, _) in zip(series, series[1:]):
        if not inside and e0 < dense:
            inside, count = True, count + 1
        elif inside and e0 > clear:
            inside = False
        if inside:
            time_in += t1 - t0
    span = series[-1][0] - series[0][0]
    return count, count / span, time_in / span, sum(e for _, e in series) / len(series)


def analyse(o, r):
    """One run's profiles and numbers."""
    work = os.path.join('runs', 'height_' + r.name)
    g = spoutedbed.load(work)
    names = window_times(work, o['average'])
    if len(names) < 2:
        sys.exit('spoutHeight: %s: %d write time(s) in the last %g s: the window needs two or '
                 'more (--write well under --average)' % (work, len(names), o['average']))
    cells = cell_sums(work, g, names)
    axis = axis_rows(g, cells)
    across = paper_rows(g, cells)
    Rd = g.Wd / 2e3
    lo, hi = profilefeatures.HEIGHTS[0] * Rd, profilefeatures.HEIGHTS[-1] * Rd
    fit = {n: axis_slope(axis, n, lo, hi) for n in Sums.NAMES}
    # the same slope over each half of the window, and over the spout's width
    halves = [axis_slope(axis_rows(g, cell_sums(work, g, part)), 'Vs', lo, hi)
              for part in (names[:len(names) // 2], names[len(names) // 2:])]
    across_width = axis_slope(axis_rows(g, cells, lambda g, x: True), 'Vp', lo, hi)
    band = [s.mean('Vp') for z, s in axis if lo <= z <= hi]
    count, rate, share, eps_probe = slugs(work, o['average'])
    return {'run': r.name, 'key': r.key, 'what': r.what, 'u_m_s': r.u, 'samples': len(names),
            'heat': g.heat,
            'axis': axis, 'across': across, 'Rd_m': Rd,
            'dVp_dz': fit['Vp'], 'dUg_dz': fit['Ug'], 'deps_dz': fit['eps'],
            'dRe_dz': fit['Re'], 'dh_dz': fit['h'], 'dVp_dz_halves': halves,
            'dVp_dz_width': across_width,
            'Vp_change': fit['Vp'] * (hi - lo) / (sum(band) / len(band)),
            'h_plate_over_axis': plate_over_axis(g, across, 'h', spoutheat.BAND),
            'h_plate_over_axis_all': plate_over_axis(g, across, 'h'),
            'Re_plate_over_axis': plate_over_axis(g, across, 'Re', spoutheat.BAND),
            'slugs': count, 'slugs_per_s': rate, 'slug_share': share,
            'eps_probe': eps_probe, 'lost': caserun.lost_particles(work),
            'wall_s': caserun.wall_time(work)}


def write_csv(analysed, path='spoutHeight.csv'):
    with open(path, 'w') as f:
        f.write('run,u_s [m/s],profile,z/R_d,x/R_d,particle velocity [m/s],'
                'gas velocity [m/s],voidage,slip Re,h [W/m2/K]\n')
        for a in analysed:
            Rd = a['Rd_m']
            rows = [('axis', z / Rd, 0.0, s) for z, s in a['axis']]
            rows += [('across', h, x / (1000 * Rd), s)
                     for h, cols in a['across'] for x, s in sorted(cols.items())]
            for kind, z, x, s in rows:
                f.write('%s,%g,%s,%.3f,%.3f,%s\n' % (
                    a['run'], a['u_m_s'], kind, z, x,
                    ','.join('%.6g' % s.mean(n) for n, _, _ in PLOTS)))


PLOTS = [('Vp', 'particle velocity [m/s]', 6), ('Ug', 'gas velocity [m/s]', 7),
         ('eps', 'voidage', 8), ('Re', 'slip Re', 9), ('h', 'h [W/m^2K]', 10)]


def plot(analysed):
    """spoutHeight.png: each quantity along the axis, one line per run."""
    panels = []
    for n, label, col in PLOTS:
        runs = [a['run'] for a in analysed if n != 'h' or a['heat']]
        if runs:
            panels.append('set ylabel "%s"\nplot %s' % (label, ', '.join(
                '"spoutHeight.csv" skip 1 using (strcol(3) eq "axis" && strcol(1) eq "%s" '
                '? $4 : 1/0):%d with lines lw 2 title "%s" noenhanced' % (r, col, r)
                for r in runs)))
    return sc.plot('spoutHeight.png', '''
set multiplot layout %d,1 title "Time-averaged along the spout axis (plates from He to Hd)"
set grid
set datafile separator ","
set xlabel "z/R_d"
set key outside right
%s
unset multiplot
''' % (len(panels), '\n'.join(panels)), size=(1000, 300 * len(panels)))


def plot_across(a):
    """spoutHeight_<run>.png: the particle velocity, and h (or the voidage
    without heat) across the spout, one line per height of Fig 4."""
    panels = []
    for n, label, col in [PLOTS[0], PLOTS[4] if a['heat'] else PLOTS[2]]:
        panels.append('set ylabel "%s"\nplot %s' % (label, ', '.join(
            '"spoutHeight.csv" skip 1 using (strcol(3) eq "across" && strcol(1) eq "%s" && '
            'abs($4 - %.3f) < 1e-3 ? $5 : 1/0):%d with linespoints lw 2 title "z/R_d %.1f"'
            % (a['run'], h, col, h) for h, _ in a['across'])))
    return sc.plot('spoutHeight_%s.png' % a['run'], '''
set multiplot layout 2,1 title "Across the spout, %s (draft plates at x/R_d = +-1)"
set grid
set datafile separator ","
set xlabel "x/R_d"
set key outside right
%s
unset multiplot
''' % (a['run'].replace('_', '\\\\_'), '\n'.join(panels)), size=(1000, 700))


KEPT = ('run', 'key', 'what', 'u_m_s', 'samples', 'heat', 'dVp_dz', 'dVp_dz_halves',
        'dVp_dz_width', 'dUg_dz', 'deps_dz', 'dRe_dz',
        'dh_dz', 'Vp_change', 'h_plate_over_axis', 'h_plate_over_axis_all',
        'Re_plate_over_axis', 'slugs',
        'slugs_per_s', 'slug_share', 'eps_probe', 'lost', 'wall_s')


def report(analysed, o):
    lo, hi = profilefeatures.HEIGHTS[0], profilefeatures.HEIGHTS[-1]
    text = ['the spout along its height (draft-plate paper Figs 4 and 12): %g s per run, '
            'averaged over the last %g s; slopes least-squares along the axis over z/R_d '
            '%.1f-%.1f; a slug: axis voidage at mid-plate below %.2f until above %.2f'
            % (o['time'], o['average'], lo, hi, SLUG_VOIDAGE, SLUG_VOIDAGE + 0.1)]
    for a in analysed:
        text += ['', '%s (u_s = %g m/s): %s; %d write times; %d particles lost; spoutFoam '
                 '%.2f h' % (a['run'], a['u_m_s'], a['what'], a['samples'], a['lost'],
                             a['wall_s'] / 3600),
                 '  along the axis, per m: dVp/dz %+.3f 1/s (%+.0f %% of the mean over the '
                 'range; %+.3f and %+.3f over the halves of the window; %+.3f over the '
                 'spout\'s width), dUg/dz %+.2f 1/s, deps/dz %+.3f, dRe/dz %+.0f'
                 % (a['dVp_dz'], 100 * a['Vp_change'], a['dVp_dz_halves'][0],
                    a['dVp_dz_halves'][1], a['dVp_dz_width'], a['dUg_dz'], a['deps_dz'],
                    a['dRe_dz'])]
        if a['heat']:
            text.append('  h: dh/dz %+.1f W/m2/K per m; beside the plates / on the axis %.3f '
                        'over Fig 12\'s z/R_d %g-%g, %.3f over all Fig 4\'s heights'
                        % ((a['dh_dz'], a['h_plate_over_axis']) + spoutheat.BAND
                           + (a['h_plate_over_axis_all'],)))
        text.append('  slip Re beside the plates / on the axis %.3f (Fig 12\'s heights); '
                    '%d slugs (%.2f per s), '
                    '%.0f %% of the time; mean axis voidage at mid-plate %.3f'
                    % (a['Re_plate_over_axis'], a['slugs'], a['slugs_per_s'],
                       100 * a['slug_share'], a['eps_probe']))
    write_csv(analysed)
    plots = [plot(analysed)] + [plot_across(a) for a in analysed]
    text += ['', 'data: spoutHeight.csv; plots: ' + sc.plots_text(plots)]
    out = '\n'.join(text) + '\n'
    sys.stdout.write(out)
    open('spoutHeight.txt', 'w').write(out)
    with open('spoutHeight.json', 'w') as f:
        json.dump({'time': o['time'], 'average': o['average'],
                   'runs': [{k: None if isinstance(a[k], float) and math.isnan(a[k]) else a[k]
                             for k in KEPT} for a in analysed]}, f, indent=1)
        f.write('\n')


def main(argv):
    o = parse(argv)
    runs = [r for r in RUNS if r.name in o['runs']]
    run_all(o, runs)
    report([analyse(o, r) for r in runs], o)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
