"""Protocols (c) and (d) of the draft-plate paper, section 4.4: the particle
circulation rate W_s (eq 14) against the gas velocity for two entrance
heights (eq 15, Fig 6), and against the friction coefficient at u_ms
(eq 16 with its minus sign restored, Fig 7).

Each point is one run of the case (in runs/<label>/, a copy of the case):
break through the packed bed at the --kick velocity, then spout at u_s
until --time seconds, W_s averaged over the last --average seconds.  Runs
that differ only in u_s share one settled bed.  Finished runs are kept, so
running the command again after an interruption continues with the missing
points: an interrupted one from its last write (the case's Allrun -c), or
again on its settled bed if spoutFoam had not started.  A longer --time
with the same averaging start (--time minus --average) continues the
finished runs, e.g. --time 30 --average 28 after --time 12 --average 10.

Results: circulation_<study>.csv / .png / .txt, and circulation_<study>.json, the
table's numbers (read by protocols/results)
"""
import argparse
import concurrent.futures
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys

from spoutlab import casefiles as sc
from spoutlab import caserun
from spoutlab import cli


def eq15(u, He):
    """W_s [kg/s] of the paper's eq 15 (fitted to its simulations)."""
    return 0.3251 * math.sqrt(u) - 0.265 if He == 95 else 0.1641 * math.sqrt(u) + 0.111


def eq16(mu):
    """W_s [kg/s] at u_ms, eq 16 with the sign lost in the OCR restored."""
    return 10 ** (-3.25 * mu - 0.194)


def whole(text):
    """A whole number, kept as written (it goes to the case's Allrun)."""
    try:
        int(text)
    except ValueError:
        raise argparse.ArgumentTypeError('expected a whole number, got %r' % text)
    return text


def run_options(p, kick='2.0,1.0', particles=True):
    """The options of a run of the case, shared by the protocols that make
    their points with run_point (circulation, profiles, velocityMaps)."""
    p.add_argument('--time', type=float, default=4.0, metavar='T',
                   help='simulated time of each run [s] (default %(default)s)')
    p.add_argument('--average', type=float, default=1.8, metavar='T',
                   help='averaging window at the end of each run [s] (default %(default)s)')
    p.add_argument('--kick', type=cli.pair, default=kick, metavar='U,T',
                   help='spin-up velocity [m/s] and time [s] that break the packed bed '
                        'through (default %(default)s)')
    if particles:
        p.add_argument('-n', type=whole, help='particles (default: system/spoutedBedDict)')
    p.add_argument('-np', type=int, default=1, metavar='RANKS', help='MPI ranks per run')
    p.add_argument('-j', '--jobs', type=int, default=1, metavar='JOBS',
                   help='runs side by side (default 1; on 2 cores: -j 2)')
    cli.add_overrides(p, 'system/spoutedBedDict for every run')


def parse(argv):
    p = cli.parser('circulation', __doc__)
    p.add_argument('study', choices=('velocity', 'friction'),
                   help='W_s against u_s for entrance heights (eq 15, Fig 6), or against '
                        'the friction coefficient at u_ms (eq 16, Fig 7)')
    p.add_argument('--He', type=cli.numbers, default=[95, 152], metavar='MM,...',
                   help='entrance heights of the velocity study [mm] (default 95,152)')
    p.add_argument('--u', type=cli.numbers, metavar='U,...',
                   help='superficial velocities [m/s] (default 1.4,1.6,1.8,2.0,2.2; '
                        'friction: 1.25)')
    p.add_argument('--mu', type=cli.numbers, default=[0.02, 0.063, 0.1, 0.2, 0.3],
                   metavar='MU,...', help='friction coefficients of the friction study '
                                          '(default 0.02,0.063,0.1,0.2,0.3)')
    p.add_argument('--target-error', type=float, metavar='F',
                   help="continue each run by --step seconds, its averaging start kept, "
                        "until W_s's standard error is below F of W_s (e.g. 0.05), at most "
                        "to --longest (default: each run to --time)")
    p.add_argument('--step', type=float, default=6.0, metavar='T',
                   help='with --target-error: seconds added at a time (default %(default)s)')
    p.add_argument('--longest', type=float, default=60.0, metavar='T',
                   help='with --target-error: the longest run [s] (default %(default)s)')
    run_options(p)
    o = vars(cli.parse(p, argv))
    if o['target_error'] is not None and not 0 < o['target_error'] < 1:
        p.error('--target-error: a fraction of W_s between 0 and 1, got %g' % o['target_error'])
    if o['step'] <= 0:
        p.error('--step: a positive time, got %g' % o['step'])
    if o['u'] is None:
        o['u'] = [1.25] if o['study'] == 'friction' else [1.4, 1.6, 1.8, 2.0, 2.2]
    return o


