#!/usr/bin/env python3
"""weakScaling: how the coupling's neighbour exchange grows with the rank
count when each rank keeps the same work (weak scaling).

A benchmark, not a test: it prints figures and asserts nothing. For each
rank count P the fluidisedColumn bed of bench/couplingOverhead (N particles
in a 120 mm column, settled once) is repeated P times side by side
(bench/in.widen) in a column P times as wide (minFluidisation's mesh with
P times the cells across), cut into P x-slabs of one bed each, and spoutFoam
runs a few CFD steps at a constant inlet velocity on P ranks. With --grid
the beds form a grid of Px x Py in x and y instead (rank_grid: 2 x 2,
4 x 2, ..., 8 x 8), cut by OpenFOAM's simple method into Px x Py boxes of
one bed each, so that a rank inside the grid has eight neighbours, the four
diagonal ones included. More ranks than cores are oversubscribed: their
wall times mean nothing, so the figures are what each rank sends and
receives per CFD step -- the solver's own count of the halo messages and
bytes (DemCoupling's last log lines) and the halo cells each rank holds. If
the exchange is neighbour-to-neighbour, an interior rank's figures do not
change with P. LIGGGHTS' own ghost-atom exchange (a spatial decomposition,
neighbour-to-neighbour by design) is not counted.

    bench/weakScaling                          # 1 2 4 8 16 32 64 ranks
    bench/weakScaling --ranks 1 2 4 --steps 5
    bench/weakScaling --grid                   # 1x1 2x1 2x2 4x2 4x4 8x4 8x8

Python 3 standard library only; uses bench/couplingOverhead's functions.
"""
import argparse
import math
import os
import re
import shutil
import sys

from spoutlab import bench
from spoutlab.bench import couplingoverhead as co

HERE = os.path.join(bench.REPO, 'bench')   # its LIGGGHTS inputs
POSITIONS = os.path.join(HERE, 'in.positions')
WIDEN = os.path.join(HERE, 'in.widen')


def bed_data(base, dem, env):
    """base/bed.data: the settled one-column bed as a LIGGGHTS data file
    (id, type 1, diameter, density 1 -- in.widen sets the density --, x y z),
    from bench/in.positions' dump (id x y z radius)."""
    path = os.path.join(base, 'bed.data')
    if os.path.isfile(path) and os.path.getmtime(path) > os.path.getmtime(
            os.path.join(dem, 'settled.restart')):
        return path
    dump = os.path.join(base, 'positions.txt')
    co.run(['liggghts', '-in', POSITIONS, '-var', 'inputs', co.INPUTS, '-var', 'dem', dem,
            '-var', 'out', dump, '-echo', 'none', '-log', 'none'],
           base, env, 'log.positions', 'LIGGGHTS in.positions')
    rows = [line.split() for line in open(dump)]
    start = next(k for k, r in enumerate(rows) if r[:2] == ['ITEM:', 'ATOMS']) + 1
    box = rows[start - 4:start - 1]   # the three lines after ITEM: BOX BOUNDS
    atoms = rows[start:]
    with open(path, 'w') as f:
        f.write('settled fluidisedColumn bed (bench/weakScaling)\n\n%d atoms\n2 atom types\n\n'
                % len(atoms))
        for (lo, hi), axis in zip(box, 'xyz'):
            f.write('%s %s %slo %shi\n' % (lo, hi, axis, axis))
        f.write('\nAtoms\n\n')
        for tag, x, y, z, r in atoms:
            f.write('%s 1 %.12g 1 %s %s %s\n' % (tag, 2 * float(r), x, y, z))
    return path


def rank_grid(ranks, grid=False):
    """(Px, Py): the beds' grid in x and y for ranks ranks, Px * Py = ranks.
    Without grid one row of ranks (x-slabs); with it Py the largest divisor
    of ranks not above its square root (as square as ranks allows: 8 is
    4 x 2, 64 is 8 x 8, a prime p is p x 1)."""
    if not grid:
        return ranks, 1
    rows = max(d for d in range(1, math.isqrt(ranks) + 1) if ranks % d == 0)
    return ranks // rows, rows


