"""Pictures of the slanted-base vessel in the x-z plane (gnuplot): the
particles of one write time as discs (snapshot), a gas cell field as
squares (field_map), the vessel's walls, base and plates drawn over both."""
import os

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
