"""The circulation rate W_s (draft-plate paper eq 14) as a time series: the
solid flux summed over the downcomers' cells of W_s's row (the cellZone
downcomerBase, spoutedbed.Geometry.circulation_row) every step by the
function object downcomerFlux of system/controlDict, and the standard error
of its mean over the averaging window by block averaging.

  series(case, g)              (times, W_s [kg/s]) of every step written
  block_standard_error(t, y, start, block)
                               the mean over t > start and its standard
                               error from blocks of `block` seconds

W_s(t) = -rho_p A_cell sum_cells (solid flux)_z, A_cell = dx Lb the cells'
horizontal face: the same cells and formula as evaluate's W_s from the
time-averaged flux, so the series' mean over the window is that W_s (the
reduced bed's agree to 10 digits).

Block averaging: successive samples of W_s are correlated (a slug, a
surge of the downcomers lasts tenths of a second), so the samples' own
spread over sqrt(n) underestimates the error of their mean. The means of
blocks much longer than that correlation time are nearly independent, and
their spread over sqrt(number of blocks) is the mean's standard error
(Flyvbjerg and Petersen, J. Chem. Phys. 1989).
"""
import math

from spoutlab import casefiles as sc

FUNCTION_OBJECT = 'downcomerFlux'
BLOCK = 1.0     # s: several circulation surges per block (W_s's correlation time is tenths of a second)


def series(case, g):
    """(times, W_s [kg/s]) of every step downcomerFlux wrote, or None if it
    wrote nothing (a run from before it existed)."""
    try:
        _, rows = sc.read_function_object(case, FUNCTION_OBJECT, 'volFieldValue.dat')
    except FileNotFoundError:
        return None
    if not rows:
        return None
    area = g.dx * g.Lb * 1e-6
    rho_p = g.particles['rhop']
    return [r[0] for r in rows], [-rho_p * area * r[3] for r in rows]


def block_standard_error(t, y, start, block=BLOCK):
    """(mean of y over t >= start, its standard error, number of blocks):
    the window, from the step at start on as OpenFOAM's fieldAverage takes
    it, cut into whole blocks of `block` seconds (a last, shorter piece is
    left out of the error, not of the mean); the error is the blocks'
    means' sample standard deviation over sqrt(blocks), None with fewer
    than two blocks."""
    window = [(ti, yi) for ti, yi in zip(t, y) if ti > start - 1e-9]
    if not window:
        return None, None, 0
    mean = sum(yi for _, yi in window) / len(window)
    blocks = {}
    for ti, yi in window:
        k = max(0, int(math.floor((ti - start) / block - 1e-9)))
        blocks.setdefault(k, []).append(yi)
    whole = int(math.floor((window[-1][0] - start) / block + 1e-9))
    means = [sum(blocks[k]) / len(blocks[k]) for k in range(whole) if k in blocks]
    if len(means) < 2:
        return mean, None, len(means)
    m = sum(means) / len(means)
    sd = math.sqrt(sum((x - m) ** 2 for x in means) / (len(means) - 1))
    return mean, sd / math.sqrt(len(means)), len(means)
