"""parallelSpeedup: the draft-plate spouted bed serial and on P ranks, side by side.

A benchmark, not a test: it prints figures and asserts nothing about speed.
One bed (N particles, 2.0 m/s) is built and settled once by the case's own
Allrun (reused by later calls with the same N) and its spout developed for
--develop seconds (once, serially); then spoutFoam runs the same simulated
time from each of the two -- the break-through from the settled bed, and
the developed spout a long run spends most of its time in -- serially and on
each rank count asked for, one run after the other, and the figures are
printed side by side:

  wall seconds per simulated second (from OpenFOAM's ClockTime between the
  first and the last step, so start-up is left out), particle-steps per
  second (N x DEM steps / wall time), speed-up and parallel efficiency
  against the serial run, and the halo of each rank.

    bench/parallelSpeedup                      # 26 000 particles, 0.3 s, 1 and 2 ranks
    bench/parallelSpeedup --particles 3000 --time 0.15 --develop 0.5
    bench/parallelSpeedup --ranks 1 2 --dir /scratch/bench

Uses numpy-free Python 3; sources etc/bashrc itself.
"""
import argparse
import os
import re
import sys

from spoutlab import foamfile
from spoutlab.bench import spoutbench


def figures(log, n, dem_per_cfd):
    """Wall s per simulated s, particle-steps/s and the halo line of a log."""
    per_second, times = spoutbench.per_simulated_second(log)
    if per_second <= 0:
        sys.exit('parallelSpeedup: %s: the run took less than the 1 s that OpenFOAM\'s '
                 'ClockTime resolves; give a longer --time' % log)
    halo = ''
    for line in open(log):
        if line.startswith('Parallel coupling:'):
            halo = line.strip()
    dt = (times[-1] - times[0]) / (len(times) - 1)
    steps_per_second = dem_per_cfd / dt / per_second
    return per_second, n * steps_per_second, halo


def table(args, what, results):
    """Each rank count's figures beside the serial run's."""
    serial = results[1][0]
    print('\nparallelSpeedup: draft-plate bed, %d particles, 2.0 m/s, %s, %g s simulated'
          % (args.particles, what, args.time))
    print('%6s %16s %22s %9s %11s' % ('ranks', 'wall s / sim s', 'particle-steps / s',
                                      'speed-up', 'efficiency'))
    for ranks, (per_second, rate, _) in results.items():
        print('%6d %16.1f %22.3g %9.2f %10.0f %%' % (
            ranks, per_second, rate, serial / per_second, 100 * serial / per_second / ranks))
    for ranks, (_, _, halo) in results.items():
        if halo:
            print('  %d ranks: %s' % (ranks, halo))
    print(flush=True)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--particles', type=int, default=26000)
    parser.add_argument('--time', type=float, default=0.3, help='simulated seconds')
    parser.add_argument('--ranks', type=int, nargs='+', default=[1, 2])
    parser.add_argument('--develop', type=float, default=1.5,
                        help='simulated seconds of spouting before the second window '
                             '(0: the settled bed only; default %(default)s)')
    parser.add_argument('--dir', default=spoutbench.default_dir('parallel'))
    args = parser.parse_args(argv)
    if 1 not in args.ranks:
        args.ranks = [1] + args.ranks
    os.makedirs(args.dir, exist_ok=True)
    settled = spoutbench.settled_bed(args.dir, args.particles)
    interval = int(re.search(r'couplingInterval\s+(\d+)', open(
        os.path.join(settled, 'constant', 'couplingProperties')).read()).group(1))
    windows = [('from the settled bed', settled, None, 0.0, 'np%d')]
    if args.develop > 0:
        source = spoutbench.developed(settled, args.dir, args.develop)
        start = foamfile.latest_time(source)
        windows.append(('the developed spout, from %s s' % start, source, start, float(start),
                        'developed-np%d'))
    for what, source, start, t0, name in windows:
        results = {}
        for ranks in args.ranks:
            print('parallelSpeedup: %s, %d rank(s), %g s simulated ...'
                  % (what, ranks, args.time), flush=True)
            case = spoutbench.run(source, args.dir, ranks, t0 + args.time, name % ranks,
                                  start=start)
            results[ranks] = figures(os.path.join(case, 'log.spoutFoam'), args.particles,
                                     interval)
        table(args, what, results)


if __name__ == '__main__':
    main()
