"""dryingOverhead: what drying adds to a coupled step of the hot spouted bed.

A benchmark, not a test: it prints figures and asserts nothing about speed.
One hot draft-plate bed (N particles, 2.0 m/s, inlet 150 C) is settled once
by the case's own Allrun with moisture on (reused by later calls with the
same N); from it spoutFoam runs the same simulated time four ways, one
after the other on one rank:

  heat       heat transfer only (dryingModel none, no moisture in LIGGGHTS)
  drying     the same with the bed's drying model (kernel diffusion, 15 shells,
             the kernel stepped once per kernelSteps coupling steps)
  resolved   the same with the kernel stepped every coupling step (kernelSteps 1)
  freeWater  the same with free-water kernels (the cheapest model)

and prints, side by side, CPU and wall seconds per simulated second (from
OpenFOAM's ExecutionTime and ClockTime between the first and the last step)
and each drying run's cost against the heat-only run.

    bench/dryingOverhead                       # 26 000 particles, 0.15 s
    bench/dryingOverhead --particles 3000 --time 0.3 --repeat 3

Uses numpy-free Python 3; sources etc/bashrc itself.
"""
import argparse
import os
import re
import shutil
import sys

from spoutlab.bench import spoutbench


def settled_bed(base, n):
    """The case with a hot, wet settled bed of n particles (built once)."""
    case = os.path.join(base, 'settled-dry-n%d' % n)
    if os.path.isfile(os.path.join(case, 'DEM', 'settled.restart')):
        return case
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(spoutbench.CASE, case)
    print('dryingOverhead: settling %d particles in %s (once)' % (n, case), flush=True)
    spoutbench.shell('./Allclean > /dev/null && ./Allrun -n %d -t 0.0003 -a 0.0003 '
                     'heat=yes moisture=yes' % n, case, os.path.join(case, 'log.bench'))
    return case


def variant(settled, base, name, model, kernel_steps=None):
    """A copy of the settled case's set-up with another drying model
    ('none': heat only, and LIGGGHTS without the moisture property), and for
    kernel diffusion kernelSteps as given (None: the case's)."""
    case = os.path.join(base, 'source-' + name)
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for d in ('constant', 'system', '0.orig', '0', 'DEM'):
        shutil.copytree(os.path.join(settled, d), os.path.join(case, d))
    drying = os.path.join(case, 'constant', 'drying')
    with open(drying) as f:
        text = f.read()
    with open(drying, 'w') as f:
        text = re.sub(r'^dryingModel\s+\w+;', 'dryingModel %s;' % model, text, flags=re.M)
        if kernel_steps is not None:
            text = re.sub(r'^\s*kernelSteps\s+\d+;\n', '', text, flags=re.M)
            text = text.replace('kernelDiffusionProps\n{\n',
                                'kernelDiffusionProps\n{\n    kernelSteps %d;\n' % kernel_steps)
        f.write(text)
    if model == 'none':
        geometry = os.path.join(case, 'DEM', 'geometry.liggghts')
        with open(geometry) as f:
            text = f.read()
        with open(geometry, 'w') as f:
            f.write(text.replace('variable moisture equal 1', 'variable moisture equal 0'))
    return case


def figures(case):
    log = os.path.join(case, 'log.spoutFoam')
    cpu, _ = spoutbench.per_simulated_second(log, 'ExecutionTime')
    wall, _ = spoutbench.per_simulated_second(log, 'ClockTime')
    return cpu, wall


def main(argv=None):
    p = argparse.ArgumentParser(prog='dryingOverhead', description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--particles', type=int, default=26000, metavar='N')
    p.add_argument('--time', type=float, default=0.15, metavar='T',
                   help='simulated seconds of each run (default 0.15)')
    p.add_argument('--repeat', type=int, default=1, metavar='R',
                   help='run each R times and keep the fastest (default 1)')
    p.add_argument('--dir', default=spoutbench.default_dir('dryingOverhead'), metavar='DIR')
    a = p.parse_args(argv)
    os.makedirs(a.dir, exist_ok=True)
    settled = settled_bed(a.dir, a.particles)
    runs = (('heat', 'none', None), ('drying', 'kernelDiffusion', None),
            ('resolved', 'kernelDiffusion', 1), ('freeWater', 'freeWater', None))
    best = {}
    for _ in range(a.repeat):
        for name, model, kernel_steps in runs:
            source = variant(settled, a.dir, name, model, kernel_steps)
            print('dryingOverhead: %s, %g s ...' % (name, a.time), flush=True)
            case = spoutbench.run(source, a.dir, 1, a.time, name)
            cpu, wall = figures(case)
            if name not in best or cpu < best[name][0]:
                best[name] = (cpu, wall)
    heat = best['heat'][0]
    print('\ndryingOverhead: draft-plate bed, %d particles, 2.0 m/s, inlet 150 C, %g s '
          'simulated, 1 rank, best of %d' % (a.particles, a.time, a.repeat))
    print('%-10s %14s %15s %18s' % ('run', 'CPU s / sim s', 'wall s / sim s', 'CPU / heat only'))
    for name, _, _ in runs:
        cpu, wall = best[name]
        print('%-10s %14.1f %15.1f %18.3f' % (name, cpu, wall, cpu / heat))
    print('(other load on the machine: %s)' % ', '.join('%.2f' % x for x in os.getloadavg()))
    return 0


if __name__ == '__main__':
    sys.exit(main())
