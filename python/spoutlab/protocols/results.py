"""Collect the protocol outputs into docs/RESULTS.md and docs/results.csv:
SpoutLab's values beside the draft-plate paper's, with the settings and wall
time of the run that produced each.

The figures (Figs 2-7, 11, 12 of the draft-plate paper, Figs 2-4 of the
no-draft one) are copied to docs/figures/.

Each protocol takes tens of minutes, so the file is in sections -- minimum
spouting, circulation vs friction, circulation vs velocity, profiles, heat
transfer, drying, drying time, coarse graining, each no-draft-plate bed,
velocity maps, mixing, the 3-D bed -- and a call rewrites the
sections whose runs it is given and keeps the others (likewise the rows of
results.csv, by section).
"""
import csv
import json
import os
import math
import re
import shutil
import sys

from spoutlab import caserun
from spoutlab import cli
from spoutlab import profilefeatures
from spoutlab.protocols import mixing as mixing_protocol


def read_json(case, name, remedy):
    """A protocol's numbers, NAME in the case copy it ran in; one line if
    they are not there (a run from before the protocols wrote them): what
    the file is missing for and REMEDY, the command that writes it again
    from the finished runs."""
    path = os.path.join(case, name)
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        sys.exit('results: %s: %s (%s in that case writes it from its finished runs)'
                 % (path, e.strerror if isinstance(e, OSError) else 'not JSON: %s' % e, remedy))


class UmsRun:
    """What protocols/minimumSpouting wrote in a case: its numbers (ums.json)
    and its steps (ums.csv)."""

    def __init__(self, case):
        self.case = case
        r = read_json(case, 'ums.json', 'protocols/minimumSpouting --report with its options')
        self.particles, self.bed, self.plates = r['particles'], r['bed_height_m'], r['plates']
        self.settings = r['settings']
        self.hours = caserun.wall_time(case) / 3600
        rows = [r.strip().split(',') for r in list(open(os.path.join(case, 'ums.csv')))[1:]]
        self.steps = [(float(r[0]), r[1], float(r[2]), r[4] == '1' if len(r) > 4 else None)
                      for r in rows]
        self.max_u = max(u for u, b, _, _ in self.steps if b != 'spinup')
        # the classifier's window-mean core per step
        self.cores = [tuple(c) for c in r['cores']]
        self.spouts = any(s for _, b, _, s in self.steps if b != 'spinup')
        ms = r.get('u_ms')
        self.u_ms_bound = ms['bound'] if ms else None
        self.u_ms = ms['u_m_s'] if ms else None
        self.dp_ms = ms['dP_Pa'] if ms else None
        rise = r.get('u_ms_by_dP')
        self.rise = (rise['u_m_s'], rise['dP_Pa']) if rise else None
        peak = r.get('peak')
        self.peak = (peak['dP_Pa'], peak['u_m_s']) if peak else (None, None)
        self.break_through = r.get('break_through_m_s')
        self.hysteresis = r.get('hysteresis_Pa')
        back = r.get('reforms')
        self.reforms = (back['u_m_s'], back['dP_Pa']) if back else None
        self.umf = r['u_mf_ergun_m_s']
        self.umf_eps = (r['u_mf_settled']['voidage'], r['u_mf_settled']['u_m_s'])
        kudra = r.get('kudra_m_s')
        self.kudra = kudra['scaled'] if kudra else None
        self.kudra_direct = kudra['direct'] if kudra else None

    def row(self, quantity, value, paper):
        return (quantity, value, paper, self.settings, '%.2f h' % self.hours)

    def loop_rows(self):
        """The packed branch and the hysteresis, when the run had them."""
        rows = []
        if self.peak[0] is not None:
            rows.append(self.row('packed bed: peak dP on the increasing branch',
                                 '%.2f kPa at %g m/s%s' % (
                                     self.peak[0] / 1000, self.peak[1],
                                     '; breaks through at %g m/s' % self.break_through
                                     if self.break_through else '; never breaks through'),
                                 'dP rises to a peak, falls at the break-through (Fig 2)'))
        if self.hysteresis is not None:
            rows.append(self.row('hysteresis (peak minus the decreasing branch at its u_s)',
                                 '%.2f kPa' % (self.hysteresis / 1000),
                                 'a loop (Fig 2; its size is not given)'))
        if self.reforms:
            rows.append(self.row('spout re-forms on rising again', '%.3f m/s (dP %.2f kPa)'
                                 % (self.reforms[0], self.reforms[1] / 1000),
                                 'above u_ms (hysteresis loop, Fig 2)'))
        return rows

    def branch_rows(self):
        """dP and the classifier's core along each branch."""
        rows = []
        for branch, name in (('packed', 'increasing from the packed bed'),
                             ('down', 'decreasing'), ('up', 'increasing again')):
            steps = [(u, dp) for u, b, dp, _ in self.steps if b == branch]
            if not steps:
                continue
            rows.append(self.row('dP, %s (u_s m/s: kPa)' % name,
                                 ', '.join('%g: %.2f' % (u, dp / 1000) for u, dp in steps),
                                 'Fig 2'))
            cores = [(u, c) for u, b, c in self.cores if b == branch]
            rows.append(self.row('densest core layer / annulus (window mean), %s' % name,
                                 ', '.join('%g: %.2f' % c for c in cores),
                                 'a spout\'s core is dilute: below 0.5'))
        return rows

    def umf_row(self):
        if self.umf is None:
            return []
        return [self.row("Ergun's u_mf", '%.3f m/s (Wen-Yu form); %.3f m/s at the settled '
                         'voidage %.3f' % (self.umf, self.umf_eps[1], self.umf_eps[0]),
                         '1.746 m/s (no-draft paper)')]


def ums_rows(case):
    """The draft-plate u_ms rows of the table, and u_ms (None if only bounded)."""
    r = UmsRun(case)
    bound = '<= ' if r.u_ms_bound else ''
    kudra = ('; Kudra eq 12 for this geometry: %.3f scaled as the paper does%s'
             % (r.kudra, ', %.3f directly' % r.kudra_direct if r.kudra_direct else '')) \
        if r.kudra else ''
    rows = []
    if r.u_ms is not None:
        rows += [r.row('u_ms, draft plates', '%s%.3f m/s' % (bound, r.u_ms),
                       '1.25 m/s (sim), 1.12 exp.' + kudra),
                 r.row('dP at u_ms' if not bound else 'dP at the lowest step',
                       '%.2f kPa' % (r.dp_ms / 1000), '1.40 kPa (sim), 1.20 eq 13')]
    else:
        rows.append(r.row('u_ms, draft plates', 'none: the bed did not spout on the '
                          'decreasing branch', '1.25 m/s (sim), 1.12 exp.' + kudra))
    return rows + r.loop_rows() + r.umf_row(), (None if bound else r.u_ms)


def coarse_failure(case, r, cg):
    """Why a coarse-grained bed may not spout, in its own numbers: parcels
    across the slab's depth, the settled voidage, and dP at the highest
    step against the bed's weight per area."""
    from spoutlab import spoutedbed
    g = spoutedbed.load(case)
    p = g.particles
    weight = p['nParticles'] * p['rhop'] * math.pi / 6 * (p['dp'] / 1000) ** 3 * 9.81 \
        / (g.W * g.Lb / 1e6)
    top = [s for s in r.steps if s[1] != 'spinup'][-1]
    return ('%.1f parcels of %g mm across the %g mm depth; settled voidage %.3f; dP %.2f kPa '
            'at %g m/s (the highest step), %.0f %% of the bed weight per area (%.2f kPa)'
            % (g.Lb / (cg * p['dp']), cg * p['dp'], g.Lb, r.umf_eps[0], top[2] / 1000,
               top[0], 100 * top[2] / weight, weight / 1000))


def coarse_section(case, csv_path):
    """The draft-plate bed coarse-grained (issue 27): protocols/minimumSpouting
    in a case copy with coarseGraining = cg, beside the cg = 1 values
    results.csv holds (its ums section)."""
    from spoutlab import spoutedbed
    cg = spoutedbed.load(case).coarseGraining
    r = UmsRun(case)
    if cg == 1:
        sys.exit('results: %s: coarseGraining 1, expected a coarse-grained run (the cg = 1 '
                 'run is UMS_DIR)' % os.path.join(case, 'constant', 'spoutedBed'))
    name = 'cg%g' % cg
    ref = reference_values(csv_path)
    settings = '%s; coarseGraining %g (parcels of %g^3 particles)' % (r.settings, cg, cg)
    rows, keys = [], []
    why = coarse_failure(case, r, cg)
    for key, what, value, unit in (
            ('u_ms_m_s', 'u_ms, draft plates', r.u_ms, 'm/s'),
            ('dP_ms_kPa', 'dP at u_ms', r.dp_ms / 1000 if r.dp_ms else None, 'kPa')):
        one = ref.get('draft.' + key, '')
        if value is None or r.u_ms_bound:
            # no u_ms: the key holds what was measured instead, the break-through
            seen = (r.break_through if key == 'u_ms_m_s' else
                    [dp / 1000 for u, b, dp, _ in r.steps if b == 'packed'
                     and abs(u - r.break_through) < 1e-6][0]) if r.break_through else None
            rows.append((what + ', cg = %g' % cg, ('none: no spouting step on the decreasing '
                         'branch' if value is None else 'only bounded')
                         + ('; the one spouting step, the break-through: %.4g %s'
                            % (seen, unit) if seen is not None else '') + '; ' + why,
                         'cg = 1: %s %s' % (one, unit), settings, '%.2f h' % r.hours))
            keys.append(('%s.%s' % (name, key), '' if seen is None else '%.4g' % seen, unit, one,
                         'NOT u_ms: no decreasing branch, the value is the increasing branch\'s '
                         'break-through (its one spouting step); %s; cg = 1: draft.%s; %s'
                         % (why, key, settings)))
            continue
        departure = ' (%+.1f %% of cg = 1)' % (100 * (value / float(one) - 1)) if one else ''
        rows.append((what + ', cg = %g against cg = 1' % cg,
                     '%.4g %s%s' % (value, unit, departure), 'cg = 1: %s %s' % (one, unit),
                     settings, '%.2f h' % r.hours))
        keys.append(('%s.%s' % (name, key), '%.4g' % value, unit, one,
                     'paper_value: cg = 1 (draft.%s); within 10 %% (issue 27); ' % key + settings))
    rows.append(('settled bed height, cg = %g' % cg, '%.3f m' % r.bed, '', settings,
                 '%.2f h' % r.hours))
    return name, rows + r.loop_rows() + r.branch_rows(), keys, \
        [('ums.png', 'coarse_%s_pressure_drop.png' % name)]


def reference_values(csv_path):
    """key -> value of the results.csv beside the figures (the cg = 1 rows)."""
    return {row['key']: row['value'] for row in csv.DictReader(open(csv_path))} \
        if os.path.isfile(csv_path) else {}


def against_one(name, key, what, value, unit, one, settings, wall, fmt='%.4g'):
    """A coarse-grained value beside cg = 1's (one, text of results.csv):
    its table row and its results.csv row; a value that is not a number
    (no parcels where it is averaged) is said so."""
    if math.isnan(value):
        return ((what, 'none: no parcels where it is averaged (the region is empty)',
                 'cg = 1: %s %s' % (one, unit), settings, wall),
                ('%s.%s' % (name, key), '', unit, one,
                 'no value: no parcels where it is averaged (the region is empty); why the '
                 'slab fails at this cg: %s.u_ms_m_s; %s' % (name, settings)))
    departure = ' (%+.1f %% of cg = 1)' % (100 * (value / float(one) - 1)) if one else ''
    return ((what, (fmt + ' %s%s') % (value, unit, departure), 'cg = 1: %s %s' % (one, unit),
             settings, wall),
            ('%s.%s' % (name, key), fmt % value, unit, one,
             'paper_value: cg = 1; within 10 %% (issue 27)%s; %s'
             % ('' if not one or abs(value / float(one) - 1) <= 0.1 else
                ': outside it; why the slab fails at this cg: %s.u_ms_m_s' % name, settings)))