def points(o):
    if o['study'] == 'velocity':
        return [('He%g_u%g' % (He, u), u, ['He=%g' % He], He, None)
                for He in o['He'] for u in o['u']]
    return [('mu%g_u%g' % (mu, o['u'][0]), o['u'][0], ['mu=%g' % mu], None, mu)
            for mu in o['mu']]


def settle_key(o, overrides):
    """What the settled bed depends on: everything but u_s."""
    return tuple(sorted(o['overrides'] + overrides + [o['n'] or '']))


def run_all(o, pts, entries=lambda p: ()):
    """Run the points (label, u_s, overrides, ...), --jobs at a time: first
    one point per settled bed, then the rest, which reuse those beds;
    entries(point), run_point's entries of each."""
    settled, first = {}, {}
    for p in pts:
        first.setdefault(settle_key(o, p[2]), p)
    rest = [p for p in pts if p not in first.values()]
    with concurrent.futures.ThreadPoolExecutor(o['jobs']) as pool:
        for batch in (list(first.values()), rest):
            list(pool.map(lambda p: run_point(o, p[0], p[1], p[2], settled, entries(p)), batch))


def run_point(o, label, u, overrides, settled, entries=()):
    """Run one point unless done; settled maps the settling overrides to a
    settled bed already made by another point; entries, (file, key, value)
    set in the copy's dictionaries (what no spoutedBedDict key sets, e.g.
    the drag law in constant/couplingProperties), which do not change the
    settled bed.  Every point runs with lostParticles delete."""
    work = os.path.join('runs', label)
    result = os.path.join(work, 'circulation.csv')
    # A particle that strikes a plate or the base faster than the soft
    # spring holds (r sqrt(k/m), 6.2 m/s at the paper's k_n) ends with its
    # centre in a wall, outside the gas mesh: a flow statistic loses nothing
    # by removing it, so the runs delete such particles and count them.
    entries = [('constant/couplingProperties', 'lostParticles', 'delete')] + list(entries)
    bed = os.path.join(work, 'DEM', 'settled.restart')
    key = settle_key(o, overrides)
    cmd = ['./Allrun', '-u', str(u), '-k', o['kick'], '-t', str(o['time']),
           '-a', str(o['average']), '-np', str(o['np'])] \
        + (['-n', o['n']] if o['n'] else []) + o['overrides'] + overrides
    done = recorded_options(work)
    if os.path.isfile(result) and covers(done, cmd[1:]):
        settled.setdefault(key, bed)
        return work
    # a run that got as far as spoutFoam goes on from its last write (the
    # Allrun's -c: interrupted, or finished and now asked for a later end
    # with the same averaging start; an interrupted continuation to its own
    # end); one that did not starts again
    continued = os.path.isfile(os.path.join(work, 'log.spoutFoam'))
    if continued:
        started = recorded_options(work, finished=False)
        if done is None and covers(started, cmd[1:]):
            cmd[1:] = started
        cmd.insert(1, '-c')
    elif os.path.isdir(work):
        restart_clean(work, bed)
    if not os.path.isdir(work):
        os.makedirs('runs', exist_ok=True)
        shutil.copytree('.', work, ignore=shutil.ignore_patterns(
            'runs', 'processor*', 'DEM', 'particles', 'postProcessing', 'log.*',
            '[0-9]*', '*.png', '*.csv'), symlinks=True)
        shutil.copytree('0.orig', os.path.join(work, '0.orig'), dirs_exist_ok=True)
    for path, entry, value in entries:
        set_entries(os.path.join(work, path), [(entry, value)])
    if key in settled and os.path.isfile(settled[key]) and not os.path.isfile(bed):
        os.makedirs(os.path.dirname(bed), exist_ok=True)
        shutil.copy(settled[key], bed)
    print('circulation: %s: %s' % (label, ' '.join(cmd[1:])), flush=True)
    with open(os.path.join(work, 'log.Allrun'), 'a' if continued else 'w') as log:
        if subprocess.call(cmd, cwd=work, stdout=log, stderr=subprocess.STDOUT) != 0:
            last = open(os.path.join(work, 'log.Allrun')).read().strip().splitlines()[-1:]
            sys.exit('circulation: run %s failed (%s), see %s/log.Allrun'
                     % (label, last[0] if last else 'no output', work))
    settled.setdefault(key, bed)
    return work


