"""The minimum spouting velocity and the pressure-drop loop of Fig 2, as the
papers ran it (draft-plate paper section 4.1, no-draft paper 'Minimum
spouting velocity'), for the vessel with or without draft plates.

Increasing branch ('packed'): start on the settled bed at --from and raise
u_s by --step until the bed spouts (pressure drop rising to a peak, then
falling once the spout breaks through) or --top is reached.  Decreasing
branch ('down'): lower u_s step by step from there until the spout
collapses and dP rises steeply; u_ms is the last step that still spouts
(the paper's criterion).  With --up, u_s then rises again ('up').  Each
step lasts --hold seconds; its pressure drop (axis probe 11 mm above the
bottom) is averaged over the last --average seconds, and whether the bed
spouts is the spout classifier's verdict over the particle files of that
window (spoutlab.spoutregime.bed_spouts).  The hysteresis is the
increasing branch's peak dP minus the decreasing branch's dP at the same
u_s.

The schedule is decided as the run goes, as at the rig: a branch changes
once --confirm successive steps agree (the break-through and one step
above it; two collapsed steps), so a bed that spouts for one step by
chance does not end the branch.

Restart: run the same command again after an interruption; spoutFoam
continues from the last written time (LIGGGHTS restarts are in DEM/) and
the finished steps decide the same schedule again.  Progress is printed
every few seconds and a line per finished step.
Results: ums.csv, ums.png, ums.txt, snapshot_<branch>_u<u>.png, and ums.json, the
report's numbers as it prints them (read by protocols/results).
"""
import json
import math
import os
import subprocess
import sys

from spoutlab import cli
from spoutlab import casefiles as sc
from spoutlab import spoutedbed
from spoutlab import bedmaps
from spoutlab import caserun
from spoutlab import spoutcorrelations
from spoutlab import spoutingloop
from spoutlab import spoutregime

# the papers' simulated u_ms [m/s] and dP_ms [kPa] by vessel and particles
PAPER = {('plates', 26000): (1.25, 1.40), ('no-plates', 10000): (2.0, 1.75)}


def options(argv):
    p = cli.parser('minimumSpouting', __doc__)
    p.add_argument('--vessel', choices=('plates', 'no-plates'), default='plates',
                   help="with draft plates (default) or without (system/spoutedBedDict "
                        "'plates')")
    p.add_argument('-n', type=int, help='particles (default: system/spoutedBedDict)')
    p.add_argument('-np', type=int, default=1, metavar='RANKS', help='MPI ranks')
    p.add_argument('--from', dest='rise_from', type=float, default=1.0, metavar='U',
                   help='first velocity of the increasing branch, on the settled bed '
                        '[m/s] (default %(default)s)')
    p.add_argument('--top', type=float, default=3.0, metavar='U',
                   help='highest velocity tried (default %(default)s): a bed still not '
                        'spouting there does not spout')
    p.add_argument('--stop', type=float, default=0.9, metavar='U',
                   help='lowest velocity of the decreasing branch (default %(default)s)')
    p.add_argument('--step', type=float, default=0.1, metavar='DU',
                   help='velocity step (default %(default)s)')
    p.add_argument('--up', action='store_true', help='after the collapse, raise u_s again')
    p.add_argument('--full-loop', action='store_true',
                   help='rise to --top, then fall to --stop, whatever the classifier says '
                        '(the paper\'s whole loop, the same steps for any verdicts); u_ms '
                        'is also read from dP alone, the step before its steepest rise on '
                        'the decreasing branch')
    p.add_argument('--confirm', type=int, default=2, metavar='N',
                   help='successive steps that confirm a break-through, a collapse or a '
                        're-formed spout (default %(default)s)')
    p.add_argument('--hold', type=float, default=2.5, metavar='T',
                   help='time per step [s] (default %(default)s)')
    p.add_argument('--average', type=float, default=1.8, metavar='T',
                   help='averaging window at the end of each step [s] (default %(default)s)')
    p.add_argument('--report', action='store_true',
                   help='write the report from the steps finished so far and stop (nothing '
                        'is run; e.g. while the protocol is still running)')
    p.add_argument('--kick', type=float, metavar='U',
                   help='instead of the increasing branch: spin the bed up at U for '
                        '--spinup seconds, then lower u_s from --start')
    p.add_argument('--spinup', type=float, default=1.5, metavar='T',
                   help='spin-up time with --kick [s] (default %(default)s)')
    p.add_argument('--start', type=float, default=2.0, metavar='U',
                   help='first velocity after the spin-up (default %(default)s)')
    cli.add_overrides(p)
    o = vars(cli.parse(p, argv))
    if o['average'] > o['hold']:
        p.error('--average must not exceed --hold')
    o['overrides'].append('plates=%s' % ('yes' if o['vessel'] == 'plates' else 'no'))
    if o['n']:
        o['overrides'].append('nParticles=%d' % o['n'])
    if o['kick'] is not None:
        o['schedule'] = spoutingloop.Schedule(o['step'], o['stop'], start=o['start'], up=o['up'],
                                            confirm=o['confirm'])
    else:
        o['schedule'] = spoutingloop.Schedule(o['step'], o['stop'], rise_from=o['rise_from'],
                                            top=o['top'], up=o['up'], confirm=o['confirm'],
                                            full_loop=o['full_loop'])
    return o