def coarse_speedup(case):
    """protocols/coarseSpeedup's runs: the same span at cg = 1 and each
    factor, one after the other; keys cg<N>.speedup (CPU time of cg = 1's
    span over cg = N's)."""
    r = read_json(case, 'speedup.json', 'protocols/coarseSpeedup with its options')
    one = r['runs'][0]
    rows, keys = [], []
    for run in r['runs']:
        span = '%g-%g s' % tuple(run['span_s'])
        what = ('%d parcels, %d DEM steps over %s: CPU %.1f s (wall %.0f s), %.1f CPU s per '
                'simulated s; dP %s Pa; %s; settling %.0f s apart; load average %s'
                % (run['parcels'], run['dem_steps'], span, run['cpu_s'], run['wall_s'],
                   run['cpu_per_simulated_s'], run['dP_Pa'],
                   'spouts' if run['spouts'] else 'does not spout',
                   run['settle_wall_s'], ' to '.join('%.2f' % x for x in run['load_average'])))
        rows.append(('cost of the span, cg = %g' % run['cg'], what, '', r['settings'],
                     '%.2f h' % (run['run_wall_s'] / 3600)))
        if run['cg'] == 1:
            continue
        # CPU per simulated s = fixed + per parcel: the two runs give both
        per = (one['cpu_per_simulated_s'] - run['cpu_per_simulated_s']) \
            / (one['parcels'] - run['parcels'])
        fixed = run['cpu_per_simulated_s'] - per * run['parcels']
        rows.append(('CPU s per simulated s independent of the parcels (gas, per-step '
                     'overheads; the line through both runs), cg = %g' % run['cg'],
                     '%.1f s (%.0f %% of cg = %g\'s) and %.2f ms more per parcel, each per simulated s: at most %.1fx '
                     'faster than cg = 1 with this time step, however few the parcels'
                     % (fixed, 100 * fixed / run['cpu_per_simulated_s'], run['cg'],
                        1000 * per, one['cpu_per_simulated_s'] / fixed),
                     '', r['settings'], ''))
        rows.append(('speed-up of cg = %g over cg = 1' % run['cg'],
                     '%.2f (CPU time; wall %.2f)' % (run['speedup'], run['speedup_wall']),
                     'at least 6 (issue 27 item 8)', r['settings'], ''))
        keys.append(('cg%g.speedup' % run['cg'], '%.3g' % run['speedup'], '', '6',
                     'target: at least 6 with u_ms within 10 %% (issue 27 item 8); CPU s of '
                     'cg = 1 over cg = %g for the same span (%s, %d DEM steps): %.1f / %.1f s '
                     '(wall %.0f / %.0f s); %s' % (run['cg'], span, run['dem_steps'],
                                                  one['cpu_s'], run['cpu_s'], one['wall_s'],
                                                  run['wall_s'], r['settings'])))
    return rows, keys


def coarse_circulation(case, ref):
    """protocols/circulation friction run with coarseGraining > 1: W_s
    beside cg = 1's draft.Ws_mu*_kg_s; keys cg<N>.Ws_mu<mu>_kg_s."""
    from spoutlab import spoutedbed
    table = read_json(case, 'circulation_friction.json',
                      'protocols/circulation friction with its options')
    rows, keys, figs = [], [], []
    for p in table['points']:
        work = os.path.join(case, 'runs', p['label'])
        cg = spoutedbed.load(work).coarseGraining
        mu = p['label'].split('_')[0]
        settings = 'u_s = %.2f m/s; %s; coarseGraining %g' % (p['u_m_s'], table['settings'], cg)
        row, key = against_one('cg%g' % cg, 'Ws_%s_kg_s' % mu, 'W_s, %s, cg = %g against cg = 1'
                               % (mu, cg), p['W_s_kg_s'], 'kg/s',
                               ref.get('draft.Ws_%s_kg_s' % mu, ''), settings,
                               '%.2f h' % (caserun.wall_time(work) / 3600))
        rows.append(row)
        keys.append(key)
        shots = sorted(f for f in os.listdir(work) if f.startswith('snapshot_')
                       and f.endswith('.png'))
        if shots:      # the last, where the bed stands at the end of the run
            figs.append((os.path.join('runs', p['label'], shots[-1]),
                         'coarse_cg%g_%s_end.png' % (cg, p['label'])))
    return rows, keys, figs


def coarse_heat(case, ref):
    """protocols/heatTransfer run with coarseGraining > 1: Re and h in
    spout and downcomer beside cg = 1's heat.* values; keys cg<N>.Re_spout,
    cg<N>.Re_downcomer, cg<N>.h_spout_W_m2K, cg<N>.h_downcomer_W_m2K."""
    from spoutlab import spoutedbed
    r = {row['key']: float(row['value'])
         for row in csv.DictReader(open(os.path.join(case, 'heat.csv')))}
    cg = spoutedbed.load(os.path.join(case, 'runs', 'heat_u%g' % r['u_s'])).coarseGraining
    settings = ('%d particles in %d parcels (coarseGraining %g), u_s = %g m/s, inlet 150 C, '
                'start 33 C, %g s; averaged over the last %g s (%d write times)'
                % (r['particles'], math.floor(r['particles'] / cg ** 3 + 0.5), cg, r['u_s'], r['time'],
                   r['average'], r['samples']))
    rows, keys = [], []
    for key, what, value, unit in (('Re_spout', 'Re, spout', r['Re_spout'], ''),
                                   ('Re_downcomer', 'Re, downcomer', r['Re_downcomer'], ''),
                                   ('h_spout_W_m2K', 'h, spout', r['h_spout'], 'W/m2/K'),
                                   ('h_downcomer_W_m2K', 'h, downcomer', r['h_downcomer'],
                                    'W/m2/K')):
        row, k = against_one('cg%g' % cg, key, '%s, cg = %g against cg = 1' % (what, cg), value,
                             unit, ref.get('heat.' + key, ''), settings,
                             '%.2f h' % (r['wall_s'] / 3600))
        rows.append(row)
        keys.append(k)
    return rows, keys


def bed3d_section(case, k):
    """The three-dimensional bed (issue 27 item 4): protocols/minimumSpouting3D
    in a copy of openfoam_cases/spoutedBed3D, beside Mathur and Gishler's
    u_ms and the dP_ms band; the k-th run given (another realisation) is
    keyed bed3d.run<k + 1>."""
    from spoutlab.protocols import minimumspouting3d as m
    u = read_json(case, 'ums.json', 'protocols/minimumSpouting3D')
    name = 'bed3d' if k == 0 else 'bed3d.run%d' % (k + 1)
    from spoutlab import spoutedbed3d
    settings = ('%d particles (insertionSeed %d), bed %.3f m deep, D_c %.3f m, D_i %.4f m; '
                'steps %s m/s' % (u['particles'], spoutedbed3d.load(case).seed,
                                  u['bed_depth_m'], u['D_c_m'], u['D_i_m'],
                                  ' '.join('%g' % s['u_s'] for s in u['steps'])))
    hours = '%.2f h' % (caserun.wall_time(case) / 3600)
    ref = u['mathur_gishler_u_ms_m_s']
    if u['u_ms_m_s'] is None:
        return [('u_ms, 3-D bed', 'none: no spouting step on the decreasing branch',
                 '%.3g m/s (Mathur-Gishler)' % ref, settings, hours)], [], []
    ratio = u['dP_ms_ratio']
    rows = [('u_ms, 3-D bed (the last spouting step, falling u_s)',
             '%.3g m/s (%+.1f %%)' % (u['u_ms_m_s'], 100 * u['u_ms_rel_error']),
             '%.3g m/s (Mathur-Gishler, band +-%d %%)' % (ref, round(100 * m.UMS_BAND)),
             settings, hours),
            ('dP_ms / bed weight per area, 3-D bed', '%.3f (%.0f Pa)' % (ratio, u['dP_ms_Pa']),
             '%.2f-%.2f' % m.DP_BAND, settings, hours)]
    keys = [('%s.u_ms_m_s' % name, '%.4g' % u['u_ms_m_s'], 'm/s', '%.4g' % ref,
             'Mathur-Gishler at the settled depth; ' + settings),
            ('%s.dP_ms_kPa' % name, '%.4g' % (u['dP_ms_Pa'] / 1000), 'kPa',
             '%.4g' % (0.75 * u['bed_weight_per_area_Pa'] / 1000),
             'paper_value: 0.75 of the bed weight per area (band %.2f-%.2f)' % m.DP_BAND)]
    tag = '' if k == 0 else '_run%d' % (k + 1)
    figs = [('ums.png', 'bed3d_pressure_drop%s.png' % tag)]
    figs += [(f, 'bed3d_%s%s.png' % (f[len('snapshot_'):-4], tag))
             for f in sorted(os.listdir(case)) if f.startswith('snapshot_') and f.endswith('.png')]
    return rows, keys, figs


def bed3d_coarse_section(case, ref):
    """protocols/minimumSpouting3D run with coarseGraining > 1: the 3-D
    bed's rows, keyed bed3d.cg<N>.*, beside cg = 1's bed3d.* values (where
    the parcels are many across the bed, unlike the draft-plate slab)."""
    from spoutlab import spoutedbed3d
    g3 = spoutedbed3d.load(case)
    cg = g3.coarseGraining
    rows, keys, figs = bed3d_section(case, 0)
    name = 'bed3d.cg%g' % cg
    u = read_json(case, 'ums.json', 'protocols/minimumSpouting3D')
    across = ('coarseGraining %g: parcels of %g mm, %.1f across the inlet, %.1f across the '
              'column' % (cg, cg * g3.particles['dp'], 1000 * u['D_i_m'] / (cg * g3.particles['dp']),
                          1000 * u['D_c_m'] / (cg * g3.particles['dp'])))
    rows = [(q + ', cg = %g' % cg, v, p, s.replace(' particles (', ' parcels (', 1) + '; ' + across,
             w) for q, v, p, s, w in rows]
    for key, what, unit in (('u_ms_m_s', 'u_ms', 'm/s'), ('dP_ms_kPa', 'dP_ms', 'kPa')):
        mine = [k for k in keys if k[0] == 'bed3d.' + key]
        one = ref.get('bed3d.' + key, '')
        if mine and one:
            value = float(mine[0][1])
            rows.append(('%s, 3-D bed, cg = %g against cg = 1' % (what, cg), '%.4g %s (%+.1f %%)'
                         % (value, unit, 100 * (value / float(one) - 1)),
                         'cg = 1: %s %s (bed3d.%s)' % (one, unit, key), rows[0][3], rows[0][4]))
    keys = [(name + k[0][len('bed3d'):], k[1], k[2], k[3],
             '%s; cg = 1: bed3d%s %s; %s'
             % (k[4], k[0][len('bed3d'):], ref.get(k[0], ''), across)) for k in keys]
    figs = [(f, 'bed3dcg%g_%s' % (cg, to[len('bed3d_'):])) for f, to in figs]
    return rows, keys, figs


# the no-draft paper's bed heights [m] by particle count
NOPLATE_BEDS = {10000: 0.409, 26000: 0.769}


