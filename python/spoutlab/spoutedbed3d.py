"""The three-dimensional spouted bed (openfoam_cases/spoutedBed3D): a
cylindrical column with a conical base, its geometry read from the case's
system/spoutedBedDict, shared by the case's generate script, its
inletVelocity, its evaluate script and the minimum-spouting protocol; and
Mathur and Gishler's u_ms correlation for it.

The gas mesh is an O-grid: a central square and four ring blocks, the same
cross-section on every layer, scaled in the cone by its diameter at that
height (so every face is planar: the cone's faces lie in planes through its
apex).  The walls are polygons of 4 nSquare sides whose area is the
nominal circle's.  Coordinates: the axis is z, the origin at the centre of
the bottom (the inlet plane).  Lengths in mm unless said.

Standard library only."""
import math
import sys

from spoutlab.spoutedbed import coarse_graining, insertion_seed, read_dict  # noqa: F401


class Geometry:
    """The vessel in mm, from the dictionary (read_dict's values)."""

    def __init__(self, d, path):
        def number(key, lo=0.0, integer=False):
            try:
                v = float(d[key])
            except (KeyError, ValueError):
                sys.exit('generate: %s: key %r expected a number, got %r'
                         % (path, key, d.get(key)))
            if not v > lo or (integer and v != int(v)):
                sys.exit('generate: %s: key %r expected %s above %g, got %r'
                         % (path, key, 'a whole number' if integer else 'a number', lo, d[key]))
            return int(v) if integer else v

        self.Dc, self.Db, self.H = number('Dc'), number('Db'), number('H')
        self.coneAngle = number('coneAngle')
        self.squareRatio = number('squareRatio')
        self.nSquare, self.nRing = number('nSquare', 0, True), number('nRing', 0, True)
        self.cellHeight = number('cellHeight')
        if self.Db > self.Dc or self.coneAngle >= 180:
            sys.exit('generate: %s: keys Db, coneAngle expected Db <= Dc and an angle below '
                     '180 deg, got Db %g, Dc %g, coneAngle %g'
                     % (path, self.Db, self.Dc, self.coneAngle))
        if self.squareRatio >= 1 / math.sqrt(2):
            sys.exit('generate: %s: key \'squareRatio\' expected below 0.707 (the square '
                     'inside the circle), got %g' % (path, self.squareRatio))
        self.R, self.Rb = self.Dc / 2, self.Db / 2
        self.zCone = (self.R - self.Rb) / math.tan(math.radians(self.coneAngle / 2))
        if self.zCone >= self.H:
            sys.exit('generate: %s: key \'H\' expected above the cone\'s height %.1f mm, got %g'
                     % (path, self.zCone, self.H))
        self.nCone = max(1, round(self.zCone / self.cellHeight)) if self.zCone > 0 else 0
        self.nColumn = max(1, round((self.H - self.zCone) / self.cellHeight))
        self.particles = {k: number(k) for k in ('dp', 'rhop', 'kn', 'e', 'mu', 'nu', 'dtDem')}
        self.particles['nParticles'] = number('nParticles', 0, True)
        self.coarseGraining = coarse_graining(d.get('coarseGraining', '1'), path)
        self.seed = insertion_seed(d.get('insertionSeed', ''), path)
        self.gas = {'rho': number('rhoGas'), 'mu': number('muGas')}

    # --- the O-grid ----------------------------------------------------------
    @property
    def sides(self):
        return 4 * self.nSquare

    @property
    def vertex_radius(self):
        """Radius [mm] of the walls' corners: the polygon of `sides` sides
        with the nominal circle's area."""
        n = self.sides
        return self.R * math.sqrt(2 * math.pi / (n * math.sin(2 * math.pi / n)))

    def scale(self, z):
        """The cross-section's scale at height z [mm]: Db/Dc at the bottom,
        1 from the top of the cone up."""
        if z >= self.zCone:
            return 1.0
        return (self.Rb + (self.R - self.Rb) * z / self.zCone) / self.R

    @property
    def square_half(self):
        return self.squareRatio * self.R

    # --- what the correlation and the inlet need (SI) -------------------------
    @property
    def column_area(self):
        return math.pi * (self.R / 1000) ** 2

    @property
    def inlet_area(self):
        return (2 * self.square_half * self.scale(0) / 1000) ** 2

    @property
    def inlet_diameter(self):
        """The inlet square's equal-area diameter [m], the correlation's D_i."""
        return math.sqrt(4 * self.inlet_area / math.pi)

    def vessel_volume(self, h):
        """The vessel's volume [m3] up to height h [m] (the polygon's area
        is the circle's at every height)."""
        z = min(h * 1000, self.zCone)
        r0, r1 = self.Rb, self.R * self.scale(z)
        cone = math.pi * z / 3 * (r0 * r0 + r0 * r1 + r1 * r1)
        column = math.pi * self.R ** 2 * max(0.0, h * 1000 - self.zCone)
        return (cone + column) * 1e-9


def load(case='.', overrides=()):
    """The geometry of a case as its run uses it: constant/spoutedBed
    (written by generate with the overrides applied) if present."""
    import os
    path = os.path.join(case, 'constant', 'spoutedBed')
    if not os.path.isfile(path):
        path = os.path.join(case, 'system', 'spoutedBedDict')
    return Geometry(read_dict(path, overrides), path)


def mathur_gishler_ums(d_p, D_c, D_i, H, rho_p, rho=1.205, g=9.81):
    """Mathur and Gishler's minimum spouting velocity [m/s] (AIChE J. 1
    (1955) 157-164), superficial over the column: all lengths in m, H the
    bed depth above the inlet."""
    return d_p / D_c * (D_i / D_c) ** (1 / 3) * math.sqrt(2 * g * H * (rho_p - rho) / rho)
