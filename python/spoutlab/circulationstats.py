"""The circulation statistics spoutFoam measures in a draft-plate run
(constant/couplingProperties 'circulation', src/spoutFoam/CirculationCoupling.H):
read circulation.json, check it and draw its residence-time distributions.

  read(path)             the file as a dict, its schema checked (SchemaError)
  littles_law(stats, s)  Little's law in state s: holdup against entry rate x
                         mean residence, with the bias and spread expected of a
                         finite window (see the function)
  boundary_terms(stats, s)
                         the same over the window with its boundary terms,
                         which holds exactly: holdup x window = completed
                         residences + openAtStart + openAtEnd
  kaplan_meier(stats, key)
                         the residence-time distribution from the completed
                         visits and those still open at the window's end
                         (censored): survival per bin edge, restricted mean,
                         the share lasting beyond the window
  littles_mean(stats, key)
                         the mean residence (or cycle) by Little's law,
                         holdup / entry rate: no visit need complete
  halves_agreement(stats, key)
                         the two halves' means against their sampling error
  cycle_vs_ws(stats, bed_mass, ws)
                         mean cycle time against bed mass / W_s (eq 14)
  plot(stats, png)       the residence-time distributions (gnuplot)
  summarize(case, lines, ws=None)
                         the evaluate script's lines

Command line: python3 -m spoutlab.circulationstats CASE_DIR [--png FILE]
Standard library only.
"""
import json
import math
import os
import sys

FORMAT = 'spoutlab-circulation 1'
REGIONS = ['spout', 'fountain', 'downcomer', 'entrainment']
DISTRIBUTIONS = REGIONS + ['cycle']
RUN_KEYS = ['case', 'u_s', 'particles', 'particleDiameter', 'particleDensity', 'particleMass',
            'heatTransferModel', 'inletTemperature', 'inletHumidityRatio', 'geometry',
            'timeStart', 'timeEnd', 'samplingInterval']
GEOMETRY_KEYS = ['Wd', 'He', 'Hd', 'plateThickness', 'width', 'depth']
CONDITION_KEYS = ['holdup', 'voidage', 'slipRe', 'h', 'km', 'Tgas', 'Y', 'Tparticle']


class SchemaError(ValueError):
    """circulation.json does not hold what the format promises."""


def _need(d, keys, where):
    if not isinstance(d, dict):
        raise SchemaError('%s: expected an object' % where)
    missing = [k for k in keys if k not in d]
    if missing:
        raise SchemaError('%s: missing %s' % (where, ', '.join(missing)))


def check_schema(stats, path='circulation.json'):
    """Raises SchemaError naming the first entry that is missing or wrong."""
    _need(stats, ['format', 'run', 'regions', 'residence', 'halves', 'conditions', 'gas',
                  'circulationRate'], path)
    if stats['format'] != FORMAT:
        raise SchemaError('%s: format %r, expected %r' % (path, stats['format'], FORMAT))
    _need(stats['run'], RUN_KEYS, path + ': run')
    _need(stats['run']['geometry'], GEOMETRY_KEYS, path + ': run/geometry')
    if stats['regions'] != REGIONS:
        raise SchemaError('%s: regions %r, expected %r' % (path, stats['regions'], REGIONS))
    for key in DISTRIBUTIONS:
        where = '%s: residence/%s' % (path, key)
        _need(stats['residence'], [key], path + ': residence')
        d = stats['residence'][key]
        _need(d, ['binWidth', 'counts', 'samples', 'mean', 'std'], where)
        if sum(d['counts']) != d['samples'] or any(int(c) != c or c < 0 for c in d['counts']):
            raise SchemaError('%s: counts (sum %g) do not add up to samples %g'
                              % (where, sum(d['counts']), d['samples']))
        c = d.get('censored')
        if c is not None and (not isinstance(c, dict) or sum(c.get('counts', [])) != c.get('samples')):
            raise SchemaError('%s/censored: counts do not add up to samples' % where)
        for half in ('first', 'second'):
            _need(stats['halves'], [half], path + ': halves')
            _need(stats['halves'][half].get(key), ['samples', 'mean', 'std'],
                  '%s: halves/%s/%s' % (path, half, key))
            if 'batches' in stats:
                where = '%s: batches/%s/%s' % (path, half, key)
                b = stats['batches'].get(half, {}).get(key)
                _need(b, ['samples', 'sum'], where)
                if len(b['samples']) != len(b['sum']) or len(b['samples']) < 2 \
                        or sum(b['samples']) != stats['halves'][half][key]['samples']:
                    raise SchemaError('%s: samples and sum, two or more each, the samples '
                                      "adding up to the half's" % where)
    for region in REGIONS:
        _need(stats['conditions'].get(region), CONDITION_KEYS, '%s: conditions/%s' % (path, region))
    _need(stats['gas'], ['inletMassFlow', 'spoutShare', 'downcomerShare'], path + ': gas')


