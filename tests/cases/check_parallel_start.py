#!/usr/bin/python3
"""check_parallel_start.py NAME SERIAL PARALLEL RANKS: a parallel run's start
(reconstructed at t = 0) is the serial run's, to 1e-12.

Every cell's void fraction, solid fraction, Us and Ksl, every particle's fluid force
(DEM/start.state) and the first two rows of coupling.csv; NAME heads the
lines printed, RANKS is said in them.
"""
import os
import struct
import sys

import numpy as np

from spoutlab import casefiles as sc
from spoutlab import foamfile

FIELDS = ('voidfraction', 'solidFraction', 'Us', 'Ksl')


def differ(worst, name, a, b, ranks, floor=1e-300):
    """Largest difference relative to the largest value (or floor)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape != b.shape:
        sys.exit('%s has %s values serially, %s on %d ranks' % (name, a.shape, b.shape, ranks))
    worst[name] = np.abs(a - b).max() / max(np.abs(a).max(), floor)


def fluid_forces(case):
    with open(os.path.join(case, 'DEM', 'start.state'), 'rb') as f:
        f.readline()
        rows, width = struct.unpack('<qi', f.read(12))
        data = np.frombuffer(f.read(8 * rows * width)).reshape(rows, width)
    data = data[np.argsort(data[:, 0])]
    return data[:, 0], data[:, 7:10]


def compare(serial, parallel, ranks):
    worst = {}
    for field in FIELDS:
        differ(worst, field, foamfile.read_field(os.path.join(serial, '0', field)),
               foamfile.read_field(os.path.join(parallel, '0', field)), ranks)
    ids_s, force_s = fluid_forces(serial)
    ids_p, force_p = fluid_forces(parallel)
    if not np.array_equal(ids_s, ids_p):
        sys.exit('the ranks hold other particles than the serial run')
    differ(worst, 'particle fluid force', force_s, force_p, ranks)
    # Row 0 is the start; row 1's momentum columns come from the first DEM
    # steps (parallel LIGGGHTS too) and the gas before its first solve.  Its
    # gas received and heat columns follow that solve, where the linear
    # solvers' tolerance, not round-off, separates a serial from a parallel run.
    rows_s = sc.read_coupling_log(serial)[:2]
    rows_p = sc.read_coupling_log(parallel)[:2]
    keys = list(rows_s[0])
    for n, key in enumerate(keys):
        rows = 2 if n < keys.index('gas received x [N]') else 1
        # at the start the gas has the particles' temperature: the heat flows
        # are round-off about zero, measured against 1 W (100 W a step later)
        differ(worst, 'coupling.csv ' + key, [r[key] for r in rows_s[:rows]],
               [r[key] for r in rows_p[:rows]], ranks, 1.0 if key.endswith('[W]') else 1e-300)
    return worst


def main():
    name, serial, parallel, ranks = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    try:
        worst = compare(serial, parallel, ranks)
    except SystemExit as stop:
        sys.exit('%s: %s' % (name, stop))
    key = max(worst, key=worst.get)
    print('%s: serial vs %d ranks at the start: largest relative difference '
          '%.1e (%s; limit 1e-12)' % (name, ranks, worst[key], key))
    for k in ('voidfraction', 'Us', 'Ksl', 'particle fluid force'):
        print('  %-22s %.1e' % (k, worst[k]))
    sys.exit(0 if worst[key] < 1e-12 else 1)


if __name__ == '__main__':
    main()
