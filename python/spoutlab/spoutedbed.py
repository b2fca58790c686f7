"""The two-dimensional slanted-base spouted bed: its geometry read from a
case's system/spoutedBedDict, shared by the case's generate script and its
post-processing (snapshots, profiles)."""
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

    def base_height(self, x):
        """z of the slanted base at |x| (0 over the inlet slot)."""
        return max(0.0, (abs(x) - self.Wi / 2) * self.tan)

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


def outline(g):
    """Line segments (x0, z0, x1, z1) in m of the vessel, base and plates."""
    half, mm = g.W / 2, 1e-3
    segs = [(-half, g.baseTop, -half, g.H), (half, g.baseTop, half, g.H),
            (-g.Wi / 2, 0, -half, g.baseTop), (g.Wi / 2, 0, half, g.baseTop),
            (-g.Wi / 2, 0, g.Wi / 2, 0)]
    if g.plates:
        for s in (-1, 1):
            xa, xb = s * g.Wd / 2, s * (g.Wd / 2 + g.t)
            segs += [(xa, g.He, xa, g.Hd), (xb, g.He, xb, g.Hd),
                     (xa, g.He, xb, g.He), (xa, g.Hd, xb, g.Hd)]
    return [tuple(v * mm for v in s) for s in segs]


def snapshot(g, vtp, png, title, vmax=1.0, field='velocity', vmin=None,
             label='vertical particle velocity [m/s]'):
    """Particles of one .vtp as discs in the x-z plane, coloured by their
    vertical velocity (like the papers' flow-pattern snapshots) or by
    another per-particle scalar (field='temperature', with vmin, vmax)."""
    from spoutlab import casefiles as sc
    points = sc.read_vtp_points(vtp)
    radii = sc.read_vtp_array(vtp, 'radius')
    values = sc.read_vtp_array(vtp, field)
    if field == 'velocity':
        values = values[2::3]
    data = png[:-4] + '.dat'
    with open(data, 'w') as f:
        for (x, y, z), r, v in zip(points, radii, values):
            f.write('%.6g %.6g %.6g %.5g\n' % (x, z, r, v))
    lo = -vmax if vmin is None else vmin
    plot_map(g, png, title, label, lo, vmax,
             'plot "%s" using 1:2:3:4 with circles lc palette fs solid noborder notitle' % data)
    os.remove(data)


def field_map(g, centres, values, png, title, label, vmin, vmax, zmax=None):
    """A cell field of the gas mesh in the x-z plane, one square per cell
    (up to zmax [m], default the vessel's height)."""
    data = png[:-4] + '.dat'
    with open(data, 'w') as f:
        for (x, y, z), v in zip(centres, values):
            f.write('%.6g %.6g %.6g\n' % (x, z, v))
    plot_map(g, png, title, label, vmin, vmax,
             'plot "%s" using 1:2:(%g):(%g):3 with boxxyerror lc palette fs solid noborder notitle'
             % (data, g.dx / 2000, g.dz / 2000), zmax)
    os.remove(data)


def clipped(segments, zmax):
    """The parts of segments (x0, z0, x1, z1) at or below zmax."""
    out = []
    for x0, z0, x1, z1 in segments:
        if z0 > z1:
            x0, z0, x1, z1 = x1, z1, x0, z0
        if z0 > zmax:
            continue
        if z1 > zmax:
            x1, z1 = x0 + (x1 - x0) * (zmax - z0) / (z1 - z0), zmax
        out.append((x0, z0, x1, z1))
    return out


def plot_map(g, png, title, label, vmin, vmax, plot, zmax=None):
    from spoutlab import casefiles as sc
    zmax = g.H / 1000 if zmax is None else min(zmax, g.H / 1000)
    arrows = '\n'.join('set arrow from %g,%g to %g,%g nohead lw 2 lc rgb "black" front'
                       % s for s in clipped(outline(g), zmax))
    height = 0.8 * zmax * 1000 / g.W * 600 + 120
    sc.plot(png, '''
set title "%s"
set size ratio -1
set xrange [%g:%g]
set yrange [0:%g]
set xlabel "x [m]"
set ylabel "z [m]"
set cblabel "%s"
set cbrange [%g:%g]
set palette defined (0 "#3b4cc0", 0.5 "#dddddd", 1 "#b40426")
%s
%s
''' % (title, -g.W / 2000, g.W / 2000, zmax, label, vmin, vmax, arrows, plot),
            size=(600, int(height)))