def read(path):
    with open(path) as f:
        stats = json.load(f)
    check_schema(stats, path)
    return stats


def window(stats):
    """The averaging window [s]: sampling times x interval."""
    run = stats['run']
    return run.get('window', run['timeEnd'] - run['timeStart'] + run['samplingInterval'])


def littles_law(stats, state):
    """Little's law L = lambda W in one state over the window T, with lambda
    the entries into the state per second and W the mean of the completed
    residences.  Over a finite window it is not exact: the visits open at
    its start (not counted in W; in L for their residual time) and at its
    end (in lambda, in L for their age) leave, for a stationary bed,
        1 - lambda W/L  ~  var(W)/(W T)   (the inspection paradox: a visit
    open at either end has a mean residual/age of E[W^2]/(2 W)),
    with a spread from the mean's sampling error, std(W)/(W sqrt(n)), and
    from the about L open visits at each end, each of residual time about
    E[W^2]/(2 W): sqrt(2/L) E[W^2]/(2 W T).
    Returns (residual, expected bias, sigma) or None without samples."""
    d = stats['residence'][state]
    c = stats['conditions'][state]
    n, mean, std = d['samples'], d['mean'], d['std']
    holdup, T = c['holdup'], window(stats)
    rate = c.get('entryRate', c.get('entries', 0) / T)
    if n < 2 or holdup <= 0 or mean <= 0:
        return None
    residual = 1 - rate * mean / holdup
    second = std ** 2 + mean ** 2                     # E[W^2]
    bias = std ** 2 / (mean * T)
    sigma = math.hypot(std / (mean * math.sqrt(n)),
                       math.sqrt(2 / holdup) * second / (2 * mean * T))
    return residual, bias, sigma


def boundary_terms(stats, state):
    """(holdup x window, completed + openAtStart + openAtEnd) [particle s]:
    every sample of a particle in the state is one sampling interval of one
    visit, completed in the window, begun before it or still open at its
    end, so the two are equal (to the file's 10 digits)."""
    c = stats['conditions'][state]
    return (c['holdup'] * window(stats),
            stats['residence'][state]['samples'] * stats['residence'][state]['mean']
            + c['openAtStart'] + c['openAtEnd'])


def kaplan_meier(stats, key):
    """The distribution of residence times (key a state or 'cycle') from the
    visits that began in the window: those that ended in it (counts) and
    those still open at its end, known only to last at least their time so
    far (residence/<key>/censored; none in files without it).  A window
    shorter than the longest visits keeps only the short ones among the
    completed: their mean is biased low, and Kaplan-Meier's product over
    the bins of (1 - ended / at risk) is not.  Actuarial form: a visit
    censored in bin i was at risk for half of it.
    Returns dict(survival=[S at each bin edge, from S(0) = 1], mean=the
    restricted mean, integral of S over the bins [s], beyond=S at the last
    edge (the share of visits longer than any seen), ended=, censored=
    (numbers of visits)) or None without a visit."""
    d = stats['residence'][key]
    w, ended = d['binWidth'], list(d['counts'])
    censored = list(d.get('censored', {}).get('counts', []))
    bins = max(len(ended), len(censored))
    ended += [0] * (bins - len(ended))
    censored += [0] * (bins - len(censored))
    at_risk = sum(ended) + sum(censored)
    if at_risk == 0:
        return None
    survival, mean = [1.0], 0.0
    for e, c in zip(ended, censored):
        exposed = at_risk - 0.5 * c
        s = survival[-1] * (1 - e / exposed) if exposed > 0 else survival[-1]
        mean += 0.5 * w * (survival[-1] + s)
        survival.append(s)
        at_risk -= e + c
    return dict(survival=survival, mean=mean, beyond=survival[-1], ended=sum(ended),
                censored=sum(censored))


