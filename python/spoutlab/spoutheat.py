"""Heat transfer in a spouted-bed run (draft-plate paper, section 4.7), from
what spoutFoam wrote: coupling.csv (energy columns), the particle .vtp files
(temperature, h) and the gas fields at write times (T, hp, Rep).

  heatHistory.csv, particleTemperature.png
      mean particle temperature of the spout and of the downcomer vs time
  heatProfiles.csv, heatTransfer.png  (Fig 12)
      h and Re across the width, averaged over the cells holding particles
      with z/R_d in 16.927 .. 22.454 and over the write times of the window
  particleTemperature_<t>.png, gasTemperature_<t>.png  (Fig 11)

Spout and downcomer are told apart by the rule the solver's spoutDowncomer
model uses (with plates: between the plates' inner faces, or above their
upper edge); without plates, by the voidage of the cell.
"""
import math
import os

from spoutlab import heatcorrelations as hc
from spoutlab import casefiles as sc
from spoutlab import foamfile
from spoutlab import bedmaps

BAND = (16.927, 22.454)   # z/R_d of Fig 12


def write_times(case='.'):
    """(time, name) of the write times that hold a gas temperature."""
    out = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, name, 'T')):
            out.append((t, name))
    return sorted(out)


def vtp_times(case='.'):
    """[(time, name as written)] of the particle files."""
    return [(t, sc.time_name(path)) for t, path in sc.particle_files(case)]


def particle_history(g, case='.'):
    """Rows (t, mean T spout, mean T downcomer, mean T all) from the .vtp files."""
    rows = []
    for t, name in vtp_times(case):
        vtp = os.path.join(case, 'particles', 'particles_%s.vtp' % name)
        T = sc.read_vtp_array(vtp, 'temperature')
        if not T:
            continue
        points = sc.read_vtp_points(vtp)
        spout = [Ti for (x, y, z), Ti in zip(points, T) if g.in_spout(1000 * x, 1000 * z)]
        down = [Ti for (x, y, z), Ti in zip(points, T) if not g.in_spout(1000 * x, 1000 * z)]
        mean = lambda v: sum(v) / len(v) if v else float('nan')  # noqa: E731
        rows.append((t, mean(spout), mean(down), mean(T)))
    return rows


def read_samples(names, case='.'):
    """(hp, Rep) cell fields of the write times `names`, each read once."""
    return [(foamfile.read_field(os.path.join(case, n, 'hp')), foamfile.read_field(os.path.join(case, n, 'Rep')))
            for n in names]


def band_profiles(g, centres, samples):
    """h and Re of the cells holding particles in the band of Fig 12, per
    column (x) and per region, averaged over the samples (read_samples)."""
    Rd = g.Wd / 2
    cells = [i for i, (x, y, z) in enumerate(centres)
             if BAND[0] <= 1000 * z / Rd <= BAND[1]]
    columns, regions = {}, {'spout': [0.0, 0.0, 0], 'downcomer': [0.0, 0.0, 0]}
    for h, re in samples:
        for i in cells:
            if re[i] <= 0:
                continue          # no particles in the cell at this time
            x, z = 1000 * centres[i][0], 1000 * centres[i][2]
            col = columns.setdefault(round(x, 3), [0.0, 0.0, 0])
            reg = regions['spout' if g.in_spout(x, z) else 'downcomer']
            for acc in (col, reg):
                acc[0] += h[i]
                acc[1] += re[i]
                acc[2] += 1
    profile = [(x / Rd, s[0] / s[2], s[1] / s[2], s[2]) for x, s in sorted(columns.items())]
    means = {k: (v[0] / v[2], v[1] / v[2]) if v[2] else (float('nan'),) * 2
             for k, v in regions.items()}
    return profile, means


def height_profiles(g, centres, samples):
    """Mean h per cell row (z/R_d) in the spout between the plates and in the
    downcomer, over the cells holding particles and the samples: rows
    (z/R_d, h spout, h downcomer)."""
    Rd = g.Wd / 2
    sums = {}
    for h, re in samples:
        for i, (x, y, z) in enumerate(centres):
            if re[i] <= 0 or 1000 * z >= g.Hd:
                continue
            acc = sums.setdefault(round(1000 * z / Rd, 3), [0.0, 0, 0.0, 0])
            k = 0 if abs(1000 * x) <= g.Wd / 2 else 2
            acc[k] += h[i]
            acc[k + 1] += 1
    nan = float('nan')
    return [(z, a[0] / a[1] if a[1] else nan, a[2] / a[3] if a[3] else nan)
            for z, a in sorted(sums.items())]