def timeline(o, speeds):
    """(start time, u_s, branch) of every step so far, and the end of the
    last one; a spin-up, if any, comes first."""
    steps, t = [], 0.0
    if o['kick'] is not None:
        steps.append((0.0, o['kick'], 'spinup'))
        t = o['spinup']
    for u, branch in speeds:
        steps.append((t, u, branch))
        t += o['hold']
    return steps, t


def extend(steps, end):
    """The inlet table and the end time for the steps so far."""
    flat = []
    for t, u, _ in steps:
        flat += ['%g' % t, '%g' % u]
    subprocess.check_call(['./inletVelocity'] + flat)
    subprocess.check_call(['foamDictionary', '-entry', 'endTime', '-set', '%g' % end,
                           'system/controlDict'], stdout=subprocess.DEVNULL)


class Step:
    """One finished step: u_s, branch, the window's mean pressure drop and
    spout-axis solid flux, its end time and the classifier's verdict."""

    def __init__(self, u, branch, dp, flux, end, verdict):
        self.u, self.branch, self.dp, self.flux, self.end = u, branch, dp, flux, end
        self.verdict = verdict
        self.spouts = verdict.spouts


VERDICTS = {}


def evaluate(o, steps, g):
    _, rows = sc.read_function_object('.', 'pressureProbe', 'p')
    _, flux = sc.read_function_object('.', 'spoutFlux', 'solidFlux')
    done = []
    for k, (t0, u, branch) in enumerate(steps):
        t1 = steps[k + 1][0] if k + 1 < len(steps) else \
            t0 + (o['spinup'] if branch == 'spinup' else o['hold'])
        lo = t1 - o['average']
        dp = [r[1] for r in rows if lo <= r[0] <= t1]
        up = [r[3] for r in flux if lo <= r[0] <= t1]     # z component of probe 0
        if not dp or rows[-1][0] < t1 - 5e-3:              # the step has not finished
            break
        if (lo, t1) not in VERDICTS:       # the particle files of a finished step stay
            VERDICTS[(lo, t1)] = spoutregime.bed_spouts(g, '.', lo, t1)
        done.append(Step(u, branch, sum(dp) / len(dp), sum(up) / len(up) if up else float('nan'),
                         t1, VERDICTS[(lo, t1)]))
    return done


def snapshots(g, done):
    """Particles coloured by vertical velocity at the last particle output
    of each step: snapshot_<branch>_u<u>.png."""
    series = sc.particle_files('.')
    names = []
    for s in done:
        shown = [(t, f) for t, f in series if t <= s.end + 1e-6]
        if not shown:
            continue
        t, f = shown[-1]
        name = 'snapshot_%s_u%g.png' % (s.branch, s.u)
        bedmaps.snapshot(g, f, name, 'u_s = %g m/s (%s), t = %g s' % (s.u, s.branch, t),
                            vmax=1.0)
        names.append(name)
    return names