def littles_mean(stats, key):
    """Mean residence in a state by Little's law, holdup / entry rate [s];
    for 'cycle' every tracked particle's holdup over the rate of entries
    into the spout, which is the rate of cycles.  Exact in the mean for a
    stationary bed over any window, long visits included; its error is the
    entry rate's.  None without entries."""
    c = stats['conditions']
    rate = lambda s: c[s].get('entryRate', c[s].get('entries', 0) / window(stats))
    if key == 'cycle':
        holdup, entries = sum(c[s]['holdup'] for s in REGIONS), rate('spout')
    else:
        holdup, entries = c[key]['holdup'], rate(key)
    return holdup / entries if entries > 0 else None


def batch_error(batches):
    """The standard error of a half's mean residence from its batches
    ({'samples': [N_j], 'sum': [S_j]}, equal lengths of time): the mean is
    the ratio R = sum S_j / sum N_j, and the scatter of the batches about it
    gives var R = m / (m - 1) sum (S_j - R N_j)^2 / (sum N_j)^2 over the m
    batches.  Visits that move together (a slug through the spout) fall in
    one batch, so unlike the error of independent visits this one counts
    them, as long as a batch outlasts such a correlation.  None with fewer
    than two batches holding visits."""
    n, s = batches['samples'], batches['sum']
    total = sum(n)
    if sum(1 for x in n if x > 0) < 2:
        return None
    r = sum(s) / total
    m = len(n)
    return math.sqrt(m / (m - 1) * sum((sj - r * nj) ** 2 for sj, nj in zip(s, n))) / total


def halves_agreement(stats, key):
    """(difference of the halves' means [s], its standard error [s], how the
    error was had): 'batches', the batch means of each half (batch_error;
    a statistics file with batches), else 'visits', the visits taken as
    independent samples, sqrt(s1^2/n1 + s2^2/n2), which slugs make too
    small.  None if a half has fewer than two visits, or its batches are
    too few to give an error."""
    a, b = stats['halves']['first'][key], stats['halves']['second'][key]
    if a['samples'] < 2 or b['samples'] < 2:
        return None
    if 'batches' in stats:
        errors = [batch_error(stats['batches'][h][key]) for h in ('first', 'second')]
        if None in errors:
            return None
        return a['mean'] - b['mean'], math.hypot(*errors), 'batches'
    return (a['mean'] - b['mean'],
            math.sqrt(a['std'] ** 2 / a['samples'] + b['std'] ** 2 / b['samples']), 'visits')


def cycle_vs_ws(stats, bed_mass, ws):
    """The mean cycle against bed mass / W_s (issue 24 key
    drytime.cycle_vs_Ws_rel) and the mean downcomer residence against
    downcomer holdup x particle mass / W_s, each as estimate / expected - 1
    for three estimates: 'little' (littles_mean; needs no completed visit,
    so a window shorter than a cycle of the full bed does), 'km' (the
    Kaplan-Meier restricted mean, NaN when more than 1 % of the visits last
    beyond the window, whose mean it then cannot give) and 'completed' (the
    mean of the completed visits alone: low when the window is short).
    Returns {'cycle': {...}, 'downcomer': {...}}, each also with 'beyond',
    Kaplan-Meier's share of visits longer than the window (NaN without
    visits)."""
    m = stats['run']['particleMass']
    expected = {'cycle': bed_mass / ws if ws > 0 else float('nan'),
                'downcomer': stats['conditions']['downcomer']['holdup'] * m / ws if ws > 0
                else float('nan')}
    rel = lambda x, key: x / expected[key] - 1 if x and x > 0 and expected[key] > 0 \
        else float('nan')
    out = {}
    for key in ('cycle', 'downcomer'):
        km = kaplan_meier(stats, key)
        beyond = km['beyond'] if km else float('nan')
        out[key] = dict(little=rel(littles_mean(stats, key), key),
                        km=rel(km['mean'], key) if km and beyond <= 0.01 else float('nan'),
                        completed=rel(stats['residence'][key]['mean'], key), beyond=beyond)
    return out


