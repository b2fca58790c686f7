"""From seconds to hours: what the long-time drying predictor (procsim dryer
spouted) takes from the CFD-DEM, and how it compares with it.

  statistics  the circulation statistics of the bed with draft plates at one
              operating point (hot air as in section 4.7, heat on, dry
              particles: the predictor takes each region's slip Re and
              voidage and evaluates its own heat and mass transfer there),
              in runs/statistics_u<u>/: spoutFoam to
              --time with the statistics sampled from --time minus
              --average (constant/couplingProperties 'circulation'), a
              restart point every --write seconds; started again, it
              continues.  Then the case's evaluate: W_s (eq 14), the
              residence-time distributions, Little's law, the two halves,
              and the mean cycle against bed mass / W_s
              (drytime.cycle_vs_Ws_rel).  The statistics file is copied here
              as circulation_u<u>.json, the predictor's input for this
              operating point.
Writes dryingTime.txt and dryingTime.json here (read by protocols/results).
"""
import json
import os
import shutil
import sys

from spoutlab import circulationstats
from spoutlab import cli
from spoutlab.protocols import heattransfer


def options(argv):
    def extra(p):
        p.add_argument('--part', choices=('statistics',), default='statistics',
                       help='what to run (default %(default)s)')
        p.add_argument('--bin', type=float, default=0.05, metavar='S',
                       help="residence-time histograms' bin width [s] (default %(default)s)")
        # the full bed at 2.0 m/s turns over in about 44 s (8.6 kg / W_s 0.196
        # kg/s): 18 s completed no downcomer visit; the cycle check needs a
        # window of several turnovers (--time of a few hundred seconds)
        p.set_defaults(time=20.0, average=18.0, write=1.0)
    o = heattransfer.options(argv, 'dryingTime', __doc__, extra)
    return o


def with_circulation(start, bin_width):
    """Adds the circulation entry to the run's couplingProperties (once)."""
    path = os.path.join('constant', 'couplingProperties')
    text = open(path).read()
    if '\ncirculation' not in text:
        with open(path, 'a') as f:
            f.write('\n// the protocol dryingTime: circulation statistics for the predictor\n'
                    'circulation { averageStart %.10g; binWidth %.10g; }\n' % (start, bin_width))


def ws_of(work):
    """W_s of eq 14 from the case's circulation.csv [kg/s]."""
    for line in open(os.path.join(work, 'circulation.csv')):
        if line.startswith('W_s downward'):
            return float(line.rsplit(',', 1)[1])
    sys.exit('dryingTime: %s/circulation.csv: no W_s row (the case evaluate failed?)' % work)


def statistics(o):
    """Run (or continue) the statistics run; its numbers and summary lines."""
    work = os.path.join('runs', 'statistics_u%g' % o['u'])
    heattransfer.run(o, work, 'dryingTime', entries=lambda: with_circulation(
        o['time'] - o['average'], o['bin']))
    lines = []
    ws = ws_of(work)
    stats = circulationstats.summarize(work, lines, ws=ws)
    run = stats['run']
    rel, rel_down = circulationstats.cycle_vs_ws(stats, run['particles'] * run['particleMass'],
                                                 ws)
    halves = {k: circulationstats.halves_agreement(stats, k)
              for k in circulationstats.DISTRIBUTIONS}
    wall = os.path.join(work, 'log.wallTime')
    r = dict(run=work, u_s=o['u'], time=o['time'], average=o['average'],
             particles=run['particles'], Ws=ws, cycle_vs_Ws_rel=rel, downcomer_vs_Ws_rel=rel_down,
             residence={k: stats['residence'][k]['mean'] for k in circulationstats.DISTRIBUTIONS},
             visits={k: stats['residence'][k]['samples'] for k in circulationstats.DISTRIBUTIONS},
             halves={k: (list(h) if h else None) for k, h in halves.items()},
             wall_s=sum(float(x) for x in open(wall)) if os.path.isfile(wall) else 0.0)
    shutil.copy(os.path.join(work, 'circulation.json'), 'circulation_u%g.json' % o['u'])
    shutil.copy(os.path.join(work, 'circulation.png'), 'dryingTime_circulation_u%g.png' % o['u'])
    return r, lines


def main(argv):
    o = options(argv)
    numbers = json.load(open('dryingTime.json')) if os.path.isfile('dryingTime.json') else {}
    r, lines = statistics(o)
    numbers.setdefault('statistics', {})['u%g' % o['u']] = r
    with open('dryingTime.json', 'w') as f:
        json.dump(numbers, f, indent=1, sort_keys=True)
    text = ['circulation statistics of the bed with draft plates: %d particles, u_s = %g m/s, '
            'hot air, %g s, statistics over the last %g s; run in %s, spoutFoam wall time %.0f min'
            % (r['particles'], o['u'], o['time'], o['average'], r['run'], r['wall_s'] / 60)]
    text += lines
    out = '\n'.join(text) + '\n'
    sys.stdout.write(out)
    open('dryingTime.txt', 'w').write(out)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