# Kudra et al.'s correlation for u_ms (eq 12 of the draft-plate paper)
def kudra_ums(g, Hb, u_exp=1.12):
    """Eq 12 as the paper uses it: Kudra's experimental u_ms (W_d = 50,
    H_e = 100 mm, H_b = 0.9 m) scaled by the correlation's dependence on
    W_d (sqrt(g W_d) and (W_d d_p/(W_i H_b))^0.084), H_e^0.15 and H_b^-0.084."""
    return (u_exp * (g.Wd / 50)**0.5 * (g.He / 100)**0.15 * (g.Wd / 50)**0.084
            * (0.9 / Hb)**0.084)


def kudra_eq12(g, Hb, phi=1.0, rho_g=1.205):
    """Eq 12 evaluated directly for the simulated geometry and bed height:
    spheres (phi = 1), air at 20 C, theta in degrees (the paper does not say;
    degrees reproduce its scaled 1.18 m/s, radians would give 40 % more)."""
    rho_p, dp = g.particles['rhop'], g.particles['dp'] / 1000
    Wd, Wi, He, Lb = g.Wd / 1000, g.Wi / 1000, g.He / 1000, g.Lb / 1000
    return (math.sqrt(9.81 * Wd) * phi**0.68 * g.theta**-0.084
            * ((rho_p - rho_g) / rho_g * He / Lb)**0.15 * (Wd * dp / (Wi * Hb))**0.084)


# --- the minimum-spouting protocol: verdicts, u_ms, the hysteresis loop -------
# Each step of the protocol is judged by the spout classifier (spouts / does
# not spout over the step's averaging window); the rules below turn the
# steps' (u_s, dP, spouts) into the paper's quantities.

def minimum_spouting(down):
    """u_ms on the decreasing branch, the paper's criterion: the lowest
    velocity that still spouts before a slight further cut collapses the
    spout, where dP begins to rise steeply.  down: (u_s, dP, spouts) in
    decreasing u_s.  Returns (u_ms, dP_ms, dP after the collapse), or None
    if the spout never collapsed."""
    # the last collapse counts: a spout that pinched off for one step and
    # recovered below it was still a spout there
    collapse = None
    for (u, dp, spouts), (_, dp_next, spouts_next) in zip(down, down[1:]):
        if spouts and not spouts_next:
            collapse = (u, dp, dp_next)
    return collapse


def steepest_rise(down):
    """u_ms by the pressure drop alone, the paper's words taken literally:
    the step of the decreasing branch after which dP rises most steeply,
    the largest increase between successive steps.  For a bed whose regime
    the classifier does not call a spout (minimum_spouting has nothing to
    read) and as a check on it where it does.  down: (u_s, dP, spouts) in
    decreasing u_s.  Returns (u_ms, dP_ms, dP one step below) or None if dP
    never rises."""
    rises = [(dp_next - dp, u, dp, dp_next)
             for (u, dp, _), (_, dp_next, _) in zip(down, down[1:])]
    rise, u, dp, dp_next = max(rises, default=(0.0, None, None, None))
    return (u, dp, dp_next) if rise > 0 else None


def spout_reforms(up):
    """On a rising branch, the first velocity at which the bed spouts:
    (u, dP) or None."""
    for u, dp, spouts in up:
        if spouts:
            return u, dp
    return None


def break_through(packed):
    """The increasing branch from the packed bed (Fig 2): dP rises while
    the voidage expansion penetrates the bed, peaks, and falls once the
    spout breaks through.  packed: (u_s, dP, spouts) in increasing u_s.
    Returns (u at the peak, peak dP, u of the break-through, its dP): the
    peak is the highest dP up to and including the first spouting step;
    the last two are None if the bed never spouted.  None for no steps."""
    if not packed:
        return None
    first = next((k for k, (_, _, s) in enumerate(packed) if s), None)
    before = packed if first is None else packed[:first + 1]
    u_peak, dp_peak, _ = max(before, key=lambda r: r[1])
    if first is None:
        return u_peak, dp_peak, None, None
    return u_peak, dp_peak, packed[first][0], packed[first][1]


def hysteresis(packed, down):
    """The size of Fig 2's loop [Pa]: the peak dP of the packed branch minus
    dP on the decreasing branch at the same u_s (linear between its steps).
    None when the decreasing branch does not span the peak's velocity."""
    peak = break_through(packed)
    pts = sorted((u, dp) for u, dp, _ in down)
    if peak is None or len(pts) < 1:
        return None
    u = peak[0]
    tol = 1e-9
    for (u0, p0), (u1, p1) in zip(pts, pts[1:]):
        if u0 - tol <= u <= u1 + tol:
            return peak[1] - (p0 + (p1 - p0) * (u - u0) / (u1 - u0))
    if len(pts) == 1 and abs(pts[0][0] - u) < tol:
        return peak[1] - pts[0][1]
    return None


