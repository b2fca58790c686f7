"""Does the bed spout?  A measured criterion on the particle output, the
same for the vessel with draft plates and without.

The spout region is a vertical column |x - axis| <= half_width from a
height `bottom` up to the bed surface: by default the gap between the
plates' inner faces (half width W_d/2) from their lower edge H_e; without
plates the central column of the same width and height, so that the two
designs are judged alike.  Both are parameters (SpoutRegion).

At each particle write time (a snapshot) four things are measured:

  bed surface  the top of the highest 19-mm layer (a gas cell, 2.4 d_p)
               outside the column whose solid fraction is at least
               SURFACE_FRACTION = 0.25, half that of a packed bed (0.55-0.6):
               the fountain's rain over the annulus stays far below it.
  core         the solid fraction of each layer (38 mm, 4.75 d_p) of the
               column between `bottom` and the surface, against that of the
               annulus below the surface.
  upward flux  the particles in that part of the column rise on average by
               at least UPWARD_VELOCITY = 0.1 m/s (a spout: 0.8-1.5 m/s; a
               packed bed: 0; about a third of sqrt(g d_p)), so the solid
               flux on the axis is upward.
  fountain     at least FOUNTAIN_PARTICLES = 5 particles in the column
               above the bed surface.

The bed spouts over a window of snapshots when

  open core    the column is dilute on average: at every height, the mean
               over the window of the layer's solid fraction is below
               DILUTE_RATIO = 0.5 of the annulus' (layers compared at the
               same relative height between `bottom` and the surface);
  persistence  the flux is upward and there is a fountain in at least
               PERSISTENCE = 0.8 of the snapshots.

The core is judged on the window's mean, not snapshot by snapshot, because
a spout carries slugs: the draft-plate paper finds slug flow in the spout
at u_ms, and the beds here show a dense plug rising through an open channel
at one write time in two (a snapshot's densest layer 0.5-1.1 of the
annulus, the window's 0.2-0.5).  A bubbling bed has no channel: its voids
pass through a core that is dense most of the time (window means 0.74-1.03
in the 26 000-particle bed without plates).  A snapshot is still called
open (`open_core`) when every layer is dilute at that instant, and spouting
when it is also rising and has a fountain; the share of those is reported
beside the verdict."""
import math

from spoutlab import spoutedbed

SURFACE_LAYER = 0.019
SURFACE_FRACTION = 0.25
CORE_LAYER = 0.038
DILUTE_RATIO = 0.5
UPWARD_VELOCITY = 0.1
FOUNTAIN_PARTICLES = 5
PERSISTENCE = 0.8


class SpoutRegion:
    """|x - axis| <= half_width, z >= bottom [m]."""

    def __init__(self, half_width, bottom, axis=0.0):
        if not (half_width > 0 and bottom >= 0):
            raise ValueError('spout region: expected a positive half width and a bottom '
                             '>= 0, got %g and %g m' % (half_width, bottom))
        self.half_width, self.bottom, self.axis = half_width, bottom, axis

    @classmethod
    def of(cls, g, half_width=None, bottom=None):
        """The default region of a vessel (spoutedbed.Geometry, in mm):
        between the plates, or where they would be."""
        return cls(g.Wd / 2000 if half_width is None else half_width,
                   g.He / 1000 if bottom is None else bottom)

    def inside(self, x):
        return abs(x - self.axis) <= self.half_width


class VesselSection:
    """Horizontal widths of the vessel [m]: the slanted base narrows it to
    the slot, the plates (if any) take their thickness beside the column."""

    def __init__(self, g, region):
        mm = 1e-3
        self.g, self.Lb = g, g.Lb * mm
        self.plates = g.plates
        self.t, self.He, self.Hd = g.t * mm, g.He * mm, g.Hd * mm
        self.region = region

    def width(self, z):
        return self.g.section_width(z)

    def column_width(self, z):
        return min(2 * self.region.half_width, self.width(z))

    def outside_width(self, z):
        plate = 2 * self.t if self.plates and self.He <= z <= self.Hd else 0.0
        return max(0.0, self.width(z) - self.column_width(z) - plate)

    def volume(self, width, z0, z1, steps=8):
        """Lb times the integral of width(z) over [z0, z1] (midpoint rule)."""
        h = (z1 - z0) / steps
        return self.Lb * h * sum(width(z0 + (k + 0.5) * h) for k in range(steps))


