"""Issue 27 item 8: how much faster the draft-plate bed runs coarse-grained.
The same span of spouting at coarseGraining 1 and at each other factor
--cg gives, run one after the other in this one command, serially (one
rank, the protocols' way), so that both wall times are taken on the same
machine under the same load.

Each factor is one run in runs/cg<N>/ (a copy of this case with
coarseGraining N and the overrides): mesh and settle its bed (timed
apart), then spout it from the settled bed at --u for --spinup seconds,
which breaks the packed bed through, and --span seconds more, the span
timed.  The time step, the gas mesh, the coupling and the writes are the
case's own at every factor: only the parcels change.  The span's cost is
spoutFoam's CPU time between the log's steps at its ends (ExecutionTime,
resolved to 0.01 s; LIGGGHTS runs inside the process), beside its wall
time (ClockTime, whole seconds); the speed-up is cg = 1's over cg = N's.
That the spans are the same kind of state is shown beside them: the mean
pressure drop over the span (axis probe) and the spout classifier's
verdict (spoutlab.spoutregime.bed_spouts).

Restart: a factor whose run finished is kept; an interrupted one starts
again from its settled bed.  Results: speedup.txt and speedup.json (read
by protocols/results --coarseSpeedup)."""
import json
import os
import re
import shutil
import subprocess
import sys
import time

from spoutlab import caserun
from spoutlab import casefiles as sc
from spoutlab import cli
from spoutlab import spoutedbed
from spoutlab import spoutregime
from spoutlab.protocols import heattransfer


def options(argv):
    p = cli.parser('coarseSpeedup', __doc__)
    p.add_argument('--cg', type=cli.numbers, default=[2.0], metavar='CG,...',
                   help='coarse-graining factors timed against cg = 1 (default 2)')
    p.add_argument('--u', type=float, default=2.0, metavar='U',
                   help='superficial velocity [m/s] (default %(default)s, the heat case\'s)')
    p.add_argument('--spinup', type=float, default=0.6, metavar='T',
                   help='spouting before the timed span [s] (default %(default)s)')
    p.add_argument('--span', type=float, default=0.9, metavar='T',
                   help='the timed span [s] (default %(default)s)')
    cli.add_overrides(p, 'system/spoutedBedDict for every run')
    o = vars(cli.parse(p, argv))
    if o['spinup'] <= 0 or o['span'] <= 0:
        p.error('--spinup and --span must be positive')
    if [cg for cg in o['cg'] if cg <= 1]:
        p.error('--cg: factors above 1 (cg = 1 is always run)')
    if [x for x in o['overrides'] if x.startswith('coarseGraining=')]:
        p.error('coarseGraining is set per run by --cg, not as an override')
    return o


def log_times(log):
    """[(simulated time, CPU s, wall s)] of every step of a solver log."""
    rows, t = [], None
    for line in open(log, errors='replace'):
        if line.startswith('Time = '):
            t = float(line.split()[2])
            continue
        m = re.match(r'ExecutionTime = ([\d.e+-]+) s\s+ClockTime = (\d+) s', line)
        if m and t is not None:
            rows.append((t, float(m.group(1)), float(m.group(2))))
    return rows


def at(rows, t):
    """The log row of the step nearest to t."""
    return min(rows, key=lambda r: abs(r[0] - t))


