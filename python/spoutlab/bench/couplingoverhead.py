"""couplingOverhead: what the CFD-DEM coupling costs on top of LIGGGHTS alone.

A benchmark, not a test: it prints figures and asserts nothing about speed.
For one bed of the fluidisedColumn (N particles, settled once and reused) it

  1. runs LIGGGHTS alone (liggghts_inputs/fluidisedColumn/in.alone: the
     contact model, walls, gravity and time step of in.coupled, no gas) for
     S x couplingInterval DEM steps from the settled bed, once as one run and
     once in runs of couplingInterval steps (as spoutFoam drives LIGGGHTS);
  2. runs spoutFoam on a copy of openfoam_cases/minFluidisation for S CFD
     steps with a constant inlet velocity in the bubbling regime (the case's
     ramp is replaced), from the same settled bed, stamping each line of its
     output with the wall clock;

and prints the particle-steps per second of each, the overhead ratios and the
split of the coupled time into DEM steps / LIGGGHTS run calls / particle
mapping and exchange / gas solve. With --np 1 2 it does all three on each
rank count (mpirun -np P, the gas mesh cut into the x-slabs LIGGGHTS uses)
and ends with the rank counts side by side: times, ratios, speed-ups.
See bench/README.md.

    bench/couplingOverhead                        # 3000 particles, 2000 CFD steps
    bench/couplingOverhead --particles 6000 --steps 1000
    bench/couplingOverhead --np 1 2               # serial and 2 ranks
    bench/couplingOverhead --help

Python 3 standard library only.
"""
import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import time

from spoutlab import bench

REPO = bench.REPO
CASE = os.path.join(REPO, 'openfoam_cases', 'minFluidisation')
INPUTS = os.path.join(REPO, 'liggghts_inputs', 'fluidisedColumn')
TOP_UP = os.path.join(REPO, 'bench', 'in.topUp')

# One random packing of in.settle places at most ~4400 particles; the rest
# are packed above the settled bed by bench/in.topUp, which has room for
# ~2000 more. 6000 settle to 0.57 m and, bubbling at 2.5 m/s, reach the lid.
MAX_PARTICLES = 6000


class BenchError(Exception):
    pass


# ---------------------------------------------------------------- environment

def environment():
    """The environment of etc/bashrc (OpenFOAM variables, build bin/ on PATH)."""
    out = subprocess.run(
        ['bash', '-c', '. "$1/etc/bashrc" && env -0', 'bash', REPO],
        check=True, stdout=subprocess.PIPE).stdout
    env = {}
    for item in out.split(b'\0'):
        if b'=' in item:
            key, value = item.split(b'=', 1)
            env[key.decode()] = value.decode()
    return env


def check_programs(env, ranks=(1,)):
    build = env['SPOUTLAB_BUILD']
    solver = os.path.join(build, 'bin', 'spoutFoam')
    if not (os.path.isfile(solver) and os.access(solver, os.X_OK)):
        raise BenchError(
            'spoutFoam is not built: no executable %s.\n'
            '  Build it first:  cmake -S %s -B <build> && cmake --build <build>\n'
            '  and point SPOUTLAB_BUILD at <build> (default: %s/build).'
            % (solver, REPO, REPO))
    programs = ['liggghts', 'blockMesh', 'foamDictionary']
    if max(ranks) > 1:
        programs += ['mpirun', 'postProcess', 'decomposePar']
    for program in programs:
        if not shutil.which(program, path=env['PATH']):
            raise BenchError('%s not found on PATH (Debian packages liggghts / '
                             'openfoam / openmpi-bin; see DESIGN.md section 2)'
                             % program)


def launcher(ranks, cores=None):
    """The command prefix that starts a program on ranks MPI ranks; more
    ranks than cores need --oversubscribe (and measure nothing useful)."""
    if ranks == 1:
        return []
    cores = cores or os.cpu_count() or 1
    return ['mpirun', '-np', str(ranks)] + (['--oversubscribe'] if ranks > cores else [])


# ----------------------------------------------------------------- processes

def _proc_stat_busy():
    """Busy CPU seconds of the whole machine so far (all cores)."""
    try:
        with open('/proc/stat') as f:
            fields = [int(x) for x in f.readline().split()[1:]]
    except (OSError, ValueError):
        return None
    # user nice system idle iowait irq softirq steal ...
    busy = sum(fields[:3]) + sum(fields[5:8])
    return busy / os.sysconf('SC_CLK_TCK')


