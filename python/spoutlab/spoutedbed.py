"""The two-dimensional slanted-base spouted bed: its geometry read from a
case's system/spoutedBedDict, shared by the case's generate script and its
post-processing, and what it holds (the settled bed's height and voidage).
The rest of the spouted bed's layer is by subject: bedmaps (pictures),
spoutcorrelations (Kudra, Ergun), spoutingloop (the minimum-spouting rules
and schedule), profilefeatures (Figs 4-5), caserun (running the case),
spoutregime (whether it spouts)."""
import math
import os
import sys


def read_dict(path, overrides):
    """The vessel's dictionary (its entries outside FoamFile, in file order)
    with the command line's key=value overrides applied."""
    from spoutlab import foamfile
    values = {k: v for k, v in foamfile.read(path).items()
              if k != 'FoamFile' and isinstance(v, str)}
    for item in overrides:
        key, _, value = item.partition('=')
        if key not in values:
            sys.exit('generate: %s: unknown key %r (expected one of: %s)'
                     % (path, key, ', '.join(sorted(values))))
        values[key] = value
    return values


def insertion_seed(text, path):
    """LIGGGHTS' insertion seed: it must be a prime above 10 000."""
    try:
        seed = int(text)
    except ValueError:
        seed = 0
    if seed <= 10000 or any(seed % k == 0 for k in range(2, math.isqrt(seed) + 1)):
        sys.exit('generate: %s: key \'insertionSeed\' expected a prime number above '
                 '10000 (LIGGGHTS\' rule), got %r' % (path, text))
    return seed


