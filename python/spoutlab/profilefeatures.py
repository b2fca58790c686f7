"""The features of the draft-plate paper's Figs 4a and 5 in the
time-averaged profiles evaluate writes (spoutProfiles.csv,
downcomerProfiles.csv): how the spout and downcomer velocities change with
height, read from the profile rows."""
import math

def slope(xs, ys):
    """Least-squares slope of ys against xs."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else 0.0


def weighted_slope(xs, ys, sigmas):
    """(slope, its standard error, reduced chi-square) of the straight line
    through (xs, ys) weighted by 1/sigma^2, sigma each y's standard error.
    The error is the one the sigmas alone give, sqrt(1 / sum w (x - xw)^2),
    times sqrt(chi-square / (n - 2)) when the points scatter about the line
    more than their errors allow (the line does not fit them as well as
    they are known); chi-square is None with two points."""
    w = [1 / s ** 2 for s in sigmas]
    sw = sum(w)
    mx = sum(wi * x for wi, x in zip(w, xs)) / sw
    my = sum(wi * y for wi, y in zip(w, ys)) / sw
    sxx = sum(wi * (x - mx) ** 2 for wi, x in zip(w, xs))
    b = sum(wi * (x - mx) * (y - my) for wi, x, y in zip(w, xs, ys)) / sxx
    error = (1 / sxx) ** 0.5
    if len(xs) < 3:
        return b, error, None
    chi2 = sum(wi * (y - my - b * (x - mx)) ** 2 for wi, x, y in zip(w, xs, ys)) / (len(xs) - 2)
    return b, error * max(1.0, chi2) ** 0.5, chi2


# z/R_d of the paper's profiles across the spout and the downcomers (Fig 4)
HEIGHTS = [5.873, 8.637, 11.400, 14.164, 16.927, 19.691, 22.454, 25.218]
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
