"""Drying in a spouted-bed run, from what spoutFoam wrote: coupling.csv
(water and latent-energy columns), the particle .vtp files (moisture,
dryingRate) and the gas fields at write times (H2O, humidity, RH).

  moistureHistory.csv, particleMoisture.png
      mean particle moisture of the spout and of the downcomer vs time, with
      the 5-95 % band of all particles
  particleMoisture_<t>.png, gasHumidity_<t>.png
      particles coloured by moisture, the gas by relative humidity

Spout and downcomer are told apart as in spoutlab.spoutheat.
"""
import os

from spoutlab import casefiles as sc
from spoutlab import foamfile
from spoutlab import heatcorrelations as hc
from spoutlab import bedmaps
from spoutlab import spoutheat


def percentile(values, q):
    """The q-quantile (0..1) of values, linear between order statistics."""
    v = sorted(values)
    if not v:
        return float('nan')
    k = q * (len(v) - 1)
    i = int(k)
    return v[i] if i + 1 >= len(v) else v[i] + (k - i) * (v[i + 1] - v[i])


def moisture_history(g, case='.'):
    """Rows (t, mean X spout, mean X downcomer, mean X, X 5 %, X 95 %) from
    the particle files (means over particles: the kernels' dry masses are
    equal)."""
    rows = []
    for t, name in spoutheat.vtp_times(case):
        vtp = os.path.join(case, 'particles', 'particles_%s.vtp' % name)
        X = sc.read_vtp_array(vtp, 'moisture')
        if not X:
            continue
        points = sc.read_vtp_points(vtp)
        spout = [Xi for (x, y, z), Xi in zip(points, X) if g.in_spout(1000 * x, 1000 * z)]
        down = [Xi for (x, y, z), Xi in zip(points, X) if not g.in_spout(1000 * x, 1000 * z)]
        mean = lambda v: sum(v) / len(v) if v else float('nan')  # noqa: E731
        rows.append((t, mean(spout), mean(down), mean(X), percentile(X, 0.05), percentile(X, 0.95)))
    return rows


def plot_history(rows, png):
    """moistureHistory.csv and its picture (a casefiles.Plot)."""
    with open('moistureHistory.csv', 'w') as f:
        f.write('time [s],mean moisture spout [kg/kg],mean moisture downcomer [kg/kg],'
                'mean moisture [kg/kg],moisture 5 % [kg/kg],moisture 95 % [kg/kg]\n')
        for r in rows:
            f.write('%.6g,%.8g,%.8g,%.8g,%.8g,%.8g\n' % r)
    return sc.plot(png, '''
set title "Particle moisture X (dry basis); band: 5-95 % of the particles"
set xlabel "time [s]"
set ylabel "moisture [kg water/kg dry solid]"
set key bottom left
set grid
set datafile separator ","
plot "moistureHistory.csv" skip 1 using 1:5:6 with filledcurves fs transparent solid 0.2 title "5-95 %", \\
     "moistureHistory.csv" skip 1 using 1:2 with linespoints lw 2 title "spout", \\
     "moistureHistory.csv" skip 1 using 1:3 with linespoints lw 2 title "downcomer", \\
     "moistureHistory.csv" skip 1 using 1:4 with lines dt 2 title "all particles"
''')


def pictures(g, names, X0, case='.'):
    """Particles coloured by moisture and the gas by relative humidity at
    the given write times."""
    centres = foamfile.read_field(os.path.join(case, '0', 'C'))
    drawn = []
    for name in names:
        vtp = os.path.join(case, 'particles', 'particles_%s.vtp' % name)
        if os.path.isfile(vtp):
            X = sc.read_vtp_array(vtp, 'moisture')
            png = 'particleMoisture_%s.png' % name
            bedmaps.snapshot(g, vtp, png, 'particles, t = %s s' % name, field='moisture',
                                vmin=min(X), vmax=X0, label='moisture X [kg/kg dry solid]')
            drawn.append(png)
        rh = os.path.join(case, name, 'RH')
        if os.path.isfile(rh):
            png = 'gasHumidity_%s.png' % name
            bedmaps.field_map(g, centres, foamfile.read_field(rh), png, 'gas, t = %s s' % name,
                                 'relative humidity', 0.0, 1.0)
            drawn.append(png)
    return drawn


def window_mean(rows, column, start):
    """Time average of a coupling.csv column over t > start."""
    total = span = 0.0
    for p, r in zip(rows, rows[1:]):
        if r['time [s]'] > start + 1e-12:
            dt = r['time [s]'] - p['time [s]']
            total += r[column] * dt
            span += dt
    return total / span if span > 0 else float('nan')


def shown_times(case='.'):
    """The write times pictured: a third, two thirds and the end of the run."""
    times = [(t, n) for t, n in spoutheat.write_times(case) if t > 0]
    if not times:
        return []
    end = times[-1][0]
    return sorted({min(times, key=lambda tn: abs(tn[0] - f * end))[1] for f in (1 / 3, 2 / 3, 1)},
                  key=float)


def summarize(g, window, lines, case='.', pictures_drawn=True):
    """Add the drying lines to the summary; return the numbers."""
    rows = sc.read_coupling_log(case)
    end = rows[-1]['time [s]']
    start = max(0.0, end - window)
    pairwise, water = hc.water_balance(rows)
    _, energy = hc.energy_balance(rows)
    history = moisture_history(g, case)
    png = 'particleMoisture.png'
    plots = [plot_history(history, png) if history
             else sc.not_drawn(png, 'no particle file with moisture')]
    heat = window_mean(rows, 'heat to particles [W]', start)
    latent = window_mean(rows, 'latent heat from particles [W]', start)
    out = {'rate': window_mean(rows, 'water lost by particles [kg/s]', start),
           'T_outlet': window_mean(rows, 'gas outlet temperature [K]', start),
           'RH_outlet': window_mean(rows, 'outlet relative humidity', start),
           'evaporation_share': latent / heat if heat else float('nan'),
           'water_balance': water, 'energy_balance': energy, 'pairwise': pairwise,
           'X_spout': history[-1][1] if history else float('nan'),
           'X_downcomer': history[-1][2] if history else float('nan')}
    lines.append('drying: at t = %g s the particles hold X = %.4f (spout), %.4f (downcomer) kg/kg '
                 'dry solid; over the last %g s they lose %.4g kg/s of water, the gas leaves at '
                 '%.2f K and %.1f %% relative humidity, and %.1f %% of the heat the gas gives them '
                 'goes into evaporation'
                 % (end, out['X_spout'], out['X_downcomer'], end - start, out['rate'],
                    out['T_outlet'], 100 * out['RH_outlet'], 100 * out['evaporation_share']))
    lines.append('  water: particles lost = vapour gained by the gas to %.1e per step; whole-run '
                 'water balance closes to %.1e, energy balance (latent heat included) to %.1e'
                 % (pairwise, water, energy))
    if pictures_drawn:
        lines.append('  moisture pictures: ' + ' '.join(pictures(g, shown_times(case), g.X0, case)))
    lines.append('  data: moistureHistory.csv; plots: ' + sc.plots_text(plots))
    return out