def noplates_section(case):
    """A no-draft-plate section (no-draft paper, Fig 2) from one protocol
    run: its name, table rows, results.csv rows and figures."""
    r = UmsRun(case)
    name = 'noplates%dk' % round(r.particles / 1000)
    paper_bed = NOPLATE_BEDS.get(r.particles)
    rows = [r.row('settled bed height', '%.3f m' % r.bed,
                  '%g m' % paper_bed if paper_bed else '')]
    keys = [('%s.bed_height_m' % name, '%.4g' % r.bed, 'm',
             '%g' % paper_bed if paper_bed else '', 'settled, 99th percentile of the tops')]
    spouting_paper = {10000: 'spouts (u_ms 2.0 m/s)', 26000: 'no spouting up to 3.0 m/s; '
                      'bubbling and slugging only'}.get(r.particles, '')
    rows.append(r.row('spouts', 'yes, breaks through at %g m/s' % r.break_through
                      if r.spouts else 'no, at any u_s up to %g m/s' % r.max_u, spouting_paper))
    keys += [('%s.spouts' % name, '%d' % r.spouts, '1/0',
              {10000: '1', 26000: '0'}.get(r.particles, ''), r.settings),
             ('%s.max_u_tried_m_s' % name, '%.4g' % r.max_u, 'm/s',
              '3.0' if r.particles == 26000 else '', r.settings)]
    if r.u_ms is not None:
        paper = ('2.0 m/s', '1.75 kPa') if r.particles == 10000 else ('', '')
        bound = '<= ' if r.u_ms_bound else ''
        rows += [r.row('u_ms, no draft plates', '%s%.3f m/s' % (bound, r.u_ms), paper[0]),
                 r.row('dP at u_ms' if not bound else 'dP at the lowest step',
                       '%.2f kPa' % (r.dp_ms / 1000), paper[1])]
        if not bound:
            keys += [('%s.u_ms_m_s' % name, '%.4g' % r.u_ms, 'm/s',
                      '2.0' if r.particles == 10000 else '', r.settings),
                     ('%s.dP_ms_kPa' % name, '%.4g' % (r.dp_ms / 1000), 'kPa',
                      '1.75' if r.particles == 10000 else '', r.settings)]
    if r.u_ms is not None and r.rise is not None:
        # the paper's words read from dP alone, beside the classifier's u_ms
        rows.append(r.row('u_ms by dP alone (the step before its steepest rise)',
                          '%.3f m/s, dP %.2f kPa' % (r.rise[0], r.rise[1] / 1000),
                          '2.0 m/s, 1.75 kPa' if r.particles == 10000 else ''))
    if r.u_ms is None and r.rise is not None:
        # the paper's criterion read from dP alone, for a bed the classifier
        # does not call a spout: both said, side by side
        paper = ('2.0 m/s', '1.75 kPa') if r.particles == 10000 else ('', '')
        why = ('by dP alone: the step before its steepest rise on the decreasing branch; the '
               'classifier calls no step a spout')
        rows += [r.row('u_ms by dP alone, no draft plates', '%.3f m/s' % r.rise[0], paper[0]),
                 r.row('dP at u_ms by dP alone', '%.2f kPa' % (r.rise[1] / 1000), paper[1])]
        keys += [('%s.u_ms_m_s' % name, '%.4g' % r.rise[0], 'm/s', paper[0][:-4], why),
                 ('%s.dP_ms_kPa' % name, '%.4g' % (r.rise[1] / 1000), 'kPa', paper[1][:-4], why)]
    elif r.u_ms is None or r.u_ms_bound:
        # the keys stay, empty, so a reader sees the quantity was sought
        why = ('no decreasing branch: the classifier found no spouting step up to %g m/s'
               % r.max_u if r.u_ms is None else 'only bounded: still spouting at the lowest step')
        keys += [('%s.u_ms_m_s' % name, '', 'm/s', '2.0' if r.particles == 10000 else '', why),
                 ('%s.dP_ms_kPa' % name, '', 'kPa', '1.75' if r.particles == 10000 else '', why)]
    if r.hysteresis is not None:
        keys.append(('%s.hysteresis_kPa' % name, '%.4g' % (r.hysteresis / 1000), 'kPa', '',
                     'peak of the increasing branch minus the decreasing branch at its u_s'))
    if r.umf is not None:
        keys.append(('%s.u_mf_ergun_m_s' % name, '%.4g' % r.umf, 'm/s', '1.746',
                     "Wen and Yu's form of Ergun's equation"))
    rows += r.loop_rows() + r.branch_rows() + r.umf_row()
    figures = [('ums.png', '%s_fig2_pressure_drop.png' % name)]
    shown = [(u, b) for u, b, _, _ in r.steps if b in ('packed', 'down')]
    # flow patterns: the break-through and u_ms, or, for a bed that never
    # spouts, the papers' velocity (2.0 and 2.2 m/s) and the highest tried
    picked = (r.break_through, r.u_ms) if r.spouts else (2.0, 2.2, r.max_u)
    for u, b in [s for s in shown if any(v is not None and abs(s[0] - v) < 1e-9
                                         for v in picked)][:3]:
        figures.append(('snapshot_%s_u%g.png' % (b, u), '%s_snapshot_%s_u%g.png' % (name, b, u)))
    return name, rows, keys, figures


# what the no-draft paper says about its Figs 3-4, by feature
MAP_FEATURES = {
    'highest U_z just above the inlet': 'highest just above the injection zone (Fig 3)',
    'U_z symmetric about the axis': 'symmetric, especially the lower bed (Fig 3)',
    'V_z on the axis falls with height': 'particles decelerate moving up (Fig 4)',
    'V_z falls with the distance from the axis': 'falls away from the central core (Fig 4)',
    'V_z negative next to the walls and the base': 'can become negative: downward (Fig 4)',
}


def maps_section(case):
    """The velocity maps (protocols/velocityMaps' maps.txt): a row per
    feature and run, the maps and profiles as figures."""
    maps = read_json(case, 'maps.json', 'protocols/velocityMaps with its options')
    settings = maps['settings']
    rows, figures = [], []
    for run in maps['runs']:
        label, n, u = run['label'], run['particles'], '%g' % run['u_m_s']
        hours = caserun.wall_time(os.path.join(case, 'runs', label)) / 3600
        paper = '%g m' % NOPLATE_BEDS[n] if n in NOPLATE_BEDS else ''
        rows.append(('settled bed, %d particles' % n, '%.3f m' % run['bed_height_m'], paper,
                     settings, '%.2f h' % hours))
        for f in run['features']:
            rows.append(('%s (%d particles, u_s = %s m/s)' % (f['feature'], n, u),
                         '%s: %s' % ('yes' if f['holds'] else 'NO', f['measured']),
                         MAP_FEATURES.get(f['feature'], ''), settings, '%.2f h' % hours))
        figures += [(f, 'noplates_' + f) for f in run['pictures']]
    return rows, [], figures


def mixing_paper(vessel, n, u):
    """What the papers say of M at this point (draft-plate paper Fig 10,
    no-draft paper Figs 5-6)."""
    if vessel == 'plates':
        return 'not given'
    if n == 10000:
        return '0.9-1 after 2 s (Fig 10b); approaches 1 (no-draft Fig 5a)'
    if n == 26000 and u >= 2.7 - 1e-9:
        return 'still rising with time (Fig 10a)'
    if n == 26000:
        return '0.5-0.6 (Fig 10a, no-draft Fig 5b)'
    return ''


def mixing_section(case):
    """The degree of mixing (protocols/mixing's mixing.json): rows and
    results.csv keys per run at the 55 x 57 mm cells and the papers' 11 x 19
    mm grid, each with both weightings (cells: the papers' eq 18, the
    headline key; particles: the key ending in _particles), M against time
    and M_final against the cell size per bed, snapshots of the papers'
    points, and the circulation rate the papers' M after 2 s would need.
    Runs longer or shorter than the protocol's default (--time) get keys
    ending in _t<time> (before the weighting and grid suffixes), and the
    figures of a case copy that holds only such runs end so too, so that a
    longer run can stand beside the default ones."""
    numbers = read_json(case, 'mixing.json', 'protocols/mixing')
    settings = numbers['settings']
    level = numbers.get('level', 0.9)
    rows, keys, figures = [], [], []
    times = set()
    for r in numbers['runs']:
        label, vessel = r['label'], r['vessel']
        n, u, t_run = r['particles'], r['u_m_s'], '%.3g' % r['time_s']
        M = {k: '%.3f' % r[k] for k in r if k.startswith('M_') and '_at_' not in k}
        grid = [z for z in r['cell_sizes'] if (z['dx_mm'], z['dz_mm']) == (11, 19)][0]
        times.add(float(t_run))
        tag = '' if float(t_run) == mixing_protocol.DEFAULT_TIME else '_t%g' % float(t_run)
        paper = mixing_paper(vessel, n, u)
        paper_value = paper.split(' ')[0] if paper[:1].isdigit() else ''
        hours = '%.2f h' % (caserun.wall_time(os.path.join(case, 'runs', label)) / 3600)
        what = '%s, %d particles, u_s = %.1f m/s' % (
            'no draft plates' if vessel == 'no-plates' else 'draft plates', n, u)
        run_settings = '%s; %s s; W_s %.3f kg/s, turnover m_bed/W_s %.2f s' % (
            settings, t_run, r['W_s_kg_s'], r['turnover_s'])
        rows.append(('M_final, %s, 55 x 57 mm cells' % what,
                     '%s (by particles %s; Lacey %s, by particles %s; lower-upper %s, by '
                     'particles %s)' % (M['M_papers_left_right'], M['M_particles_left_right'],
                                        M['M_lacey_left_right'],
                                        M['M_lacey_particles_left_right'],
                                        M['M_papers_lower_upper'],
                                        M['M_particles_lower_upper']),
                     paper, run_settings, hours))
        rows.append(('M_final, %s, the papers\' 11 x 19 mm cells' % what,
                     '%.3f (by particles %.3f; random mixing about %.3f, by particles %.3f; '
                     '%.0f cells of %.1f particles)' % (
                         grid['M_papers'], grid['M_particles'], grid['random_mixing_M_papers'],
                         grid['random_mixing_M_particles'], grid['sampling_cells'],
                         grid['particles_per_cell']),
                     paper, run_settings, hours))
        bed = 'mixing%dk' % round(n / 1000) if vessel == 'no-plates' \
            else 'mixingDraft%dk' % round(n / 1000)
        key = ('%s.M_final' % bed if (vessel, n, u) == ('no-plates', 10000, 2.0)
               else '%s.M_final_u%.1f' % (bed, u)) + tag
        common = 'papers\' M, left-right halves; %s s at %.1f m/s' % (t_run, u)
        keys += [
            (key, M['M_papers_left_right'], '', paper_value,
             'weighting cells (eq 18: the sum over the sampling cells, N = their number); '
             'sampling cells 55 x 57 mm; %s; Lacey %s; weighted by particles: %s_particles'
             % (common, M['M_lacey_left_right'], key)),
            (key + '_particles', M['M_particles_left_right'], '', '',
             'weighting particles (each cell by its particles, the headline before issue '
             '25; the paper value is on the cells key); sampling cells 55 x 57 mm; %s; '
             'Lacey %s' % (common, M['M_lacey_particles_left_right'])),
            (key + '_grid11x19', '%.3f' % grid['M_papers'], '', paper_value,
             'weighting cells (eq 18); sampling cells 11 x 19 mm, the papers\' grid '
             '(%.1f particles a cell; random mixing gives about %.3f); %s'
             % (grid['particles_per_cell'], grid['random_mixing_M_papers'], common)),
            (key + '_grid11x19_particles', '%.3f' % grid['M_particles'], '', '',
             'weighting particles; sampling cells 11 x 19 mm (random mixing gives %.3f); %s'
             % (grid['random_mixing_M_particles'], common))]
        if (vessel, n, u) in KEY_MIXING_POINTS:
            # the labels at the end of the run (Figs 8-9 by colour)
            last = [f for f in r['snapshots'] if f.endswith('_label.png')][-1:]
            figures += [(f, 'mixing_' + f) for f in last]
    r, k = mixing_circulation(numbers['runs'], level)
    rows, keys = rows + r, keys + k
    beds = sorted({f for f in os.listdir(case)
                   if re.match(r'mixing_(cellsize_)?\w+_n\d+\.png$', f)})
    tag = '_t%g' % min(times) if times and mixing_protocol.DEFAULT_TIME not in times else ''
    return rows, keys, [(f, f[:-4] + tag + '.png') for f in beds] + figures