def run(o, cg):
    """Prepare (once) and run the factor cg in runs/cg<N>/; returns its
    numbers."""
    name = 'cg%g' % cg
    work = os.path.join('runs', name)
    end = o['spinup'] + o['span']
    if os.path.isdir(work) and not os.path.isfile(os.path.join(work, 'log.settleWallTime')):
        shutil.rmtree(work)                 # stopped while settling: start again
    if not os.path.isdir(work):
        os.makedirs('runs', exist_ok=True)
        shutil.copytree('.', work, ignore=shutil.ignore_patterns(
            'runs', 'processor*', 'DEM', 'particles', 'postProcessing', 'log.*',
            '[0-9]*', '*.png', '*.csv', '*.txt', '*.json'), symlinks=True)
        shutil.copytree('0.orig', os.path.join(work, '0.orig'), dirs_exist_ok=True)
    here = os.getcwd()
    heattransfer.inside(work)
    try:
        if not os.path.isfile('log.settleWallTime'):
            t0 = time.time()
            caserun.prepare_case(['coarseGraining=%g' % cg] + o['overrides'], 'coarseSpeedup',
                                 probes_only=True)
            open('log.settleWallTime', 'w').write('%.1f\n' % (time.time() - t0))
        done = (caserun.last_time('log.spoutFoam') or 0.0) >= end - 1e-3
        if not done and os.path.isfile('log.spoutFoam'):
            # interrupted: again from the settled bed, so the span is one process
            for f in os.listdir('.'):
                if re.match(r'[0-9.]+$', f) and f != '0' or f in ('postProcessing', 'particles'):
                    shutil.rmtree(f)
            for f in os.listdir('DEM'):
                if f.startswith('restart_'):
                    os.remove(os.path.join('DEM', f))
            os.remove('log.spoutFoam')
        if not done:
            subprocess.check_call(['./inletVelocity', '%g' % o['u']])
            heattransfer.setting('endTime', '%g' % end)
            load = os.getloadavg()[0]
            caserun.run_spoutfoam(end, 1, 'coarseSpeedup (cg %g)' % cg)
            open('log.loadAverage', 'w').write('%.2f %.2f\n' % (load, os.getloadavg()[0]))
        rows = log_times('log.spoutFoam')
        a, b = at(rows, o['spinup']), at(rows, end)
        g = spoutedbed.load('.')
        _, probe = sc.read_function_object('.', 'pressureProbe', 'p')
        dp = [r[1] for r in probe if a[0] <= r[0] <= b[0]]
        verdict = spoutregime.bed_spouts(g, '.', a[0], b[0])
        parcels = len(sc.read_vtp_points('particles/particles_0.vtp'))
        settle = float(open('log.settleWallTime').read())
        load = [float(x) for x in open('log.loadAverage').read().split()] \
            if os.path.isfile('log.loadAverage') else []
    finally:
        heattransfer.inside(here)
    return {'cg': cg, 'parcels': parcels, 'span_s': [a[0], b[0]],
            'dem_steps': len([r for r in rows if a[0] < r[0] <= b[0]]),
            'cpu_s': round(b[1] - a[1], 2), 'wall_s': b[2] - a[2],
            'run_cpu_s': round(rows[-1][1], 2), 'run_wall_s': rows[-1][2],
            'settle_wall_s': settle, 'load_average': load,
            'dP_Pa': round(sum(dp) / len(dp)) if dp else None,
            'spouts': verdict.spouts, 'classifier': verdict.describe()}


def main(argv):
    o = options(argv)
    runs = [run(o, cg) for cg in [1.0] + o['cg']]
    one = runs[0]
    lines = ['coarse-graining speed-up: the draft-plate bed (%s) at u_s = %g m/s from its '
             'settled bed, %g s of spouting, then %g s timed, serially, one factor after '
             'the other' % (' '.join(o['overrides']) or 'the case as it is', o['u'],
                            o['spinup'], o['span']), '',
             '%4s %8s %10s %9s %9s %10s %9s %8s  %s' % (
                 'cg', 'parcels', 'DEM steps', 'CPU [s]', 'wall [s]', 'CPU/sim s',
                 'speed-up', 'dP [Pa]', 'spout classifier over the span')]
    for r in runs:
        r['cpu_per_simulated_s'] = round(r['cpu_s'] / (r['span_s'][1] - r['span_s'][0]), 1)
        r['speedup'] = round(one['cpu_s'] / r['cpu_s'], 2)
        r['speedup_wall'] = round(one['wall_s'] / r['wall_s'], 2) if r['wall_s'] else None
        lines.append('%4g %8d %10d %9.2f %9.0f %10.1f %9.2f %8s  %s' % (
            r['cg'], r['parcels'], r['dem_steps'], r['cpu_s'], r['wall_s'],
            r['cpu_per_simulated_s'], r['speedup'], r['dP_Pa'], r['classifier']))
    lines += ['', 'settling (LIGGGHTS alone, not in the span): %s s of wall time'
              % ', '.join('cg %g %.0f' % (r['cg'], r['settle_wall_s']) for r in runs),
              'load average (1 min) at the start and end of each run: %s'
              % '; '.join('cg %g %s' % (r['cg'], ' '.join('%.2f' % x for x in r['load_average']))
                          for r in runs)]
    text = '\n'.join(lines) + '\n'
    sys.stdout.write(text)
    open('speedup.txt', 'w').write(text)
    with open('speedup.json', 'w') as f:
        json.dump({'settings': lines[0], 'u_m_s': o['u'], 'runs': runs}, f, indent=1)
        f.write('\n')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