def downcomer_columns(g, profile):
    """h across the downcomer: the spread (max - min)/mean of the columns
    inside it, and the mean of the columns beside the plates and by the
    walls (on each side the innermost and the outermost column)."""
    nan = float('nan')
    z = 0.5 * sum(BAND) * g.Wd / 2
    sides = [sorted((abs(x), h) for x, h, _, _ in profile
                    if side * x > 0 and not g.in_spout(x * g.Wd / 2, z)) for side in (-1, 1)]
    if not all(len(cols) > 2 for cols in sides):
        return {'h_downcomer_spread': nan, 'h_by_plates': nan, 'h_by_walls': nan}
    inside = [h for cols in sides for _, h in cols[1:-1]]
    return {'h_downcomer_spread': (max(inside) - min(inside)) / (sum(inside) / len(inside)),
            'h_by_plates': sum(cols[0][1] for cols in sides) / 2,
            'h_by_walls': sum(cols[-1][1] for cols in sides) / 2}


def slope(rows, column, lo, hi):
    """Least-squares d h/d(z/R_d) of one column over lo <= z/R_d <= hi."""
    pts = [(r[0], r[column]) for r in rows if lo <= r[0] <= hi and r[column] == r[column]]
    if len(pts) < 2:
        return float('nan')
    n = len(pts)
    mz = sum(p[0] for p in pts) / n
    mh = sum(p[1] for p in pts) / n
    return (sum((p[0] - mz) * (p[1] - mh) for p in pts)
            / sum((p[0] - mz) ** 2 for p in pts))


def plot_history(rows, png):
    """heatHistory.csv and its picture (a casefiles.Plot)."""
    with open('heatHistory.csv', 'w') as f:
        f.write('time [s],mean particle temperature spout [K],'
                'mean particle temperature downcomer [K],mean particle temperature [K]\n')
        for r in rows:
            f.write('%.6g,%.8g,%.8g,%.8g\n' % r)
    return sc.plot(png, '''
set title "Mean particle temperature (spout: between the plates and above them)"
set xlabel "time [s]"
set ylabel "temperature [K]"
set key top left
set grid
set datafile separator ","
plot "heatHistory.csv" skip 1 using 1:2 with linespoints lw 2 title "spout", \\
     "heatHistory.csv" skip 1 using 1:3 with linespoints lw 2 title "downcomer", \\
     "heatHistory.csv" skip 1 using 1:4 with lines dt 2 title "all particles"
''')


def plot_profiles(profile, png):
    """heatProfiles.csv and its picture (a casefiles.Plot); without a
    particle in the band, no picture, and the Plot says why."""
    with open('heatProfiles.csv', 'w') as f:
        f.write('x/R_d,h [W/m2/K],Re,samples\n')
        for r in profile:
            f.write('%.4f,%.6g,%.6g,%d\n' % r)
    if not profile:
        return sc.not_drawn(png, 'no particle in z/R_d %g-%g over the averaging window' % BAND)
    return sc.plot(png, '''
set multiplot layout 2,1 title "Heat-transfer coefficient and Reynolds number, z/R_d %g-%g (Fig 12)"
set grid
set datafile separator ","
set xlabel "x/R_d (draft plates at +-1, walls at +-9)"
set ylabel "h [W/m^2K]"
plot "heatProfiles.csv" skip 1 using 1:2 with linespoints pt 7 notitle
set ylabel "Re"
set logscale y
plot "heatProfiles.csv" skip 1 using 1:3 with linespoints pt 7 notitle
unset multiplot
''' % BAND, size=(900, 800))