def needed_rate(new, figure_dir):
    """mixing10k.Ws_needed_kg_s as this call's mixing section gives it, else
    as results.csv has it (None if neither does)."""
    keys = new['mixing'][1] if 'mixing' in new else []
    ref = reference_values(os.path.join(os.path.dirname(figure_dir), 'results.csv'))
    return ([k[1] for k in keys if k[0] == 'mixing10k.Ws_needed_kg_s']
            or [ref.get('mixing10k.Ws_needed_kg_s')])[0]


def mixing_candidates_section(case, needed):
    """Whether anything in the model moves W_s toward the circulation the
    papers' mixing needs (protocols/mixing --candidates'
    mixingCandidates.json): per candidate W_s, its change on the reference
    run and M_final; needed, the W_s the papers' M after 2 s would need
    (mixing10k.Ws_needed_kg_s), if known."""
    numbers = read_json(case, 'mixingCandidates.json', 'protocols/mixing --candidates')
    settings = numbers['settings']
    paper = ('W_s about %s kg/s for the papers\' M after 2 s (mixing10k.Ws_needed_kg_s)'
             % needed if needed else '')
    rows, keys = [], []
    reference = [c['W_s_kg_s'] for c in numbers['runs'] if c['name'] == 'reference'][0]
    for c in numbers['runs']:
        rel = c['W_s_kg_s'] / reference - 1
        hours = '%.2f h' % (caserun.wall_time(os.path.join(case, 'runs', c['label'])) / 3600)
        change = ' '.join(c['changes']) or 'none'
        spouts = '' if c['spouts'] else '; by the spout classifier the bed does not ' \
            'spout (%s): W_s is then no spout-downcomer circulation' % c['regime']
        rows.append(('W_s and M_final, %s: %s' % (c['name'], c['what']),
                     '%.3f kg/s (%+.1f %% on the reference), turnover %.2f s; M_final %.3f (by '
                     'particles %.3f; 11 x 19 mm cells %.3f)%s'
                     % (c['W_s_kg_s'], 100 * rel, c['turnover_s'], c['M_final'],
                        c['M_final_particles'], c['M_final_grid11x19'], spouts),
                     paper, '%s; change: %s; run %s' % (settings, change, c['label']), hours))
        key = 'mixing10k.candidate.%s.' % c['name']
        note = 'candidate %s (%s; change: %s; %s); %s' % (
            c['name'], c['what'], change, 'spouts' if c['spouts'] else 'does not spout',
            settings)
        keys += [(key + 'Ws_kg_s', '%.4g' % c['W_s_kg_s'], 'kg/s', '',
                  note + ('; the papers\' M after 2 s would need %s kg/s' % needed
                          if needed else '')),
                 (key + 'Ws_rel', '%.3f' % rel, '', '',
                  'W_s / the reference run\'s W_s - 1; ' + note),
                 (key + 'M_final', '%.3f' % c['M_final'], '', '0.9-1',
                  'weighting cells (eq 18), 55 x 57 mm sampling cells; ' + note)]
    for c in numbers.get('failed', []):
        rows.append(('W_s and M_final, %s: %s' % (c['name'], c['what']), 'no finished run',
                     paper, settings, ''))
    return rows, keys, [('mixingcand_M.png', 'mixingcand_M.png')]


def spout_height_section(case):
    """The spout along its height (protocols/spoutHeight's spoutHeight.json):
    per run the slopes along the axis, h beside the plates over h on the
    axis and the slugs; keys spout.<quantity>_<run's key>."""
    numbers = read_json(case, 'spoutHeight.json', 'protocols/spoutHeight')
    settings = ('%g s per run, averaged over the last %g s; least squares along the axis '
                'over z/R_d 5.9-25.2 (Fig 4\'s heights); slug: axis voidage at mid-plate '
                'below 0.6 until above 0.7' % (numbers['time'], numbers['average']))
    paper = {'Vp': 'falls with height (Fig 4), slugging near u_ms',
             'h': 'falls with height, lower next to the plates (Fig 12)'}
    rows, keys = [], []
    for r in numbers['runs']:
        note = 'run %s: %s; %s' % (r['run'], r['what'], settings)
        hours = '%.2f h' % (r['wall_s'] / 3600)
        lost = caserun.lost_text(r['lost'])
        rows.append(('particle velocity along the spout axis, %s' % r['run'],
                     'dVp/dz %+.3f 1/s (%+.0f %% of its mean over the heights; halves of the '
                     'window %+.3f, %+.3f; over the spout\'s width %+.3f); gas %+.2f 1/s, '
                     'voidage %+.3f 1/m, slip Re %+.0f 1/m; %d slugs (%.2f per s, %.0f %% of '
                     'the time; axis voidage at mid-plate %.3f)%s'
                     % (r['dVp_dz'], 100 * r['Vp_change'], r['dVp_dz_halves'][0],
                        r['dVp_dz_halves'][1], r['dVp_dz_width'], r['dUg_dz'], r['deps_dz'],
                        r['dRe_dz'], r['slugs'], r['slugs_per_s'], 100 * r['slug_share'],
                        r['eps_probe'], lost), paper['Vp'], note, hours))
        keys += [('spout.dVp_dz_' + r['key'], '%.4g' % r['dVp_dz'], '1/s', '< 0', note),
                 ('spout.slugs_per_s_' + r['key'], '%.3g' % r['slugs_per_s'], '1/s', '', note)]
        if r['heat']:
            rows.append(('h along the spout axis and across it, %s' % r['run'],
                         'dh/dz %+.1f W/m2/K per m; beside the plates / on the axis %.3f over '
                         'Fig 12\'s z/R_d 16.9-22.5 (slip Re %.3f), %.3f over all Fig 4\'s '
                         'heights' % (r['dh_dz'], r['h_plate_over_axis'],
                                      r['Re_plate_over_axis'], r['h_plate_over_axis_all']),
                         paper['h'], note, hours))
            keys += [('spout.dh_dz_' + r['key'], '%.4g' % r['dh_dz'], 'W/m2/K/m', '< 0', note),
                     ('spout.h_plate_over_axis_' + r['key'], '%.4g' % r['h_plate_over_axis'],
                      '', '< 1', note)]
    # along the axis, every run; across the spout, the paper's two points
    pngs = [('spoutHeight.png', 'spoutheight_axis.png')] + [
        ('spoutHeight_%s.png' % run, 'spoutheight_across_%s.png' % run)
        for run in ('u1.4', 'u2_hot')]
    return rows, keys, [p for p in pngs if os.path.isfile(os.path.join(case, p[0]))]


def mixing_circulation(runs, level):
    """The circulation rate the papers' M = level after 2 s of the 10 000-
    particle bed would need.  The papers' scale has random mixing at 1, ours
    (55 x 57 mm cells) at M_random < 1, so their level is level M_random
    here.  If M depends on time only through the number of turnovers
    t W_s/m_bed, a run that first reaches it at t_reach with W_s needs
    W_s t_reach/(2 s) to reach it at 2 s.  From the longest run of that bed
    that reaches it (cells weighting; the particle weighting beside it); M
    at one turnover in every run of the bed shows whether M follows the
    turnovers."""
    bed = [r for r in runs if r['vessel'] == 'no-plates' and r['particles'] == 10000]
    if not bed:
        return [], []
    rows, keys = [], []
    def at(r, name):
        return '-' if r.get(name) is None else '%.3f' % r[name]

    spread = '; '.join('%g m/s, %.3g s: W_s %.3f kg/s, turnover %.2f s, M_papers at half a '
                       'turnover %s, at one %s' % (
                           r['u_m_s'], r['time_s'], r['W_s_kg_s'], r['turnover_s'],
                           at(r, 'M_papers_at_half_turnover'), at(r, 'M_papers_at_turnover'))
                       for r in bed)
    title = 'W_s the papers\' M = %g after 2 s would need (10 000 particles)' % level
    paper = 'M 0.9-1 after 2 s (Fig 10b)'
    reached = [r for r in bed if r.get('t_reach_cells_s') is not None]
    if not reached:
        best = max(bed, key=lambda r: r['M_papers_left_right'] / r['level_cells'])
        rows.append((title, 'not reached within %.3g s: M_papers (55 x 57 mm) at most %.3f '
                     'against the %.3f (%g of random mixing) sought (%g m/s)'
                     % (max(r['time_s'] for r in bed), best['M_papers_left_right'],
                        best['level_cells'], level, best['u_m_s']), paper, spread, ''))
        return rows, keys
    r = max(reached, key=lambda r: r['time_s'])
    t_reach, w_s = r['t_reach_cells_s'], r['W_s_kg_s']
    need = w_s * t_reach / 2.0
    by_particles = r.get('t_reach_particles_s')
    rows.append((title, '%.2f kg/s, %.1f times the %.3f kg/s measured (turnover %.2f s instead '
                 'of %.2f s): M_papers (55 x 57 mm) first reaches %.3f, %g of its random-mixing '
                 'value, at %.2f s = %.2f turnovers%s' % (
                     need, need / w_s, w_s, 2.0 * r['turnover_s'] / t_reach, r['turnover_s'],
                     r['level_cells'], level, t_reach, t_reach / r['turnover_s'],
                     '' if by_particles is None else '; weighted by particles (%.3f) at %.2f s, '
                     'needing %.2f kg/s' % (r['level_particles'], by_particles,
                                            w_s * by_particles / 2.0)),
                 paper, 'from %s (%g m/s, %.3g s): M taken as a function of the turnovers '
                 't W_s/m_bed, so W_needed = W_s t_reach/(2 s); %s' % (
                     r['label'], r['u_m_s'], r['time_s'], spread), ''))
    keys.append(('mixing10k.Ws_needed_kg_s', '%.3g' % need, 'kg/s', '',
                 'weighting cells (M_papers, 55 x 57 mm cells): the W_s that would bring M to '
                 '%g of random mixing (%.3f) after 2 s if M follows the turnovers t W_s/m_bed: '
                 'W_s %.3f kg/s measured at %g m/s times t_reach %.2f s / 2 s (%s, %.3g s); '
                 'turnover %.2f s' % (level, r['level_cells'], w_s, r['u_m_s'], t_reach,
                                      r['label'], r['time_s'], r['turnover_s'])))
    if by_particles is not None:
        keys.append(('mixing10k.Ws_needed_kg_s_particles', '%.3g' % (w_s * by_particles / 2.0),
                     'kg/s', '', 'weighting particles (M_particles, 55 x 57 mm cells): as '
                     'mixing10k.Ws_needed_kg_s with t_reach %.2f s (level %.3f)'
                     % (by_particles, r['level_particles'])))
    return rows, keys