def _own_cpu():
    r = [resource.getrusage(w) for w in (resource.RUSAGE_SELF,
                                         resource.RUSAGE_CHILDREN)]
    return sum(x.ru_utime + x.ru_stime for x in r)


class Timed:
    """Wall time of a block, and how many cores other programs kept busy
    meanwhile (machine busy time minus this script's and its children's)."""

    def __init__(self):
        self.wall = self.others = 0.0

    def __enter__(self):
        self._t = time.perf_counter()
        self._own = _own_cpu()
        self._busy = _proc_stat_busy()
        return self

    def __exit__(self, *exc):
        self.wall = time.perf_counter() - self._t
        busy = _proc_stat_busy()
        if busy is not None and self._busy is not None and self.wall > 0:
            own = _own_cpu() - self._own
            self.others = max(0.0, (busy - self._busy - own) / self.wall)
        return False


def in_dir(env, cwd):
    """env for a child started in cwd (OpenFOAM warns when PWD differs)."""
    return dict(env, PWD=os.path.abspath(cwd))


def run(cmd, cwd, env, log, what):
    with open(os.path.join(cwd, log), 'w') as f:
        result = subprocess.run(cmd, cwd=cwd, env=in_dir(env, cwd), stdout=f,
                                stderr=subprocess.STDOUT)
    if result.returncode != 0:
        raise BenchError('%s failed (exit %d); last lines of %s:\n%s'
                         % (what, result.returncode, os.path.join(cwd, log),
                            tail(os.path.join(cwd, log))))


def tail(path, n=8):
    try:
        with open(path, errors='replace') as f:
            return ''.join(f.readlines()[-n:])
    except OSError:
        return '(no log)'


def foam_set(case, env, path, entry, value):
    run(['foamDictionary', '-entry', entry, '-set', value, path], case, env,
        'log.foamDictionary', 'foamDictionary -entry %s -set %s %s'
        % (entry, value, path))


