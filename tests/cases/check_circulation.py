#!/usr/bin/env python3
"""check_circulation.py WHOLE KILLED [RANKS]: the circulation statistics of
spoutedBedCirculation's two runs (uninterrupted and killed + restarted).

  schema          circulation.json holds every key of the format, the
                  histograms add up to their samples
  holdups         every particle is in one state at every sampling time:
                  the holdups add up to the particles (1e-9)
  dense sampling  no sample found a particle two regions ahead of its state,
                  and the largest step |v| dt is under a tenth of the
                  narrowest region (the spout's half-width)
  Little's law    per state, over the window with its boundary terms:
                  holdup x window = completed residences + the incomplete
                  first visits + the visits open at the end, to the 10
                  digits of the file (1e-8): each sample of a particle is
                  one sampling interval of exactly one visit, so a state
                  machine that loses or double-counts time fails it.  The
                  stationary form, 1 - rate x mean residence / holdup, is
                  printed beside it with what a stationary bed would give
                  over this window (spoutlab.circulationstats.littles_law):
                  a 0.9 s window is short beside the slow states' visits
  censored        every entry into a state in the window either completed
                  its visit or was still open at the end: completed +
                  censored = entries, per state and for the cycle (one
                  per spout entry), exactly
  restart         the restarted run's statistics equal the uninterrupted
                  run's: the binary state at the end bit for bit,
                  circulation.json as text.  On RANKS > 1 the two runs part
                  in the last bits some 0.1 s after the restart (LIGGGHTS
                  writes a wall mesh's triangles rank by rank, so the
                  restarted run holds them in another order, and a
                  particle touching two triangles sums their forces the
                  other way round) and then chaotically: there each run's
                  own statistics pass the checks above instead, the
                  restarted run's with the sums it carried over the restart
"""
import os
import sys

from spoutlab import circulationstats as cs

whole, killed = sys.argv[1:3]
ranks = int(sys.argv[3]) if len(sys.argv) > 3 else 1
failures = []


def check(name, ok, detail=''):
    print('%-58s %s %s' % (name, 'PASS' if ok else 'FAIL', detail))
    if not ok:
        failures.append(name)


def check_run(case, label):
    """The checks of one run's circulation.json; its run block."""
    try:
        stats = cs.read(os.path.join(case, 'circulation.json'))
        check(label + 'schema of circulation.json', True)
    except (OSError, ValueError) as e:
        check(label + 'schema of circulation.json', False, str(e))
        sys.exit(1)
    run = stats['run']
    total = sum(stats['conditions'][s]['holdup'] for s in cs.REGIONS)
    check(label + 'holdups add up to the particles',
          abs(total - run['particles']) <= 1e-9 * run['particles'],
          '%.10g of %d' % (total, run['particles']))
    step, half = run['maxStepDisplacement'], run['geometry']['Wd'] / 2
    check(label + 'no region skipped between two samples', run['skippedSamples'] == 0,
          '%d samples' % run['skippedSamples'])
    check(label + 'largest step under a tenth of the spout half-width', step < 0.1 * half,
          '%.3g mm against %.3g mm' % (1e3 * step, 1e3 * half))
    checked = 0
    for s in cs.REGIONS:
        occupied, visits = cs.boundary_terms(stats, s)
        law = cs.littles_law(stats, s)
        checked += 1
        check(label + "Little's law with its boundary terms, " + s,
              abs(occupied - visits) <= 1e-8 * max(occupied, 1e-30),
              'holdup x window %.8g, visits %.8g particle s; stationary form %s'
              % (occupied, visits, '1 - rate W/L %.3f (a stationary bed: %.3f +- %.3f)' % law
                 if law else 'no completed visits'))
    check(label + "Little's law checked in every state", checked == 4, '%d' % checked)
    for k in cs.DISTRIBUTIONS:
        d = stats['residence'][k]
        entries = stats['conditions']['spout' if k == 'cycle' else k]['entries']
        censored = d.get('censored', {}).get('samples', float('nan'))
        check(label + 'completed + censored = entries, ' + k, d['samples'] + censored == entries,
              '%d + %g of %d' % (d['samples'], censored, entries))
    for k in cs.DISTRIBUTIONS:
        h = cs.halves_agreement(stats, k)
        if h:
            print('%-58s info %.3g s apart, %.1f standard errors (of %s)'
                  % (label + 'halves, ' + k, h[0], abs(h[0]) / h[1] if h[1] else 0,
                     'batch means' if h[2] == 'batches' else 'independent visits'))
    return run


run = check_run(whole, '')
if ranks > 1:
    check_run(killed, 'restarted: ')
    print('spoutedBedCirculation: %s' % ('FAILED: ' + ', '.join(failures) if failures
                                         else 'all checks pass (%d ranks)' % ranks))
    sys.exit(1 if failures else 0)

end = '%g' % round(run['timeEnd'], 6)
states = [open(os.path.join(c, 'DEM', 'restart_%s.circulation' % end), 'rb').read()
          for c in (whole, killed)]
check('restart: the state at %s s bit for bit' % end, states[0] == states[1],
      '%d bytes' % len(states[0]))
texts = [open(os.path.join(c, 'circulation.json')).read().replace('"case": "killed"', '"case": "whole"')
         for c in (whole, killed)]
check('restart: circulation.json the same', texts[0] == texts[1])
print('spoutedBedCirculation: %s' % ('FAILED: ' + ', '.join(failures) if failures else 'all checks pass'))
sys.exit(1 if failures else 0)
