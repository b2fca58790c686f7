"""Running the spouted-bed case from a protocol (its Allmesh and settling,
spoutFoam serially or on P ranks, with progress) and what a run used (its
particle count, the u_s schedule of constant/inletVelocity, the averaging
window)."""
import os
import re
import sys

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


def last_time(log, since=0):
    """The last 'Time = ' of a solver log (after byte `since`), or None."""
    try:
        with open(log, 'rb') as f:
            f.seek(max(since, os.path.getsize(log) - 20000))
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
    if ranks > 1 and not os.path.isdir('processor0'):
        subprocess.check_call(['bash', '-c', '. "$SPOUTLAB_DIR/etc/caseFunctions" '
                               '&& decomposeSlabs %d' % ranks])
    # the one launch, etc/caseFunctions launchSpoutFoam
    cmd = ['bash', '-c', '. "$SPOUTLAB_DIR/etc/caseFunctions" && launchSpoutFoam %d' % ranks]
    # the rate from the first time step this launch logs: a run killed
    # after its last write logged times it now goes back over
    before = os.path.getsize('log.spoutFoam') if os.path.exists('log.spoutFoam') else 0
    log = open('log.spoutFoam', 'a')
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
    first = None
    while proc.poll() is None:
        time.sleep(10)
        now = last_time('log.spoutFoam', before)
        if now is None:
            continue
        if first is None:
            first = (time.time(), now)
        elif now > first[1]:
            rate = (time.time() - first[0]) / (now - first[1])
            print('%s: t = %.2f of %.2f s, %.0f s wall per simulated s, about %.0f min left'
                  % (who, now, end, rate, (end - now) * rate / 60), flush=True)
    if proc.returncode != 0:
        sys.exit('%s: spoutFoam failed, see log.spoutFoam' % who)


def wall_time(case):
    """Wall time of the spoutFoam run(s) in case from their logs (ClockTime,
    summed over restarts, so a segment killed before it could record its
    time counts too) [s]."""
    total = 0.0
    for root, _, files in os.walk(case):
        for f in files:
            if f == 'log.spoutFoam':
                last = 0.0
                start = 0.0
                for line in open(os.path.join(root, f), errors='replace'):
                    m = re.match(r'ExecutionTime = [\d.e+-]+ s\s+ClockTime = (\d+) s', line)
                    if m:
                        value = float(m.group(1))
                        if value < last:          # a restart: the clock began again
                            start += last
                        last = value
                total += start + last
    return total


def run_particles(case='.'):
    """(number, source) of the particles a run had at its start: counted in
    its first particles/*.vtp, else the first row of postProcessing/
    coupling.csv; (None, None) before a run."""
    from spoutlab import casefiles as sc
    files = sc.particle_files(case)
    if files:
        path = files[0][1]
        return len(sc.read_vtp_points(path)), os.path.join('particles', os.path.basename(path))
    if os.path.isfile(os.path.join(case, 'postProcessing', 'coupling.csv')):
        rows = sc.read_coupling_log(case)
        if rows:
            return int(rows[0]['particles']), 'postProcessing/coupling.csv'
    return None, None


LOST = re.compile(r'spoutFoam: (?:deleting )?(\d+) particle\(s\) '
                  r'(?:lost by LIGGGHTS|outside the CFD mesh)')


def lost_particles(case='.'):
    """Particles a run removed (lostParticles delete), counted from the lines
    spoutFoam writes to its log when it deletes them; 0 without a log."""
    path = os.path.join(case, 'log.spoutFoam')
    if not os.path.isfile(path):
        return 0
    with open(path, errors='replace') as f:
        return sum(int(m.group(1)) for m in map(LOST.match, f) if m)


def lost_text(lost):
    """'; 1 particle lost', for a summary line, or '' when none was."""
    return '; %d particle%s lost' % (lost, '' if lost == 1 else 's') if lost else ''


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