def interior_ranks(grid):
    """The ranks with a neighbour on both sides in every direction the grid
    is cut, numbered as OpenFOAM's simple method numbers its boxes (x
    fastest: rank i + Px j for the box (i, j), as the halo cells of 4 x 4 and
    8 x 4 runs show; decomposeSlabs' x-slabs likewise); none if none is."""
    px, py = grid
    inner = lambda k, n: n == 1 or 0 < k < n - 1
    return [i + px * j for j in range(py) for i in range(px) if inner(i, px) and inner(j, py)]


def widened_bed(work, data, grid, width, depth, env):
    """work/DEM/settled.restart: grid (Px, Py) beds, Px side by side in x,
    Py rows of them in y."""
    dem = os.path.join(work, 'DEM')
    os.makedirs(dem, exist_ok=True)
    co.run(['liggghts', '-in', WIDEN, '-var', 'inputs', co.INPUTS, '-var', 'data', data,
            '-var', 'copies', str(grid[0]), '-var', 'rows', str(grid[1]),
            '-var', 'W', '%.12g' % width, '-var', 'L', '%.12g' % depth,
            '-var', 'out', os.path.join(dem, 'settled.restart'),
            '-echo', 'none', '-log', 'none', '-screen', os.path.join(dem, 'log.widen')],
           work, env, 'log.widen.out', 'LIGGGHTS in.widen')
    return dem


HALO_CELLS = re.compile(r'^Parallel coupling: .*halo cells per rank \(reach \S+ m\):([\d ]+)$')
TRAFFIC = re.compile(r'\(([-+.\deE]+), ([-+.\deE]+)\)')


def exchange(log):
    """Per rank: halo cells, messages and kB per CFD step (serial: none)."""
    cells, traffic = [], []
    for line in open(log, errors='replace'):
        m = HALO_CELLS.match(line.strip())
        if m:
            cells = [int(c) for c in m.group(1).split()]
        elif line.startswith('Halo exchange per step'):
            traffic = [(float(a), float(b)) for a, b in TRAFFIC.findall(line)]
    return cells, traffic


def summary(grid, cells, traffic):
    """The row of one grid (Px, Py): the most any rank sends and holds, and
    the mean over the interior ranks (interior_ranks; None if none)."""
    interior = [traffic[k] for k in interior_ranks(grid) if k < len(traffic)]
    mean = lambda values: sum(values) / len(values) if values else None
    return {
        'halo_cells_max': max(cells) if cells else 0,
        'messages_max': max((m for m, _ in traffic), default=0.0),
        'kB_max': max((b for _, b in traffic), default=0.0),
        'messages_interior': mean([m for m, _ in interior]),
        'kB_interior': mean([b for _, b in interior])}