def plot(stats, png):
    """The residence-time distributions (probability density per state and
    of the cycle) to png; a casefiles.Plot."""
    from spoutlab import casefiles as sc
    data = png[:-4] + '.dat'
    with open(data, 'w') as f:
        for key in DISTRIBUTIONS:
            d = stats['residence'][key]
            w, n = d['binWidth'], max(d['samples'], 1)
            f.write('# %s\n' % key)
            for i, c in enumerate(d['counts']):
                f.write('%.6g %.6g\n' % ((i + 0.5) * w, c / (n * w)))
            f.write('\n\n')
    curves = ', \\\n     '.join(
        '"%s" index %d using 1:2 with steps title "%s (mean %.3g s, %d visits)"'
        % (data, i, k, stats['residence'][k]['mean'], stats['residence'][k]['samples'])
        for i, k in enumerate(DISTRIBUTIONS) if stats['residence'][k]['samples'] > 0)
    if not curves:
        return sc.not_drawn(png, 'no completed visit in the window')
    script = ('set title "Residence-time distributions, %s, u_s = %.3g m/s"\n'
              'set xlabel "residence time [s]"\nset ylabel "probability density [1/s]"\n'
              'set logscale y\nset grid\nset key top right\nplot %s\n'
              % (stats['run']['case'], stats['run']['u_s'], curves))
    return sc.plot(png, script)


def summarize(case, lines, ws=None, png='circulation.png'):
    """Appends the statistics' lines to lines (evaluate's summary); ws: W_s
    of eq 14 [kg/s] for the cycle check."""
    stats = read(os.path.join(case, 'circulation.json'))
    run = stats['run']
    lines.append('circulation statistics (circulation.json, every %.3g s from %.4g to %.4g s, '
                 'largest step %.2g mm): %s' % (
                     run['samplingInterval'], run['timeStart'], run['timeEnd'],
                     1e3 * run.get('maxStepDisplacement', float('nan')),
                     ', '.join('%s %.3g s (%d)' % (k, stats['residence'][k]['mean'],
                                                   stats['residence'][k]['samples'])
                               for k in DISTRIBUTIONS)))
    for s in REGIONS:
        law = littles_law(stats, s)
        if law:
            occupied, visits = boundary_terms(stats, s)
            lines.append("  Little's law, %s: 1 - rate x residence / holdup %.3f (a stationary "
                         'bed over this window: %.3f +- %.3f); with the open visits at both ends '
                         '%.6f' % ((s,) + law + (1 - visits / occupied,)))
    for k in DISTRIBUTIONS:
        h = halves_agreement(stats, k)
        if h:
            lines.append('  halves, %s: means differ by %.3g s, %.1f standard errors (of %s)'
                         % (k, h[0], abs(h[0]) / h[1] if h[1] > 0 else float('inf'),
                            'batch means' if h[2] == 'batches' else 'independent visits'))
        else:
            lines.append('  halves, %s: not compared, %d and %d visits ended within the halves '
                         'of %.3g s (its visits outlast a half)'
                         % ((k,) + tuple(stats['halves'][half][k]['samples']
                                         for half in ('first', 'second'))
                            + ((run['timeEnd'] - run['timeStart']) / 2,)))
    for k in DISTRIBUTIONS:
        km = kaplan_meier(stats, k)
        if km and km['censored']:
            lines.append("  %s: %d visits open at the window's end; Kaplan-Meier: %.1f %% last "
                         'beyond the window, restricted mean %.3g s; by Little\'s law %.3g s'
                         % (k, km['censored'], 100 * km['beyond'], km['mean'],
                            littles_mean(stats, k) or float('nan')))
    if ws:
        bed = run['particles'] * run['particleMass']
        c = cycle_vs_ws(stats, bed, ws)
        lines.append("  mean cycle / (bed mass / W_s) - 1: by Little's law %+.3f "
                     '(drytime.cycle_vs_Ws_rel), Kaplan-Meier %+.3f, completed cycles %+.3f; '
                     "downcomer residence / (holdup / W_s) - 1: by Little's law %+.3f, "
                     'Kaplan-Meier %+.3f, completed %+.3f'
                     % tuple(c[k][e] for k in ('cycle', 'downcomer')
                             for e in ('little', 'km', 'completed')))
    drawn = plot(stats, os.path.join(case, png))
    lines.append('  residence-time distributions: %s' % (png if drawn else drawn))
    return stats


def main(argv):
    from spoutlab import cli
    p = cli.parser('circulationstats', __doc__)
    p.add_argument('case', help='the case directory holding circulation.json')
    p.add_argument('--png', default='circulation.png')
    a = p.parse_args(argv)
    lines = []
    summarize(a.case, lines, png=a.png)
    print('\n'.join(lines))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
