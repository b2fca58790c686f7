"""The protocols' one command: python3 -m spoutlab.protocols NAME [OPTIONS]
(NAME --help lists a protocol's options).  The spouted bed's case runs it
as protocols/NAME (protocols/run, linked under each name); an installed
package has it as spoutlab-protocol NAME.  Run it in a copy of
openfoam_cases/spoutDraftPlates."""
import importlib
import sys

# command name: (module of spoutlab.protocols, what it reproduces)
COMMANDS = {
    'minimumSpouting': ('minimumspouting', 'the minimum spouting velocity and the '
                        'pressure-drop loop of Fig 2 (draft-plate paper section 4.1, '
                        'no-draft paper)'),
    'minimumSpouting3D': ('minimumspouting3d', 'u_ms and dP_ms of the three-dimensional '
                          'spouted bed (openfoam_cases/spoutedBed3D) beside Mathur and '
                          "Gishler's correlation"),
    'circulation': ('circulation', 'the particle circulation rate W_s against the gas '
                    'velocity and the friction coefficient (draft-plate paper section 4.4)'),
    'profiles': ('profiles', 'time-averaged spout and downcomer profiles (draft-plate '
                 'paper sections 4.2-4.3, Figs 4-5)'),
    'spoutHeight': ('spoutheight', 'the spout along its height: particle and gas velocity, '
                    'voidage, slip Re and h against z, and the slugs (draft-plate paper '
                    'Figs 4 and 12)'),
    'velocityMaps': ('velocitymaps', 'time-averaged gas and particle velocity without '
                     'draft plates (no-draft paper, Figs 3-4)'),
    'mixing': ('mixing', 'the degree of mixing against time (draft-plate paper Fig 10, '
               'no-draft paper Figs 5-6)'),
    'heatTransfer': ('heattransfer', 'hot air through the bed with draft plates '
                     '(draft-plate paper section 4.7, Figs 11-12)'),
    'drying': ('drying', 'the bed with draft plates as a dryer, wet corn in hot air '
               '(draft-plate paper section 4.7 conditions)'),
    'dryingTime': ('dryingtime', 'what the long-time drying predictor takes from the '
                   'CFD-DEM: circulation statistics of the bed with draft plates'),
    'coarseSpeedup': ('coarsespeedup', 'the draft-plate bed coarse-grained against cg = 1: '
                      'the same span of spouting at each factor, one after the other, timed '
                      '(issue 27 item 8)'),
    'results': ('results', "the protocol outputs collected into docs/RESULTS.md and "
                "docs/results.csv beside the papers' values"),
}


def usage():
    return ('usage: protocols/NAME [OPTIONS] (python3 -m spoutlab.protocols NAME ...), '
            'NAME one of:\n' + ''.join('  %-16s %s\n' % (name, what)
                                       for name, (_, what) in COMMANDS.items()))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] in ('-h', '--help'):
        sys.stdout.write(usage())
        return 0 if argv else 2
    name = argv[0]
    if name not in COMMANDS:
        sys.stderr.write('spoutlab.protocols: no protocol %r (one of %s)\n'
                         % (name, ', '.join(COMMANDS)))
        return 2
    module = importlib.import_module('spoutlab.protocols.' + COMMANDS[name][0])
    return module.main(argv[1:])


if __name__ == '__main__':
    sys.exit(main())
