"""peerDPMFoam: spoutFoam (OpenFOAM gas + LIGGGHTS) against OpenFOAM's own
CFD-DEM solver DPMFoam (its colliding cloud, pairCollision with
pairSpringSliderDashpot / wallSpringSliderDashpot) on the same two cases.

A benchmark, not a test: it prints figures and asserts nothing about speed.

  packed bed    openfoam_cases/packedBed: gas through the settled bed at
                superficial velocities below u_mf, the pressure drop over the
                probed span against Ergun with the layer voidage of the bed;
  fluidised     openfoam_cases/minFluidisation at a constant velocity above
                u_mf, the time-averaged pressure drop against the bed weight
                per area.

Both solvers get the same settled bed (one LIGGGHTS packing, DPMFoam
injecting every particle where LIGGGHTS left it), the same particles, gas,
mesh, inlet schedule and simulated time; the contact parameters come from
liggghts_inputs/fluidisedColumn/in.parameters and are mapped onto DPMFoam's
model here (contact_mapping). The solvers run serially, one after the other.
See bench/README.md, "peerDPMFoam".

    bench/peerDPMFoam                              # both cases, both solvers
    bench/peerDPMFoam --cases fluidised --fluidised-time 1
    bench/peerDPMFoam --check                      # the DPMFoam set-up only (ctest)

Needs numpy (/usr/bin/python3).
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

from spoutlab import foamfile
from spoutlab import bedlayers, bench, draglaws
from spoutlab.bench import couplingoverhead as co  # the environment, process and settling helpers

REPO = bench.REPO
INPUTS = os.path.join(REPO, 'liggghts_inputs', 'fluidisedColumn')
CASES = {'packed': os.path.join(REPO, 'openfoam_cases', 'packedBed'),
         'fluidised': os.path.join(REPO, 'openfoam_cases', 'minFluidisation')}
DPM_TEMPLATE = os.path.join(REPO, 'bench', 'dpmColumn')
G = 9.81


BenchError = co.BenchError


# ----------------------------------------------------------------- parameters

def liggghts_variable(path, name):
    """A numeric 'variable NAME equal|index VALUE' of a LIGGGHTS input."""
    with open(path) as f:
        m = re.search(r'^variable\s+%s\s+(?:equal|index)\s+([-0-9.eE+]+)\s' % name,
                      f.read(), re.M)
    if not m:
        raise BenchError("%s: key '%s' expected as 'variable %s equal <number>'"
                         % (path, name, name))
    return float(m.group(1))


def foam_constant(path, key):
    with open(path) as f:
        m = re.search(r'^\s*%s\s+([-0-9.eE+]+)\s*;' % key, f.read(), re.M)
    if not m:
        raise BenchError("%s: key '%s' expected as '%s <number>;'" % (path, key, key))
    return float(m.group(1))


class Parameters:
    """One source for both solvers: the particles and contacts of
    in.parameters, the gas of the spoutFoam case."""

    def __init__(self, case):
        p = os.path.join(INPUTS, 'in.parameters')
        self.d = liggghts_variable(p, 'dp')
        self.rho_p = liggghts_variable(p, 'rhop')
        self.k_n = liggghts_variable(p, 'kn')
        self.e = liggghts_variable(p, 'e')
        self.mu_f = liggghts_variable(p, 'mu')
        self.nu = liggghts_variable(p, 'nu')
        self.dt_dem = liggghts_variable(p, 'dt')
        self.width = liggghts_variable(p, 'W')
        self.depth = liggghts_variable(p, 'L')
        self.height = liggghts_variable(p, 'H')
        t = os.path.join(case, 'constant', 'transportProperties')
        self.rho_g = foam_constant(t, 'rho')
        self.mu_g = foam_constant(t, 'mu')
        self.m_p = self.rho_p * math.pi / 6 * self.d ** 3


# ------------------------------------------------------------ contact mapping

def restitution(c):
    """Restitution of a head-on contact m x'' = -k x - alpha sqrt(m k) x^(1/4) x'
    (DPMFoam's dashpot on a linear spring), in units x = delta omega / v,
    tau = omega t, where c = alpha (v/omega)^(1/4); velocity Verlet, 4000
    steps per contact."""
    h = math.pi / 4000
    x, w, a = 0.0, 1.0, 0.0
    while True:
        x += h * w + 0.5 * h * h * a
        w_half = w + 0.5 * h * a
        a = -x - c * max(x, 0.0) ** 0.25 * w_half
        w = w_half + 0.5 * h * a
        if x <= 0.0:
            return -w


def damping_for(e):
    """c of restitution(c) = e (restitution falls with c)."""
    lo, hi = 0.0, 5.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if restitution(mid) > e:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def contact_mapping(par, v_ref):
    """DPMFoam's pairSpringSliderDashpot and wallSpringSliderDashpot for the
    linear spring-dashpot of in.parameters.

    Normal spring: F = k_n delta^b with k_n = 4/3 sqrt(R) E*; b = 1 makes it
    linear, so E* is chosen to give LIGGGHTS' k_n exactly:
      particle-particle R = d/4, E* = E/(2(1 - nu^2));
      particle-wall     R = d/2, 1/E*_w = (1 - nu^2)/E + (1 - nu_w^2)/E_w.
    Damping: eta = alpha sqrt(M k_n) delta^(1/4) is not LIGGGHTS' constant
    dashpot, so e depends on the impact speed; alpha gives e at v_ref
    (M = m/2 between particles, m against a wall).
    Tangential: DPMFoam's k_t = 8 sqrt(R delta) G* (Mindlin) and a
    tangential dashpot equal to the normal one cannot be made LIGGGHTS'
    constant k_t without a dashpot; only mu is the same."""
    nu = par.nu
    estar_pp = par.k_n / (4.0 / 3.0 * math.sqrt(par.d / 4))
    young = 2 * (1 - nu ** 2) * estar_pp
    estar_pw = par.k_n / (4.0 / 3.0 * math.sqrt(par.d / 2))
    young_w = (1 - nu ** 2) / (1 / estar_pw - (1 - nu ** 2) / young)
    c = damping_for(par.e)
    out = {'E': young, 'E_wall': young_w, 'nu': nu, 'c': c, 'v_ref': v_ref}
    for kind, m_eff in (('pp', par.m_p / 2), ('pw', par.m_p)):
        omega = math.sqrt(par.k_n / m_eff)
        alpha = c / (v_ref / omega) ** 0.25
        out['alpha_' + kind] = alpha
        # e at other impact speeds with this alpha, for the report
        out['e_' + kind] = {v: restitution(alpha * (v / omega) ** 0.25)
                            for v in (0.05, v_ref, 1.0)}
    # DPMFoam's substep estimate (PairSpringSliderDashpot::nSubCycles): the
    # Hertz contact time at the fastest relative speed over
    # collisionResolutionSteps; with b = 1 and this E* it stays above
    # LIGGGHTS' step below this speed, so there is one substep per fluid step
    r_min = par.d / 4
    out['u_one_substep'] = (par.rho_p / estar_pp
                            * (5.429675 * r_min / par.dt_dem) ** 2.5) ** 2
    return out


# ---------------------------------------------------------------- bed

def settled_positions(base, n, env):
    """The settled bed (bench/couplingOverhead's settle, reused) and its
    particles as an array of rows (id, x, y, z, r)."""
    dem = co.settle(base, n, env)
    out = os.path.join(dem, 'positions.txt')
    if not os.path.isfile(out):
        co.run(['liggghts', '-in', os.path.join(REPO, 'bench', 'in.positions'),
                '-var', 'inputs', INPUTS, '-var', 'dem', dem, '-var', 'out', out,
                '-echo', 'none', '-log', 'none',
                '-screen', os.path.join(dem, 'log.positions')],
               dem, env, 'log.positions.out', 'LIGGGHTS in.positions')
    with open(out) as f:
        text = f.read()
    rows = np.array([[float(x) for x in line.split()]
                     for line in text.split('ITEM: ATOMS')[1].splitlines()[1:]
                     if line.strip()])
    if len(rows) != n:
        raise BenchError('%s: %d particles, expected %d' % (out, len(rows), n))
    return dem, rows


# ------------------------------------------------------------ case set-up

def copy_inputs(src, work, subdirs=('system', 'constant', '0.orig')):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for sub in subdirs:
        shutil.copytree(os.path.join(src, sub), os.path.join(work, sub),
                        ignore=shutil.ignore_patterns('polyMesh'))


def inlet_entry(levels, hold):
    """The inlet of 0/U: constant superficial velocity, or levels held for
    `hold` s each with 0.05 s ramps between them (the packedBed schedule)."""
    if len(levels) == 1:
        return '{ type fixedValue; value uniform (0 0 %.12g); }' % levels[0]
    rows = []
    for i, u in enumerate(levels):
        rows.append('(%.12g (0 0 %.12g)) (%.12g (0 0 %.12g))'
                    % (i * hold, u, (i + 1) * hold - 0.05, u))
    return '{ type uniformFixedValue; uniformValue table (%s); }' % ' '.join(rows)


def setup_spoutFoam(kind, work, dem, n, inlet, end_time, env):
    copy_inputs(CASES[kind], work)
    shutil.copytree(os.path.join(work, '0.orig'), os.path.join(work, '0'))
    if dem:
        os.makedirs(os.path.join(work, 'DEM'))
        shutil.copy(os.path.join(dem, 'settled.restart'), os.path.join(work, 'DEM'))
    co.foam_set(work, env, '0/U', 'boundaryField.inlet', inlet)
    co.foam_set(work, env, 'system/controlDict', 'endTime', '%.12g' % end_time)
    co.foam_set(work, env, 'system/controlDict', 'writeControl', 'runTime')
    co.foam_set(work, env, 'system/controlDict', 'writeInterval', '%.12g' % (2 * end_time))
    co.foam_set(work, env, 'constant/couplingProperties', 'liggghtsVariables.n', str(n))
    co.run(['blockMesh'], work, env, 'log.blockMesh', 'blockMesh')
    # layer centres and volumes for the packed-bed reference (bedlayers)
    co.run(['postProcess', '-funcs', '(writeCellCentres writeCellVolumes)', '-time', '0'],
           work, env, 'log.postProcess', 'postProcess')


def write_positions(path, rows):
    with open(path, 'w') as f:
        f.write('FoamFile\n{\n    version 2.0;\n    format ascii;\n'
                '    class vectorField;\n    object kinematicCloudPositions;\n}\n\n'
                '// the settled LIGGGHTS bed, written by bench/peerDPMFoam\n%d\n(\n'
                % len(rows))
        for r in rows:
            f.write('(%.12g %.12g %.12g)\n' % (r[1], r[2], r[3]))
        f.write(')\n')


def set_entry(path, values):
    """Set top-level 'key value;' entries of a dictionary in place."""
    with open(path) as f:
        text = f.read()
    for key, value in values.items():
        text, count = re.subn(r'^(%s\s+)[^;]*;' % re.escape(key),
                              lambda m: '%s%.12g;' % (m.group(1), value), text, flags=re.M)
        if count != 1:
            raise BenchError("%s: expected one entry '%s'" % (path, key))
    with open(path, 'w') as f:
        f.write(text)


def setup_DPMFoam(kind, work, spout_case, rows, par, mapping, inlet, end_time,
                  sample_every, relax_time, env):
    """The DPMFoam case from bench/dpmColumn, the spoutFoam case's mesh (inlet
    and outlet as wall patches, see 0.orig/U.air) and inlet, the particles
    and the mapped contact model."""
    copy_inputs(DPM_TEMPLATE, work)
    with open(os.path.join(spout_case, 'system', 'blockMeshDict')) as f:
        mesh = f.read()
    mesh, count = re.subn(r'\{\s*type\s+patch\s*;', '{ type wall;', mesh)
    if count != 2:
        raise BenchError('%s/system/blockMeshDict: expected the inlet and outlet as '
                         "'{ type patch; ...}', found %d" % (spout_case, count))
    with open(os.path.join(work, 'system', 'blockMeshDict'), 'w') as f:
        f.write(mesh)
    shutil.copytree(os.path.join(work, '0.orig'), os.path.join(work, '0'))
    write_positions(os.path.join(work, 'constant', 'kinematicCloudPositions'), rows)

    def cset(entry, value, path='constant/kinematicCloudProperties'):
        co.foam_set(work, env, path, entry, value)

    # (foamDictionary would read the dot of rho.air as a scope)
    set_entry(os.path.join(work, 'constant', 'transportProperties'),
              {'rho.air': par.rho_g, 'nu': par.mu_g / par.rho_g})
    co.foam_set(work, env, '0/U.air', 'boundaryField.inlet', inlet)
    cset('constantProperties.rho0', '%.12g' % par.rho_p)
    cset('constantProperties.youngsModulus', '%.12g' % mapping['E'])
    cset('constantProperties.poissonsRatio', '%.12g' % par.nu)
    cset('subModels.injectionModels.settledBed.sizeDistribution.'
         'fixedValueDistribution.value', '%.12g' % par.d)
    coll = 'subModels.pairCollisionCoeffs.'
    cset(coll + 'maxInteractionDistance', '%.12g' % par.d)
    pair = coll + 'pairSpringSliderDashpotCoeffs.'
    cset(pair + 'alpha', '%.12g' % mapping['alpha_pp'])
    cset(pair + 'mu', '%.12g' % par.mu_f)
    wall = coll + 'wallSpringSliderDashpotCoeffs.'
    cset(wall + 'youngsModulus', '%.12g' % mapping['E_wall'])
    cset(wall + 'poissonsRatio', '%.12g' % par.nu)
    cset(wall + 'alpha', '%.12g' % mapping['alpha_pw'])
    cset(wall + 'mu', '%.12g' % par.mu_f)
    cset('subModels.standardWallInteractionCoeffs.e', '%.12g' % par.e)
    cset('subModels.standardWallInteractionCoeffs.mu', '%.12g' % par.mu_f)

    cd = 'system/controlDict'
    co.foam_set(work, env, cd, 'deltaT', '%.12g' % par.dt_dem)
    co.foam_set(work, env, cd, 'endTime', '%.12g' % end_time)
    co.foam_set(work, env, cd, 'writeInterval', '%.12g' % end_time)
    co.foam_set(work, env, cd, 'functions.inletPressure.writeInterval', str(sample_every))
    if kind == 'packed':
        # the spoutFoam case's probes, sampled at the same times
        probes = co.foam_get(spout_case, env, 'system/controlDict',
                             'functions.bedProbes.probeLocations')
        co.foam_set(work, env, cd, 'functions.bedProbes',
                    '{ type probes; libs (sampling); fields (p alpha.air); probeLocations %s; '
                    'writeControl timeStep; writeInterval %d; log false; }'
                    % (probes, sample_every))
    co.run(['blockMesh'], work, env, 'log.blockMesh', 'blockMesh')
    return inject_bed(work, par, relax_time, env)


def inject_bed(work, par, relax_time, env):
    """Give DPMFoam the LIGGGHTS bed as its initial cloud, settled in its own
    contact model.

    Two things keep the injected bed from being DPMFoam's initial state as it
    stands. The contacts' tangential springs start from zero in DPMFoam, so
    the friction that held LIGGGHTS' packing is gone at first and the bed
    sags into a new rest (a few cm/s for some ms). And injected at the first
    step, the particles take alpha.air from 1 to the bed's 0.4 at once;
    DPMFoam's pressure equation carries ddt(alpha.air), so the gas the bed
    displaces leaves through it within one step (hundreds of m/s) and blows
    the bed up at the next. So the bed is injected in a copy of the case
    (relax/) without gas forces on the particles and settles there for
    relax_time under gravity and contacts, as in.settle lets LIGGGHTS; its
    particles and their alpha.air become 0/ of the run proper, which has no
    injection: alpha.air is consistent at t = 0 and ddt(alpha.air) starts
    at zero."""
    relax = os.path.join(work, 'relax')
    shutil.rmtree(relax, ignore_errors=True)
    os.makedirs(relax)
    for sub in ('system', 'constant', '0'):
        shutil.copytree(os.path.join(work, sub), os.path.join(relax, sub))
    cd = 'system/controlDict'
    co.foam_set(relax, env, cd, 'endTime', '%.12g' % relax_time)
    co.foam_set(relax, env, cd, 'writeInterval', '%.12g' % relax_time)
    co.foam_set(relax, env, cd, 'functions', '{}')
    co.foam_set(relax, env, '0/U.air', 'boundaryField.inlet',
                '{ type fixedValue; value uniform (0 0 0); }')
    cloud = 'constant/kinematicCloudProperties'
    co.foam_set(relax, env, cloud, 'subModels.particleForces', '{ gravity; }')
    co.foam_set(relax, env, cloud, 'solution.coupled', 'false')
    co.run(['DPMFoam'], relax, env, 'log.DPMFoam', 'DPMFoam (injection and settling)')
    times = [(float(d), d) for d in os.listdir(relax) if re.fullmatch(r'[0-9.]+', d)]
    last = os.path.join(relax, max(times)[1])
    if max(times)[0] < relax_time - 1e-3 or not os.path.isdir(os.path.join(last, 'lagrangian')):
        raise BenchError('DPMFoam settling in %s wrote no cloud at t = %g s (see its '
                         'log.DPMFoam)' % (relax, relax_time))
    shutil.rmtree(os.path.join(work, '0', 'lagrangian'), ignore_errors=True)
    shutil.copytree(os.path.join(last, 'lagrangian'), os.path.join(work, '0', 'lagrangian'))
    shutil.copy(os.path.join(last, 'alpha.air'), os.path.join(work, '0', 'alpha.air'))
    co.foam_set(work, env, cloud, 'subModels.injectionModels', '{}')
    return last


# ------------------------------------------------------------------ running

def run_solver(solver, work, env):
    """Run a solver, stamping its output with the wall clock: the time loop
    runs from 'Starting time loop' to 'End'; CPU from its ExecutionTime."""
    print('%s in %s' % (solver, work))
    loop = end = None
    first_exec = last_exec = None
    steps = 0
    with co.Timed() as t, open(os.path.join(work, 'log.' + solver), 'w') as log:
        proc = subprocess.Popen([solver], cwd=work, env=co.in_dir(env, work),
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        for raw in proc.stdout:
            now = time.perf_counter()
            log.write(raw.decode(errors='replace'))
            if raw.startswith(b'Starting time loop'):
                loop = now
            elif raw.startswith(b'Time = '):
                steps += 1
            elif raw.startswith(b'ExecutionTime = '):
                cpu = float(raw.split()[2])
                first_exec = cpu if first_exec is None else first_exec
                last_exec = cpu
            elif raw.strip() == b'End':
                end = now
        proc.wait()
    if proc.returncode != 0 or end is None or loop is None:
        raise BenchError('%s failed (exit %d); last lines of %s:\n%s'
                         % (solver, proc.returncode, os.path.join(work, 'log.' + solver),
                            co.tail(os.path.join(work, 'log.' + solver))))
    # CPU of the loop after its first step (the first holds the injection
    # and the first locating), scaled to all steps
    cpu = ((last_exec - first_exec) * steps / (steps - 1)
           if steps > 1 and last_exec is not None else None)
    return {'wall': end - loop, 'cpu': cpu, 'steps': steps, 'others': t.others,
            'total_wall': t.wall}


# --------------------------------------------------------------- evaluation

def function_object(case, name, filename):
    """Rows (time, values...) of postProcessing/<name>/0/<filename>."""
    rows = []
    with open(os.path.join(case, 'postProcessing', name, '0', filename)) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            rows.append([float(x) for x in line.replace('(', ' ').replace(')', ' ').split()])
    return np.array(rows)


def pressure_scale(solver, par):
    """Pa per unit of the solver's p: DPMFoam's is kinematic."""
    return par.rho_g if solver == 'DPMFoam' else 1.0


def gas_head(solver, par, dz):
    """The gas's own hydrostatic head over dz in the solver's p [Pa]: DPMFoam
    has g in its gas momentum equation, spoutFoam's p excludes it."""
    return par.rho_g * G * dz if solver == 'DPMFoam' else 0.0


def packed_bed_result(solver, case, spout_case, rows, par, levels, hold):
    """Per level (means over the last 40 % of each hold): the span pressure
    drop, Ergun summed over the layers with each layer's voidage from the
    settled particles (exact sphere slices: the reference), and Ergun with
    the voidage the solver itself has at the probes (its gas and drag alone,
    without its voidage model)."""
    column = bedlayers.Column(spout_case)
    eps = column.voidage(rows[:, 3], rows[:, 4], 'divided')
    with open(os.path.join(case, 'postProcessing', 'bedProbes', '0', 'p')) as f:
        z = [float(m.group(1).split()[2]) for m in
             re.finditer(r'#\s*Probe\s+\d+\s+\(([^)]*)\)', f.read())]
    cells = [column.layer_of(h) for h in z]
    # as openfoam_cases/packedBed/evaluate: the probes two layers clear of
    # the floor and three of the layer holding the bed surface
    surface = column.layer_of(float(np.max(rows[:, 3] + rows[:, 4])))
    if cells[0] < 2 or cells[-1] > surface - 3:
        raise BenchError('the packed bed (surface in layer %d) does not hold the probes of '
                         'layers %d-%d with room to spare: use more particles (3000 settle '
                         'to 0.29 m)' % (surface, cells[0], cells[-1]))
    pressure = function_object(case, 'bedProbes', 'p')
    voidage = function_object(case, 'bedProbes',
                              'alpha.air' if solver == 'DPMFoam' else 'voidfraction')
    law = draglaws.Gidaspow()

    def span(u, probed_eps):
        """Ergun from probe to probe: each pair crosses half of each layer."""
        G = np.array([draglaws.packed_bed_gradient(law, e, par.d, u, par.rho_g, par.mu_g)
                      for e in probed_eps])
        return float(np.sum(column.dz / 2 * (G[:-1] + G[1:])))

    out = []
    for i, u in enumerate(levels):
        t0, t1 = i * hold, (i + 1) * hold - 0.05
        sel = (pressure[:, 0] >= t0 + 0.6 * (t1 - t0)) & (pressure[:, 0] <= t1 + 1e-9)
        p = pressure[sel, 1:].mean(axis=0) * pressure_scale(solver, par)
        dp = p[0] - p[-1] - gas_head(solver, par, z[-1] - z[0])
        own = voidage[sel, 1:].mean(axis=0)
        out.append((u, dp, span(u, eps[cells]), span(u, own)))
    return out, (z[0], z[-1])


# the fluidised bed's pressure swings with its slugs; means of blocks this
# long [s] are taken as independent for the standard error of the mean (the
# pressure signal decorrelates within 0.1-0.15 s; slugs come every few tenths)
BLOCK = 0.5


def fluidised_result(solver, case, par, n, t_start):
    """Mean inlet pressure from t_start on, its standard error (block
    means), the rms fluctuation, and the bed weight per area."""
    data = function_object(case, 'inletPressure', 'surfaceFieldValue.dat')
    sel = data[:, 0] >= t_start
    t = data[sel, 0]
    p = data[sel, 1] * pressure_scale(solver, par) - gas_head(solver, par, par.height)
    blocks = np.floor((t - t_start) / BLOCK).astype(int)
    means = np.array([p[blocks == b].mean() for b in np.unique(blocks)
                      if np.sum(blocks == b) > 1])
    error = float(means.std(ddof=1) / math.sqrt(len(means))) if len(means) > 1 else float('nan')
    area = par.width * par.depth
    weight = n * par.m_p * G * (1 - par.rho_g / par.rho_p) / area
    return float(p.mean()), error, float(p.std()), weight


def read_cloud(time_dir, par):
    """DPMFoam's particles at a written time as rows (id, x, y, z, r), in the
    order of injection (= the LIGGGHTS ids)."""
    path = os.path.join(time_dir, 'lagrangian', 'kinematicCloud', 'positions')
    with open(path) as f:
        text = f.read()
    body = text[text.index('(', text.index('}')) + 1:]
    xyz = np.array([[float(v) for v in m.groups()] for m in
                    re.finditer(r'\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)', body)])
    ids = np.arange(1, len(xyz) + 1, dtype=float)
    return np.column_stack([ids, xyz, np.full(len(xyz), par.d / 2)])


def bed_change(before, after, spout_case):
    """Largest change of a layer's voidage inside the bed (clear of its
    surface layer) and the change of the bed top [m]."""
    column = bedlayers.Column(spout_case)
    e0 = column.voidage(before[:, 3], before[:, 4], 'divided')
    e1 = column.voidage(after[:, 3], after[:, 4], 'divided')
    top0 = float(np.max(before[:, 3] + before[:, 4]))
    top1 = float(np.max(after[:, 3] + after[:, 4]))
    inside = column.faces[1:] < min(top0, top1) - column.dz
    return float(np.max(np.abs(e1 - e0)[inside])), top1 - top0


def last_time_dir(case, end_time):
    """The time directory a run wrote at its end (the last step lands within
    round-off of endTime and is named as it fell), or None."""
    last = foamfile.time_dirs(case)[-1]
    return os.path.join(case, last[1]) if last[0] > end_time - 1e-3 else None


# ------------------------------------------------------- contact search work

def mesh_divisions(case):
    """(nx, ny, nz) of the single block of a case's blockMeshDict."""
    path = os.path.join(case, 'system', 'blockMeshDict')
    with open(path) as f:
        m = re.search(r'hex\s*\([^)]*\)\s*\(\s*(\d+)\s+(\d+)\s+(\d+)\s*\)', f.read())
    if not m:
        raise BenchError("%s: expected one 'hex (...) (nx ny nz)' block" % path)
    return tuple(int(v) for v in m.groups())


def contact_candidates(rows, par, divisions, skin):
    """Distance checks per particle per DEM step of the two contact searches
    on the bed `rows`:
      LIGGGHTS  its Verlet list: the pairs closer than d + skin (half list),
                rebuilt only when a particle has moved skin/2;
      DPMFoam   pairCollision's cell lists, built on the gas mesh: every pair
                within a cell and between cells closer than
                maxInteractionDistance (here d; on these meshes the 26 cells
                around), all checked at every substep."""
    xyz = rows[:, 1:4]
    n = len(xyz)
    close = 0
    for i in range(0, n, 500):
        d2 = np.sum((xyz[i:i + 500, None, :] - xyz[None, :, :]) ** 2, axis=2)
        close += int(np.sum(d2 < (par.d + skin) ** 2)) - min(500, n - i)
    verlet = close / 2 / n
    size = np.array([par.width, par.depth, par.height]) / np.array(divisions)
    cell = np.minimum((xyz / size).astype(int), np.array(divisions) - 1)
    count = {}
    for c in map(tuple, cell):
        count[c] = count.get(c, 0) + 1
    pairs = 0
    for c, k in count.items():
        pairs += k * (k - 1) / 2
        for o in count:
            if o > c and max(abs(a - b) for a, b in zip(o, c)) <= 1:
                pairs += k * count[o]
    return verlet, pairs / n


# ------------------------------------------------------------------ report

def fmt(x, spec='%.3g'):
    return '—' if x is None else spec % x


def liggghts_skin():
    path = os.path.join(INPUTS, 'in.contact')
    with open(path) as f:
        m = re.search(r'^neighbor\s+([-0-9.eE+]+)\s+bin', f.read(), re.M)
    if not m:
        raise BenchError("%s: expected 'neighbor <skin> bin'" % path)
    return float(m.group(1))


def report(args, par, mapping, n, results, uptime_lines, search):
    lines = []
    w = lines.append
    w('')
    w('peerDPMFoam: %d particles, d = %g mm, rho_p = %g kg/m3, k_n = %g N/m, e = %g, '
      'mu = %g, nu = %g; gas rho = %g kg/m3, mu = %g Pa s'
      % (n, par.d * 1e3, par.rho_p, par.k_n, par.e, par.mu_f, par.nu, par.rho_g, par.mu_g))
    w('DPMFoam contact mapping: E = %.5g Pa, E_wall = %.5g Pa (b = 1: k_n = %g N/m), '
      'alpha = %.4g (p-p), %.4g (p-w) for e = %g at %g m/s; e at 0.05 / %g / 1 m/s: '
      'p-p %s, p-w %s; one substep per fluid step up to %.3g m/s'
      % (mapping['E'], mapping['E_wall'], par.k_n, mapping['alpha_pp'], mapping['alpha_pw'],
         par.e, mapping['v_ref'], mapping['v_ref'],
         '/'.join('%.3f' % e for e in mapping['e_pp'].values()),
         '/'.join('%.3f' % e for e in mapping['e_pw'].values()),
         mapping['u_one_substep']))
    w('')
    head = ('| case | solver | simulated [s] | fluid dt / DEM dt [s] | DEM steps | '
            'loop wall [s] | wall s / sim s | CPU s / sim s | particle-steps/s | '
            'other load [cores] | dP [Pa] | reference [Pa] | dP error |')
    w(head)
    w('|' + '---|' * (head.count('|') - 1))
    ratios = {}
    for (kind, solver), r in results.items():
        sim = r['sim_time']
        dem_steps = r['dem_steps']
        per_sim = r['run']['wall'] / sim
        cpu_per_sim = r['run']['cpu'] / sim if r['run']['cpu'] else None
        rate = n * dem_steps / r['run']['wall']
        ratios.setdefault(kind, {})[solver] = (per_sim, cpu_per_sim, r['worst'])
        w('| %s | %s | %g | %.3g / %.3g | %d | %.1f | %.1f | %s | %.3g | %.2f | %s | %s | %s |'
          % (kind, solver, sim, r['dt_fluid'], par.dt_dem, dem_steps, r['run']['wall'],
             per_sim, fmt(cpu_per_sim, '%.1f'), rate, r['run']['others'],
             r['dp_text'], r['ref_text'], r['err_text']))
    w('')
    for kind, by in ratios.items():
        if 'spoutFoam' in by and 'DPMFoam' in by:
            s, d = by['spoutFoam'], by['DPMFoam']
            w('%s: DPMFoam / spoutFoam wall time per simulated s = %.1f (CPU %s); '
              'largest |dP error| spoutFoam %.2f %%, DPMFoam %.2f %%'
              % (kind, d[0] / s[0], fmt(d[1] / s[1] if d[1] and s[1] else None, '%.1f'),
                 100 * s[2], 100 * d[2]))
    for kind, solver in results:
        note = results[(kind, solver)].get('note')
        if note:
            w('%s, %s: %s' % (kind, solver, note))
    for kind, (verlet, cells) in search.items():
        w('contact search, settled bed on the %s mesh: LIGGGHTS %.1f pairs per particle '
          'in its Verlet list (skin %g mm, rebuilt when a particle moved half of it), '
          'DPMFoam %.0f distance checks per particle at every step (cell lists on the '
          'gas mesh)' % (kind, verlet, 1e3 * liggghts_skin(), cells))
    w('load (uptime) before / after: %s' % ' / '.join(uptime_lines))
    text = '\n'.join(lines)
    print(text)
    with open(os.path.join(args.dir, 'summary.txt'), 'w') as f:
        f.write(text + '\n')


def uptime():
    try:
        with open('/proc/loadavg') as f:
            return 'load average ' + ' '.join(f.read().split()[:3])
    except OSError:
        return 'load unknown'


# -------------------------------------------------------------- set-up check

# A bed settled by LIGGGHTS stays at rest in DPMFoam only if the contact
# model gives the same normal forces (a Hertz exponent, or a wall spring off
# by its share of the moduli, lets it sink or bounce at cm/s within the
# check's 15 ms); LIGGGHTS itself left it below 0.5 mm/s rms.
CHECK_STEPS = 50
CHECK_VRMS = 5e-3          # m/s
# Settling again in DPMFoam (its tangential springs start from zero) the
# bed sags a little as friction is rebuilt: measured 0.5 mm and 0.003 in a
# layer's voidage for 1200 particles. A normal force that is not LIGGGHTS'
# (e.g. the Hertz exponent b = 1.5 with this E: 1.6 mm overlap at 0.05 N
# instead of 0.06 mm) sinks the bed by centimetres.
CHECK_SAG = 2e-3           # m, a quarter of a diameter
CHECK_VOIDAGE = 0.01
# With no gas flow and no particle moving, the inlet pressure is the gas's
# own head rho_g g H (9.5 Pa in the 0.8 m column), which the dP evaluation
# takes off DPMFoam's p; 5 % of it.
CHECK_HEAD_TOL = 0.05


def last_cloud_report(log):
    """The last 'Cloud:' block of a DPMFoam log: parcels, mass, kinetic
    energy and the escaped parcels."""
    with open(log, errors='replace') as f:
        text = f.read()
    block = text[text.rindex('Cloud: '):]
    def number(label):
        m = re.search(r'%s\s*=\s*(\S+)' % re.escape(label), block)
        if not m:
            raise BenchError("%s: no '%s' in the last cloud report" % (log, label))
        return float(m.group(1))
    escaped = sum(int(m.group(1)) for m in
                  re.finditer(r'- escape\s*=\s*(\d+)', block))
    return {'parcels': int(number('Current number of parcels')),
            'mass': number('Current mass in system'),
            'ke': number('Linear kinetic energy'), 'escaped': escaped}


def check_setup(base, rows, par, mapping, relax_time, env):
    """The DPMFoam column at rest for CHECK_STEPS steps: every particle
    injected and kept, the bed still at rest, the inlet pressure the gas
    head. Returns the failures (empty: the set-up is valid)."""
    n = len(rows)
    spout_case = os.path.join(base, 'fluidised', 'spoutFoam')
    end_time = CHECK_STEPS * par.dt_dem
    inlet = inlet_entry([0.0], None)
    setup_spoutFoam('fluidised', spout_case, None, n, inlet, end_time, env)
    work = os.path.join(base, 'fluidised', 'DPMFoam')
    relaxed = setup_DPMFoam('fluidised', work, CASES['fluidised'], rows, par, mapping,
                            inlet, end_time, 1, relax_time, env)
    change, rise = bed_change(rows, read_cloud(relaxed, par), spout_case)
    run_solver('DPMFoam', work, env)
    cloud = last_cloud_report(os.path.join(work, 'log.DPMFoam'))
    mass = n * par.m_p
    vrms = math.sqrt(2 * cloud['ke'] / cloud['mass'])
    p_in = function_object(work, 'inletPressure', 'surfaceFieldValue.dat')[-1, 1]
    p_in *= pressure_scale('DPMFoam', par)
    head = par.rho_g * G * par.height      # what gas_head() takes off DPMFoam's p
    checks = [
        ('bed top after settling in DPMFoam', abs(rise) < CHECK_SAG,
         '%+.2f mm from LIGGGHTS\' (limit %g mm)' % (1e3 * rise, 1e3 * CHECK_SAG)),
        ('layer voidage after settling in DPMFoam', change < CHECK_VOIDAGE,
         'changed by up to %.4f (limit %g)' % (change, CHECK_VOIDAGE)),
        ('parcels in the system', cloud['parcels'] == n, '%d of %d' % (cloud['parcels'], n)),
        ('parcels escaped', cloud['escaped'] == 0, '%d' % cloud['escaped']),
        ('mass in the system', abs(cloud['mass'] / mass - 1) < 1e-6,
         '%.8g kg, N m_p = %.8g kg' % (cloud['mass'], mass)),
        ('rms particle speed after %d steps' % CHECK_STEPS, vrms < CHECK_VRMS,
         '%.3g m/s (limit %g)' % (vrms, CHECK_VRMS)),
        ('inlet pressure at rest = gas head', abs(p_in / head - 1) < CHECK_HEAD_TOL,
         '%.4g Pa, rho_g g H = %.4g Pa' % (p_in, head)),
    ]
    failures = []
    for name, ok, value in checks:
        print('  %s %s: %s' % ('ok  ' if ok else 'FAIL', name, value))
        if not ok:
            failures.append(name)
    return failures


# --------------------------------------------------------------------- main

def run_case(kind, solver, args, par, mapping, base, dem, rows, env):
    n = len(rows)
    if kind == 'packed':
        levels, hold = args.packed_velocities, args.hold
        end_time = len(levels) * hold - 0.05 if len(levels) > 1 else hold
    else:
        levels, hold = [args.velocity], None
        end_time = args.fluidised_time
    inlet = inlet_entry(levels, hold)
    spout_case = os.path.join(base, kind, 'spoutFoam')
    work = os.path.join(base, kind, solver)
    notes = []
    if solver == 'spoutFoam':
        setup_spoutFoam(kind, work, dem, n, inlet, end_time, env)
        dt_fluid = float(co.foam_get(work, env, 'system/controlDict', 'deltaT'))
        bed = rows                  # frozen (packed) or the start (fluidised)
    else:
        if not os.path.isdir(os.path.join(spout_case, 'constant', 'polyMesh')):
            setup_spoutFoam(kind, spout_case, dem, n, inlet, end_time, env)
        dt_spout = float(co.foam_get(spout_case, env, 'system/controlDict', 'deltaT'))
        # sample at the same simulated times as spoutFoam's function objects
        # (every 10 of its steps)
        every = max(1, int(round(10 * dt_spout / par.dt_dem)))
        relaxed = setup_DPMFoam(kind, work, CASES[kind], rows, par, mapping, inlet,
                                end_time, every, args.relax_time, env)
        dt_fluid = par.dt_dem
        bed = read_cloud(relaxed, par)
        change, rise = bed_change(rows, bed, spout_case)
        notes.append('settled %g s in its own contact model before the run: layer voidage '
                     'changed by up to %.4f, bed top by %+.1f mm'
                     % (args.relax_time, change, 1e3 * rise))
    res = {'run': run_solver(solver, work, env), 'sim_time': end_time,
           'dt_fluid': dt_fluid, 'dem_steps': int(round(end_time / par.dt_dem))}
    if kind == 'packed':
        out, (z0, z1) = packed_bed_result(solver, work, spout_case, bed, par, levels, hold)
        errors = [dp / ref - 1 for _, dp, ref, _ in out]
        own = [dp / ref_own - 1 for _, dp, _, ref_own in out]
        res['worst'] = max(abs(e) for e in errors)
        res['dp_text'] = ' '.join('%.1f' % dp for _, dp, _, _ in out)
        res['ref_text'] = ' '.join('%.1f' % ref for _, _, ref, _ in out)
        res['err_text'] = ' '.join('%+.1f%%' % (100 * e) for e in errors)
        notes.insert(0, 'u_s = %s m/s, dP over z = %.2f-%.2f m; against Ergun at the '
                     "solver's own voidage at the probes: %s"
                     % (' '.join('%g' % u for u in levels), z0, z1,
                        ' '.join('%+.1f%%' % (100 * e) for e in own)))
        last = last_time_dir(work, end_time) if solver == 'DPMFoam' else None
        if last:
            change, rise = bed_change(bed, read_cloud(last, par), spout_case)
            notes.append('its bed (not frozen) moved during the run: layer voidage by up '
                         'to %.4f, bed top by %+.1f mm' % (change, 1e3 * rise))
    else:
        mean, error, std, weight = fluidised_result(solver, work, par, n, args.average_from)
        res['worst'] = abs(mean / weight - 1)
        res['dp_text'] = '%.0f ± %.0f' % (mean, error) if error == error else '%.0f' % mean
        res['ref_text'] = '%.0f' % weight
        res['err_text'] = '%+.1f%%' % (100 * (mean / weight - 1))
        if error == error:      # not NaN: at least two blocks
            res['err_text'] = '%+.1f ± %.1f%%' % (100 * (mean / weight - 1),
                                                  100 * error / weight)
        notes.insert(0, 'u_s = %g m/s, dP = mean inlet pressure for t >= %g s ± its '
                     'standard error (%g s blocks; fluctuations %.0f Pa rms), reference '
                     'W/A = N m g (1 - rho_g/rho_p)/A'
                     % (args.velocity, args.average_from, BLOCK, std))
    res['note'] = '; '.join(notes)
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--particles', type=int,
                    help='particles in the bed (default 3000; --check: 1200)')
    ap.add_argument('--cases', nargs='+', choices=('packed', 'fluidised'),
                    default=['packed', 'fluidised'])
    ap.add_argument('--solvers', nargs='+', choices=('spoutFoam', 'DPMFoam'),
                    default=['spoutFoam', 'DPMFoam'])
    ap.add_argument('--packed-velocities', type=float, nargs='+',
                    default=[0.3, 0.6, 0.9, 1.2, 1.5],
                    help='superficial velocities of the packed bed [m/s] (below u_mf)')
    ap.add_argument('--hold', type=float, default=0.6,
                    help='simulated time at each packed-bed velocity [s]')
    ap.add_argument('--velocity', type=float, default=2.5,
                    help='superficial velocity of the fluidised column [m/s] (above u_mf)')
    ap.add_argument('--fluidised-time', type=float, default=5.0,
                    help='simulated time of the fluidised column [s]')
    ap.add_argument('--average-from', type=float, default=2.0,
                    help='start of the fluidised dP average [s]')
    ap.add_argument('--relax-time', type=float, default=0.2,
                    help='DPMFoam settles the injected bed this long before the run [s]')
    ap.add_argument('--impact-speed', type=float, default=0.3,
                    help='impact speed at which DPMFoam restitutes with e [m/s]')
    ap.add_argument('--dir', help='work directory (default $SPOUTLAB_BUILD/bench/peer)')
    ap.add_argument('--check', action='store_true',
                    help='only check the DPMFoam set-up: the column at rest for %d '
                         'steps (a ctest)' % CHECK_STEPS)
    args = ap.parse_args(argv)
    try:
        env = co.environment()
        if args.particles is None:
            args.particles = 1200 if args.check else 3000
        if not args.check:
            co.check_programs(env)
        for program in ('DPMFoam', 'liggghts', 'blockMesh'):
            if not shutil.which(program, path=env['PATH']):
                raise BenchError('%s not found on PATH (Debian package openfoam / '
                                 'liggghts)' % program)
        args.dir = os.path.abspath(args.dir or os.path.join(env['SPOUTLAB_BUILD'],
                                                            'bench', 'peer'))
        base = os.path.join(args.dir, 'n%d' % args.particles)
        os.makedirs(base, exist_ok=True)
        par = Parameters(CASES['packed'])
        mapping = contact_mapping(par, args.impact_speed)
        dem, rows = settled_positions(base, args.particles, env)
        if args.check:
            failures = check_setup(base, rows, par, mapping, args.relax_time, env)
            print('peerDPMFoam --check: %s' % ('the DPMFoam set-up is valid' if not failures
                                               else 'FAILED: ' + ', '.join(failures)))
            return 1 if failures else 0
        loads = [uptime()]
        results = {}
        for kind in args.cases:
            for solver in args.solvers:
                results[(kind, solver)] = run_case(kind, solver, args, par, mapping,
                                                   base, dem, rows, env)
        loads.append(uptime())
        search = {kind: contact_candidates(rows, par, mesh_divisions(CASES[kind]),
                                           liggghts_skin()) for kind in args.cases}
        report(args, par, mapping, len(rows), results, loads, search)
    except BenchError as e:
        print('peerDPMFoam: %s' % e, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