def foam_get(case, env, path, entry):
    out = subprocess.run(['foamDictionary', '-entry', entry, '-value', path],
                         cwd=case, env=in_dir(env, case), stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    if out.returncode != 0:
        raise BenchError('cannot read %s from %s:\n%s' % (entry, path, out.stderr))
    return out.stdout.strip()


# --------------------------------------------------------------- LIGGGHTS logs

LOOP = re.compile(r'^Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms')
THERMO_HEAD = re.compile(r'^\s*Step\s+Time\s+Atoms\b')


def read_liggghts_log(path):
    """Sum of 'Loop time' lines and the thermo rows (as dicts) of a log.

    On P ranks rank 0 alone prints a 'Loop time' line per run, the loop's
    wall time there (ranks that finish early wait in it for the others)."""
    loop_time, steps, runs, atoms, procs = 0.0, 0, 0, 0, 0
    rows, names = [], None
    with open(path, errors='replace') as f:
        for line in f:
            m = LOOP.match(line)
            if m:
                loop_time += float(m.group(1))
                steps += int(m.group(3))
                atoms = int(m.group(4))
                procs = int(m.group(2))
                runs += 1
                names = None
                continue
            if THERMO_HEAD.match(line):
                names = line.split()
                continue
            if names:
                fields = line.split()
                if len(fields) == len(names):
                    try:
                        rows.append(dict(zip(names, map(float, fields))))
                    except ValueError:
                        names = None
                else:
                    names = None
    return {'loop': loop_time, 'steps': steps, 'runs': runs, 'atoms': atoms,
            'procs': procs, 'rows': rows}


def settled_count(log):
    count = None
    with open(log, errors='replace') as f:
        for line in f:
            m = re.match(r'SETTLED: N = (\d+) particles', line)
            if m:
                count = int(m.group(1))
    return count


# ------------------------------------------------------------------- settling

def settle(base, n, env):
    """base/settle/DEM/settled.restart with exactly n particles (reused)."""
    work = os.path.join(base, 'settle')
    dem = os.path.join(work, 'DEM')
    restart = os.path.join(dem, 'settled.restart')
    marker = os.path.join(dem, 'particles')
    if os.path.isfile(restart) and os.path.isfile(marker):
        with open(marker) as f:
            if f.read().strip() == str(n):
                print('settled bed of %d particles found in %s' % (n, dem))
                return dem
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    print('settling %d particles (once; reused by later runs) in %s' % (n, dem))
    with Timed() as t:
        # etc/caseFunctions' settleParticles, as the case's Allrun does
        run(['bash', '-c',
             '. "$1/etc/caseFunctions" && settleParticles "$2" -var n "$3"',
             'bash', REPO, os.path.join(INPUTS, 'in.settle'), str(n)],
            work, env, 'log.settleParticles', 'settleParticles')
        got = settled_count(os.path.join(dem, 'log.settle'))
        if got is not None and got < n:
            print('  in.settle placed %d particles; adding %d with bench/in.topUp'
                  % (got, n - got))
            run(['liggghts', '-in', TOP_UP, '-var', 'inputs', INPUTS,
                 '-var', 'dem', dem, '-var', 'n', str(n),
                 '-var', 'out', os.path.join(dem, 'settled.topUp.restart'),
                 '-echo', 'none', '-log', 'none',
                 '-screen', os.path.join(dem, 'log.topUp')],
                work, env, 'log.topUp.out', 'LIGGGHTS in.topUp')
            got = settled_count(os.path.join(dem, 'log.topUp'))
            os.replace(os.path.join(dem, 'settled.topUp.restart'), restart)
    if got != n:
        raise BenchError('the settled bed has %s particles, not %d (see the logs '
                         'in %s)' % (got, n, dem))
    with open(marker, 'w') as f:
        f.write('%d\n' % n)
    print('  done in %.1f s' % t.wall)
    return dem


# ------------------------------------------------------------- DEM alone

def dem_alone(base, dem, dem_steps, chunk, env, ranks=1):
    """LIGGGHTS in.alone on ranks ranks: one run (chunk 0) or runs of chunk
    steps. in.coupled's 'processors * 1 1' cuts the box into x-slabs, as in
    the coupled run."""
    work = os.path.join(base, 'alone' if chunk == 0 else 'alone-chunk%d' % chunk)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    log = os.path.join(work, 'log.liggghts')
    print('LIGGGHTS alone: %d DEM steps%s on %s in %s'
          % (dem_steps, ' in runs of %d' % chunk if chunk else '', ranks_text(ranks), work))
    with Timed() as t:
        run(launcher(ranks) + ['liggghts', '-in', os.path.join(INPUTS, 'in.alone'),
             '-var', 'inputs', INPUTS, '-var', 'dem', dem,
             '-var', 'steps', str(dem_steps), '-var', 'chunk', str(chunk),
             '-echo', 'none', '-log', 'none', '-screen', log],
            work, env, 'log.stdout', 'LIGGGHTS in.alone')
    res = read_liggghts_log(log)
    res.update(wall=t.wall, others=t.others)
    return res


# ------------------------------------------------------------------ coupled

def prepare_case(base, dem, n, steps, velocity, env, ranks=1, grid=(1, 1)):
    """The coupled case in base/coupled; a grid (px, py) other than (1, 1)
    widens the column to px columns side by side and py rows of them
    (bench/weakScaling: dem then holds the widened bed of n particles) and
    on ranks > 1 cuts it as decompose does."""
    work = os.path.join(base, 'coupled')
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    # only the case's inputs: the source directory may hold someone's run
    for sub in ('system', 'constant', '0.orig'):
        shutil.copytree(os.path.join(CASE, sub), os.path.join(work, sub),
                        ignore=shutil.ignore_patterns('polyMesh'))
    if grid != (1, 1):
        width, depth = widen_mesh(os.path.join(work, 'system', 'blockMeshDict'), *grid)
        for entry, value in (('W', width), ('L', depth)):
            foam_set(work, env, 'constant/couplingProperties', 'liggghtsVariables.' + entry,
                     '%.12g' % value)
    shutil.copytree(os.path.join(work, '0.orig'), os.path.join(work, '0'))
    os.makedirs(os.path.join(work, 'DEM'))
    shutil.copy(os.path.join(dem, 'settled.restart'), os.path.join(work, 'DEM'))

    # a constant superficial velocity instead of the case's ramp
    foam_set(work, env, '0/U', 'boundaryField.inlet',
             '{ type fixedValue; value uniform (0 0 %s); }' % velocity)
    delta_t = float(foam_get(work, env, 'system/controlDict', 'deltaT'))
    foam_set(work, env, 'system/controlDict', 'endTime', '%.12g' % (steps * delta_t))
    # no field, particle or restart writes inside the timed loop
    foam_set(work, env, 'system/controlDict', 'writeControl', 'timeStep')
    foam_set(work, env, 'system/controlDict', 'writeInterval', str(steps + 1))
    foam_set(work, env, 'constant/couplingProperties', 'liggghtsVariables.n', str(n))
    interval = int(foam_get(work, env, 'constant/couplingProperties',
                            'couplingInterval'))
    run(['blockMesh'], work, env, 'log.blockMesh', 'blockMesh')
    if ranks > 1:
        decompose(work, ranks, env, grid)
    cells = None
    with open(os.path.join(work, 'log.blockMesh')) as f:
        m = re.search(r'nCells:\s*(\d+)', f.read())
        cells = int(m.group(1)) if m else None
    n_corr = int(foam_get(work, env, 'system/fvSolution', 'PISO.nCorrectors'))
    return work, delta_t, interval, cells, n_corr


def widen_mesh(path, copies, rows=1, write=True):
    """blockMeshDict's W and nx times copies, L and ny times rows: that many
    columns side by side in x and rows of them in y (the cells keep their
    size). Returns the new width W and depth L [m]; write=False leaves the
    file as it is. (foamDictionary would expand the $W of the vertices
    while rewriting the file.)"""
    text = open(path).read()
    values = {}
    for entry, factor, kind in (('W', copies, float), ('nx', copies, int),
                                ('L', rows, float), ('ny', rows, int)):
        pattern = re.compile(r'^(%s\s+)([^;]*);' % entry, re.M)
        found = pattern.findall(text)
        try:
            values[entry] = factor * kind(found[0][1])
        except (IndexError, ValueError):
            raise BenchError('%s: expected one top-level entry %s with a number, found %s'
                             % (path, entry, found or 'none'))
        if len(found) != 1:
            raise BenchError('%s: expected one top-level entry %s, found %d'
                             % (path, entry, len(found)))
        text = pattern.sub(lambda m: '%s%.12g;' % (m.group(1), values[entry]), text)
    if write:
        with open(path, 'w') as f:
            f.write(text)
    return values['W'], values['L']


def decompose(work, ranks, env, grid=(1, 1)):
    """The gas mesh cut for ranks ranks as the case scripts cut it:
    x-slabs (0/C, the cell centres, then etc/caseFunctions' decomposeSlabs)
    unless grid (px, py) has py > 1: then OpenFOAM's simple method in
    px x py boxes (the column's uniform cells make them a grid of boxes).
    spoutFoam hands the same cuts to LIGGGHTS."""
    if grid[1] > 1:
        with open(os.path.join(work, 'system', 'decomposeParDict'), 'w') as f:
            f.write('FoamFile { version 2.0; format ascii; class dictionary; '
                    'object decomposeParDict; }\n'
                    '// written by bench/weakScaling: %d x %d boxes in x and y\n'
                    'numberOfSubdomains %d;\nmethod simple;\ncoeffs { n (%d %d 1); }\n'
                    % (grid[0], grid[1], ranks, grid[0], grid[1]))
        run(['decomposePar'], work, env, 'log.decomposePar', 'decomposePar')
        return
    run(['postProcess', '-func', 'writeCellCentres', '-time', '0'], work, env,
        'log.postProcess', 'postProcess -func writeCellCentres')
    run(['bash', '-c', '. "$1/etc/caseFunctions" && decomposeSlabs "$2"',
         'bash', REPO, str(ranks)], work, env, 'log.decomposeSlabs',
        'decomposeSlabs %d' % ranks)


def coupled(work, env, ranks=1):
    """Run spoutFoam (on ranks ranks: the case decomposed, -parallel),
    stamping each line of its output with the wall clock.

    Per time step the solver prints 'Time = ' before LIGGGHTS runs,
    'Coupling: ' once the particles are mapped and the forces exchanged, and
    'ExecutionTime = ' after the gas solve; the stamps split the step."""
    print('spoutFoam (coupled) on %s in %s' % (ranks_text(ranks), work))
    command = launcher(ranks) + ['spoutFoam'] + (['-parallel'] if ranks > 1 else [])
    stamps = {'start': None, 'loop': None, 'end': None}
    t_step, t_coupling, t_exec = [], [], []
    with Timed() as t, open(os.path.join(work, 'log.spoutFoam'), 'w') as log:
        stamps['start'] = time.perf_counter()
        proc = subprocess.Popen(command, cwd=work, env=in_dir(env, work),
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        for raw in proc.stdout:
            now = time.perf_counter()
            log.write(raw.decode(errors='replace'))
            if raw.startswith(b'Time = '):
                t_step.append(now)
            elif raw.startswith(b'Coupling: ') and stamps['loop'] is not None:
                t_coupling.append(now)
            elif raw.startswith(b'ExecutionTime = '):
                t_exec.append(now)
            elif raw.startswith(b'Starting time loop'):
                stamps['loop'] = now
            elif raw.strip() == b'End':
                stamps['end'] = now
        proc.wait()
        stamps['exit'] = time.perf_counter()
    if proc.returncode != 0 or stamps['end'] is None:
        raise BenchError('spoutFoam failed (exit %d); last lines of %s:\n%s'
                         % (proc.returncode, os.path.join(work, 'log.spoutFoam'),
                            tail(os.path.join(work, 'log.spoutFoam'))))
    if not (len(t_step) == len(t_coupling) == len(t_exec)):
        raise BenchError('unexpected spoutFoam output: %d "Time =", %d "Coupling:", '
                         '%d "ExecutionTime" lines' % (len(t_step), len(t_coupling),
                                                        len(t_exec)))
    res = read_liggghts_log(os.path.join(work, 'log.liggghts'))
    res.update(
        wall=t.wall, others=t.others, cfd_steps=len(t_step),
        startup=stamps['loop'] - stamps['start'],
        loop_wall=stamps['end'] - stamps['loop'],
        shutdown=stamps['exit'] - stamps['end'],
        dem_and_coupling=sum(c - s for s, c in zip(t_step, t_coupling)),
        gas=sum(e - c for c, e in zip(t_coupling, t_exec)))
    return res


# ------------------------------------------------------------- one rank count

def rank_dir(base, ranks):
    """Where the runs on ranks ranks go (the settled bed stays in base)."""
    return os.path.join(base, 'np%d' % ranks)


def rank_count_runs(base, case, ranks, dem, dem_steps, interval, env):
    """One round of the three kinds of run, all on ranks MPI ranks."""
    work = rank_dir(base, ranks)
    return {'alone': dem_alone(work, dem, dem_steps, 0, env, ranks),
            'chunked': dem_alone(work, dem, dem_steps, interval, env, ranks),
            'coupled': coupled(case, env, ranks)}


def keep_fastest(best, results):
    """The fastest of each kind so far (the coupled run by its time loop)."""
    for kind, r in results.items():
        key = 'loop_wall' if kind == 'coupled' else 'wall'
        if kind not in best or r[key] < best[kind][key]:
            best[kind] = r


def check_runs(runs, ranks, n, steps, dem_steps):
    """Each run did what was asked: the DEM steps, particles and ranks."""
    for name, r in (('LIGGGHTS alone', runs['alone']),
                    ('LIGGGHTS alone in runs', runs['chunked']),
                    ('coupled LIGGGHTS', runs['coupled'])):
        if (r['steps'], r['atoms'], r['procs']) != (dem_steps, n, ranks):
            raise BenchError('%s ran %d DEM steps with %d particles on %d procs, '
                             'expected %d with %d on %d'
                             % (name, r['steps'], r['atoms'], r['procs'],
                                dem_steps, n, ranks))
    if runs['coupled']['cfd_steps'] != steps:
        raise BenchError('spoutFoam on %s ran %d CFD steps, expected %d'
                         % (ranks_text(ranks), runs['coupled']['cfd_steps'], steps))


def ranks_text(ranks):
    return 'serial (1 rank)' if ranks == 1 else '%d MPI ranks' % ranks


# ------------------------------------------------------------------- report

def bed_state(rows, dp=0.008):
    """Mean rms particle speed and highest bed top over the second half."""
    rows = [r for r in rows if 'vrms' in r and 'zmax' in r]
    if not rows:
        return 'bed state not in the log'
    late = rows[len(rows) // 2:]
    vrms = sum(r['vrms'] for r in late) / len(late)
    top = max(r['zmax'] for r in late) + dp / 2
    return 'rms particle speed %.3g m/s, bed top up to %.2f m' % (vrms, top)


def load_note(ranks, others, cores=None):
    """Lines saying the runs were spoilt, when other programs left fewer
    free cores than ranks (with 0.15 of a core to spare); none otherwise."""
    cores = cores or os.cpu_count() or 1
    if others <= cores - ranks + 0.15:
        return []
    if ranks > cores:
        return ['NOTE: %d ranks on %d cores, oversubscribed: the wall times are meaningless'
                % (ranks, cores)]
    if ranks == 1:
        return ['NOTE: other programs kept up to %.2f of the %d cores busy during the runs;'
                % (others, cores),
                '      with less than a core free for this benchmark the times are',
                '      inflated (re-run on a quiet machine, or use --repeat)']
    return ['NOTE: on %d ranks other programs kept up to %.2f of the %d cores busy:'
            % (ranks, others, cores),
            '      a %d-rank run on %d cores with anything else running is meaningless'
            % (ranks, cores),
            '      (a waiting rank polls its core, so one rank sharing a core holds up',
            '      every exchange); measure the %d-rank figures on a quiet machine' % ranks]


def report(args, ranks, setup, runs):
    """One rank count's figures: what ran, the times, the split, the ratios."""
    lines = []
    w = lines.append
    w('')
    w('SpoutLab coupling benchmark: %s, figures not a test%s'
      % (ranks_text(ranks), ', best of %d' % args.repeat if args.repeat > 1 else ''))
    describe_runs(w, args, ranks, setup, runs)
    times_table(w, args, setup, runs)
    coupled_split(w, args, setup, runs)
    figures = rank_figures(runs)
    w('  overhead ratio   coupled / DEM alone              %6.2f  (time loop / loop time)'
      % figures['per_alone'])
    w('                   coupled / DEM inside coupled     %6.2f  (same particle motion)'
      % figures['per_inside'])
    w('                   coupled / DEM alone, processes   %6.2f  (with start-up)'
      % figures['per_alone_process'])
    for line in load_note(ranks, figures['others']):
        w('  ' + line)
    w('')
    return '\n'.join(lines)


def describe_runs(w, args, ranks, setup, runs):
    alone, chunked, cpl = runs['alone'], runs['chunked'], runs['coupled']
    n, interval = args.particles, setup['interval']
    w('  bed    fluidisedColumn 0.12 x 0.04 x 0.8 m, %d particles of 8 mm, '
      'settled once' % n)
    w('  steps  %d CFD steps x %d = %d DEM steps of %.3g s (%.3g s of bed time)'
      % (args.steps, interval, args.steps * interval, setup['delta_t'] / interval,
         args.steps * setup['delta_t']))
    w('  gas    %s cells, constant inlet velocity %g m/s (u_mf of this bed ~ 1.8 m/s)'
      % (setup['cells'], args.velocity))
    if ranks > 1:
        w('  ranks  %d, x-slabs: the gas mesh by decomposeSlabs, LIGGGHTS on the same'
          % ranks)
        w('         cuts in the coupled run and by its own (processors * 1 1) alone')
    w('')
    w('  what each run does')
    w('  DEM alone    LIGGGHTS in.alone, one run of %d steps, no gas: the settled bed'
      % alone['steps'])
    w('               stays at rest under gravity (lasting contacts, hardly any')
    w('               neighbour-list builds):')
    w('               %s' % bed_state(alone['rows']))
    w('  DEM alone/%d  the same as %d runs of %d steps (run %d pre no post no), the'
      % (interval, chunked['runs'], interval, interval))
    w('               way spoutFoam calls LIGGGHTS; gives the cost of a run call')
    w('  coupled      spoutFoam, LIGGGHTS in-process (%d runs of %d steps); the gas'
      % (cpl['runs'], interval))
    w('               lifts the bed, which bubbles and slugs:')
    w('               %s' % bed_state(cpl['rows']))
    w('')


def times_table(w, args, setup, runs):
    alone, chunked, cpl = runs['alone'], runs['chunked'], runs['coupled']
    ps = args.particles * args.steps * setup['interval']
    w('  %-36s %9s %17s %13s' % ('', 'wall [s]', 'particle-steps/s', 'other load'))
    rows = (
        ('DEM alone      LIGGGHTS loop time', alone['loop'], None),
        ('               whole process', alone['wall'], alone['others']),
        ('DEM alone/%-4d LIGGGHTS loop time' % setup['interval'], chunked['loop'], None),
        ('               whole process', chunked['wall'], chunked['others']),
        ('coupled        spoutFoam time loop', cpl['loop_wall'], None),
        ('               whole process', cpl['wall'], cpl['others']))
    for name, seconds, others in rows:
        w('  %-36s %9.2f %17.3e %13s' % (name, seconds, ps / seconds,
                                          '' if others is None else
                                          '%.2f cores' % others))
    w('')


def coupled_split(w, args, setup, runs):
    """The coupled time loop into DEM steps, run calls, mapping and gas."""
    alone, chunked, cpl = runs['alone'], runs['chunked'], runs['coupled']
    n, interval = args.particles, setup['interval']
    ps = n * args.steps * interval
    total = cpl['loop_wall']
    dem = cpl['loop']
    # what a 'run' call costs besides its steps: the chunked process minus
    # the single-run process, loop times taken out of both
    per_call = ((chunked['wall'] - chunked['loop']) - (alone['wall'] - alone['loop'])) \
        / max(chunked['runs'] - alone['runs'], 1)
    calls = max(per_call, 0.0) * cpl['runs']
    mapping = cpl['dem_and_coupling'] - dem - calls
    gas = cpl['gas']
    other = total - cpl['dem_and_coupling'] - gas

    def share(x):
        return '%8.2f %6.1f %%' % (x, 100 * x / total)

    w('  coupled time loop, split          wall [s]    share')
    w('    DEM steps (LIGGGHTS loop time)  %s   %.3e particle-steps/s'
      % (share(dem), ps / dem))
    w('    LIGGGHTS run calls              %s   %.0f us per call (from DEM alone/%d)%s'
      % (share(calls), 1e6 * per_call, interval,
         '' if per_call >= 0 else ': below the noise, taken as 0'))
    w('    particle mapping and exchange   %s   %.2f us per particle per CFD step'
      % (share(mapping), 1e6 * mapping / (n * args.steps)))
    w('      (gather x/v/r, cell location, void fraction, Us, drag, forces back)')
    if setup['cells']:
        w('    gas solve (PISO, %d correctors)  %s   %.3e cell-updates/s'
          % (setup['n_corr'], share(gas), setup['cells'] * args.steps / gas))
    else:
        w('    gas solve (PISO)                %s' % share(gas))
    w('    other (time loop, functions)    %s' % share(other))
    w('  not in the ratios: start-up %.2f s (mesh, LIGGGHTS input and restart, '
      'first mapping),' % cpl['startup'])
    w('  shut-down %.2f s' % cpl['shutdown'])
    w('')


# ------------------------------------------------------------ side by side

# the three times compared across rank counts, with their labels
KINDS = (('coupled', 'coupled time loop'),
         ('inside', 'DEM inside coupled'),
         ('alone', 'DEM alone'))


def rank_figures(runs):
    """Times and ratios of one rank count; each ratio is between runs on
    that same number of ranks."""
    alone, cpl = runs['alone'], runs['coupled']
    return {'coupled': cpl['loop_wall'], 'inside': cpl['loop'], 'alone': alone['loop'],
            'per_alone': cpl['loop_wall'] / alone['loop'],
            'per_inside': cpl['loop_wall'] / cpl['loop'],
            'per_alone_process': cpl['wall'] / alone['wall'],
            'others': max(r['others'] for r in runs.values())}


def speed_ups(figures):
    """Per rank count P, each kind's serial time over its time on P ranks;
    None without a serial run."""
    if 1 not in figures:
        return None
    serial = figures[1]
    return {p: {kind: serial[kind] / f[kind] for kind, _ in KINDS}
            for p, f in figures.items()}


def side_by_side(best, cores=None):
    """The rank counts' times, ratios and speed-ups in columns."""
    counts = sorted(best)
    figures = {p: rank_figures(best[p]) for p in counts}
    up = speed_ups(figures)
    lines = []
    w = lines.append

    def row(label, values, form='%9.2f'):
        w('  %-44s' % label + ''.join(form % v for v in values))

    w('')
    w('SpoutLab coupling benchmark: the rank counts side by side')
    row('', ['%d rank%s' % (p, '' if p == 1 else 's') for p in counts], '%9s')
    row('wall [s]  coupled, spoutFoam time loop', [figures[p]['coupled'] for p in counts])
    row('          DEM inside coupled (loop time)', [figures[p]['inside'] for p in counts])
    row('          DEM alone (LIGGGHTS loop time)', [figures[p]['alone'] for p in counts])
    w('  ratio, both runs on the same rank count')
    row('          coupled / DEM alone', [figures[p]['per_alone'] for p in counts])
    row('          coupled / DEM inside coupled', [figures[p]['per_inside'] for p in counts])
    row('          coupled / DEM alone, processes', [figures[p]['per_alone_process']
                                                     for p in counts])
    if up is None:
        w('  speed-up: needs a serial run in the list (--np 1 %s)'
          % ' '.join(str(p) for p in counts))
    else:
        w('  speed-up, 1-rank time / P-rank time')
        for kind, label in KINDS:
            row('          ' + label, [up[p][kind] for p in counts])
        row('          coupled, parallel efficiency [%]',
            [100 * up[p]['coupled'] / p for p in counts], '%9.0f')
    row('other load [cores], busiest of the three runs', [figures[p]['others']
                                                          for p in counts])
    for p in counts:
        for line in load_note(p, figures[p]['others'], cores):
            w('  ' + line)
    w('')
    return '\n'.join(lines)


# --------------------------------------------------------------------- main

def options(argv=None):
    """The command line, checked: BenchError names the option at fault."""
    parser = argparse.ArgumentParser(
        description='CFD-DEM coupling benchmark: spoutFoam on a bubbling '
                    'fluidisedColumn bed against LIGGGHTS alone with the same '
                    'particles and DEM steps, on one or more rank counts. '
                    'Prints figures, asserts nothing.')
    parser.add_argument('--particles', type=int, default=3000, metavar='N',
                        help='particles in the bed (default 3000, at most %d)'
                             % MAX_PARTICLES)
    parser.add_argument('--steps', type=int, default=2000, metavar='N',
                        help='CFD (coupling) steps; DEM steps = N x '
                             'couplingInterval (default 2000)')
    parser.add_argument('--velocity', type=float, default=2.5, metavar='U',
                        help='constant superficial inlet velocity [m/s] '
                             '(default 2.5: bubbling)')
    parser.add_argument('--repeat', type=int, default=1, metavar='R',
                        help='run everything R times and keep the fastest of '
                             'each kind (default 1)')
    parser.add_argument('--np', type=int, nargs='+', default=[1], metavar='P',
                        help='MPI rank counts, each run in turn and compared '
                             'side by side (default 1; e.g. --np 1 2)')
    parser.add_argument('--dir', metavar='DIR',
                        help='work directory (default $SPOUTLAB_BUILD/bench)')
    args = parser.parse_args(argv)
    given = ' '.join(str(p) for p in args.np)
    if min(args.np) < 1:
        raise BenchError('--np %s: expected rank counts of 1 or more' % given)
    if len(set(args.np)) != len(args.np):
        raise BenchError('--np %s: expected each rank count once' % given)
    if not 1 <= args.particles <= MAX_PARTICLES:
        raise BenchError('--particles %d: expected 1 ... %d (a bubbling bed of '
                         '%d already reaches the lid of the 0.8 m column)'
                         % (args.particles, MAX_PARTICLES, MAX_PARTICLES))
    if args.steps < 1:
        raise BenchError('--steps %d: expected a positive number of CFD steps'
                         % args.steps)
    if args.repeat < 1:
        raise BenchError('--repeat %d: expected 1 or more' % args.repeat)
    if args.velocity <= 0:
        raise BenchError('--velocity %g: expected a positive inlet velocity [m/s]'
                         % args.velocity)
    return args


def main(argv=None):
    sys.stdout.reconfigure(line_buffering=True)
    try:
        args = options(argv)
        env = environment()
        check_programs(env, args.np)
        work = os.path.abspath(args.dir or os.path.join(env['SPOUTLAB_BUILD'], 'bench'))
        base = os.path.join(work, 'n%d' % args.particles)
        os.makedirs(base, exist_ok=True)

        dem = settle(base, args.particles, env)
        setups = {}
        for ranks in args.np:
            case, delta_t, interval, cells, n_corr = prepare_case(
                rank_dir(base, ranks), dem, args.particles, args.steps,
                args.velocity, env, ranks)
            setups[ranks] = {'case': case, 'delta_t': delta_t, 'interval': interval,
                             'cells': cells, 'n_corr': n_corr}

        # the rank counts take turns within each repeat, so a change of the
        # machine's load spreads over all of them
        best = {ranks: {} for ranks in args.np}
        for _ in range(args.repeat):
            for ranks, setup in setups.items():
                keep_fastest(best[ranks], rank_count_runs(
                    base, setup['case'], ranks, dem, args.steps * setup['interval'],
                    setup['interval'], env))

        texts = []
        for ranks, setup in setups.items():
            check_runs(best[ranks], ranks, args.particles, args.steps,
                       args.steps * setup['interval'])
            texts.append(report(args, ranks, setup, best[ranks]))
        if len(args.np) > 1:
            texts.append(side_by_side(best))
        text = '\n'.join(texts)
        print(text)
        with open(os.path.join(base, 'summary.txt'), 'w') as f:
            f.write(text.lstrip('\n') + '\n')
        print('(also in %s)' % os.path.join(base, 'summary.txt'))
    except BenchError as err:
        print('couplingOverhead: %s' % err, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    return 0


if __name__ == '__main__':
    sys.exit(main())
