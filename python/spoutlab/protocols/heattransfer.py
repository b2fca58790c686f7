"""Section 4.7 of the draft-plate paper: hot air through the spouted bed with
draft plates.  The bed spouts at u_s = 2.0 m/s with inlet air at 150 C; bed
and air start at 33 C; c_p,p = 2400 J/kg/K (system/spoutedBedDict).

The run is one case in runs/heat_u<u>/ (a copy of this case with heat on):
it is prepared once (mesh, settled bed), then spoutFoam runs to --time with
progress on the terminal; started again after an interruption, it continues
from the last time written (every --write seconds).  Then the case's
evaluate gives the paper's figures:
  Fig 11   particleTemperature_<t>.png, gasTemperature_<t>.png
  Fig 12   heatTransfer.png, heatProfiles.csv: h and Re across the width,
           z/R_d 16.927-22.454, averaged over the last --average seconds
  history  particleTemperature.png, heatHistory.csv: mean particle
           temperature of spout and downcomer vs time
and heat.txt / heat.csv here (read by protocols/results).

--write is rounded to a whole number of time steps (3e-4 s).
"""
import os
import shutil
import subprocess
import sys

from spoutlab import cli
from spoutlab import foamfile
from spoutlab import spoutedbed
from spoutlab import caserun
from spoutlab import spoutheat

PAPER = {'Re_spout': 5690, 'Re_downcomer': 130}


def options(argv, name='heatTransfer', doc=__doc__, extra=None):
    """The run's options; extra(p) adds a protocol's own."""
    p = cli.parser(name, doc)
    p.add_argument('--u', type=float, default=2.0, metavar='U',
                   help='superficial velocity [m/s] (default %(default)s)')
    p.add_argument('--time', type=float, default=6.0, metavar='T',
                   help='simulated time [s] (default %(default)s)')
    p.add_argument('--average', type=float, default=1.8, metavar='T',
                   help='averaging window at the end [s] (default %(default)s)')
    p.add_argument('--write', type=float, default=0.15, metavar='T',
                   help='write interval [s] (default %(default)s)')
    if extra:
        extra(p)
    p.add_argument('-n', type=int, help='particles (default: system/spoutedBedDict)')
    p.add_argument('-np', type=int, default=1, metavar='RANKS', help='MPI ranks')
    cli.add_overrides(p)
    o = vars(cli.parse(p, argv))
    if not 0 < o['average'] <= o['time']:
        p.error('--average must be positive and at most --time')
    return o


def inside(path):
    """chdir that OpenFOAM's utilities accept (they compare $PWD with cwd)."""
    os.chdir(path)
    os.environ['PWD'] = os.getcwd()


def setting(entry, value):
    subprocess.check_call(['foamDictionary', '-entry', entry, '-set', value,
                           'system/controlDict'], stdout=subprocess.DEVNULL)


def run(o, work, name='heatTransfer', extra=(), entries=None):
    """Prepare (once) and run or continue the case in work, with heat and
    the `extra` overrides of system/spoutedBedDict; entries(), if given, is
    called in work before spoutFoam (a protocol's own dictionary entries)."""
    if not os.path.isdir(work):
        os.makedirs('runs', exist_ok=True)
        shutil.copytree('.', work, ignore=shutil.ignore_patterns(
            'runs', 'processor*', 'DEM', 'particles', 'postProcessing', 'log.*',
            '[0-9]*', '*.png', '*.csv', '*.txt'), symlinks=True)
        shutil.copytree('0.orig', os.path.join(work, '0.orig'), dirs_exist_ok=True)
    here = os.getcwd()
    inside(work)
    try:
        overrides = (['heat=yes'] + list(extra) + o['overrides']
                     + (['nParticles=%d' % o['n']] if o['n'] else []))
        caserun.prepare_case(overrides, name)
        subprocess.check_call(['./inletVelocity', '%g' % o['u']])
        setting('endTime', '%g' % o['time'])
        dt = foamfile.scalar('system/controlDict', 'deltaT')
        setting('writeInterval', '%.10g' % (max(1, round(o['write'] / dt)) * dt))
        setting('functions.averages.timeStart', '%g' % (o['time'] - o['average']))
        if entries:
            entries()
        if (caserun.last_time('log.spoutFoam') or 0.0) < o['time'] - 1e-3:
            caserun.run_spoutfoam(o['time'], o['np'], name)
        with open('log.evaluate', 'w') as log:
            if subprocess.call(['./evaluate', '--window', '%g' % o['average']],
                               stdout=log, stderr=subprocess.STDOUT) != 0:
                sys.exit('%s: evaluate failed, see %s/log.evaluate' % (name, work))
    finally:
        inside(here)


def report(o, work):
    g = spoutedbed.load(work)
    lines = []
    here = os.getcwd()
    inside(work)
    try:
        r = spoutheat.summarize(g, o['average'], lines, pictures=False)
        wall = caserun.wall_time('.')
    finally:
        inside(here)
    text = ['gas-to-particle heat transfer (draft-plate paper, section 4.7): %d particles, '
            'u_s = %g m/s, %g s, averages over the last %g s; run in %s'
            % (int(g.particles['nParticles']), o['u'], o['time'], o['average'], work)]
    text += lines
    text.append('paper: Re about %d in the spout and %d in the downcomer; h higher in the '
                'spout and falling with height, roughly uniform in the downcomer'
                % (PAPER['Re_spout'], PAPER['Re_downcomer']))
    text.append('spoutFoam wall time: %.0f min' % (wall / 60))
    out = '\n'.join(text) + '\n'
    sys.stdout.write(out)
    open('heat.txt', 'w').write(out)
    with open('heat.csv', 'w') as f:
        f.write('key,value\n')
        for key in ('Re_spout', 'Re_downcomer', 'h_spout', 'h_downcomer', 'balance',
                    'pairwise', 'Tp_spout', 'Tp_downcomer', 'T_outlet', 'samples',
                    'dh_dz_spout', 'dh_dz_downcomer', 'h_downcomer_spread', 'h_by_plates',
                    'h_by_walls'):
            f.write('%s,%.10g\n' % (key, r[key]))
        f.write('particles,%d\nu_s,%g\ntime,%g\naverage,%g\nwall_s,%.0f\n'
                % (int(g.particles['nParticles']), o['u'], o['time'], o['average'], wall))
    for name in os.listdir(work):
        if name.endswith('.png') and ('Temperature' in name or name == 'heatTransfer.png'):
            shutil.copy(os.path.join(work, name), 'heat_' + name)


def main(argv):
    o = options(argv)
    work = os.path.join('runs', 'heat_u%g' % o['u'])
    run(o, work)
    report(o, work)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