def branch(done, name):
    return [(s.u, s.dp, s.spouts) for s in done if s.branch == name]


def reported(fmt, value):
    """value as the report prints it (fmt), as a number."""
    return float(fmt % value)


def write_steps(done):
    """ums.csv: one row per finished step."""
    with open('ums.csv', 'w') as f:
        f.write('superficial velocity [m/s],branch,pressure drop [Pa],'
                'solid flux on the spout axis [m/s],spouts (classifier)\n')
        for s in done:
            f.write('%.4g,%s,%.6g,%.6g,%d\n' % (s.u, s.branch, s.dp, s.flux, s.spouts))


def settings_lines(o, n, Hb, vessel, packed, down, up):
    """The report's first two lines: the bed and the schedule as run."""
    if packed:
        how = 'from %g m/s up to %g on the settled bed' % (packed[0][0], packed[-1][0])
        how += ', then down to %g' % down[-1][0] if down else ''
    else:
        how = 'after a spin-up at %g m/s for %g s, from %g m/s down to %g' % (
            o['kick'], o['spinup'], down[0][0], down[-1][0])
    how += ' and back up to %g' % up[-1][0] if up else ''
    return ['minimum spouting velocity protocol (%d particles, settled bed %.3f m, %s)'
            % (n, Hb, vessel),
            'steps %s by %g m/s, %g s each, pressure drop averaged over the last %g s, '
            'spouts or not by the spout classifier over the same window'
            % (how, o['step'], o['hold'], o['average'])]


def steps_table(shown):
    """The table of the steps, a blank line before and after."""
    lines = ['', '%8s %6s %12s %16s %7s  %s' % ('u_s', 'branch', 'dP [Pa]', 'spout flux [m/s]',
                                                'spouts', 'classifier')]
    lines += ['%8.3f %6s %12.0f %16.4g %7s  %s' % (s.u, s.branch, s.dp, s.flux,
                                                   'yes' if s.spouts else 'no',
                                                   s.verdict.describe()) for s in shown]
    lines.append('')
    return lines


def packed_branch(packed, lines, numbers):
    """The increasing branch from the packed bed: its peak and the break-through."""
    u_peak, dp_peak, u_b, dp_b = spoutingloop.break_through(packed)
    numbers['peak'] = {'dP_Pa': reported('%.0f', dp_peak), 'u_m_s': reported('%.3f', u_peak)}
    numbers['break_through_m_s'] = None if u_b is None else reported('%.3f', u_b)
    if u_b is None:
        lines.append('the bed does not spout at any u_s up to %.3f m/s (highest tried); '
                     'peak dP %.0f Pa at %.3f m/s' % (packed[-1][0], dp_peak, u_peak))
    else:
        lines.append('packed bed: dP peaks at %.0f Pa at %.3f m/s; the spout breaks '
                     'through at %.3f m/s (dP %.0f Pa, %+.0f %% of the peak)'
                     % (dp_peak, u_peak, u_b, dp_b, 100 * (dp_b / dp_peak - 1)))


def minimum_spouting(down, ref, lines, numbers):
    """u_ms from the classifier on the decreasing branch (or its bound), and
    from dP alone; returns the classifier's (u_ms, dP_ms, dP below) or None."""
    ms = spoutingloop.minimum_spouting(down)
    if ms:
        numbers['u_ms'] = {'u_m_s': reported('%.3f', ms[0]), 'dP_Pa': reported('%.0f', ms[1]),
                           'bound': False}
        lines.append('u_ms = %.3f m/s, dP_ms = %.0f Pa%s: at the next cut the bed stops '
                     'spouting, dP %.0f Pa (%+.0f %%)'
                     % (ms[0], ms[1], ref, ms[2], 100 * (ms[2] / ms[1] - 1)))
    elif down and down[-1][2]:
        numbers['u_ms'] = {'u_m_s': reported('%.3f', down[-1][0]),
                           'dP_Pa': reported('%.0f', down[-1][1]), 'bound': True}
        lines.append('u_ms <= %.3f m/s, dP_ms = %.0f Pa%s: the bed still spouted at the '
                     'lowest step: lower --stop' % (down[-1][0], down[-1][1], ref))
    elif down:
        lines.append('no u_ms: the bed did not spout on the decreasing branch')
    rise = spoutingloop.steepest_rise(down)
    if rise:
        numbers['u_ms_by_dP'] = {'u_m_s': reported('%.3f', rise[0]),
                                 'dP_Pa': reported('%.0f', rise[1])}
        lines.append('u_ms by dP alone = %.3f m/s, dP_ms = %.0f Pa%s: the step before dP\'s '
                     'steepest rise on the decreasing branch, to %.0f Pa one step below'
                     % (rise[0], rise[1], ref, rise[2]))
    return ms