def set_entries(path, entries):
    """Entries of an OpenFOAM dictionary set as text (its includes are
    written later, by the case's generate): a top-level key, or 'sub/key'
    for a key of a top-level sub-dictionary."""
    if not entries:
        return
    text = open(path).read()
    for key, value in entries:
        sub, _, name = key.rpartition('/')
        start, end = 0, len(text)
        if sub:
            block = re.search(r'^%s\s*\{[^}]*\}' % re.escape(sub), text, flags=re.M)
            if not block:
                sys.exit('circulation: %s: expected a top-level sub-dictionary %r' % (path, sub))
            start, end = block.span()
        pattern = r'((?:^|[{;])\s*)%s\s+[^;]*;' if sub else r'^()%s\s+[^;]*;.*$'
        part, n = re.subn(pattern % re.escape(name),
                          r'\g<1>%s %s;%s' % (name, value, '' if sub else '   // set by the protocol'),
                          text[start:end], flags=re.M)
        if n != 1:
            sys.exit('circulation: %s: expected one %s entry %r, found %d'
                     % (path, 'sub-dictionary' if sub else 'top-level', key, n))
        text = text[:start] + part + text[end:]
    open(path, 'w').write(text)


def window(words):
    """(end, averaging start) [s] of the case's Allrun options (words), its
    defaults -t 3 -a 1.8 where absent."""
    value = dict(zip(words, words[1:]))
    end = float(value.get('-t', 3))
    return end, max(0.0, end - float(value.get('-a', 1.8)))


def covers(recorded, asked):
    """Whether a finished run's options (recorded) give what the asked ones
    would: the same but for -t and -a, the same averaging start, and an end
    at or after the asked one (a run continued past it, --target-error)."""
    if recorded is None:
        return False

    def others(words):
        return [w for i, w in enumerate(words)
                if w not in ('-t', '-a') and (i == 0 or words[i - 1] not in ('-t', '-a'))]
    (end, start), (asked_end, asked_start) = window(recorded), window(asked)
    return (others(recorded) == others(asked) and abs(start - asked_start) < 1e-9
            and end >= asked_end - 1e-9)