def options(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    p.add_argument('--ranks', type=int, nargs='+', default=[1, 2, 4, 8, 16, 32, 64],
                   metavar='P', help='rank counts, one bed per rank (default 1 2 4 ... 64)')
    p.add_argument('--particles', type=int, default=3000, metavar='N',
                   help='particles per rank (default 3000)')
    p.add_argument('--steps', type=int, default=10, metavar='S',
                   help='CFD steps per run (default 10)')
    p.add_argument('--grid', action='store_true',
                   help='the beds in a grid of ranks in x and y, as square as the rank '
                        'count allows (2x2, 4x2, ..., 8x8), instead of one row of x-slabs')
    p.add_argument('--velocity', type=float, default=2.5, metavar='U',
                   help='superficial inlet velocity [m/s] (default 2.5: bubbling)')
    p.add_argument('--dir', metavar='DIR',
                   help='work directory (default $SPOUTLAB_BUILD/bench/weak)')
    a = p.parse_args(argv)
    if min(a.ranks) < 1 or a.steps < 1 or a.velocity <= 0:
        p.error('expected rank counts and --steps of 1 or more and a positive --velocity')
    if not 1 <= a.particles <= co.MAX_PARTICLES:
        p.error('--particles %d: expected 1 ... %d' % (a.particles, co.MAX_PARTICLES))
    return a


def main(argv=None):
    sys.stdout.reconfigure(line_buffering=True)
    a = options(argv)
    try:
        env = co.environment()
        co.check_programs(env, a.ranks)
        work = os.path.abspath(a.dir or os.path.join(env['SPOUTLAB_BUILD'], 'bench', 'weak'))
        base = os.path.join(work, 'n%d' % a.particles)
        os.makedirs(base, exist_ok=True)
        data = bed_data(base, co.settle(base, a.particles, env), env)
        cores = os.cpu_count() or 1
        rows = []
        for ranks in sorted(set(a.ranks)):
            grid = rank_grid(ranks, a.grid)
            run_dir = os.path.join(base, 'grid%dx%d' % grid if a.grid else 'np%d' % ranks)
            shutil.rmtree(run_dir, ignore_errors=True)
            os.makedirs(run_dir)
            width, depth = co.widen_mesh(os.path.join(co.CASE, 'system', 'blockMeshDict'),
                                         *grid, write=False)
            dem = widened_bed(run_dir, data, grid, width, depth, env)
            print('weakScaling: %d rank(s) (%d x %d), %d particles, %.2f x %.2f m, %d CFD '
                  'steps%s' % (ranks, grid[0], grid[1], ranks * a.particles, width, depth,
                               a.steps, ' (oversubscribed)' if ranks > cores else ''))
            case, delta_t, interval, cells, _ = co.prepare_case(
                run_dir, dem, ranks * a.particles, a.steps, a.velocity, env, ranks, grid)
            res = co.coupled(case, env, ranks)
            halo, traffic = exchange(os.path.join(case, 'log.spoutFoam'))
            row = summary(grid, halo, traffic)
            row.update(ranks=ranks, grid=grid, particles=ranks * a.particles, cells=cells,
                       per_step=res['loop_wall'] / res['cfd_steps'],
                       timed=ranks <= cores and res['others'] < 0.15)
            rows.append(row)
        print(report(a, rows, cores))
    except co.BenchError as err:
        print('weakScaling: %s' % err, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    return 0


def report(a, rows, cores):
    lines = ['', 'weakScaling: fluidised column, %d particles and %d x 2 x 40 gas cells per '
             'rank, %s, %g m/s, %d CFD steps; the coupling\'s halo exchange per rank and CFD '
             'step' % (a.particles, rows[0]['cells'] // (80 * rows[0]['ranks']),
                       'a grid of ranks in x and y' if a.grid else 'x-slabs', a.velocity,
                       a.steps),
             '%6s %6s %10s %7s %11s %17s %14s %17s %11s %14s' % (
                 'ranks', 'grid', 'particles', 'cells', 'halo cells', 'messages, max',
                 'kB, max', 'messages, inner', 'kB, inner', 'wall s / step')]
    inner = lambda value: '-' if value is None else '%.1f' % value
    for r in rows:
        lines.append('%6d %6s %10d %7d %11d %17.1f %14.1f %17s %11s %14s' % (
            r['ranks'], '%dx%d' % r['grid'], r['particles'], r['cells'], r['halo_cells_max'],
            r['messages_max'], r['kB_max'], inner(r['messages_interior']),
            inner(r['kB_interior']),
            '%.3f' % r['per_step'] if r['timed'] else '(oversubscribed)'
            if r['ranks'] > cores else '(busy machine)'))
    lines.append('inner: the mean over the ranks with a neighbour on both sides in every '
                 'direction cut (-: none); halo cells: the most any rank holds')
    return '\n'.join(lines)


if __name__ == '__main__':
    sys.exit(main())