def spout_reforms(up, ms, lines, numbers):
    """Raising u_s again after the collapse: where the spout re-forms."""
    back = spoutingloop.spout_reforms(up)
    if back:
        above = ms is not None and back[0] > ms[0] + 1e-6
        numbers['reforms'] = {'u_m_s': reported('%.3f', back[0]),
                              'dP_Pa': reported('%.0f', back[1])}
        lines.append('increasing u_s again: the bed spouts again at %.3f m/s, dP %.0f Pa '
                     '(%s)' % (back + ('above u_ms: a hysteresis in u_s' if above
                                       else 'not above u_ms: no hysteresis in u_s',)))
    elif up:
        lines.append('increasing u_s again: the spout did not re-form up to %.3f m/s'
                     % up[-1][0])


def correlations(g, Hb, eps, lines, numbers):
    """Ergun's u_mf (Wen and Yu's form, and at the settled voidage) and, with
    plates, Kudra's u_ms for this bed."""
    rho = g.gas['rho']
    p = g.particles
    umf = spoutcorrelations.ergun_umf(p['dp'] / 1000, p['rhop'], rho, g.gas['mu'])
    umf_eps = spoutcorrelations.ergun_umf(p['dp'] / 1000, p['rhop'], rho, g.gas['mu'], eps)
    numbers['u_mf_ergun_m_s'] = reported('%.3f', umf)
    numbers['u_mf_settled'] = {'voidage': reported('%.3f', eps),
                               'u_m_s': reported('%.3f', umf_eps)}
    lines.append("Ergun's u_mf: %.3f m/s in Wen and Yu's form (the no-draft paper: 1.746 m/s); "
                 "%.3f m/s at the settled bed's voidage %.3f"
                 % (umf, umf_eps, eps))
    if g.plates:
        numbers['kudra_m_s'] = {'scaled': reported('%.3f', spoutcorrelations.kudra_ums(g, Hb)),
                                'direct': reported('%.3f', spoutcorrelations.kudra_eq12(g, Hb))}
        lines.append("Kudra's eq 12 scaled to this geometry and bed height: %.3f m/s; evaluated "
                     "directly: %.3f m/s (eq 13 as the paper evaluates it: 1.20 kPa)"
                     % (spoutcorrelations.kudra_ums(g, Hb), spoutcorrelations.kudra_eq12(g, Hb)))


def plot_loop(vessel, n, paper):
    """ums.png: the pressure-drop loop of Fig 2, the paper's point if known."""
    mark = (',\\\n     "<echo %g,%g" using 1:2 with points pt 9 ps 2 title "paper: u_{ms}, dP_{ms}"'
            % paper) if paper else ''
    sc.plot('ums.png', '''
set title "Pressure drop vs superficial velocity (%s, %d particles)"
set xlabel "superficial gas velocity u_s [m/s]"
set ylabel "pressure drop [kPa]"
set grid
set key top right
set datafile separator ","
plot "ums.csv" skip 1 using 1:(strcol(2) eq "packed" ? $3/1000 : 1/0) with linespoints pt 13 title "increasing u_s from the packed bed", \\
     "ums.csv" skip 1 using 1:(strcol(2) eq "down" ? $3/1000 : 1/0) with linespoints pt 7 title "decreasing u_s", \\
     "ums.csv" skip 1 using 1:(strcol(2) eq "up" ? $3/1000 : 1/0) with linespoints pt 5 title "increasing u_s again"%s
''' % (vessel, n, mark))


