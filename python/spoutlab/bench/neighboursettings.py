"""neighbourSettings: LIGGGHTS' neighbour skin and bin size on the spouting full bed.

A benchmark, not a test.  LIGGGHTS rebuilds its neighbour lists whenever a
particle has moved half the skin since the last build; a rebuild costs
several plain DEM steps, so the skin trades fewer rebuilds against more
pairs checked at every step, and the bin size sets how many bins each
rebuild searches.  This runs the full draft-plate bed at 2.0 m/s serially:

  1. the settled bed (made once, shared with parallelSpeedup);
  2. the spout developed from it to --develop seconds, written once and
     reused;
  3. from there, --window simulated seconds for every skin / bin pair, one
     after the other: CPU s per simulated s of the whole run and of the
     LIGGGHTS steps inside it, DEM steps per neighbour-list build.

It prints the largest particle speed of the developed bed and what it
moves per DEM step, beside each skin's half (the distance that triggers a
rebuild).  The case's in.contact takes its settings from the LIGGGHTS
variables skinRatio (skin / particle diameter) and binRatio (bin size /
neighbour cutoff, d + skin; 0.5 is LIGGGHTS' default).

    bench/neighbourSettings
    bench/neighbourSettings --skins 0.25 0.5 --bins 0.5 1 --window 0.15

CPU time (OpenFOAM's ExecutionTime, single-threaded) rather than wall time:
it resolves 0.01 s where ClockTime resolves 1 s, and it is what a shared
machine inflates least.  Numpy-free; sources etc/bashrc itself.
"""
import argparse
import math
import os
import re
import sys

from spoutlab import casefiles
from spoutlab import foamfile
from spoutlab.bench import spoutbench


def liggghts_loop(case):
    """Sum of LIGGGHTS' loop times (one per coupling step)."""
    return sum(float(m.group(1)) for m in re.finditer(
        r'^Loop time of ([0-9.e+-]+)', open(os.path.join(case, 'log.liggghts')).read(), re.M))


def builds(log):
    m = None
    for line in open(log):
        m = re.match(r'LIGGGHTS: (\d+) neighbour list builds in (\d+) DEM steps', line) or m
    if not m:
        sys.exit('neighbourSettings: no neighbour-build line in %s' % log)
    return int(m.group(1)), int(m.group(2))


def largest_speed(case, t):
    path = os.path.join(case, 'particles', 'particles_%s.vtp' % t)
    v = casefiles.read_vtp_array(path, 'velocity')
    return max(math.sqrt(v[i] ** 2 + v[i + 1] ** 2 + v[i + 2] ** 2) for i in range(0, len(v), 3))


def geometry(case):
    text = open(os.path.join(case, 'DEM', 'geometry.liggghts')).read()
    value = lambda name: float(re.search(r'^variable %s\s+equal\s+(\S+)' % name, text, re.M).group(1))
    return value('dp'), value('dt')


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--particles', type=int, default=26000)
    parser.add_argument('--develop', type=float, default=1.5,
                        help='simulated seconds of spouting before the windows')
    parser.add_argument('--window', type=float, default=0.1, help='simulated seconds per pair')
    parser.add_argument('--skins', type=float, nargs='+', default=[0.25, 0.375, 0.5, 0.625, 0.75],
                        help='skin / particle diameter')
    parser.add_argument('--bins', type=float, nargs='+', default=[0.5, 1.0],
                        help='bin size / neighbour cutoff')
    parser.add_argument('--dir', default=spoutbench.default_dir('parallel'))
    args = parser.parse_args(argv)
    os.makedirs(args.dir, exist_ok=True)
    settled = spoutbench.settled_bed(args.dir, args.particles)
    source = spoutbench.developed(settled, args.dir, args.develop)
    start = foamfile.latest_time(source)
    dp, dt = geometry(source)
    vmax = largest_speed(source, start)
    rows = []
    for skin in args.skins:
        for b in args.bins:
            name = 'neighbour-s%g-b%g' % (skin, b)
            print('neighbourSettings: skin %g d, bins %g cutoff ...' % (skin, b), flush=True)
            case = spoutbench.run(source, args.dir, 1, float(start) + args.window, name,
                                  start=start, variables={'skinRatio': skin, 'binRatio': b})
            log = os.path.join(case, 'log.spoutFoam')
            total, times = spoutbench.per_simulated_second(log, 'ExecutionTime')
            span = times[-1] - times[0]
            n, steps = builds(log)
            rows.append((skin, b, total, liggghts_loop(case) / span, steps / max(n, 1)))
    print('\nneighbourSettings: draft-plate bed, %d particles, 2.0 m/s, from %s s for %g s'
          % (args.particles, start, args.window))
    print('largest particle speed %.2f m/s: %.2f mm per DEM step (dt %g s, d %g mm)'
          % (vmax, 1e3 * vmax * dt, dt, 1e3 * dp))
    print('%8s %8s %10s %10s %14s %16s %18s' % (
        'skin/d', 'skin/2', 'bin/cutoff', 'bin [mm]', 'CPU s / sim s', 'LIGGGHTS s / sim s',
        'DEM steps / build'))
    for skin, b, total, dem, per_build in rows:
        print('%8g %6.2f mm %10g %10.1f %14.1f %16.1f %18.2f' % (
            skin, 0.5e3 * skin * dp, b, 1e3 * b * dp * (1 + skin), total, dem, per_build))


if __name__ == '__main__':
    main()
