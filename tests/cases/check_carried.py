#!/usr/bin/env python3
"""check_carried.py CASE TIME: what spoutFoam's circulation statistics say the
gas crossing the cores' sides carries (circulation.json, gas.carried), against
the same sums made here from the fields the run wrote at TIME, for a run whose
statistics sampled TIME alone.

The cores' sides are the mesh faces at |x| = Wd/2 whose normal is along x,
below He (the jet) and above Hd (the fountain's core), Wd, He, Hd from
constant/spoutedBed [mm]; each face's flux phi leaves the core where the
normal points away from the axis; the gas it carries is its upwind cell's: T
and H2O (where the run dries) of the cell it comes from.  The same of the
net upward flows through the spout gap and the downcomers, on the plane of
horizontal faces nearest to mid-plate height (He + Hd)/2 from below, and out
of the jet's top (the plane nearest to He from below, |x| < Wd/2).  Read from the ASCII polyMesh and fields
with nothing of spoutFoam's own, so a wrong upwind cell, a wrong sign or a
face counted twice shows as a difference beyond the ten digits the file
keeps.
"""
import json
import os
import re
import sys

import numpy as np

from spoutlab import foamfile

case, time = sys.argv[1:3]
TOL = 1e-8


def foam_list(path):
    """The list body of an ASCII polyMesh file: its items as strings."""
    with open(path) as f:
        text = re.sub(r'/\*.*?\*/|//[^\n]*', '', f.read(), flags=re.S)
    body = text[text.index('}') + 1:]
    m = re.search(r'(\d+)\s*\(', body)
    n, start = int(m.group(1)), m.end()
    inner = body[start:body.rindex(')')]
    items = re.findall(r'\d+\([^)]*\)|\([^)]*\)|[-+0-9.eE]+', inner)
    if len(items) != n:
        sys.exit('check_carried: %s: expected %d items, read %d' % (path, n, len(items)))
    return items


mesh = os.path.join(case, 'constant', 'polyMesh')
points = np.array([[float(v) for v in p.strip('()').split()] for p in foam_list(os.path.join(mesh, 'points'))])
faces = [[int(v) for v in f[f.index('(') + 1:-1].split()] for f in foam_list(os.path.join(mesh, 'faces'))]
owner = np.array([int(v) for v in foam_list(os.path.join(mesh, 'owner'))])
neighbour = np.array([int(v) for v in foam_list(os.path.join(mesh, 'neighbour'))])
phi = np.array(foamfile.read_field(os.path.join(case, time, 'phi')))
T = np.array(foamfile.read_field(os.path.join(case, time, 'T')))
# the vapour where the run dries (then the file has its H2O too)
vapour = os.path.join(case, time, 'H2O')
Y = np.array(foamfile.read_field(vapour)) if os.path.exists(vapour) else np.zeros_like(T)
geometry = os.path.join(case, 'constant', 'spoutedBed')
half, He, Hd = (0.5e-3 * foamfile.scalar(geometry, 'Wd'), 1e-3 * foamfile.scalar(geometry, 'He'),
                1e-3 * foamfile.scalar(geometry, 'Hd'))

plate = 1e-3 * foamfile.scalar(geometry, 'plateThickness')
# sums[core][way] = [flow, flow T, flow H2O]; way 0 out of the core, 1 into it
sums = np.zeros((2, 2, 3))
geometry_of = []
for f in range(len(neighbour)):
    p = points[faces[f]]
    geometry_of.append((p.mean(axis=0), 0.5 * np.cross(p[2] - p[0], p[3] - p[1])))  # a quad's area
# planes[k] = the same of the net upward flow through the spout gap (k 0)
# and the downcomers (1), on the plane of horizontal faces nearest to
# mid-plate height from below, and (2) out of the jet's top, the plane
# nearest to He from below, |x| < Wd/2
planes = np.zeros((3, 3))


def horizontal(area):
    return abs(area[2]) >= 0.99 * np.linalg.norm(area)


def plane_below(z):
    return max(c[2] for c, a in geometry_of if horizontal(a) and c[2] <= z + 1e-9)


mid, top = plane_below(0.5 * (He + Hd)), plane_below(He)
for f, (centre, area) in enumerate(geometry_of):
    if not horizontal(area):
        continue
    ks = []
    if abs(centre[2] - mid) <= 1e-9:
        ks.append(0 if abs(centre[0]) < half else 1 if abs(centre[0]) > half + plate else -1)
    if abs(centre[2] - top) <= 1e-9 and abs(centre[0]) < half:
        ks.append(2)
    for k in ks:
        if k >= 0:
            upwind = owner[f] if phi[f] > 0 else neighbour[f]
            planes[k] += phi[f] * np.sign(area[2]) * np.array([1, T[upwind], Y[upwind]])
for f, (centre, area) in enumerate(geometry_of):
    if abs(area[0]) < 0.99 * np.linalg.norm(area) or abs(abs(centre[0]) - half) > 1e-6 * half:
        continue
    core = 0 if centre[2] < He else 1 if centre[2] > Hd else -1
    if core < 0:
        continue
    owner_inside = area[0] * centre[0] > 0   # the normal points away from the axis
    out = phi[f] if owner_inside else -phi[f]
    upwind = owner[f] if (out > 0) == owner_inside else neighbour[f]
    way = 0 if out > 0 else 1
    sums[core, way] += abs(out) * np.array([1, T[upwind], Y[upwind]])

gas = json.load(open(os.path.join(case, 'circulation.json')))['gas']
failures = 0


def compare(name, key, here, there, rel_shown=True):
    """One value rebuilt here against the file's, within TOL."""
    global failures
    rel = abs(there / here - 1)
    ok = rel <= TOL
    failures += not ok
    print('%-18s %-4s fields %.10g, circulation.json %.10g%s: %s'
          % (name, key, here, there, ' (rel %.1e)' % rel if rel_shown else '',
             'PASS' if ok else 'FAIL'))


def compare_carried(name, flow, flowT, flowY):
    """The T (and H2O where the run dries) a flow carries."""
    for key, here in (('T', flowT / flow), ('H2O', flowY / flow))[:2 if os.path.exists(vapour) else 1]:
        compare(name, key, here, gas['carried'][name][key])


names = (('outOfJet', 'intoJet'), ('outOfFountainCore', 'intoFountainCore'))
for core in range(2):
    for way in range(2):
        compare_carried(names[core][way], *sums[core, way])
    # the mass flows themselves, as the ratio out / in (rho and the inlet's
    # flow, by which the file divides them, cancel)
    compare(names[core][0], '/in', sums[core, 0, 0] / sums[core, 1, 0],
            gas[names[core][0]] / gas[names[core][1]], rel_shown=False)
for k, name in enumerate(('spoutGap', 'downcomers', 'jetTop')):
    compare_carried(name, *planes[k])
compare('spout/downcomers', '', planes[0, 0] / planes[1, 0],
        gas['spoutShare'] / gas['downcomerShare'], rel_shown=False)
sys.exit('check_carried: %d values differ' % failures if failures else 0)