def extend(o, pts, entries=lambda p: ()):
    """--target-error: the points whose W_s standard error is above it (or
    that have none: a window shorter than two blocks) continue by --step
    seconds from where they ended, their averaging start kept, --jobs at a
    time, until each is below it or at --longest."""
    if o['target_error'] is None:
        return
    while True:
        todo = []
        for p in pts:
            work = os.path.join('runs', p[0])
            ws, err = w_s(work), w_s_error(work)
            end, start = window(recorded_options(work))
            if (err is None or err > o['target_error'] * ws) \
                    and end + o['step'] <= o['longest'] + 1e-9:
                print('circulation: %s: W_s = %.4f kg/s%s, above --target-error %g: on to %g s'
                      % (p[0], ws, error_text(ws, err), o['target_error'], end + o['step']),
                      flush=True)
                todo.append((p, dict(o, time=round(end + o['step'], 9),
                                     average=round(end + o['step'] - start, 9))))
        if not todo:
            return
        with concurrent.futures.ThreadPoolExecutor(o['jobs']) as pool:
            list(pool.map(lambda t: run_point(t[1], t[0][0], t[0][1], t[0][2], {},
                                              entries(t[0])), todo))


def recorded_options(work, finished=True):
    """The options of the case's Allrun that made work, as words (its
    log.options; etc/caseFunctions startCase), if it got to evaluate (or
    only started, finished False); else None."""
    path = os.path.join(work, 'log.options')
    if not os.path.isfile(path):
        return None
    lines = open(path).read().splitlines()
    if finished and not any(line.startswith('evaluate:') for line in lines):
        return None
    return next((shlex.split(line[len('options:'):]) for line in lines
                 if line.startswith('options:')), None)


def restart_clean(work, bed):
    """An interrupted run: remove what it wrote (./Allclean, which a second
    ./Allrun asks for) but keep its settled bed, which later runs reuse."""
    kept = None
    if os.path.isfile(bed):
        kept = work + '.settled.restart'
        shutil.move(bed, kept)
    subprocess.check_call(['./Allclean'], cwd=work, stdout=subprocess.DEVNULL)
    if kept:
        os.makedirs(os.path.dirname(bed), exist_ok=True)
        shutil.move(kept, bed)


def circulation_csv(work):
    """The rows of a run's circulation.csv: {quantity: value [kg/s]}."""
    rows = {}
    for row in list(open(os.path.join(work, 'circulation.csv')))[1:]:
        name, _, value = row.rsplit(',', 2)
        rows[name] = float(value)
    return rows


def w_s(work):
    """W_s (eq 14) from the run's time-averaged fields [kg/s]."""
    for name, value in circulation_csv(work).items():
        if name.startswith('W_s downward'):
            return value
    raise ValueError(work)


def w_s_error(work):
    """The standard error of W_s from the every-step series' blocks [kg/s],
    or None (a window shorter than two blocks, a run from before the
    series)."""
    for name, value in circulation_csv(work).items():
        if name.startswith('W_s standard error'):
            return value
    return None


def error_text(ws, err):
    """' +- 0.0123 (4.1 %)', the standard error beside W_s, or ''."""
    return '' if err is None else ' +- %.4f (%.1f %%)' % (err, 100 * err / ws if ws else float('nan'))


