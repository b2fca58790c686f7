"""The benchmarks' one command: python3 -m spoutlab.bench NAME [OPTIONS]
(NAME --help lists its options); bench/NAME runs it."""
import importlib
import sys

# command name: module of spoutlab.bench
COMMANDS = {'couplingOverhead': 'couplingoverhead', 'dryingOverhead': 'dryingoverhead',
            'neighbourSettings': 'neighboursettings', 'parallelAgreement': 'parallelagreement',
            'parallelSpeedup': 'parallelspeedup', 'peerDPMFoam': 'peerdpmfoam',
            'weakScaling': 'weakscaling'}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] not in COMMANDS:
        sys.stderr.write('spoutlab.bench: NAME one of %s (bench/README.md)\n'
                         % ', '.join(COMMANDS))
        return 2
    name = argv[0]
    sys.argv = [name] + argv[1:]   # the benchmark's messages and usage name it
    module = importlib.import_module('spoutlab.bench.' + COMMANDS[name])
    return module.main(argv[1:])


if __name__ == '__main__':
    sys.exit(main())
