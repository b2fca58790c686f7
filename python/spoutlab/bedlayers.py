"""A bed of spheres in a column of horizontal layers (one CFD cell across):
the solid volume and the voidage of each layer worked out from the particles
themselves, for the evaluate scripts of the column cases.

How a particle's volume is shared between layers follows the solver's
voidFractionModel (docs/DESIGN.md §3.4), computed exactly here:
  divided  the volume of the sphere between the layer planes (a slice
           bounded by two spherical caps); the solver approximates this with
           30 equal pieces;
  centre   the whole sphere to the layer holding its centre.
divided_share places the solver's 30 pieces themselves (its voidage to
round-off), for a reference that must see the particles as the solver maps
them (openfoam_cases/packedBedDrying).
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


def coarse_graining(path='constant/couplingProperties'):
    """The case's coarseGraining cg (default 1): each DEM particle, whose
    radius the particle files hold, is a parcel of cg^3 particles of
    diameter 2 r / cg."""
    text = foamfile.entry(path, 'coarseGraining', '1')
    try:
        cg = float(text)
    except (TypeError, ValueError):
        cg = 0.0
    if not cg >= 1:
        raise SystemExit("%s: key 'coarseGraining' expected a factor >= 1, got '%s'"
                         % (path, text))
    return cg


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


def divided_offsets(n_shells=3, n_rings=2, n_azimuthal=4):
    """The centroids of the divided model's equal-volume pieces of a unit
    ball, turned to its fixed oblique orientation (coupling/SphereSampling,
    DividedVoidFraction: shells equal in r^3, each a polar cap, n_rings
    bands of n_azimuthal sectors and a cap, equal in cos(theta); odd shells
    turned by half a sector; then Rodrigues' rotation by 1.7 rad about
    (3, 1, 2)); an array of N x 3."""
    points = []
    for k in range(n_shells):
        r_in = (k / n_shells) ** (1 / 3)
        r_out = 1.0 if k + 1 == n_shells else ((k + 1) / n_shells) ** (1 / 3)
        mean_r = 0.75 * (r_out ** 4 - r_in ** 4) / (r_out ** 3 - r_in ** 3)
        offset = math.pi / n_azimuthal if k % 2 == 1 else 0.0
        per_shell = 2 + n_rings * n_azimuthal
        cap = 2.0 / per_shell
        band = (2.0 - 2.0 * cap) / n_rings
        sectors = [(1.0 - cap, 1.0, None)]
        for b in range(n_rings):
            high = 1.0 - cap - b * band
            low = -1.0 + cap if b + 1 == n_rings else high - band
            dphi = 2 * math.pi / n_azimuthal
            sectors += [(low, high, (offset + m * dphi, offset + (m + 1) * dphi))
                        for m in range(n_azimuthal)]
        sectors.append((-1.0, -1.0 + cap, None))
        for low, high, phis in sectors:
            width = 2 * math.pi if phis is None else phis[1] - phis[0]
            solid_angle = (high - low) * width
            z = 0.5 * (high ** 2 - low ** 2) * width
            x = y = 0.0
            if phis is not None:
                def s(v):
                    return 0.5 * (v * math.sqrt(1 - v * v) + math.asin(v))
                x = (s(high) - s(low)) * (math.sin(phis[1]) - math.sin(phis[0]))
                y = (s(high) - s(low)) * (math.cos(phis[0]) - math.cos(phis[1]))
            points.append(np.array([x, y, z]) * mean_r / solid_angle)
    axis = np.array([3.0, 1.0, 2.0]) / math.sqrt(14.0)
    c, s_ = math.cos(1.7), math.sin(1.7)
    return np.array([v * c + np.cross(axis, v) * s_ + axis * (axis @ v) * (1 - c) for v in points])


def divided_share(points, r, faces, lower, upper):
    """Solid volume per layer (rows) of each particle (columns) as the
    divided model shares it in a column of horizontal layers between the
    planes faces, the mesh being the box lower..upper: a sphere wholly
    inside its layer stays there; otherwise each piece goes to the layer of
    its centroid, or to the centre's layer if the centroid is outside the
    mesh."""
    points = np.asarray(points, float)
    offsets = divided_offsets()
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    volume = 4 * math.pi * r ** 3 / 3
    share = np.zeros((len(faces) - 1, len(r)))
    layer = np.clip(np.searchsorted(faces, points[:, 2], side='right') - 1, 0, len(faces) - 2)
    for i, (x, radius) in enumerate(zip(points, r)):
        inside = (np.all(x - radius >= lower) and np.all(x + radius <= upper)
                  and x[2] - radius >= faces[layer[i]] and x[2] + radius <= faces[layer[i] + 1])
        if inside:
            share[layer[i], i] = volume[i]
            continue
        pieces = x + radius * offsets
        out = np.any(pieces < lower, axis=1) | np.any(pieces > upper, axis=1)
        cells = np.clip(np.searchsorted(faces, pieces[:, 2], side='right') - 1, 0, len(faces) - 2)
        cells[out] = layer[i]
        np.add.at(share[:, i], cells, volume[i] / len(offsets))
    return share
