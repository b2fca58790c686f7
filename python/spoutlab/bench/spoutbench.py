"""Shared by the spouted-bed benchmarks (parallelSpeedup, neighbourSettings):
the settled draft-plate bed, made once by the case's own Allrun, the spout
developed from it, and spoutFoam runs from either.  Numpy-free."""
import os
import re
import shutil
import subprocess
import sys

from spoutlab import bench

REPO = bench.REPO
CASE = os.path.join(REPO, 'openfoam_cases', 'spoutDraftPlates')


def default_dir(name):
    return os.path.join(os.environ.get('SPOUTLAB_BUILD', os.path.join(REPO, 'build')),
                        'bench', name)


def shell(script, cwd, log):
    """Run a bash script with the project's environment, output to log."""
    with open(log, 'w') as out:
        done = subprocess.run(
            ['bash', '-c', '. "%s/etc/caseFunctions" && %s' % (REPO, script)],
            cwd=cwd, stdout=out, stderr=subprocess.STDOUT)
    if done.returncode != 0:
        sys.exit('%s: "%s" failed in %s, see %s'
                 % (os.path.basename(sys.argv[0]), script, cwd, log))


def settled_bed(base, n):
    """The case with a settled bed of n particles (built once)."""
    case = os.path.join(base, 'settled-n%d' % n)
    if os.path.isfile(os.path.join(case, 'DEM', 'settled.restart')):
        return case
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(CASE, case)
    print('%s: settling %d particles in %s (once)' % (os.path.basename(sys.argv[0]), n, case),
          flush=True)
    shell('./Allclean > /dev/null && ./Allrun -n %d -t 0.0003 -a 0.0003' % n,
          case, os.path.join(case, 'log.bench'))
    return case


def developed(settled, base, t):
    """The bed spouting at 2.0 m/s since t = 0, written at t (made once,
    serially)."""
    case = os.path.join(base, 'developed-%g' % t)
    if os.path.isdir(case) and any(f.startswith('restart_') for f in os.listdir(
            os.path.join(case, 'DEM'))):
        return case
    print('%s: developing the spout to %g s (once) ...' % (os.path.basename(sys.argv[0]), t),
          flush=True)
    return run(settled, base, 1, t, os.path.basename(case), write=True)


def run(source, base, ranks, end, name=None, start=None, variables=None, write=False):
    """spoutFoam on ranks ranks from source's settled bed (start None) or
    from its written time start, to end; writes nothing inside the run (or,
    with write, the end time once); LIGGGHTS variables (liggghtsVariables of
    constant/couplingProperties) as given.  Returns the case directory."""
    case = os.path.join(base, name or 'np%d' % ranks)
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(os.path.join(case, 'DEM'))
    for d in ('constant', 'system', '0.orig') + ((start,) if start else ()):
        shutil.copytree(os.path.join(source, d), os.path.join(case, d))
    for f in os.listdir(os.path.join(source, 'DEM')):
        if start and f.startswith('restart_%s.' % start) or \
                not f.startswith('restart_') and not f.endswith('.state'):
            shutil.copy(os.path.join(source, 'DEM', f), os.path.join(case, 'DEM'))
    if variables:
        with open(os.path.join(case, 'constant', 'couplingProperties'), 'a') as f:
            f.write('\nliggghtsVariables\n{\n%s}\n'
                    % ''.join('    %s %s;\n' % kv for kv in sorted(variables.items())))
    centres = os.path.join(source, '0', 'C')   # decomposeSlabs reads 0/C
    if not start:
        script = 'restore0Dir && cp %s 0/ && ' % centres
    elif ranks > 1:
        script = 'mkdir -p 0 && cp %s 0/ && ' % centres
    else:
        script = ''
    script += ('foamDictionary -entry endTime -set %g system/controlDict > /dev/null && '
               'foamDictionary -entry writeInterval -set %g system/controlDict > /dev/null && '
               % (end, end if write else 10 * end))
    if ranks > 1:
        script += 'decomposeSlabs %d > /dev/null && ' % ranks
    if ranks > os.cpu_count():
        script += 'SPOUTLAB_MPIRUN_ARGS="--oversubscribe ${SPOUTLAB_MPIRUN_ARGS:-}" '
    # the one launch, etc/caseFunctions launchSpoutFoam
    script += 'launchSpoutFoam %d > log.spoutFoam 2>&1' % ranks
    shell(script, case, os.path.join(case, 'log.bench'))
    return case


def per_simulated_second(log, clock='ClockTime'):
    """Seconds of OpenFOAM's ClockTime (wall) or ExecutionTime (CPU) per
    simulated second, between the first and the last step, so start-up is
    left out; also the steps' times."""
    times, clocks = [], []
    t = None
    for line in open(log):
        if line.startswith('Time = '):
            t = float(line.split()[2])
        m = re.search(r'%s = ([0-9.e+-]+)' % clock, line)
        if m and t is not None:
            times.append(t)
            clocks.append(float(m.group(1)))
    if len(times) < 3:
        sys.exit('%s: %s has fewer than 3 steps' % (os.path.basename(sys.argv[0]), log))
    return (clocks[-1] - clocks[0]) / (times[-1] - times[0]), times
