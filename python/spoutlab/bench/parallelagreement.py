"""parallelAgreement: is a run on P ranks the same physics as a serial one, over seconds?

A benchmark-style check, not a test (each run is minutes of the full bed).
The first coupling step of a serial and a 2-rank run agrees to round-off
(ctest case.parallelCoupling), but a granular bed is chaotic: round-off
differences grow, and after a second the particles are elsewhere.  What
must agree is the statistics.  This runs the draft-plate bed's own Allrun
three times at the same superficial velocity:

  serial, seed A      the case as it is (insertionSeed A)
  serial, seed B      another random bed (insertionSeed B): how far two
                      equally valid serial runs differ
  P ranks, seed A     the first run's settled bed on P ranks

and prints the time-averaged pressure drop and circulation rate W_s of
each (the case's summary.txt, averaged over the last --average seconds),
the serial/parallel difference beside the seed-to-seed difference, and
whether the first lies within the second.  One pair of seeds is one
sample of the scatter, so the pressure drop's averages also get a standard
error from the means of 0.3 s blocks: what the averaging window alone
would make two runs differ by.

    bench/parallelAgreement                        # 26 000 particles, 2.0 m/s, 3 s each
    bench/parallelAgreement --time 4 --average 2.5 --ranks 2

Finished runs are kept (a second call reuses them); numpy-free.
"""
import argparse
import csv
import math
import os
import re
import shutil
import sys

from spoutlab.bench import spoutbench


def case_run(base, name, options, settled=None):
    """The case's Allrun with options in base/name (kept once finished);
    the settled bed copied from settled first, if given."""
    case = os.path.join(base, name)
    summary = os.path.join(case, 'summary.txt')
    record = os.path.join(case, 'bench.options')   # not log.*: Allrun takes those for results
    if os.path.isfile(summary) and os.path.isfile(record) and \
            open(record).read().strip() == ' '.join(options):
        return summary
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(spoutbench.CASE, case, ignore=shutil.ignore_patterns(
        'runs', 'processor*', 'DEM', 'postProcessing', 'log.*', '[0-9]*', '*.png', '*.csv'))
    shutil.copytree(os.path.join(spoutbench.CASE, '0.orig'), os.path.join(case, '0.orig'))
    if settled:
        os.makedirs(os.path.join(case, 'DEM'))
        shutil.copy(settled, os.path.join(case, 'DEM', 'settled.restart'))
    print('parallelAgreement: %s: ./Allrun %s ...' % (name, ' '.join(options)), flush=True)
    spoutbench.shell('./Allrun %s' % ' '.join(options), case, os.path.join(case, 'bench.out'))
    with open(record, 'w') as f:
        f.write(' '.join(options) + '\n')
    return summary


def figures(summary):
    """Time-averaged pressure drop [Pa] and W_s [kg/s] of a summary.txt."""
    text = open(summary).read()
    dp = re.search(r'averaged over the last [0-9.]+ s: ([0-9.e+-]+) Pa', text)
    ws = re.search(r'circulation rate W_s \(eq 14, z = \d+ mm\): ([0-9.e+-]+) kg/s', text)
    if not dp or not ws:
        sys.exit('parallelAgreement: %s: no averaged pressure drop or W_s line' % summary)
    return float(dp.group(1)), float(ws.group(1))


def standard_error(summary, window, block=0.3):
    """Standard error of the pressure drop's time average over the last
    window seconds, from the means of blocks of block seconds (pressure
    fluctuations of a spouted bed last a fraction of a second, so block
    means are close to independent)."""
    rows = list(csv.reader(open(os.path.join(os.path.dirname(summary), 'pressureDrop.csv'))))[1:]
    t = [float(r[0]) for r in rows]
    dp = [float(r[2]) for r in rows]
    start = t[-1] - window
    blocks = {}
    for ti, v in zip(t, dp):
        if ti > start:
            blocks.setdefault(min(int((ti - start) / block), int(window / block) - 1), []).append(v)
    means = [sum(b) / len(b) for b in blocks.values()]
    if len(means) < 2:
        return float('nan')
    m = sum(means) / len(means)
    return math.sqrt(sum((x - m) ** 2 for x in means) / (len(means) - 1) / len(means))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--particles', type=int, default=26000)
    parser.add_argument('--velocity', type=float, default=2.0, help='u_s [m/s]')
    parser.add_argument('--time', type=float, default=3.0, help='simulated seconds per run')
    parser.add_argument('--average', type=float, default=1.8,
                        help='averaging window at the end [s] (the paper\'s 1.8)')
    parser.add_argument('--seeds', type=int, nargs=2, default=[49979687, 15485867],
                        metavar=('A', 'B'), help='insertion seeds (primes above 10000)')
    parser.add_argument('--ranks', type=int, default=2)
    parser.add_argument('--dir', default=spoutbench.default_dir('agreement'))
    args = parser.parse_args(argv)
    os.makedirs(args.dir, exist_ok=True)

    def options(seed, ranks):
        return ['-u', '%g' % args.velocity, '-t', '%g' % args.time, '-a', '%g' % args.average,
                '-n', str(args.particles), '-np', str(ranks), 'insertionSeed=%d' % seed]

    a, b = args.seeds
    runs = [('serial, seed A', case_run(args.dir, 'serial-%d' % a, options(a, 1))),
            ('serial, seed B', case_run(args.dir, 'serial-%d' % b, options(b, 1)))]
    settled = os.path.join(args.dir, 'serial-%d' % a, 'DEM', 'settled.restart')
    runs.append(('%d ranks, seed A' % args.ranks,
                 case_run(args.dir, 'np%d-%d' % (args.ranks, a), options(a, args.ranks), settled)))
    values = [(name, figures(s)) for name, s in runs]
    errors = [standard_error(s, args.average) for _, s in runs]

    print('\nparallelAgreement: draft-plate bed, %d particles, u_s %g m/s, %g s each, '
          'averages over the last %g s' % (args.particles, args.velocity, args.time, args.average))
    print('%-18s %14s %22s %12s' % ('run', 'dP [Pa]', 'standard error [Pa]', 'W_s [kg/s]'))
    for (name, (dp, ws)), se in zip(values, errors):
        print('%-18s %14.0f %22.0f %12.4f' % (name, dp, se, ws))
    (dp_a, ws_a), (dp_b, ws_b), (dp_p, ws_p) = (v for _, v in values)
    for what, serial, seed, par, unit in (('dP', dp_a, dp_b, dp_p, 'Pa'),
                                          ('W_s', ws_a, ws_b, ws_p, 'kg/s')):
        scatter, diff = abs(serial - seed), abs(serial - par)
        print('%-4s serial vs %d ranks %.4g %s, seed A vs seed B %.4g %s: %s'
              % (what, args.ranks, diff, unit, scatter, unit,
                 'within the seed scatter' if diff <= scatter else 'OUTSIDE the seed scatter'))
    # the block standard errors show how much of the seed scatter the
    # averaging window alone would explain
    print('dP   block standard errors (0.3 s blocks; too small if the bed sways more '
          'slowly) combined: seed A vs B %.0f Pa, serial vs %d ranks %.0f Pa'
          % (math.hypot(errors[0], errors[1]), args.ranks, math.hypot(errors[0], errors[2])))


if __name__ == '__main__':
    main()