# the runs whose label snapshots go into docs/figures
KEY_MIXING_POINTS = (('no-plates', 10000, 2.0), ('no-plates', 26000, 2.5),
                     ('no-plates', 26000, 3.0), ('plates', 26000, 2.0))


def profile_rows(case):
    """The profiles protocol's features (profiles.json), a row each."""
    if not os.path.isfile(os.path.join(case, 'profiles.txt')):
        return []
    rows = []
    for point in read_json(case, 'profiles.json', 'protocols/profiles with its options')['points']:
        u = '%g' % point['u_m_s']
        for f in point['features']:
            rows.append(('%s (u_s = %s m/s)' % (f['feature'], u),
                         '%s: lower %.3f, upper %.3f m/s' % ('yes' if f['holds'] else 'NO',
                                                              f['lower_m_s'], f['upper_m_s']),
                         'yes (Figs 4a, 5)', 'profiles protocol; lower region z/R_d < 12',
                         '%.2f h' % (caserun.wall_time(os.path.join(case, 'runs', 'He95_u%s' % u))
                                     / 3600)))
    return rows


def spout_height_rows(case, u_ms):
    """The spout velocity along the height in every run with the paper's
    base settings (H_e = 95 mm, mu = 0.3): where it stops accelerating and
    how much it slows above.  The paper's Fig 4 is at 1.12 u_ms, where
    slugs slow the upper spout; the runs span several u_s / u_ms."""
    runs = os.path.join(case, 'runs')
    rows = []
    for label in sorted(os.listdir(runs)) if os.path.isdir(runs) else []:
        path = os.path.join(runs, label, 'spoutProfiles.csv')
        if not (label.startswith('He95_u') or label.startswith('mu0.3_u')) \
                or not os.path.isfile(path):
            continue
        series = profilefeatures.by_height(profilefeatures.read_profile(path))
        u = label.split('_u')[1]
        (z_top, v_top), (z_end, v_end) = max(series, key=lambda hv: hv[1]), series[-1]
        rows.append(('spout velocity along the height, %s' % label,
                     'fastest %.2f m/s at z/R_d %.1f; %.2f at %.1f (%+.0f %%)'
                     % (v_top, z_top, v_end, z_end, 100 * (v_end / v_top - 1)),
                     'falls with height at 1.12 u_ms (slugs)',
                     'u_s = %s m/s%s; z/R_d %.1f to %.1f'
                     % (u, ' = %.2f u_ms' % (float(u) / u_ms) if u_ms else '', series[0][0],
                        z_end),
                     '%.2f h' % (caserun.wall_time(os.path.join(runs, label)) / 3600)))
    return rows


def fig3_velocities(ums):
    """Flow patterns worth showing (Fig 3): the first and last step of the
    decreasing branch, u_ms and the step that collapsed the spout."""
    down = [float(r.split(',')[0]) for r in list(open(os.path.join(ums, 'ums.csv')))[1:]
            if r.split(',')[1] == 'down']
    r = UmsRun(ums)
    picked = {down[0], down[-1]}
    if r.u_ms is not None and not r.u_ms_bound:
        k = min(range(len(down)), key=lambda i: abs(down[i] - r.u_ms))
        picked.update(down[k:k + 2])
    return sorted(picked, reverse=True)


def copy(case, pairs, out_dir):
    """Copy (source, target) PNGs of a case into out_dir; the names copied."""
    os.makedirs(out_dir, exist_ok=True)
    names = []
    for src, dst in pairs:
        if os.path.isfile(os.path.join(case, src)):
            shutil.copy(os.path.join(case, src), os.path.join(out_dir, dst))
            names.append(dst)
    return names


def ums_figures(ums):
    return [('ums.png', 'fig2_pressure_drop.png')] + \
        [('snapshot_down_u%g.png' % u, 'fig3_snapshot_u%g.png' % u) for u in fig3_velocities(ums)]


def slope_note(slope):
    """How d log10 W_s / d mu was fitted, and how well the line fits."""
    if slope[1] is None:
        return 'least squares over the friction runs'
    return ('least squares over the friction runs weighted by their W_s standard errors; '
            'reduced chi-square %s%s' % ('%.2g' % slope[2] if slope[2] is not None else '-',
                                         ', the error scaled by its root' if slope[2] and
                                         slope[2] > 1 else ''))


def circulation_rows(case, study):
    """Rows of one study, its points (label, W_s, correlation) and, for the
    friction study, the fitted slope: (slope, its standard error or None,
    reduced chi-square or None); weighted by the points' standard errors
    when every point has one (log10 W_s's error: SE / (W_s ln 10))."""
    rows, points, slope = [], [], None
    for _ in (study,):
        if not os.path.isfile(os.path.join(case, 'circulation_%s.txt' % study)):
            continue
        mus, logs, sigmas = [], [], []
        table = read_json(case, 'circulation_%s.json' % study,
                          'protocols/circulation %s with its options' % study)
        how = table['settings']
        various = len(set(p.get('time_s') for p in table['points'])) > 1
        for p in table['points']:
            label, ws, ref = p['label'], p['W_s_kg_s'], p['correlation_kg_s']
            err = p.get('W_s_err_kg_s')
            points.append((label, ws, ref))
            rows.append(('W_s, %s' % label, '%.3f kg/s (%+.0f %%)%s'
                         % (ws, 100 * (ws / ref - 1),
                            '' if err is None else ', standard error %.3f (%.1f %%)'
                            % (err, 100 * err / ws)) + caserun.lost_text(p.get('particles_lost')),
                         '%.3f kg/s (eq %s)' % (ref, '15' if study == 'velocity' else '16'),
                         'u_s = %.2f m/s; %s%s' % (p['u_m_s'], how, '; this run to %g s'
                                                   % p['time_s'] if various else ''),
                         '%.2f h' % (caserun.wall_time(os.path.join(case, 'runs', label)) / 3600)))
            if study == 'friction' and ws > 0:
                mus.append(float(label[2:label.index('_')]))
                logs.append(math.log10(ws))
                sigmas.append(err / (ws * math.log(10)) if err else None)
        if len(mus) > 1:
            slope = (profilefeatures.weighted_slope(mus, logs, sigmas) if None not in sigmas
                     else (profilefeatures.slope(mus, logs), None, None))
            rows.append(('d log10 W_s / d mu', '%.2f' % slope[0] + (
                ' +- %.2f (one standard error)' % slope[1] if slope[1] is not None else ''),
                '-3.25 (eq 16)', slope_note(slope), ''))
    return rows, points, slope


def heat_section(case):
    """Section 4.7 from protocols/heatTransfer's heat.csv."""
    r = {row['key']: float(row['value']) for row in csv.DictReader(open(os.path.join(case, 'heat.csv')))}
    settings = ('%d particles, u_s = %g m/s, inlet 150 C, start 33 C, %g s; averaged over '
                'the last %g s (%d write times), z/R_d 16.927-22.454'
                % (r['particles'], r['u_s'], r['time'], r['average'], r['samples']))
    wall = '%.2f h' % (r['wall_s'] / 3600)
    rows = [('Re, spout', '%.0f' % r['Re_spout'], '5690', settings, wall),
            ('Re, downcomer', '%.0f' % r['Re_downcomer'], '130', settings, wall),
            ('h, spout', '%.1f W/m2/K' % r['h_spout'], 'higher than in the downcomer (Fig 12)',
             settings, wall),
            ('h, downcomer', '%.1f W/m2/K' % r['h_downcomer'], 'roughly uniform (Fig 12)',
             settings, wall),
            ('h along the height over the band, spout', '%+.2f W/m2/K per R_d'
             % r['dh_dz_spout'], 'falls with height', settings, wall),
            ('h across the downcomer', '%.0f %% spread inside; %.1f W/m2/K beside the plates, '
             '%.1f by the walls' % (100 * r['h_downcomer_spread'], r['h_by_plates'],
                                    r['h_by_walls']),
             'roughly uniform; slightly higher by the plates and the wall', settings, wall),
            ('mean particle temperature, spout / downcomer', '%.2f / %.2f K at %g s'
             % (r['Tp_spout'], r['Tp_downcomer'], r['time']), 'spout hotter (Fig 11)',
             settings, wall),
            ('gas outlet temperature', '%.2f K at %g s' % (r['T_outlet'], r['time']), '',
             settings, wall),
            ('energy balance residual', '%.1e of the particles\' heat' % r['balance'],
             'closes (energy lost by the gas = gained by the particles)', settings, wall)]
    keys = [('heat.Re_spout', '%.6g' % r['Re_spout'], '', '5690', settings),
            ('heat.Re_downcomer', '%.6g' % r['Re_downcomer'], '', '130', settings),
            ('heat.h_spout_W_m2K', '%.6g' % r['h_spout'], 'W/m2/K', '', settings),
            ('heat.h_downcomer_W_m2K', '%.6g' % r['h_downcomer'], 'W/m2/K', '', settings),
            ('heat.dh_dz_spout_W_m2K', '%.3g' % r['dh_dz_spout'], 'W/m2/K per R_d', '',
             'least-squares slope of h along the spout over the band'),
            ('heat.Tp_spout_K', '%.6g' % r['Tp_spout'], 'K', '', 'at the end of the run'),
            ('heat.Tp_downcomer_K', '%.6g' % r['Tp_downcomer'], 'K', '', 'at the end of the run'),
            ('heat.T_outlet_K', '%.6g' % r['T_outlet'], 'K', '', 'at the end of the run'),
            ('heat.energy_balance_rel', '%.3g' % r['balance'], '', '0',
             'whole-run residual / heat received by the particles')]
    figures = [(f, 'fig11_' + f) for f in sorted(os.listdir(case))
               if f.startswith(('heat_particleTemperature_', 'heat_gasTemperature_'))]
    figures += [('heat_particleTemperature.png', 'fig11_particleTemperature_history.png'),
                ('heat_heatTransfer.png', 'fig12_heat_transfer.png')]
    return rows, keys, figures