def report(o, done, g):
    """ums.csv, ums.txt (also printed), ums.json and ums.png from the
    finished steps, and a snapshot at the end of each."""
    n = int(g.particles['nParticles'])
    Hb, eps = spoutedbed.settled_bed(g, 'particles/particles_0.vtp')
    paper = PAPER.get((o['vessel'], n))
    write_steps(done)
    packed, down, up = branch(done, 'packed'), branch(done, 'down'), branch(done, 'up')
    shown = [s for s in done if s.branch != 'spinup']
    vessel = 'draft plates' if g.plates else 'no draft plates'
    lines = settings_lines(o, n, Hb, vessel, packed, down, up) + steps_table(shown)
    # the numbers of the report as it prints them, for protocols/results (ums.json)
    numbers = {'particles': n, 'bed_height_m': reported('%.3f', Hb), 'plates': g.plates,
               'settings': '; '.join(lines[:2]),
               'cores': [[reported('%.3f', s.u), s.branch, reported('%.2f', s.verdict.core_ratio)]
                         for s in shown if s.verdict.snapshots
                         and not math.isnan(s.verdict.core_ratio)]}
    ref = ' (paper: %g m/s, %.2f kPa)' % paper if paper else ''
    if packed:
        packed_branch(packed, lines, numbers)
    # the hysteresis compares the rise with the steps taken on the way down;
    # u_ms is read from the whole decreasing branch, which begins at the top
    # of the rise, where the bed spouts
    loop = spoutingloop.hysteresis(packed, down)
    if packed and down:
        down = packed[-1:] + down
    ms = minimum_spouting(down, ref, lines, numbers)
    if loop is not None:
        numbers['hysteresis_Pa'] = reported('%.0f', loop)
        lines.append('hysteresis = %.0f Pa: the increasing branch\'s peak dP minus the '
                     'decreasing branch\'s dP at %.3f m/s'
                     % (loop, spoutingloop.break_through(packed)[0]))
    spout_reforms(up, ms, lines, numbers)
    correlations(g, Hb, eps, lines, numbers)
    lines.append('flow patterns at the end of each step (Fig 3): '
                 + ' '.join(snapshots(g, shown)))
    text = '\n'.join(lines) + '\n'
    sys.stdout.write(text)
    open('ums.txt', 'w').write(text)
    with open('ums.json', 'w') as f:
        json.dump(numbers, f, indent=1)
        f.write('\n')
    plot_loop(vessel, n, paper)


def main(argv):
    o = options(argv)
    # mesh and settle (skipped when continuing); the protocol reads probes
    # and particle files, not time-averaged fields
    if not o['report']:
        caserun.prepare_case(o['overrides'], 'minimumSpouting', probes_only=True)
    elif not os.path.isfile('log.spoutFoam'):
        sys.exit('minimumSpouting: --report: no run here yet (no log.spoutFoam)')
    g = spoutedbed.load('.')
    plan = o['schedule']
    speeds = [plan.first()]
    shown = 0
    while True:
        steps, end = timeline(o, speeds)
        if not o['report']:
            extend(steps, end)
            if (caserun.last_time('log.spoutFoam') or 0.0) < end - 1e-3:  # the log rounds
                caserun.run_spoutfoam(end, o['np'], 'minimumSpouting')
        done = evaluate(o, steps, g)
        for k in range(shown, 0 if o['report'] else len(done)):
            s = done[k]
            print('minimumSpouting: step %d, u_s = %g m/s (%s): dP %.0f Pa, spout flux '
                  '%.3g m/s; the bed %s' % (k + 1, s.u, s.branch, s.dp, s.flux,
                                           s.verdict.describe()), flush=True)
        shown = len(done)
        if o['report'] and len(done) < len(steps):   # --report: the run went no further
            break
        nxt = plan.next([(s.u, s.branch, s.spouts) for s in done if s.branch != 'spinup'])
        if nxt is None:
            break
        speeds.append(nxt)
    if not [s for s in done if s.branch != 'spinup']:
        sys.exit('minimumSpouting: no finished step to report yet')
    report(o, done, g)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
