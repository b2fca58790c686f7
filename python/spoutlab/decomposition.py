#!/usr/bin/python3
"""Slab decomposition across x for parallel coupled runs.

The coupling exchanges particle data between neighbouring ranks only if each
rank's LIGGGHTS subdomain covers the same region as its OpenFOAM cells.
LIGGGHTS splits its box into slabs across x ('processors * 1 1'), so the
gas mesh is split into x-slabs as well: OpenFOAM's 'manual' method with each
cell's rank from its centre, the cut planes between columns of cells (cell
faces), placed so the ranks get equal numbers of cells.  spoutFoam reads the
slabs back from the decomposed mesh and sets LIGGGHTS' cuts to the same
planes.

    python3 -m spoutlab.decomposition CASE N
        writes CASE/constant/cellDecomposition and CASE/system/decomposeParDict
        (N slabs); needs CASE/0/C (postProcess -func writeCellCentres)
"""
import os
import sys

from spoutlab import cli
from spoutlab import foamfile


def slab_cuts(x, n):
    """n - 1 cut positions between distinct cell-centre x (the faces of a
    structured grid's columns), each where the cumulative cell count comes
    closest to its share k/n."""
    columns = sorted(set(round(v, 12) for v in x))
    if len(columns) < n:
        raise ValueError('%d columns of cells cannot make %d slabs' % (len(columns), n))
    counts = {c: 0 for c in columns}
    for v in x:
        counts[round(v, 12)] += 1
    cumulative, total = [], 0
    for c in columns:
        total += counts[c]
        cumulative.append(total)
    cuts, first = [], 0
    for k in range(1, n):
        target = k * total / n
        # boundary after column j; at least one column per slab
        candidates = range(first, len(columns) - (n - k))
        j = min(candidates, key=lambda j: abs(cumulative[j] - target))
        cuts.append(0.5 * (columns[j] + columns[j + 1]))
        first = j + 1
    return cuts


def ranks(x, cuts):
    """Rank of each cell: the number of cuts left of its centre."""
    return [sum(1 for c in cuts if v > c) for v in x]


def write(case, n):
    centres = foamfile.read_field(os.path.join(case, '0', 'C'))
    x = [c[0] for c in centres]
    cuts = slab_cuts(x, n)
    owner = ranks(x, cuts)
    header = ('FoamFile\n{\n    version     2.0;\n    format      ascii;\n'
              '    class       %s;\n    location    "%s";\n    object      %s;\n}\n')
    with open(os.path.join(case, 'constant', 'cellDecomposition'), 'w') as f:
        f.write(header % ('labelList', 'constant', 'cellDecomposition'))
        f.write('// x-slabs cut at %s m\n%d\n(\n' % (' '.join('%.6g' % c for c in cuts), len(owner)))
        f.write('\n'.join(str(r) for r in owner))
        f.write('\n)\n')
    with open(os.path.join(case, 'system', 'decomposeParDict'), 'w') as f:
        f.write(header % ('dictionary', 'system', 'decomposeParDict'))
        f.write('// written by spoutlab.decomposition: x-slabs, as LIGGGHTS\n'
                '// decomposes its box (processors * 1 1)\n'
                'numberOfSubdomains %d;\nmethod          manual;\n'
                'coeffs\n{\n    dataFile    "cellDecomposition";\n}\n' % n)
    return cuts


def main():
    parser = cli.Parser(prog='decomposition', description=__doc__.split('\n\n')[0])
    parser.add_argument('case')
    parser.add_argument('ranks', type=int)
    args = parser.parse_args()
    if args.ranks < 2:
        parser.error('ranks: expected 2 or more, got %d' % args.ranks)
    try:
        cuts = write(args.case, args.ranks)
    except (OSError, ValueError) as e:
        sys.exit('decomposition: %s' % e)
    print('decomposition: %d x-slabs, cuts at %s m'
          % (args.ranks, ', '.join('%.4g' % c for c in cuts)))


if __name__ == '__main__':
    main()
