"""The spouted bed with draft plates as a dryer: the draft-plate paper's
section 4.7 conditions (u_s = 2.0 m/s, inlet air at 150 C, bed and air at
33 C at the start) with wet corn, X_0 = 0.3333 kg/kg dry solid (25 % wet
basis), the inlet's humidity ratio and the drying model of
system/spoutedBedDict (kernel diffusion by default).

Two parts, each prepared once and continued where it stopped when the
protocol is started again:
  kernel   the single-kernel checks of openfoam_cases/singleKernel, each in
           runs/kernel_<check>/: the film-law wet bulb of a free-water
           kernel, and Thompson's thin-layer time to moisture ratio 0.5 at
           40, 60 and 80 C (a minute or two in all);
  bed      the whole bed in runs/drying_u<u>/, spoutFoam to --time with
           progress (every --write seconds a restart point), then the
           case's evaluate: moisture of spout and downcomer, drying rate,
           outlet air, the share of the heat that evaporates water, both
           balances, moisture pictures and history.
Writes drying.txt and drying.json here (read by protocols/results).
"""
import json
import os
import shutil
import subprocess
import sys

from spoutlab import caserun
from spoutlab import spoutdrying
from spoutlab import spoutedbed
from spoutlab.protocols import heattransfer

# the single-kernel checks: name -> Allrun arguments of openfoam_cases/singleKernel
KERNEL_CHECKS = {
    'wetBulb': ['-c', 'wetBulb'],
    'thinLayer40C': ['-c', 'thinLayer', 'dryingModel=kernelDiffusion', 'Tgas=40', 'endTime=33000',
                     'writeInterval=33000'],
    'thinLayer60C': ['-c', 'thinLayer', 'dryingModel=kernelDiffusion', 'Tgas=60', 'endTime=15000',
                     'writeInterval=15000'],
    'thinLayer80C': ['-c', 'thinLayer', 'dryingModel=kernelDiffusion', 'Tgas=80', 'endTime=7000',
                     'writeInterval=7000'],
}


def options(argv):
    def part(p):
        p.add_argument('--part', choices=('kernel', 'bed', 'both'), default='both',
                       help='what to run (default %(default)s)')
    return heattransfer.options(argv, 'drying', __doc__, part)


def kernel_checks():
    """Run (or reuse) the single-kernel checks; their numbers by check."""
    source = os.path.join(os.environ.get('SPOUTLAB_DIR', '../..'), 'openfoam_cases', 'singleKernel')
    numbers = {}
    for name, args in KERNEL_CHECKS.items():
        work = os.path.join('runs', 'kernel_' + name)
        result = os.path.join(work, 'results.json')
        if not os.path.isfile(result):
            shutil.rmtree(work, ignore_errors=True)
            shutil.copytree(source, work)
            print('drying: single kernel, %s' % name, flush=True)
            with open(os.path.join(work, 'log.protocol'), 'w') as log:
                subprocess.call(['bash', '-c', './Allclean > /dev/null && ./Allrun "$@"', 'Allrun']
                                + args, cwd=work, stdout=log, stderr=subprocess.STDOUT)
            if not os.path.isfile(result):
                sys.exit('drying: the single-kernel check %s failed, see %s/log.protocol'
                         % (name, work))
        numbers[name] = json.load(open(result))
        numbers[name]['passed'] = 'FAIL' not in open(os.path.join(work, 'results.txt')).read()
    return numbers


def bed(o):
    """Run (or continue) the bed and evaluate it; its drying numbers."""
    work = os.path.join('runs', 'drying_u%g' % o['u'])
    heattransfer.run(o, work, 'drying', ['moisture=yes'])
    g = spoutedbed.load(work)
    here = os.getcwd()
    heattransfer.inside(work)
    try:
        lines = []
        r = spoutdrying.summarize(g, o['average'], lines, pictures_drawn=False)
        wall = caserun.wall_time('.')
    finally:
        heattransfer.inside(here)
    r.update(particles=int(g.particles['nParticles']), u_s=o['u'], time=o['time'],
             average=o['average'], wall_s=wall, X0=g.X0, W_in=g.inletW, T_in=g.Tin, run=work)
    for name in os.listdir(work):
        if name.endswith('.png') and ('Moisture' in name or 'RH' in name or 'Humidity' in name):
            shutil.copy(os.path.join(work, name), 'drying_' + name)
    return r, lines


def report(numbers, lines):
    text = ['the spouted bed as a dryer (draft-plate paper section 4.7 conditions, wet corn)']
    k = numbers.get('kernel', {})
    if 'wetBulb' in k:
        w = k['wetBulb']
        text.append('single kernel: free-water rest temperature %.4f K from the film law '
                    '(error %.2g K); thermodynamic wet bulb %.2f K (%.2f K apart; %.2f K at Le = 1)'
                    % (w['wetbulb_film_K'], w['wetbulb_err_K'], w['wetbulb_thermodynamic_K'],
                       w['wetbulb_film_K'] - w['wetbulb_thermodynamic_K'],
                       w['wetbulb_lewis1_K'] - w['wetbulb_thermodynamic_K']))
    for T in (40, 60, 80):
        t = k.get('thinLayer%dC' % T)
        if t:
            text.append('thin layer at %d C: time to MR 0.5 %+.1f %% against Thompson et al. '
                        '(1968)' % (T, 100 * t['thinlayer_t50_rel']))
    if 'bed' in numbers:
        b = numbers['bed']
        text.append('bed: %d particles, u_s = %g m/s, %g s (averages over the last %g s), '
                    'run in %s, spoutFoam wall time %.0f min'
                    % (b['particles'], b['u_s'], b['time'], b['average'], b['run'], b['wall_s'] / 60))
        text += lines
    out = '\n'.join(text) + '\n'
    sys.stdout.write(out)
    open('drying.txt', 'w').write(out)


def main(argv):
    o = options(argv)
    numbers = json.load(open('drying.json')) if os.path.isfile('drying.json') else {}
    lines = []
    if o['part'] in ('kernel', 'both'):
        numbers['kernel'] = kernel_checks()
    if o['part'] in ('bed', 'both'):
        numbers['bed'], lines = bed(o)
    with open('drying.json', 'w') as f:
        json.dump(numbers, f, indent=1, sort_keys=True)
    report(numbers, lines)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