def drying_section(case):
    """The dryer from protocols/drying's drying.json: the single-kernel checks
    and the bed."""
    r = read_json(case, 'drying.json', 'protocols/drying with its options')
    k, b = r.get('kernel', {}), r.get('bed')
    rows, keys = [], []
    if 'wetBulb' in k:
        w = k['wetBulb']
        settings = ('one free-water kernel at rest in air at %g C, W %g, %g m/s (singleKernel)'
                    % (w['air_temperature_C'], w['humidity_ratio'], w['velocity']))
        rows += [('film-law wet bulb, free-water kernel', '%.4f K (error %.1e K)'
                  % (w['wetbulb_film_K'], w['wetbulb_err_K']), 'psychrometric %.2f K'
                  % w['wetbulb_thermodynamic_K'], settings, ''),
                 ('film law vs psychrometric wet bulb', '%+.2f K (%+.2f K at Le = 1)'
                  % (w['wetbulb_film_K'] - w['wetbulb_thermodynamic_K'],
                     w['wetbulb_lewis1_K'] - w['wetbulb_thermodynamic_K']), '', settings, '')]
        keys.append(('dry.wetbulb_err_K', '%.3g' % w['wetbulb_err_K'], 'K', '',
                     'free-water kernel at rest vs the film-law balance solved in the test; '
                     'psychrometric wet bulb %.2f K' % w['wetbulb_thermodynamic_K']))
    for T in (40, 60, 80):
        t = k.get('thinLayer%dC' % T)
        if t:
            settings = ('one kernel (kernel diffusion, D_0 and E_a calibrated on the same equation), '
                        'air at %d C, W %g, %g m/s' % (T, t['humidity_ratio'], t['velocity']))
            rows.append(('time to MR 0.5, %d C' % T, '%+.1f %%' % (100 * t['thinlayer_t50_rel']),
                         'Thompson, Peart and Foster 1968 (20 %)', settings, ''))
            keys.append(('dry.thinlayer_t50_rel_%dC' % T, '%.3g' % t['thinlayer_t50_rel'], '', '0',
                         'SpoutLab / Thompson et al. (1968) - 1 (D_0, E_a calibrated on it); '
                         'Crank\'s sphere with the same D_eff %+.3f'
                         % t.get('thinlayer_sphere_rel', float('nan'))))
    if b:
        settings = ('%d particles, u_s = %g m/s, inlet %.0f C (W %g), X_0 %.4g, %g s; averages '
                    'over the last %g s' % (b['particles'], b['u_s'], b['T_in'] - 273.15, b['W_in'],
                                            b['X0'], b['time'], b['average']))
        wall = '%.2f h' % (b['wall_s'] / 3600)
        rows += [('moisture at the end, spout / downcomer', '%.4f / %.4f kg/kg dry solid'
                  % (b['X_spout'], b['X_downcomer']), '', settings, wall),
                 ('drying rate', '%.4g kg/s' % b['rate'], '', settings, wall),
                 ('outlet air', '%.2f K, RH %.2f %%' % (b['T_outlet'], 100 * b['RH_outlet']), '',
                  settings, wall),
                 ('share of the heat given that evaporates water', '%.1f %%'
                  % (100 * b['evaporation_share']), '', settings, wall),
                 ('water / energy balance residual', '%.1e / %.1e' % (b['water_balance'],
                                                                     b['energy_balance']),
                  'closes', settings, wall)]
        keys += [('dry.rate_kg_s', '%.4g' % b['rate'], 'kg/s', '', settings),
                 ('dry.evaporation_heat_share', '%.4g' % b['evaporation_share'], '', '',
                  'latent heat / heat the gas gives the particles; ' + settings),
                 ('dry.T_outlet_K', '%.6g' % b['T_outlet'], 'K', '', settings),
                 ('dry.RH_outlet', '%.4g' % b['RH_outlet'], '', '', settings),
                 ('dry.water_balance_rel', '%.3g' % b['water_balance'], '', '0',
                  'whole-run residual / water the particles lost'),
                 ('dry.energy_balance_rel', '%.3g' % b['energy_balance'], '', '0',
                  'whole-run residual, latent heat included')]
    pngs = [(f, 'drying_' + f[len('drying_'):]) for f in sorted(os.listdir(case))
            if f.startswith('drying_') and f.endswith('.png')]
    return rows, keys, pngs


def drytime_study(study):
    """The design study's rows and keys (dryingTime --part study): per point
    the time to 15 % w.b., kWh per kg water, the hottest kernel, the final
    spread; keys with _n<N> for a bed other than the paper's 26 000."""
    rows, keys = [], []
    n, ums = study[0]['particles'], study[0]['ums']
    suffix = '' if n == 26000 else '_n%d' % n
    settings = ('%d particles, draft plates at Hd = %g m, u_ms %g m/s (this bed\'s); batches from 25 to 15 %% '
                'w.b. at 25 C, %s, gasModel plugFlow; one statistics run per velocity (the '
                'circulation does not depend on the inlet temperature)'
                % (n, study[0].get('Hd', float('nan')), ums,
                   study[0].get('drying_model', 'kernelDiffusion')))
    for k in sorted({q['u_over_ums'] for q in study}):
        first = next(q for q in study if q['u_over_ums'] == k)   # the velocity's statistics
        if 'cycle_s' in first:
            rows.append(('design study: the circulation statistics at %g u_ms (%g m/s)'
                         % (k, first['u_s']),
                         "mean cycle %.3g s (Little's law)" % first['cycle_s'], '',
                         settings, '%.2f h' % (first['statistics_wall_s'] / 3600)))
    for q in study:
        point = 'drytime.%gC_%gums%s' % (q['T_in_C'], q['u_over_ums'], suffix)
        where = '%g C, %g u_ms (%g m/s); ' % (q['T_in_C'], q['u_over_ums'], q['u_s'])
        rows.append(('design study at %g C, %g u_ms: time to 15 %%, kWh per kg water, hottest '
                     'kernel, final std of moisture' % (q['T_in_C'], q['u_over_ums']),
                     '%s, %.3g kWh/kg, %.1f C, %.2g kg/kg d.b.'
                     % ('%.2f h' % q['hours'] if q['reached'] else 'not reached',
                        q['kWh_per_kg'], q['Tmax_C'], q['spread']),
                     '', settings, '%.2f h statistics, %.0f s predictor'
                     % (q['statistics_wall_s'] / 3600, q['wall_s'])))
        keys += [(point + '.hours', '%.3g' % q['hours'] if q['reached'] else '', 'h', '',
                  where + ('time to 15 % w.b.; ' if q['reached']
                           else 'no value: 15 % w.b. not reached in the batch; ') + settings),
                 (point + '.kWh_per_kg', '%.3g' % q['kWh_per_kg'], 'kWh/kg', '',
                  where + "heater energy per kg of water evaporated (the tray-dryer paper's "
                  'definition); ' + settings),
                 (point + '.Tmax_K', '%.4g' % (q['Tmax_C'] + 273.15), 'K', '',
                  where + 'the hottest kernel of the batch; ' + settings),
                 (point + '.spread', '%.3g' % q['spread'], 'kg/kg', '',
                  where + "std of the kernels' moisture at the end (d.b.); " + settings)]
    return rows, keys


def halves_error(halves):
    """How the halves' errors were had (circulationstats.halves_agreement;
    a dryingTime.json before batches gives pairs, errors of independent
    visits)."""
    if any(h and len(h) > 2 and h[2] == 'batches' for _, h in halves):
        return ('of the batch means of the quarters of each half (visits that move together, '
                'as in slugs, fall in one batch)')
    return ('of independent visits (visits that move together, as in slugs, make the true '
            'error larger)')


def cycle_row(st):
    """The cycle check's cell: Little's law's mean cycle against bed mass /
    W_s, Kaplan-Meier's and the completed cycles' beside it (older
    dryingTime.json: the completed cycles' alone)."""
    rel = st['cycle_vs_Ws_rel']
    if 'cycle_little_s' not in st:
        return '%.3g s (%d completed cycles): %+.1f %%' % (st['residence']['cycle'],
                                                           st['visits']['cycle'], 100 * rel)
    c = st['checks']['cycle']
    km = ('Kaplan-Meier %+.1f %%' % (100 * c['km']) if c['km'] == c['km'] else
          'Kaplan-Meier: %.0f %% of the cycles last beyond the window' % (100 * c['beyond']))
    ended = ('the %d completed cycles %.3g s (%+.1f %%)'
             % (st['visits']['cycle'], st['residence']['cycle'], 100 * c['completed'])
             if st['visits']['cycle'] else 'no cycle ended within the window')
    # W_s's own error (1 s blocks): the check cannot be finer than it
    ws = (' (W_s +- %.1f %%)' % (100 * st['Ws_err'] / st['Ws'])
          if st.get('Ws_err') and st['Ws'] > 0 else '')
    return ('%.3g s against %.3g s%s: %+.1f %%; %s; %s'
            % (st['cycle_little_s'], st['cycle_expected_s'], ws, 100 * rel, km, ended))


def drytime_statistics(label, st):
    """The rows, keys and figures of one operating point's circulation
    statistics (dryingTime.json's statistics/<label>)."""
    rows, keys, pngs = [], [], []
    settings = ('%d particles, draft plates, u_s = %g m/s, hot air (heat on), %g s; '
                'statistics and W_s over the last %g s' % (st['particles'], st['u_s'],
                                                            st['time'], st['average']))
    wall = '%.2f h' % (st['wall_s'] / 3600)
    regions = ('spout', 'fountain', 'downcomer', 'entrainment')
    if 'little' in st:    # the visits open at the window's end too
        residence = ('mean residence by Little\'s law (visits: ended + open at the window\'s '
                     'end): spout / fountain / downcomer / entrainment zone',
                     ' / '.join('%.3g s (%d + %d)' % (st['little'][k], st['visits'][k],
                                                      st['entries'][k] - st['visits'][k])
                                for k in regions))
    else:
        residence = ('mean residence: spout / fountain / downcomer / entrainment zone',
                     ' / '.join('%.3g s (%d)' % (st['residence'][k], st['visits'][k])
                                for k in regions))
    halves = sorted(st['halves'].items())
    rows += [residence + ('', settings, wall),
             ("mean cycle by Little's law (all particles / spout entry rate) against bed "
              'mass / W_s (eq 14)', cycle_row(st), 'within 5 % (issue 24)', settings, wall),
             ("the window's two halves: difference of the mean residences / its standard "
              'error, ' + halves_error(halves),
              ', '.join('%s %.1f' % (k, abs(h[0]) / h[1]) for k, h in halves if h and h[1] > 0)
              + ''.join('; %s not compared (too few visits end within a half)' % k
                        for k, h in halves if not h),
              'within the sampling error (about 2 or less)', settings, wall)]
    keys.append(('drytime.cycle_vs_Ws_rel' + ('' if label == 'u2' else '_' + label),
                 '%.3g' % st['cycle_vs_Ws_rel'], '', '0',
                 ("mean cycle by Little's law / (bed mass / W_s) - 1, W_s of eq 14 %.4g "
                  'kg/s%s; ' if 'cycle_little_s' in st else
                  'mean cycle / (bed mass / W_s) - 1, W_s of eq 14 %.4g kg/s%s; ')
                 % (st['Ws'], ' +- %.2g (1 s blocks)' % st['Ws_err'] if st.get('Ws_err') else '')
                 + settings))
    pngs.append(('dryingTime_circulation_%s.png' % label,
                 'drytime_circulation_%s.png' % label))
    return rows, keys, pngs