def write_table(o, table):
    """circulation_<study>.csv, .txt and .json from the table's rows (label,
    u_s, He, mu, W_s, correlation, standard error, particles lost, (end,
    averaging start)); returns the files' stem."""
    name = 'circulation_%s' % o['study']
    with open(name + '.csv', 'w') as f:
        f.write('run,superficial velocity [m/s],He [mm],friction coefficient,'
                'W_s SpoutLab [kg/s],W_s paper correlation [kg/s],'
                'W_s standard error [kg/s],particles lost\n')
        for row in table:
            f.write('%s,%g,%s,%s,%.6g,%.6g,%s,%d\n' % (row[0], row[1], row[2] or '', row[3] or '',
                                                       row[4], row[5],
                                                       '' if row[6] is None else '%.6g' % row[6],
                                                       row[7]))
    kick = o['kick'].split(',')
    windows = set(r[8] for r in table)
    if len(windows) == 1:
        end, start = table[0][8]
        text = '# %g s per run (spin-up at %s m/s for %s s), W_s averaged over the last %g s\n' \
            % (end, kick[0], kick[1], round(end - start, 9))
    else:   # runs continued to their --target-error
        text = ('# spin-up at %s m/s for %s s; W_s averaged from t = %s s to each run\'s end%s\n'
                % (kick[0], kick[1], '/'.join('%g' % s for s in sorted(set(w[1] for w in windows))),
                   '' if o['target_error'] is None else ' (--target-error %g)' % o['target_error']))
    text += '\n'.join('%-18s u_s = %.2f m/s  W_s = %.4f kg/s%s  correlation %.4f kg/s%s%s'
                      % (r[0], r[1], r[4], error_text(r[4], r[6]), r[5],
                         caserun.lost_text(r[7]),
                         '' if len(windows) == 1 else '  (to %g s)' % r[8][0])
                      for r in table) + '\n'
    open(name + '.txt', 'w').write(text)
    sys.stdout.write(text)
    # the table's numbers as it prints them, for protocols/results
    with open(name + '.json', 'w') as f:
        json.dump({'settings': text.splitlines()[0][1:].strip(),
                   'points': [{'label': r[0], 'u_m_s': float('%.2f' % r[1]),
                               'W_s_kg_s': float('%.4f' % r[4]),
                               'W_s_err_kg_s': None if r[6] is None else float('%.3g' % r[6]),
                               'correlation_kg_s': float('%.4f' % r[5]),
                               'particles_lost': r[7], 'time_s': r[8][0],
                               'average_s': round(r[8][0] - r[8][1], 9)} for r in table]},
                  f, indent=1)
        f.write('\n')
    return name


def main(argv):
    o = parse(argv)
    run_all(o, points(o))
    extend(o, points(o))
    table = []
    for label, u, _, He, mu in points(o):
        work = os.path.join('runs', label)
        ws, err, lost = w_s(work), w_s_error(work), caserun.lost_particles(work)
        ref = eq15(u, He) if He is not None else eq16(mu)
        table.append((label, u, He, mu, ws, ref, err, lost, window(recorded_options(work))))
        print('circulation: %s: W_s = %.4f kg/s%s (paper eq %s: %.4f)%s'
              % (label, ws, error_text(ws, err), '15' if He is not None else '16', ref,
                 caserun.lost_text(lost)), flush=True)
    name = write_table(o, table)
    if o['study'] == 'velocity':
        sc.plot(name + '.png', '''
set title "Particle circulation rate vs gas velocity (Fig 6)"
set xlabel "superficial gas velocity u_s [m/s]"
set ylabel "W_s [kg/s]"
set grid
set key top left
set datafile separator ","
plot [1:2.5] 0.3251*sqrt(x)-0.265 lw 2 title "eq 15, He = 95 mm", \\
     0.1641*sqrt(x)+0.111 lw 2 title "eq 15, He = 152 mm", \\
     "%s.csv" skip 1 using 2:($3 == 95 ? $5 : 1/0) with points pt 7 ps 1.5 title "SpoutLab, He = 95 mm", \\
     "%s.csv" skip 1 using 2:($3 == 152 ? $5 : 1/0) with points pt 5 ps 1.5 title "SpoutLab, He = 152 mm"
''' % (name, name))
    else:
        sc.plot(name + '.png', '''
set title "Circulation rate at u_{ms} vs friction coefficient (Fig 7)"
set xlabel "friction coefficient"
set ylabel "log10 W_s [kg/s]"
set grid
set datafile separator ","
plot [0:0.32] -3.25*x-0.194 lw 2 title "eq 16: log10 W_s = -3.25 mu - 0.194", \\
     "%s.csv" skip 1 using 4:(log10($5)) with points pt 7 ps 1.5 title "SpoutLab", \\
     "<echo 0.063,0.39" using 1:(log10($2)) with points pt 9 ps 2 title "experiment (Kalwar), 0.39 kg/s"
''' % name)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
