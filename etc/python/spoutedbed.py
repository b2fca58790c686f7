"""The two-dimensional slanted-base spouted bed: its geometry read from a
case's system/spoutedBedDict, shared by the case's generate script and its
post-processing (snapshots, profiles)."""
import math
import os
import re
import sys


def read_dict(path, overrides):
    values = {}
    text = re.sub(r'/\*.*?\*/', '', open(path).read(), flags=re.S)
    for line in text.splitlines():
        line = line.split('//')[0].strip()
        m = re.match(r'^(\w+)\s+([^;{}]+);$', line)
        if m and m.group(1) != 'FoamFile':
            values[m.group(1)] = m.group(2).strip()
    for item in overrides:
        key, _, value = item.partition('=')
        if key not in values:
            sys.exit('generate: %s: unknown key %r (expected one of: %s)'
                     % (path, key, ', '.join(sorted(values))))
        values[key] = value
    return values


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
    import spoutlab_case as sc
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


def field_map(g, centres, values, png, title, label, vmin, vmax):
    """A cell field of the gas mesh in the x-z plane, one square per cell."""
    data = png[:-4] + '.dat'
    with open(data, 'w') as f:
        for (x, y, z), v in zip(centres, values):
            f.write('%.6g %.6g %.6g\n' % (x, z, v))
    plot_map(g, png, title, label, vmin, vmax,
             'plot "%s" using 1:2:(%g):(%g):3 with boxxyerror lc palette fs solid noborder notitle'
             % (data, g.dx / 2000, g.dz / 2000))
    os.remove(data)


def plot_map(g, png, title, label, vmin, vmax, plot):
    import spoutlab_case as sc
    arrows = '\n'.join('set arrow from %g,%g to %g,%g nohead lw 2 lc rgb "black" front'
                       % s for s in outline(g))
    height = 0.8 * g.H / g.W * 600 + 120
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
''' % (title, -g.W / 2000, g.W / 2000, g.H / 1000, label, vmin, vmax, arrows, plot),
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


# The spout has collapsed when the upward solid flux on its axis (time-
# averaged over a step) falls below this fraction of the flux at the first
# step of the decreasing branch.  A collapsed bed's 1.8-s mean flux scatters
# around zero by up to a quarter of a working spout's (full bed: -0.013 to
# +0.010 m/s against 0.02-0.06 m/s), so the threshold sits above that.
SPOUT_STOPPED = 0.25


def minimum_spouting(down, stopped=SPOUT_STOPPED):
    """u_ms on the decreasing branch, as section 4.1 defines it: the velocity
    at which a slight further cut collapses the spout.  down: (u_s, dP,
    upward solid flux on the spout axis) in decreasing u_s.  Returns
    (u_ms, dP_ms, dP after the collapse), or None if the spout never
    collapsed."""
    reference = down[0][2] if down else 0.0
    for (u, dp, _), (_, dp_next, flux_next) in zip(down, down[1:]):
        if flux_next < stopped * reference:
            return u, dp, dp_next
    return None


def spout_reforms(up, reference, stopped=SPOUT_STOPPED):
    """On the increasing branch (which starts collapsed), the first velocity
    at which the spout carries particles again: (u, dP) or None.  reference:
    the flux at the first step of the decreasing branch."""
    for u, dp, flux in up:
        if flux >= stopped * reference:
            return u, dp
    return None


def next_velocity(done, start, stop, step, up, confirm=2, stopped=SPOUT_STOPPED):
    """The minimum-spouting schedule, decided as it goes, the way it is done
    at the rig: the u_s of the next step after the finished ones, or None when
    the protocol is complete.  done: (u_s, branch 'down'/'up', spout flux) of
    the finished steps after the spin-up, oldest first.  Lowering u_s stops
    at `stop` or once `confirm` successive steps have collapsed (flux below
    `stopped` x the flux of the first step); with `up`, u_s then rises again
    until `confirm` successive steps spout or `start` is reached.  Steps
    beyond that only repeat the confirmed state and cost minutes each."""
    tol = 1e-6 * step
    if not done:
        return round(start - step, 6)
    reference = done[0][2]

    def streak(branch, collapsed):
        n = 0
        for u, b, flux in reversed(done):
            if b != branch or (flux < stopped * reference) != collapsed:
                break
            n += 1
        return n

    u, branch, _ = done[-1]
    if branch == 'down' and u - step >= stop - tol and streak('down', True) < confirm:
        return round(u - step, 6)
    if not up or u + step > start + tol or (branch == 'up' and streak('up', False) >= confirm):
        return None
    return round(u + step, 6)


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
    """Generate, mesh and settle the case in the working directory; skipped
    when a mesh and a settled bed are there already (a protocol continuing)."""
    import subprocess
    if os.path.isdir('constant/polyMesh') and os.path.isfile('DEM/settled.restart'):
        return
    script = '''set -e
. "$SPOUTLAB_DIR/etc/caseFunctions"
./generate %s > log.generate
rm -rf 0
runApplication blockMesh
runApplication topoSet
runApplication subsetMesh gas -patch walls -overwrite
restore0Dir
runApplication postProcess -func writeCellCentres -time 0
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
    import spoutlab_case as sc
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
    text = open(os.path.join(case, 'constant', 'inletVelocity')).read()
    table = [(float(t), float(v) * g.Wi / g.W) for t, v in
             re.findall(r'\(\s*([-+.\deE]+)\s*\(\s*\S+\s+\S+\s+([-+.\deE]+)\s*\)\s*\)', text)]
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
    text = open(os.path.join(case, 'system', 'controlDict')).read()
    m = re.search(r'\baverages\s*\{[^}]*?\btimeStart\s+([-+.\deE]+)\s*;', text, re.S)
    return float(m.group(1)) if m else None