def drytime_section(case):
    """The long-time predictor's side of the CFD-DEM from protocols/
    dryingTime's dryingTime.json: the circulation statistics per operating
    point, and the predictor against a direct drying run (part consistency)."""
    r = read_json(case, 'dryingTime.json', 'protocols/dryingTime with its options')
    rows, keys, pngs = [], [], []
    for label, st in sorted(r.get('statistics', {}).items()):
        more = drytime_statistics(label, st)
        rows, keys, pngs = rows + more[0], keys + more[1], pngs + more[2]
    c = r.get('consistency')
    if c:
        settings = ('%d particles, draft plates at Hd = %g m, u_s = %g m/s, inlet %.0f C (W %g), '
                    '%s from X_0 %.4g; window %g s from t = %g s; predictor %d samples from the '
                    "kernels at the window's start, the run's own statistics, gasModel %s"
                    % (c['particles'], c['Hd'], c['u_s'], c['T_in'] - 273.15, c['W_in'],
                       c['drying_model'], c['X0'], c['window'], c['window_start'], c['samples'],
                       c.get('gas_model', 'compartments')))
        if c.get('exchange_share'):
            settings += ('; the cores exchange the share of the measured flow across their sides '
                         'that carries heat (%s)' % ', '.join(
                             '%s %.2f' % kv for kv in sorted(c['exchange_share'].items())))
        wall = '%.2f h' % (c['wall_s'] / 3600)
        rows += [('bed-mean drying rate over the window, predictor / direct CFD-DEM',
                  '%.4g / %.4g kg/kg d.b. per s: %+.1f %%'
                  % (c['rate_predictor'], c['rate_direct'], 100 * c['rate_rel']),
                  'within 5 % (issue 24)', settings, wall),
                 ("spread (std) of the kernels' moisture at the window's end, predictor / direct",
                  '%.4g / %.4g kg/kg d.b. (%.4g at the start): %+.1f %%'
                  % (c['spread_predictor'], c['spread_direct'], c['spread_start'],
                     100 * c['spread_rel']), 'within 20 % (issue 24)', settings, wall)]
        if 'regions' in c and 'rate_unlimited_air' in c:
            rows.append(('gas the kernels saw, predictor / CFD-DEM: T [C] and W per region; the '
                         'rate with unlimited air',
                         '; '.join('%s %.0f / %.0f, %.4f / %.4f'
                                   % ((k,) + tuple(c['regions'][k]['Tgas_C'])
                                      + tuple(c['regions'][k]['W']))
                                   for k in ('spout', 'fountain', 'fountainCore', 'downcomer',
                                             'entrainment', 'jet') if k in c['regions'])
                         + '; unlimited air %.2f x the direct rate'
                         % (c['rate_unlimited_air'] / c['rate_direct']), '', settings, wall))
        if 'mixed_cup_C' in c:
            rows.append(('gas through the spout gap and the downcomers at mid-plate height (and '
                         "out of the jet's top), flow-weighted (mixed cup), against what their "
                         'kernels saw (CFD-DEM)',
                         'spout %.1f / %.1f C, downcomers %.1f / %.1f C'
                         % (c['mixed_cup_C']['spout'], c['regions']['spout']['Tgas_C'][1],
                            c['mixed_cup_C']['downcomer'],
                            c['regions']['downcomer']['Tgas_C'][1])
                         + ('; out of the jet\'s top %.1f / %.1f C' % (
                             c['mixed_cup_C']['jet'], c['regions']['jet']['Tgas_C'][1])
                            if 'jet' in c['mixed_cup_C'] else ''), '', settings, wall))
        if 'rate_region_means' in c:
            rows.append(("free-water rate from the CFD-DEM's region means (holdup, k_m, gas and "
                         'kernel state), against the direct rate',
                         '%.4g / %.4g kg/kg d.b. per s: %+.1f %%'
                         % (c['rate_region_means'], c['rate_direct'],
                            100 * (c['rate_region_means'] / c['rate_direct'] - 1)),
                         "close to 0: the predictor's departure is then its compartments' gas",
                         settings, wall))
        keys += [('drytime.consistency_rate_rel', '%.3g' % c['rate_rel'], '', '0',
                  'predictor / direct - 1 of the bed-mean drying rate; direct %.4g kg/kg/s; '
                  % c['rate_direct'] + settings),
                 ('drytime.consistency_spread_rel', '%.3g' % c['spread_rel'], '', '0',
                  "predictor / direct - 1 of the std of the kernels' moisture at the end; direct "
                  '%.4g kg/kg; ' % c['spread_direct'] + settings)]
    if r.get('study'):
        study_rows, study_keys = drytime_study(r['study'])
        rows += study_rows
        keys += study_keys
        n = r['study'][0]['particles']
        pngs.append(('dryingTime_study.png', 'drytime_study%s.png' % ('' if n == 26000 else
                                                                     '_n%d' % n)))
    return rows, keys, [p for p in pngs if os.path.isfile(os.path.join(case, p[0]))]


SECTIONS = [
    ('ums', 'Minimum spouting (section 4.1, Figs 2-3)'),
    ('friction', 'Circulation rate vs friction at u_ms (section 4.4, eq 16, Fig 7)'),
    ('velocity', 'Circulation rate vs gas velocity (section 4.4, eq 15, Fig 6)'),
    ('profiles', 'Spout and downcomer profiles (sections 4.2-4.3, Figs 4-5)'),
    ('spoutheight', 'The spout along its height (sections 4.2 and 4.7, Figs 4 and 12; '
                    'issue 25 item 2)'),
    ('heat', 'Gas-to-particle heat transfer (section 4.7, Figs 11-12)'),
    ('drying', 'Drying: one kernel, and the bed as a dryer at the section 4.7 conditions'),
    ('drytime', 'Drying time: the circulation statistics the long-time predictor takes from '
                'the CFD-DEM'),
    ('coarse', 'Coarse graining: the draft-plate bed in parcels against cg = 1 (issue 27)'),
    ('noplates10k', 'Without draft plates, 10 000 particles (no-draft paper, Fig 2a)'),
    ('noplates26k', 'Without draft plates, 26 000 particles (no-draft paper, Fig 2b)'),
    ('maps', 'Gas and particle velocity without draft plates (no-draft paper, Figs 3-4)'),
    ('mixing', 'Degree of mixing (draft-plate paper section 4.6, Fig 10; no-draft paper '
               'Figs 5-6)'),
    ('mixingcand', 'Mixing: whether anything in the model moves the circulation toward the '
                   "papers' (issue 25 item 3), one run per candidate"),
    ('bed3d', 'Three-dimensional spouted bed: u_ms and dP_ms against Mathur and Gishler '
              '(issue 27 item 4)'),
    ('bed3dcoarse', 'Three-dimensional spouted bed coarse-grained against cg = 1 (issue 27)'),
]
CSV_HEADER = ['key', 'value', 'unit', 'paper_value', 'note']


def section_of_key(key):
    if key.startswith(('heat.', 'noplates10k.', 'noplates26k.', 'maps.')):
        return key.split('.')[0]
    if key.startswith('spout.'):
        return 'spoutheight'
    if key.startswith('dry.'):
        return 'drying'
    if key.startswith('drytime.'):
        return 'drytime'
    if re.match(r'cg[\d.]+\.', key):
        return 'coarse'
    if key.startswith('mixing10k.candidate.'):
        return 'mixingcand'
    if key.startswith('mixing'):
        return 'mixing'
    if re.match(r'bed3d\.cg[\d.]+\.', key):
        return 'bed3dcoarse'
    if key.startswith('bed3d'):
        return 'bed3d'
    if key.startswith('draft.Ws_He'):
        return 'velocity'
    if key.startswith(('draft.Ws_mu', 'draft.dlogWs')):
        return 'friction'
    return 'ums'


FIGURES = {'ums': ('fig2_', 'fig3_'), 'friction': ('fig7_',), 'velocity': ('fig6_',),
           'profiles': ('fig4_5_',), 'spoutheight': ('spoutheight_',), 'heat': ('fig11_', 'fig12_'), 'drying': ('drying_',),
           'drytime': ('drytime_',), 'coarse': ('coarse_',),
           'noplates10k': ('noplates10k_',), 'noplates26k': ('noplates26k_',),
           'maps': ('noplates_maps_',), 'mixing': ('mixing_',), 'mixingcand': ('mixingcand_',),
           'bed3d': ('bed3d_',),
           'bed3dcoarse': ('bed3dcg',)}


def remove_figures(section, figure_dir):
    """A regenerated section's old figures go (their times may differ)."""
    if os.path.isdir(figure_dir):
        for f in os.listdir(figure_dir):
            if f.startswith(FIGURES[section]):
                os.remove(os.path.join(figure_dir, f))


def coarse_runs_section(coarse, runs, figure_dir):
    """The coarse-graining section from every coarse-grained case copy
    given: minimumSpouting runs (coarse), and runs['circulation'],
    ['heat'], ['speedup'] (rows, results.csv rows, figures)."""
    remove_figures('coarse', figure_dir)
    csv_path = os.path.join(os.path.dirname(figure_dir), 'results.csv')
    ref = reference_values(csv_path)
    rows, keys, pngs = [], [], []
    for case in coarse:
        _, r, k, p = coarse_section(case, csv_path)
        rows, keys, pngs = rows + r, keys + k, pngs + copy(case, p, figure_dir)
    for case in runs.get('circulation', ()):
        r, k, p = coarse_circulation(case, ref)
        rows, keys, pngs = rows + r, keys + k, pngs + copy(case, p, figure_dir)
    for name, section in (('heat', lambda c: coarse_heat(c, ref)),
                          ('speedup', coarse_speedup)):
        for case in runs.get(name, ()):
            r, k = section(case)
            rows, keys = rows + r, keys + k
    return rows, keys, pngs


def drytime_sections(cases, figure_dir, sources):
    """One drying-time section from every dryingTime case copy given (the
    reduced bed's, the paper's full bed's), figures from each; a key from
    two copies stops with one line."""
    remove_figures('drytime', figure_dir)
    rows, keys, pngs = [], [], []
    for case in cases:
        sources.setdefault('drytime', []).append(case)
        r, k, p = drytime_section(case)
        twice = {key[0] for key in k} & {key[0] for key in keys}
        if twice:
            sys.exit('results: --dryingTime %s: %s also from an earlier --dryingTime (one '
                     'operating point per key)' % (case, ', '.join(sorted(twice))))
        rows, keys, pngs = rows + r, keys + k, pngs + copy(case, p, figure_dir)
    return rows, keys, pngs


def build(ums, circ, heat, figure_dir, noplates=(), maps=None, mixing=(), drying=None,
          drytime=None, coarse=(), bed3d=(), coarse_runs=None, mixing_candidates=None,
          spout_height=None):
    """section -> (table rows, results.csv rows, figures, drag_velocities)."""
    new, sources = {}, {}

    def figures(section, case, pairs):
        sources.setdefault(section, []).append(case)
        remove_figures(section, figure_dir)
        return copy(case, pairs, figure_dir)

    if ums:
        rows, u_ms = ums_rows(ums)
        run = UmsRun(ums)
        keys = []
        if u_ms:
            keys = [('draft.u_ms_m_s', '%.4g' % u_ms, 'm/s', '1.25', rows[0][3]),
                    ('draft.dP_ms_kPa', '%.4g' % (run.dp_ms / 1000), 'kPa', '1.40',
                     rows[0][3])]
        loop = run.hysteresis
        if loop is not None:
            keys.append(('draft.hysteresis_kPa', '%.4g' % (loop / 1000), 'kPa', '',
                         'peak of the increasing branch from the packed bed minus the '
                         'decreasing branch at its u_s'))
        new['ums'] = (rows, keys, figures('ums', ums, ums_figures(ums)))
    if circ:
        u_ms = ums_rows(ums)[1] if ums else None
        rows, points, slope = circulation_rows(circ, 'friction')
        if rows:
            keys = [('draft.Ws_%s_kg_s' % label.split('_')[0], '%.4g' % ws, 'kg/s',
                     '0.39' if label.startswith('mu0.063_') else '%.3g' % ref,
                     'eq 16: %.3g kg/s%s' % (ref, '; experiment (Kalwar) 0.39 kg/s'
                                             if label.startswith('mu0.063_') else ''))
                    for label, ws, ref in points]
            if slope is not None:
                keys.append(('draft.dlogWs_dmu', '%.3g' % slope[0], '', '-3.25',
                             slope_note(slope)))
            if slope is not None and slope[1] is not None:
                keys.append(('draft.dlogWs_dmu_err', '%.2g' % slope[1], '', '',
                             'one standard error of draft.dlogWs_dmu; ' + slope_note(slope)))
            new['friction'] = (rows, keys, figures('friction', circ, [
                ('circulation_friction.png', 'fig7_circulation_friction.png')]))
        rows, points, _ = circulation_rows(circ, 'velocity')
        if rows:
            keys = [('draft.Ws_%s_kg_s' % label, '%.4g' % ws, 'kg/s', '%.3g' % ref, 'eq 15')
                    for label, ws, ref in points]
            new['velocity'] = (rows, keys, figures('velocity', circ, [
                ('circulation_velocity.png', 'fig6_circulation_velocity.png')]))
        rows = profile_rows(circ)
        if rows:                       # the profiles protocol ran in this case
            rows += spout_height_rows(circ, u_ms)
            pngs = [(f, 'fig4_5_' + f) for f in sorted(os.listdir(circ))
                    if f.startswith('profiles_u') and f.endswith('.png')]
            new['profiles'] = (rows, [], figures('profiles', circ, pngs))
    for name, case, section in (('spoutheight', spout_height, spout_height_section),
                                ('heat', heat, heat_section), ('drying', drying, drying_section)):
        if case:        # one case copy, one section
            rows, keys, pngs = section(case)
            new[name] = (rows, keys, figures(name, case, pngs))
    for case in noplates:
        name, rows, keys, pngs = noplates_section(case)
        if name not in FIGURES:
            sys.exit('results: %s: %s has no section (expected 10 000 or 26 000 particles)'
                     % (os.path.join(case, 'ums.json'), name))
        new[name] = (rows, keys, figures(name, case, pngs))
    runs = coarse_runs or {}
    if coarse or runs.get('circulation') or runs.get('heat') or runs.get('speedup'):
        new['coarse'] = coarse_runs_section(coarse, runs, figure_dir)
    if maps:
        rows, keys, pngs = maps_section(maps)
        new['maps'] = (rows, keys, figures('maps', maps, pngs))
    if mixing:          # one section from every copy given, as drytime_sections
        remove_figures('mixing', figure_dir)
        rows, keys, pngs = [], [], []
        for case in mixing:
            r, k, p = mixing_section(case)
            rows, keys, pngs = rows + r, keys + k, pngs + copy(case, p, figure_dir)
        new['mixing'] = (rows, keys, pngs)
    if drytime:
        new['drytime'] = drytime_sections(drytime, figure_dir, sources)
    if mixing_candidates:
        rows, keys, pngs = mixing_candidates_section(mixing_candidates,
                                                     needed_rate(new, figure_dir))
        new['mixingcand'] = (rows, keys, figures('mixingcand', mixing_candidates, pngs))
    if bed3d:
        remove_figures('bed3d', figure_dir)
        rows, keys, pngs = [], [], []
        for k, case in enumerate(bed3d):
            r, kk, p = bed3d_section(case, k)
            rows, keys, pngs = rows + r, keys + kk, pngs + copy(case, p, figure_dir)
        new['bed3d'] = (rows, keys, pngs)
    if runs.get('bed3d'):
        remove_figures('bed3dcoarse', figure_dir)
        ref = reference_values(os.path.join(os.path.dirname(figure_dir), 'results.csv'))
        rows, keys, pngs = [], [], []
        for case in runs['bed3d']:
            r, k, p = bed3d_coarse_section(case, ref)
            rows, keys, pngs = rows + r, keys + k, pngs + copy(case, p, figure_dir)
        new['bed3dcoarse'] = (rows, keys, pngs)
    return {name: s + (drag_velocities(sources.get(name, [])),) for name, s in new.items()}