def at_least(text, lowest, path, key, expected):
    """A finite number >= lowest, else one line naming the key and what it
    expected."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value >= lowest):
        sys.exit('generate: %s: key %r expected %s, got %r' % (path, key, expected, text))
    return value


def coarse_graining(text, path):
    """The coarse-graining factor cg >= 1 (a DEM particle a parcel of cg^3)."""
    return at_least(text, 1, path, 'coarseGraining',
                    'a factor >= 1 (parcel diameter / particle diameter)')


def wall_friction(text, mu, path):
    """The particle-wall friction coefficient: 'same' as the particles' mu,
    or a number >= 0."""
    if text == 'same':
        return mu
    return at_least(text, 0, path, 'muWall', 'same (as mu) or a friction coefficient >= 0')


class Geometry:
    """The vessel in mm, from the dictionary."""

    def __init__(self, d, path):
        def number(key, positive=True):
            try:
                v = float(d[key])
            except (KeyError, ValueError):
                sys.exit('generate: %s: key %r expected a number, got %r'
                         % (path, key, d.get(key)))
            if positive and not v > 0:
                sys.exit('generate: %s: key %r expected a positive number, got %r'
                         % (path, key, d[key]))
            return v

        self.W, self.Lb, self.Wi = number('W'), number('Lb'), number('Wi')
        self.theta = number('theta')
        self.plates = d.get('plates', 'yes') in ('yes', 'on', 'true')
        self.Wd, self.He, self.Hd = number('Wd'), number('He'), number('Hd')
        self.t = number('plateThickness')
        self.H = number('H')
        self.refine = int(number('refine'))
        self.dx = number('cellWidth') / self.refine
        self.dz = number('cellHeight') / self.refine
        self.particles = {k: number(k) for k in
                          ('nParticles', 'dp', 'rhop', 'kn', 'e', 'mu', 'nu', 'dtDem')}
        self.particles['muWall'] = wall_friction(d.get('muWall', 'same'),
                                                 self.particles['mu'], path)
        self.coarseGraining = coarse_graining(d.get('coarseGraining', '1'), path)
        self.seed = insertion_seed(d.get('insertionSeed', '49979687'), path)
        self.tan = math.tan(math.radians(self.theta))
        self.nx = round(self.W / self.dx)
        self.nz = round(self.H / self.dz)
        self.nInlet = round(self.Wi / self.dx)
        if abs(self.nx * self.dx - self.W) > 1e-9 or abs(self.nz * self.dz - self.H) > 1e-9:
            sys.exit('generate: %s: W and H must be whole numbers of cells '
                     '(W/cellWidth = %g, H/cellHeight = %g)'
                     % (path, self.W / self.dx, self.H / self.dz))
        if abs(self.nInlet * self.dx - self.Wi) > 1e-9 or (self.nx - self.nInlet) % 2:
            sys.exit('generate: %s: the inlet slot Wi must span a whole, centred '
                     'number of cells' % path)
        if self.plates and self.Wd / 2 + self.t >= self.W / 2:
            sys.exit('generate: %s: the draft plates do not fit in the vessel' % path)
        self.baseTop = (self.W - self.Wi) / 2 * self.tan   # base meets the walls
        self.gas = {'rho': number('rhoGas'), 'mu': number('muGas')}
        self.heat = d.get('heat', 'no') in ('yes', 'on', 'true')
        if self.heat:
            self.gas = {'rho': number('rhoGasHot'), 'mu': number('muGasHot'),
                        'Cp': number('CpGas'), 'kappa': number('kappaGas')}
            self.Tin = number('Tin', positive=False) + 273.15
            self.T0 = number('T0', positive=False) + 273.15
            self.cpp = number('cpp')
            self.correlations = (d.get('spoutCorrelation', 'RanzMarshall'),
                                 d.get('downcomerCorrelation', 'Sartori'))
            self.spoutVoidage = number('spoutVoidage')
            if not (self.Tin > 0 and self.T0 > 0):
                sys.exit('generate: %s: keys Tin and T0 expected temperatures '
                         'above -273.15 C, got %r and %r' % (path, d['Tin'], d['T0']))
        self.moisture = d.get('moisture', 'no') in ('yes', 'on', 'true')
        if self.moisture:
            self._read_drying(d, path, number)

    # the settings of each drying model in system/spoutedBedDict, passed on
    # as its <model>Props (coupling/DryingModel.hpp and the models' headers)
    DRYING_SETTINGS = {'freeWater': (),
                       'reactionEngineering': ('a', 'b', 'c', 'isotherm'),
                       'kernelDiffusion': ('D0', 'activationEnergy', 'nShells', 'kernelSteps',
                                           'isotherm')}

    def _read_drying(self, d, path, number):
        if not self.heat:
            sys.exit('generate: %s: key moisture expected heat yes (drying needs the '
                     'particle temperatures)' % path)
        self.X0 = number('X0', positive=False)
        self.inletW = number('inletHumidityRatio', positive=False)
        if self.X0 < 0 or self.inletW < 0:
            sys.exit('generate: %s: keys X0 and inletHumidityRatio expected 0 or more, '
                     'got %r and %r' % (path, d['X0'], d['inletHumidityRatio']))
        self.dryingModel = d.get('dryingModel', 'kernelDiffusion')
        if self.dryingModel not in self.DRYING_SETTINGS:
            sys.exit('generate: %s: key dryingModel expected one of %s, got %r'
                     % (path, ', '.join(sorted(self.DRYING_SETTINGS)), self.dryingModel))
        self.dryingProps = {k: d[k] for k in self.DRYING_SETTINGS[self.dryingModel] if k in d}
        self.kernelHeatCapacity = number('kernelHeatCapacity')
        self.gas.update({'Dv': number('DvGas'), 'pressure': number('pGas')})

    def in_spout(self, x, z):
        """The heat-transfer region rule with plates, x and z in mm: between
        the plates' inner faces, or above their upper edge (the fountain)."""
        return abs(x) <= self.Wd / 2 or z >= self.Hd

    # the vessel's cross-section: the slanted base, read both ways, and the
    # open width it leaves at each height with its integral
    def base_height(self, x):
        """z of the slanted base at |x| (0 over the inlet slot), in mm."""
        return max(0.0, (abs(x) - self.Wi / 2) * self.tan)

    def section_width(self, z):
        """The vessel's width [m] at the height z [m]: the slot, widening
        along the base up to the walls (plates not taken out)."""
        return min(self.W * 1e-3, self.Wi * 1e-3 + 2 * max(z, 0.0) / self.tan)

    def section_area(self, h):
        """The x-z area [m2] of the vessel below h [m], section_width
        integrated exactly, less the draft plates."""
        mm = 1e-3
        W, Wi, top = self.W * mm, self.Wi * mm, self.baseTop * mm
        hb = min(h, top)
        area = Wi * hb + hb * hb / self.tan + W * max(0.0, h - top)
        if self.plates:
            area -= 2 * self.t * mm * max(0.0, min(h, self.Hd * mm) - self.He * mm)
        return area

    # where eq 14's circulation rate W_s is taken (evaluate, and the cellZone
    # downcomerBase whose solid flux spoutFoam sums every step)
    def circulation_row(self):
        """z [mm] of the cell row of W_s: the row whose centre lies nearest one
        cell height above the base's top, the first full row above it."""
        return (round((self.baseTop + self.dz) / self.dz - 0.5) + 0.5) * self.dz

    def downcomer_x(self):
        """|x| [mm] beyond which a cell centre lies in a downcomer: outside
        the plates' outer faces."""
        return self.Wd / 2 + self.t

    def removed_boxes(self):
        """Boxes (x0, x1, z0, z1) of gas cells removed from the full box:
        per column, the cells wholly below the base line at the column's inner
        edge; and the cells inside the draft plates."""
        boxes = []
        half = self.W / 2
        for i in range(self.nx):
            x0, x1 = -half + i * self.dx, -half + (i + 1) * self.dx
            inner = min(abs(x0), abs(x1)) if x0 * x1 > 0 else 0.0
            line = self.base_height(inner)
            k = int(math.floor(line / self.dz + 1e-9))   # cells wholly below
            if k > 0:
                boxes.append((x0, x1, 0.0, k * self.dz))
        if self.plates:
            for side in (-1, 1):
                xa = side * self.Wd / 2
                xb = side * (self.Wd / 2 + self.t)
                boxes.append((min(xa, xb), max(xa, xb), self.He, self.Hd))
        return boxes


def load(case='.', overrides=()):
    """The vessel of a case: as its last ./generate wrote it (with the
    command line's overrides) if it has run, else from the dictionary."""
    path = os.path.join(case, 'constant', 'spoutedBed')
    if not os.path.isfile(path):
        path = os.path.join(case, 'system', 'spoutedBedDict')
    return Geometry(read_dict(path, overrides), path)



def settled_bed(g, vtp):
    """(bed height [m], mean voidage) of a settled bed: the height is the
    99th percentile of the particle tops (a few particles resting on the
    surface do not count); the voidage is that of the vessel below half
    of it, clear of the uneven surface (with plates, the spout and the
    downcomers settle to different levels), walls and base included."""
    from spoutlab import casefiles as sc
    z = [p[2] for p in sc.read_vtp_points(vtp)]
    r = sc.read_vtp_array(vtp, 'radius')
    height = sorted(z)[int(0.99 * (len(z) - 1))] + max(r)
    h = 0.5 * height
    solid = sum(4 / 3 * math.pi * ri ** 3 for zi, ri in zip(z, r) if zi < h)
    return height, 1 - solid / vessel_volume(g, h)


def vessel_volume(g, h):
    """Volume [m3] of the vessel below the height h [m]: the slanted base
    widening from the slot to the walls, less the draft plates."""
    return g.section_area(h) * (g.Lb * 1e-3)