class Schedule:
    """The minimum-spouting schedule, decided as the run goes, the way it is
    done at the rig.  Two ways to begin:

      rise_from  the paper's Fig 2: start on the settled (packed) bed at
                 rise_from and raise u_s by `step` ('packed' branch) until
                 `confirm` successive steps spout (the break-through and a
                 step above it, where dP has fallen and levels off) or `top`
                 is reached; a bed that never spouts ends there;
      start      spin the bed up first (the protocol's kick), then begin the
                 decreasing branch at start.

    The decreasing branch ('down') runs from one step below the top of the
    rise (or from start) until `confirm` successive steps have collapsed or
    `stop` is reached; with `full_loop` the rise goes on to `top` and the
    fall to `stop` whatever the classifier says (the paper's whole Fig 2
    loop, a schedule the classifier's verdicts cannot change, read by dP:
    steepest_rise); with `up`, u_s then rises again ('up') until `confirm`
    successive steps spout or it is back at the top.  Steps beyond that
    only repeat a confirmed state and cost minutes each."""

    def __init__(self, step, stop, rise_from=None, top=None, start=None, up=False, confirm=2,
                 full_loop=False):
        if (rise_from is None) == (start is None):
            raise ValueError('a schedule begins either on the packed bed (rise_from) or '
                             'after a spin-up (start), not both or neither')
        if rise_from is not None and not (top is not None and top >= rise_from):
            raise ValueError('the packed branch needs a top velocity >= its first, got %r'
                             % top)
        self.step, self.stop, self.up, self.confirm = step, stop, up, confirm
        self.full_loop = full_loop
        self.rise_from, self.start = rise_from, start
        self.top = top if rise_from is not None else start
        self.tol = 1e-6 * step

    def first(self):
        return (self.rise_from, 'packed') if self.rise_from is not None else (self.start, 'down')

    def next(self, done):
        """(u_s, branch) of the step after the finished ones, or None when
        the protocol is complete.  done: (u_s, branch, spouts), oldest first."""
        def streak(branch, spouts):
            n = 0
            for _, b, s in reversed(done):
                if b != branch or s != spouts:
                    break
                n += 1
            return n

        def at(u):
            return round(u, 6)

        u, branch, spouts = done[-1]
        if branch == 'packed':
            if streak('packed', True) >= self.confirm and not self.full_loop:
                return self.lower(u)
            if u + self.step <= self.top + self.tol:
                return at(u + self.step), 'packed'
            # at the top: lower it only if it spouts there at all
            return self.lower(u) if spouts or self.full_loop else None
        if branch == 'down' and (self.full_loop or streak('down', False) < self.confirm):
            nxt = self.lower(u)
            if nxt:
                return nxt
        if not self.up or (branch == 'up' and streak('up', True) >= self.confirm):
            return None
        return (at(u + self.step), 'up') if u + self.step <= self.top + self.tol else None

    def lower(self, u):
        return (round(u - self.step, 6), 'down') if u - self.step >= self.stop - self.tol \
            else None


# write times drift from their nominal values by a time step or so (0.0999,
# 0.2001 for 0.1, 0.2 with 0.3 ms steps): a particle file this close to a
# window's end belongs to the window
WINDOW_SLACK = 1e-3


def bed_spouts(g, case, t0, t1):
    """Whether the bed spouts between t0 and t1 [s]: the spout classifier
    (spoutlab.spoutregime: open dilute core through the bed, upward
    flux in it, a fountain, persistent over the particle files written in
    the window), with its default spout region for the vessel.  The one
    place the protocols ask; returns the classifier's Verdict (.spouts,
    .describe())."""
    from spoutlab import mixing
    from spoutlab import casefiles as sc
    from spoutlab import spoutregime
    region = spoutregime.SpoutRegion.of(g)
    snapshots = []
    for t, path in mixing.particle_files(case):
        if t0 - WINDOW_SLACK <= t <= t1 + WINDOW_SLACK:
            vz = sc.read_vtp_array(path, 'velocity')[2::3]
            snapshots.append(spoutregime.measure(g, region, sc.read_vtp_points(path), vz,
                                                 sc.read_vtp_array(path, 'radius'), t))
    return spoutregime.Verdict(snapshots)


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
    mm = 1e-3
    W, Wi, Lb, top = g.W * mm, g.Wi * mm, g.Lb * mm, g.baseTop * mm
    hb = min(h, top)
    area = Wi * hb + hb * hb / g.tan + W * max(0.0, h - top)
    if g.plates:
        area -= 2 * g.t * mm * max(0.0, min(h, g.Hd * mm) - g.He * mm)
    return area * Lb