def drag_velocity(case):
    """The gas velocity of the drag in a protocol's case copy: its
    constant/couplingProperties' dragVelocity; a copy without the entry is
    from before it was written there, when cellCentre was the default.
    (Read as text: the copy's #include files exist only in its runs.)"""
    path = os.path.join(case, 'constant', 'couplingProperties')
    if not os.path.isfile(path):
        return None
    found = re.search(r'^\s*dragVelocity\s+(\w+)\s*;', open(path).read(), re.M)
    return found.group(1) if found else 'cellCentre'


def drag_velocities(cases):
    """The dragVelocity values of a section's case copies, sorted."""
    return sorted({v for v in map(drag_velocity, cases) if v})


def drag_velocity_line(names):
    """The section's line saying which gas velocity its runs' drag took."""
    text = {'flux': "the fluxes' interstitial velocity (`dragVelocity flux`, the default)",
            'cellCentre': "the cell-centre U (`dragVelocity cellCentre`, the default until "
                          "issue 25 made it flux)"}
    return ('Drag from %s.' % ' and '.join(text.get(n, '`%s`' % n) for n in names)
            if names else '')


def old_sections(path):
    """The sections of an existing RESULTS.md, by name."""
    text = open(path).read() if os.path.isfile(path) else ''
    return dict(re.findall(r'<!-- section (\w+) -->\n(.*?)<!-- end \1 -->\n', text, re.S))


def section_text(name, title, rows, figures, drag=''):
    lines = ['## %s' % title, ''] + ([drag, ''] if drag else []) + \
        ['| quantity | SpoutLab | paper | settings | wall time |', '|---|---|---|---|---|']
    # a '|' inside a cell would end it
    lines += ['| %s | %s | %s | %s | %s |' % tuple(str(c).replace('|', '\\|') for c in r)
              for r in rows]
    if figures:
        lines += [''] + ['![%s](figures/%s)' % (f[:-4], f) for f in figures]
    return '\n'.join(lines) + '\n\n'


def with_drag(row, names):
    """A results.csv row whose note ends with its section's drag velocities
    (drag_velocities), e.g. '; dragVelocity flux'."""
    if names:
        row['note'] = '; '.join(([row['note']] if row['note'] else [])
                                + ['dragVelocity ' + n for n in names])
    return row


def write_csv(path, new):
    """results.csv: the regenerated sections' rows, the others as they were."""
    kept = []
    if os.path.isfile(path):
        kept = [r for r in csv.DictReader(open(path)) if section_of_key(r['key']) not in new]
    rows = kept + [with_drag(dict(zip(CSV_HEADER, k)), s[3]) for s in new.values() for k in s[1]]
    order = [name for name, _ in SECTIONS]
    rows.sort(key=lambda r: order.index(section_of_key(r['key'])))
    with open(path, 'w', newline='') as f:
        w = csv.DictWriter(f, CSV_HEADER)
        w.writeheader()
        w.writerows(rows)
    return len(rows)


def parse(argv):
    p = cli.parser('results', __doc__)
    p.add_argument('cases', nargs='*', metavar='CASE_DIR',
                   help='UMS_DIR, a case copy where protocols/minimumSpouting ran (ums.json, '
                        'ums.csv), then CIRCULATION_DIR, one where protocols/circulation '
                        'and profiles ran')
    p.add_argument('--circulation', metavar='CIRCULATION_DIR',
                   help='CIRCULATION_DIR without a UMS_DIR: its sections (friction, '
                        'velocity, profiles) rewritten, minimum spouting kept')
    p.add_argument('--heat', metavar='HEAT_DIR',
                   help='a case copy where protocols/heatTransfer ran (heat.csv)')
    p.add_argument('--drying', metavar='DRYING_DIR',
                   help='a case copy where protocols/drying ran (drying.json)')
    p.add_argument('--dryingTime', action='append', default=[], metavar='DRYINGTIME_DIR',
                   help='a case copy where protocols/dryingTime ran (dryingTime.json); repeat '
                        'for several, e.g. the reduced bed and the full one')
    p.add_argument('--noplates', action='append', default=[], metavar='UMS_DIR',
                   help='a case copy where minimumSpouting --vessel no-plates ran, with '
                        '10 000 or 26 000 particles (repeat for both)')
    p.add_argument('--coarse', action='append', default=[], metavar='UMS_DIR',
                   help='a case copy where minimumSpouting ran on the draft-plate bed with '
                        'coarseGraining > 1 (repeat for several factors)')
    p.add_argument('--bed3dCoarse', action='append', default=[], metavar='UMS3D_DIR',
                   help='a copy of openfoam_cases/spoutedBed3D where protocols/'
                        'minimumSpouting3D ran with coarseGraining > 1 (keys bed3d.cg<N>.*)')
    for name, protocol in (('Circulation', 'circulation friction'),
                           ('Heat', 'heatTransfer'), ('Speedup', 'coarseSpeedup')):
        p.add_argument('--coarse' + name, action='append', default=[], metavar='DIR',
                       help='a case copy where protocols/%s ran with coarseGraining > 1 '
                            '(coarseSpeedup: at every factor); its rows join the coarse-'
                            'graining section, which a call rewrites whole: give it every '
                            '--coarse* run' % protocol)
    p.add_argument('--maps', metavar='MAPS_DIR',
                   help='a case copy where protocols/velocityMaps ran (maps.txt)')
    p.add_argument('--mixing', action='append', default=[], metavar='MIXING_DIR',
                   help='a case copy where protocols/mixing ran (mixing.txt); repeat for '
                        'several, e.g. one with longer runs')
    p.add_argument('--mixingCandidates', metavar='CANDIDATES_DIR',
                   help='a case copy where protocols/mixing --candidates ran '
                        '(mixingCandidates.json)')
    p.add_argument('--spoutHeight', metavar='SPOUTHEIGHT_DIR',
                   help='a case copy where protocols/spoutHeight ran (spoutHeight.json)')
    p.add_argument('--bed3d', action='append', default=[], metavar='UMS3D_DIR',
                   help='a copy of openfoam_cases/spoutedBed3D where protocols/'
                        'minimumSpouting3D ran (repeat for other realisations)')
    p.add_argument('-o', dest='out', metavar='RESULTS.md',
                   default=os.path.join(os.environ.get('SPOUTLAB_DIR', '../..'), 'docs',
                                        'RESULTS.md'),
                   help='the table to write (default: docs/RESULTS.md of the repository); '
                        'results.csv and figures/ go beside it')
    a = cli.parse(p, argv)
    if len(a.cases) > 2:
        p.error('expected at most UMS_DIR and CIRCULATION_DIR, got %d directories'
                % len(a.cases))
    if a.circulation and len(a.cases) > 1:
        p.error('--circulation: CIRCULATION_DIR given twice (second directory and option)')
    return p, a


def main(argv):
    p, a = parse(argv)
    out, cases, heat, noplates, maps, mixing = (a.out, a.cases, a.heat, a.noplates, a.maps,
                                                a.mixing)
    if not (cases or a.circulation or heat or noplates or maps or mixing or a.mixingCandidates or a.drying
            or a.dryingTime or a.coarse or a.bed3d or a.coarseCirculation or a.coarseHeat
            or a.coarseSpeedup or a.bed3dCoarse or a.spoutHeight):
        p.print_help()
        return 2
    ums = cases[0] if cases else None
    circ = cases[1] if len(cases) > 1 else a.circulation
    new = build(ums, circ, heat, os.path.join(os.path.dirname(out), 'figures'), noplates, maps,
                mixing, a.drying, a.dryingTime, a.coarse, a.bed3d,
                {'circulation': a.coarseCirculation, 'heat': a.coarseHeat,
                 'speedup': a.coarseSpeedup, 'bed3d': a.bed3dCoarse}, a.mixingCandidates,
                a.spoutHeight)
    old = old_sections(out)
    lines = ['# SpoutLab vs the source papers', '',
             'Written by `openfoam_cases/spoutDraftPlates/protocols/results` from the protocol',
             'outputs; do not edit by hand. Each section comes from the runs named in its',
             'settings; a call of `results` rewrites the sections whose runs it is given.',
             'Targets: docs/DESIGN.md §4. The same numbers, machine-readable: results.csv.',
             'A section that does not say from which gas velocity its drag was taken is from',
             'before `dragVelocity flux` became the default: `cellCentre`.', '']
    for name, title in SECTIONS:
        text = section_text(name, title, new[name][0], new[name][2],
                            drag_velocity_line(new[name][3])) \
            if name in new else old.get(name)
        if text:
            lines.append('<!-- section %s -->\n%s<!-- end %s -->' % (name, text, name))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    open(out, 'w').write('\n'.join(lines) + '\n')
    n = write_csv(os.path.join(os.path.dirname(out), 'results.csv'), new)
    print('results: wrote %s (sections %s) and results.csv (%d rows)'
          % (out, ', '.join(new), n))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