def snapshots(g, names, case='.'):
    """Fig 11: particles and gas coloured by temperature at the given times."""
    centres = foamfile.read_field(os.path.join(case, '0', 'C'))
    vtps = {n: os.path.join(case, 'particles', 'particles_%s.vtp' % n) for n in names}
    vtps = {n: v for n, v in vtps.items() if os.path.isfile(v)}
    # particles warm by a few kelvin in seconds: a scale from T_0 to the
    # hottest particle shown, not to T_in, makes the pattern visible
    hottest = max([max(sc.read_vtp_array(v, 'temperature')) for v in vtps.values()] + [g.T0 + 1])
    pictures = []
    for name in names:
        if name in vtps:
            png = 'particleTemperature_%s.png' % name
            bedmaps.snapshot(g, vtps[name], png, 'particles, t = %s s' % name,
                                field='temperature', vmin=g.T0, vmax=math.ceil(hottest),
                                label='particle temperature [K]')
            pictures.append(png)
        png = 'gasTemperature_%s.png' % name
        bedmaps.field_map(g, centres, foamfile.read_field(os.path.join(case, name, 'T')), png,
                             'gas, t = %s s' % name, 'gas temperature [K]', g.T0, g.Tin)
        pictures.append(png)
    return pictures


def summarize(g, window, lines, case='.', pictures=True):
    """Add the heat-transfer lines to the summary; return the numbers."""
    rows = sc.read_coupling_log(case)
    last = rows[-1]
    pairwise, balance = hc.energy_balance(rows)
    history = particle_history(g, case)
    plots = [plot_history(history, 'particleTemperature.png')]
    times = write_times(case)
    end = times[-1][0]
    averaged = [n for t, n in times if t >= end - window - 1e-9 and t > 0]
    centres = foamfile.read_field(os.path.join(case, '0', 'C'))
    samples = read_samples(averaged, case)
    profile, means = band_profiles(g, centres, samples)
    plots.append(plot_profiles(profile, 'heatTransfer.png'))
    heights = height_profiles(g, centres, samples)
    with open('heatHeight.csv', 'w') as f:
        f.write('z/R_d,h spout [W/m2/K],h downcomer [W/m2/K]\n')
        for r in heights:
            f.write('%.3f,%.6g,%.6g\n' % r)
    down = downcomer_columns(g, profile)
    out = {'Tp_spout': history[-1][1], 'Tp_downcomer': history[-1][2],
           'T_outlet': last['gas outlet temperature [K]'],
           'h_spout': means['spout'][0], 'Re_spout': means['spout'][1],
           'h_downcomer': means['downcomer'][0], 'Re_downcomer': means['downcomer'][1],
           'balance': balance, 'pairwise': pairwise, 'samples': len(averaged),
           'dh_dz_spout': slope(heights, 1, *BAND), 'dh_dz_downcomer': slope(heights, 2, *BAND),
           **down}
    lines.append('heat transfer: inlet %.1f K, start %.1f K; at t = %g s the particles '
                 'average %.2f K in the spout, %.2f K in the downcomer; gas leaves at %.2f K'
                 % (g.Tin, g.T0, last['time [s]'], out['Tp_spout'], out['Tp_downcomer'],
                    out['T_outlet']))
    if profile:
        lines.append('  z/R_d %g-%g, %d write times: Re %.0f (spout), %.0f (downcomer); '
                     'h %.1f, %.1f W/m2/K' % (BAND + (len(averaged), out['Re_spout'],
                                                      out['Re_downcomer'], out['h_spout'],
                                                      out['h_downcomer'])))
        lines.append('  h along the band: %+.2f (spout) and %+.2f (downcomer) W/m2/K per R_d '
                     'of height; across the downcomer h spans %.0f %% of its mean inside, '
                     '%.1f W/m2/K beside the plates, %.1f by the walls'
                     % (out['dh_dz_spout'], out['dh_dz_downcomer'],
                        100 * out['h_downcomer_spread'], out['h_by_plates'], out['h_by_walls']))
    else:
        lines.append('  z/R_d %g-%g: no particles there at the %d write times of the window '
                     '(bed below it, or the window too short): no h and Re profiles'
                     % (BAND + (len(averaged),)))
    lines.append('  energy: heat given by the gas = heat received by the particles to %.1e; '
                 'whole-run balance closes to %.1e of the particles\' heat' % (pairwise, balance))
    if pictures:
        # at a third, two thirds and the end of the run (0/T is the uniform start)
        later = [(t, n) for t, n in times if t > 0]
        shown = sorted({min(later, key=lambda tn: abs(tn[0] - f * end))[1]
                        for f in (1 / 3, 2 / 3, 1)}, key=float)
        lines.append('  temperature pictures: ' + ' '.join(snapshots(g, shown, case)))
    lines.append('  data: heatHistory.csv heatProfiles.csv heatHeight.csv; plots: '
                 + sc.plots_text(plots))
    return out
