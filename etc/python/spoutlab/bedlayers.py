"""A bed of spheres in a column of horizontal layers (one CFD cell across):
the solid volume and the voidage of each layer worked out from the particles
themselves, for the evaluate scripts of the column cases.

How a particle's volume is shared between layers follows the solver's
voidFractionModel (docs/DESIGN.md §3.4), computed exactly here:
  divided  the volume of the sphere between the layer planes (a slice
           bounded by two spherical caps); the solver approximates this with
           30 equal pieces;
  centre   the whole sphere to the layer holding its centre.
Needs numpy (/usr/bin/python3).
"""
import math
import os

import numpy as np

from spoutlab import foamfile


def sphere_slice(zc, r, a, b):
    """Volume of the spheres (centres at height zc, radii r) between the
    planes z = a and z = b: pi [r^2 u - u^3/3] between the clipped heights
    u = z - zc."""
    u0 = np.clip(a - zc, -r, r)
    u1 = np.clip(b - zc, -r, r)
    return math.pi * (r ** 2 * (u1 - u0) - (u1 ** 3 - u0 ** 3) / 3)


def centre_share(zc, r, a, b):
    """Volume of the spheres whose centre lies in [a, b)."""
    return np.where((zc >= a) & (zc < b), 4 / 3 * math.pi * r ** 3, 0.0)


def void_fraction_model(path='constant/couplingProperties'):
    name = foamfile.entry(path, 'voidFractionModel', None)
    if name not in ('divided', 'centre'):
        raise SystemExit("%s: key 'voidFractionModel' expected divided or centre, got '%s'"
                         % (path, name))
    return name


class Column:
    """The horizontal layers of cells of a column mesh, from the cell centres
    and volumes postProcess wrote into 0/C and 0/V (writeCellCentres,
    writeCellVolumes): faces[k] .. faces[k + 1] is layer k, volumes[k] the
    volume of its cells, area the cross-section."""

    def __init__(self, case='.'):
        zc = np.array([c[2] for c in foamfile.read_field(os.path.join(case, '0', 'C'))])
        volumes = np.array(foamfile.read_field(os.path.join(case, '0', 'V')))
        # cells of one layer share their centre height (to round-off)
        levels = np.unique(np.round(zc, 9))
        layer = np.searchsorted(levels, np.round(zc, 9))
        self.centres = levels
        self.volumes = np.bincount(layer, weights=volumes, minlength=len(levels))
        dz = np.diff(self.centres)
        if len(dz) == 0 or np.max(np.abs(dz - dz[0])) > 1e-9 * dz[0]:
            raise SystemExit('evaluate: 0/C: expected uniform horizontal layers of cells')
        self.dz = float(dz[0])
        bottom = self.centres[0] - self.dz / 2
        self.faces = bottom + self.dz * np.arange(len(levels) + 1)
        self.area = float(self.volumes[0]) / self.dz

    def layer_of(self, z):
        return int(np.argmin(np.abs(self.centres - z)))

    def solid(self, z, r, model):
        """Solid volume per layer [m3] for particles at heights z, radii r."""
        share = sphere_slice if model == 'divided' else centre_share
        return np.array([share(z, r, a, b).sum()
                         for a, b in zip(self.faces[:-1], self.faces[1:])])

    def voidage(self, z, r, model):
        return 1 - self.solid(z, r, model) / self.volumes