class Snapshot:
    """What one particle write time shows; see the module docstring."""

    def __init__(self, time, surface, annulus_fraction, core_fractions, core_velocity,
                 fountain):
        self.time = time
        self.surface = surface
        self.annulus_fraction = annulus_fraction
        self.core_fractions = core_fractions
        self.core_velocity = core_velocity
        self.fountain = fountain
        self.open_core = bool(core_fractions) and annulus_fraction > 0 and \
            max(core_fractions) < DILUTE_RATIO * annulus_fraction
        self.upward = core_velocity is not None and core_velocity >= UPWARD_VELOCITY
        self.has_fountain = fountain >= FOUNTAIN_PARTICLES
        self.spouts = self.open_core and self.upward and self.has_fountain

    def densest_core_ratio(self):
        if not self.core_fractions or not self.annulus_fraction > 0:
            return float('nan')
        return max(self.core_fractions) / self.annulus_fraction


def measure(g, region, points, vz, radii, time=0.0):
    """The Snapshot of one particle field: positions [m], vertical
    velocities [m/s], radii [m]."""
    section = VesselSection(g, region)
    volumes = [4 / 3 * math.pi * r ** 3 for r in radii]
    outside = [(p[2], v) for p, v in zip(points, volumes) if not region.inside(p[0])]
    # the bed surface, from the layers outside the column
    layers = max(1, int(math.ceil(max([g.H / 1000] + [z for z, _ in outside]) / SURFACE_LAYER)))
    solid = [0.0] * layers
    for z, v in outside:
        solid[min(layers - 1, max(0, int(z // SURFACE_LAYER)))] += v
    surface = 0.0
    for k in range(layers):
        room = section.volume(section.outside_width, k * SURFACE_LAYER, (k + 1) * SURFACE_LAYER)
        if room > 0 and solid[k] / room >= SURFACE_FRACTION:
            surface = (k + 1) * SURFACE_LAYER
    # the annulus below the surface (its top layer, half filled, left out)
    top = surface - SURFACE_LAYER
    lo = min(region.bottom, max(top - SURFACE_LAYER, 0.0))
    room = section.volume(section.outside_width, lo, top) if top > lo else 0.0
    annulus = (sum(v for z, v in outside if lo <= z < top) / room) if room > 0 else 0.0
    # the column: layers from its bottom to the surface, and above it
    core_fractions, rising = [], []
    fountain = 0
    height = surface - region.bottom
    n = int(height // CORE_LAYER) if height >= CORE_LAYER else 0
    h = height / n if n else 0.0
    solid = [0.0] * n
    for p, w, v in zip(points, vz, volumes):
        if not region.inside(p[0]):
            continue
        z = p[2]
        if z >= surface:
            fountain += 1
        elif n and z >= region.bottom:
            solid[min(n - 1, int((z - region.bottom) // h))] += v
            rising.append(w)
    for k in range(n):
        z0 = region.bottom + k * h
        core_fractions.append(solid[k] / section.volume(section.column_width, z0, z0 + h))
    velocity = sum(rising) / len(rising) if rising else None
    return Snapshot(time, surface, annulus, core_fractions, velocity, fountain)


class Verdict:
    """The bed over a window of snapshots; see the module docstring."""

    def __init__(self, snapshots):
        self.snapshots = snapshots
        n = len(snapshots)
        self.count = n
        self.fraction = sum(s.spouts for s in snapshots) / n if n else 0.0
        self.core_ratio = mean_core_ratio(snapshots)
        self.open_core = self.core_ratio < DILUTE_RATIO
        self.spouts = n > 0 and self.open_core and \
            self.share('upward') >= PERSISTENCE and self.share('has_fountain') >= PERSISTENCE

    def share(self, attribute):
        n = len(self.snapshots)
        return sum(bool(getattr(s, attribute)) for s in self.snapshots) / n if n else 0.0

    def describe(self):
        if not self.snapshots:
            return 'not decided: no particle file in the averaging window'
        return ('%s over %d particle write times (t = %g-%g s): core %.2f of the annulus '
                '(need < %.2f), upward flux %.0f %%, fountain %.0f %% (need %.0f %%); '
                '%d of %d write times open at every layer and spouting'
                % ('SPOUTS' if self.spouts else 'does NOT spout', self.count,
                   self.snapshots[0].time, self.snapshots[-1].time, self.core_ratio,
                   DILUTE_RATIO, 100 * self.share('upward'), 100 * self.share('has_fountain'),
                   100 * PERSISTENCE, round(self.fraction * self.count), self.count))


def mean_core_ratio(snapshots):
    """The densest layer of the window-mean core profile, as a fraction of
    the annulus' solid fraction; the snapshots' layers are matched by their
    height relative to the surface (as many layers as the shallowest
    snapshot has).  inf when a snapshot has no core layer or no annulus."""
    if not snapshots or any(not s.core_fractions or not s.annulus_fraction > 0
                            for s in snapshots):
        return float('inf')
    m = min(len(s.core_fractions) for s in snapshots)
    profile = [0.0] * m
    for s in snapshots:
        n = len(s.core_fractions)
        for j in range(m):
            profile[j] += s.core_fractions[int((j + 0.5) * n / m)] / s.annulus_fraction
    return max(profile) / len(snapshots)


def classify_case(g, case='.', start=0.0, region=None):
    """Verdict over the particle files particles/particles_<t>.vtp with
    t >= start."""
    from spoutlab import casefiles as sc
    region = region or SpoutRegion.of(g)
    snapshots = []
    for t, path in sc.particle_files(case):
        if t < start - 1e-9:
            continue
        points = sc.read_vtp_points(path)
        vz = sc.read_vtp_array(path, 'velocity')[2::3]
        radii = sc.read_vtp_array(path, 'radius')
        snapshots.append(measure(g, region, points, vz, radii, t))
    return Verdict(snapshots)


# write times drift from their nominal values by a time step or so (0.0999,
# 0.2001 for 0.1, 0.2 with 0.3 ms steps): a particle file this close to a
# window's end belongs to the window
WINDOW_SLACK = 1e-3


def bed_spouts(g, case, t0, t1):
    """Whether the bed spouts between t0 and t1 [s]: the spout classifier
    (open dilute core through the bed, upward
    flux in it, a fountain, persistent over the particle files written in
    the window), with its default spout region for the vessel.  The one
    place the protocols ask; returns the classifier's Verdict (.spouts,
    .describe())."""
    from spoutlab import casefiles as sc
    region = SpoutRegion.of(g)
    snapshots = []
    for t, path in sc.particle_files(case):
        if t0 - WINDOW_SLACK <= t <= t1 + WINDOW_SLACK:
            vz = sc.read_vtp_array(path, 'velocity')[2::3]
            snapshots.append(measure(g, region, sc.read_vtp_points(path), vz,
                                                 sc.read_vtp_array(path, 'radius'), t))
    return Verdict(snapshots)


def write_csv(verdict, path):
    with open(path, 'w') as f:
        f.write('time [s],bed surface [m],annulus solid fraction,densest core layer / annulus,'
                'core mean vertical velocity [m/s],fountain particles,open core,upward flux,'
                'fountain,spouts\n')
        for s in verdict.snapshots:
            f.write('%.6g,%.4g,%.4g,%.4g,%.4g,%d,%d,%d,%d,%d\n'
                    % (s.time, s.surface, s.annulus_fraction, s.densest_core_ratio(),
                       s.core_velocity if s.core_velocity is not None else float('nan'),
                       s.fountain, s.open_core, s.upward, s.has_fountain, s.spouts))


# The pressure drop of a spouting bed against the weight per unit area of
# the bed column above the probe, p_col = rho_p g phi_a (H_s - z_probe), the
# pressure drop the column would carry fluidised.  The annulus is a packed,
# unfluidised bed, so its gas pressure gradient stays below rho_p g phi_a
# (else it lifts); the spout and the annulus meet below H_e and both end at
# the outlet pressure above the bed, so the time-averaged probe pressure
# cannot exceed p_col.  A spouting bed stays well above zero: the papers'
# spouting beds give 1.40 kPa against a p_col of about 6.3 kPa (plates, 0.9 m,
# 0.22) and 1.75 kPa against 2.7 kPa (no plates, 0.409 m, 0.64) at u_ms,
# changing little above it; a tenth of p_col still catches a probe that
# reads the freeboard or a gas that carries nothing.
PRESSURE_BAND = (0.1, 1.0)


def column_weight(verdict, rho_p, z_probe):
    """p_col [Pa] from the window's mean bed surface and annulus solid
    fraction; nan without snapshots."""
    s = verdict.snapshots
    if not s:
        return float('nan')
    surface = sum(x.surface for x in s) / len(s)
    phi = sum(x.annulus_fraction for x in s) / len(s)
    return rho_p * 9.81 * phi * max(surface - z_probe, 0.0)


def region_from_text(text, g, what):
    """A region given as 'HALF_WIDTH_MM,BOTTOM_MM' on a command line."""
    try:
        half, bottom = (float(v) for v in text.split(','))
        return SpoutRegion(half / 1000, bottom / 1000)
    except ValueError:
        raise SystemExit('%s: --spout-region expected HALF_WIDTH_MM,BOTTOM_MM (two '
                         'numbers, half width > 0), got %r' % (what, text))


if __name__ == '__main__':
    # stand-alone use: python3 -m spoutlab.spoutregime [CASE]
    from spoutlab import cli
    p = cli.Parser(prog='spoutregime', description='Whether the bed of a '
                                'spouted-bed case spouts: the classifier over all its '
                                'particle files.')
    p.add_argument('case', nargs='?', default='.', help='the case (default: here)')
    case = p.parse_args().case
    print(classify_case(spoutedbed.load(case), case).describe())