# --- Ergun's minimum fluidisation velocity ----------------------------------

def ergun_umf(d, rho_p, rho_g, mu, eps_mf=None, phi=1.0, g=9.81):
    """u_mf [m/s] from the Ergun equation at incipient fluidisation,
    Ar = 150 (1 - e)/(phi^2 e^3) Re + 1.75/(phi e^3) Re^2, Re = rho_g u d/mu,
    Ar = d^3 rho_g (rho_p - rho_g) g/mu^2.  Without eps_mf, Wen and Yu's
    form of it (1/(phi e^3) = 14, (1 - e)/(phi^2 e^3) = 11), the 'simple
    correlation' the no-draft paper quotes (1.746 m/s)."""
    ar = d ** 3 * rho_g * (rho_p - rho_g) * g / mu ** 2
    if eps_mf is None:
        a, b = 1.75 * 14, 150 * 11
    else:
        a, b = 1.75 / (phi * eps_mf ** 3), 150 * (1 - eps_mf) / (phi ** 2 * eps_mf ** 3)
    re = (-b + math.sqrt(b * b + 4 * a * ar)) / (2 * a)
    return re * mu / (rho_g * d)


def slope(xs, ys):
    """Least-squares slope of ys against xs."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else 0.0


WALL_BAND = 2.0     # 'next to the walls' in Fig 5: within 2 R_d (55 mm, 7 d_p) of them


def mean_velocity(cells):
    return sum(c[2] for c in cells) / len(cells)


def read_profile(path):
    """Rows (z/R_d, y/R_d, velocity) of a profile CSV written by evaluate."""
    rows = []
    for line in list(open(path))[1:]:
        z, y, v, _ = (float(x) for x in line.split(','))
        rows.append((z, y, v))
    return rows


def by_height(rows, pick=mean_velocity):
    """(z/R_d, pick(cells of that height)) for the heights of the profile rows
    (z/R_d, y/R_d, velocity); empty cells (nan) and heights where pick
    returns None are left out."""
    out = []
    for h in sorted({r[0] for r in rows}):
        cells = [r for r in rows if r[0] == h and not math.isnan(r[2])]
        value = pick(cells) if cells else None
        if value is not None:
            out.append((h, value))
    return out


def profile_features(spout, downcomer, split=12.0):
    """The features of the paper's Figs 4a and 5 in time-averaged profiles.
    spout, downcomer: rows (z/R_d, y/R_d, velocity) as evaluate writes them
    (downcomer velocity positive downwards).  Returns a list of
    (feature, value in the lower region, value in the upper region, holds).

    Fig 5 is read as it is drawn, against y/R_d with the plates at 1 and the
    wall at 9: 'next to the plates' is the innermost bin, 'next to the walls'
    the bins within WALL_BAND of the outermost one of the whole profile, at
    the heights that reach them.  (Low down the outermost bin of a height
    lies on the slanting base, not on the wall.)"""
    def next_to_plate(cells):
        return mean_velocity([c for c in cells if abs(c[1]) == min(abs(d[1]) for d in cells)])

    wall = max((abs(r[1]) for r in downcomer), default=0.0)

    def next_to_wall(cells):
        near = [c for c in cells if abs(c[1]) >= wall - WALL_BAND - 1e-9]
        return mean_velocity(near) if near else None

    def low_high(series):
        low = [v for h, v in series if h < split]
        high = [v for h, v in series if h >= split]
        return (sum(low) / len(low) if low else float('nan'),
                sum(high) / len(high) if high else float('nan'))

    features = []
    for name, rows, pick, falls in (
            ('spout velocity falls with height', spout, mean_velocity, True),
            ('downcomer velocity higher in the lower region', downcomer, mean_velocity, True),
            ('downcomer velocity next to the plates falls with height', downcomer,
             next_to_plate, True),
            ('downcomer velocity next to the walls rises with height', downcomer,
             next_to_wall, False)):
        series = by_height(rows, pick)
        lo, hi = low_high(series)
        s = slope([h for h, _ in series], [v for _, v in series]) if len(series) > 1 else 0.0
        decided = not (math.isnan(lo) or math.isnan(hi))
        features.append((name, lo, hi, decided and (s < 0) == falls and (lo > hi) == falls))
    return features


# --- running the case from a protocol ----------------------------------------

def prepare_case(overrides, who, probes_only=False):
    """Mesh (the case's Allmesh) and settle the case in the working
    directory; skipped when a mesh and a settled bed are there already (a
    protocol continuing)."""
    import subprocess
    if os.path.isdir('constant/polyMesh') and os.path.isfile('DEM/settled.restart'):
        return
    script = '''set -e
. "$SPOUTLAB_DIR/etc/caseFunctions"
./Allmesh %s
settleParticles "$SPOUTLAB_DIR/liggghts_inputs/spoutDraftPlates/in.settle"
''' % ' '.join(overrides)
    if probes_only:
        script += ('foamDictionary -entry functions.averages.enabled -set false '
                   'system/controlDict > /dev/null\n')
    if subprocess.call(['bash', '-c', script]) != 0:
        sys.exit('%s: case preparation failed' % who)


def last_time(log):
    """The last 'Time = ' of a solver log, or None."""
    try:
        with open(log, 'rb') as f:
            f.seek(max(0, os.path.getsize(log) - 20000))
            lines = f.read().decode(errors='replace').splitlines()
    except OSError:
        return None
    for line in reversed(lines):
        if line.startswith('Time = '):
            return float(line.split()[2])
    return None


def run_spoutfoam(end, ranks, who):
    """Run (or continue, from the latest written time) spoutFoam up to the
    controlDict's end time, printing progress every 10 s of wall time."""
    import subprocess
    import time
    if ranks > 1:
        if not os.path.isdir('processor0'):
            subprocess.check_call(['bash', '-c', '. "$SPOUTLAB_DIR/etc/caseFunctions" '
                                   '&& decomposeSlabs %d' % ranks])
        cmd = (['mpirun', '-np', str(ranks)]
               + os.environ.get('SPOUTLAB_MPIRUN_ARGS', '').split()
               + ['spoutFoam', '-parallel'])
    else:
        cmd = ['spoutFoam']
    start = last_time('log.spoutFoam') or 0.0
    log = open('log.spoutFoam', 'a')
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
    t0 = time.time()
    while proc.poll() is None:
        time.sleep(10)
        now = last_time('log.spoutFoam')
        if now:
            rate = (time.time() - t0) / max(now - start, 1e-9)
            print('%s: t = %.2f of %.2f s, %.0f s wall per simulated s, about %.0f min left'
                  % (who, now, end, rate, (end - now) * rate / 60), flush=True)
    if proc.returncode != 0:
        sys.exit('%s: spoutFoam failed, see log.spoutFoam' % who)


def run_particles(case='.'):
    """(number, source) of the particles a run had at its start: counted in
    its first particles/*.vtp, else the first row of postProcessing/
    coupling.csv; (None, None) before a run."""
    from spoutlab import casefiles as sc
    folder = os.path.join(case, 'particles')
    if os.path.isdir(folder):
        vtps = sorted((f for f in os.listdir(folder)
                       if f.startswith('particles_') and f.endswith('.vtp')),
                      key=lambda f: float(f[len('particles_'):-4]))
        if vtps:
            path = os.path.join(folder, vtps[0])
            return len(sc.read_vtp_points(path)), os.path.join('particles', vtps[0])
    if os.path.isfile(os.path.join(case, 'postProcessing', 'coupling.csv')):
        rows = sc.read_coupling_log(case)
        if rows:
            return int(rows[0]['particles']), 'postProcessing/coupling.csv'
    return None, None


def inlet_schedule(g, case='.'):
    """The superficial velocity u_s against time as constant/inletVelocity
    sets it: [(u_s, t_from, t_to)], t_to None for the last; the slot
    velocity of the table times Wi/W."""
    from spoutlab import foamfile
    table = [(t, v[2] * g.Wi / g.W) for t, v in
             foamfile.read_table(os.path.join(case, 'constant', 'inletVelocity'))]
    steps = []
    for t, u in table:
        if steps and abs(steps[-1][0] - u) < 1e-9:
            steps[-1][2] = t
        else:
            steps.append([u, t, t])
    return [(u, t0, t1 if k + 1 < len(steps) else None)
            for k, (u, t0, t1) in enumerate(steps)]


def describe_schedule(steps):
    """'2 m/s' or '2 m/s for 0-0.1 s, then 1.5 m/s from 0.15 s'."""
    if len(steps) == 1:
        return '%.3g m/s' % steps[0][0]
    parts = ['%.3g m/s for %g-%g s' % (u, t0, t1) for u, t0, t1 in steps[:-1]]
    return ', '.join(parts) + ', then %.3g m/s from %g s (linear ramps between)' % (
        steps[-1][0], steps[-1][1])


def average_start(case='.'):
    """timeStart of the averages function object of system/controlDict."""
    from spoutlab import foamfile
    value = foamfile.entry(os.path.join(case, 'system', 'controlDict'),
                           'functions/averages/timeStart', None)
    return float(value) if value is not None else None
