"""Protocol (b) of the draft-plate paper, sections 4.2-4.3: time-averaged
particle velocity and voidage across the spout (Fig 4) and downward
particle velocity across the downcomers (Fig 5) at u_s = 1.40 m/s, and the
downcomer again at a second velocity.

Each velocity is one run in runs/He<He>_u<u>/ made exactly as a point of
`circulation velocity` (same labels, same settings), so the two protocols
share runs when started in the same directory; finished runs are kept, and
running the command again after an interruption continues.

Results: profiles.txt (the paper's features, lower vs upper region) and, per
velocity, profiles_u<u>_{spoutVelocity,spoutVoidage,downcomerVelocity}.png
and the CSV files of the run.
"""
import json
import os
import shutil
import sys

from spoutlab import cli
from spoutlab import profilefeatures
from spoutlab.protocols import circulation as circ


def parse(argv):
    p = cli.parser('profiles', __doc__)
    p.add_argument('--u', type=cli.numbers, default=[1.4, 2.0], metavar='U,...',
                   help='superficial velocities [m/s] (default 1.4,2.0)')
    p.add_argument('--He', type=cli.numbers, default=[95], metavar='MM',
                   help='entrance height [mm] (default 95; of a list, the first)')
    circ.run_options(p)
    return vars(cli.parse(p, argv))


def main(argv):
    o = parse(argv)
    He = o['He'][0]
    lines = ['time-averaged profiles (draft-plate paper, Figs 4 and 5); lower region '
             'z/R_d < 12, upper region above; %g s per run, averaged over the last %g s'
             % (o['time'], o['average'])]
    settled = {}
    numbers = []   # the features as printed, for protocols/results (profiles.json)
    for u in o['u']:
        label = 'He%g_u%g' % (He, u)
        work = circ.run_point(o, label, u, ['He=%g' % He], settled)
        for name in ('spoutVelocity', 'spoutVoidage', 'downcomerVelocity'):
            shutil.copy(os.path.join(work, name + '.png'), 'profiles_u%g_%s.png' % (u, name))
        spout = profilefeatures.read_profile(os.path.join(work, 'spoutProfiles.csv'))
        down = profilefeatures.read_profile(os.path.join(work, 'downcomerProfiles.csv'))
        lines.append('')
        lines.append('u_s = %g m/s (%s):' % (u, work))
        features = profilefeatures.profile_features(spout, down)
        for name, low, high, holds in features:
            lines.append('  %-58s lower %.3f m/s, upper %.3f m/s: %s'
                         % (name, low, high, 'yes' if holds else 'NO'))
        numbers.append({'u_m_s': u, 'features': [
            {'feature': name, 'lower_m_s': float('%.3f' % low), 'upper_m_s': float('%.3f' % high),
             'holds': bool(holds)} for name, low, high, holds in features]})
        # where the spout stops accelerating, and how much it slows above
        series = profilefeatures.by_height(spout)
        top = max(series, key=lambda hv: hv[1])
        lines.append('  spout velocity by height (z/R_d: m/s)  '
                     + ', '.join('%.1f: %.2f' % hv for hv in series))
        lines.append('  fastest at z/R_d = %.1f (%.2f m/s); at the top %.2f m/s (%+.0f %%)'
                     % (top[0], top[1], series[-1][1], 100 * (series[-1][1] / top[1] - 1)))
    text = '\n'.join(lines) + '\n'
    sys.stdout.write(text)
    open('profiles.txt', 'w').write(text)
    with open('profiles.json', 'w') as f:
        json.dump({'points': numbers}, f, indent=1)
        f.write('\n')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
