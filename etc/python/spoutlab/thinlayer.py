"""Thin-layer drying of shelled corn: the published thin-layer equation the
drying models are compared with, and the one calibration the project makes
from it.

Thompson, Peart and Foster (1968), "Mathematical simulation of corn drying
- a new model", Trans. ASAE 11(4) 582-586, fitted to thin layers of shelled
corn in heated air:

    t = A ln MR + B (ln MR)^2,  A = -1.862 + 0.00488 T,  B = 427.4 exp(-0.033 T)

t in hours, T the air temperature in degF, MR = (X - X_eq)/(X_0 - X_eq).

No Arrhenius fit of the effective diffusivity of whole corn kernels could be
read in a published source here (docs/RESULTS.md, drying), so the
kernel-diffusion model's D_0 and E_a are calibrated on Thompson's equation:
at each air temperature, the sphere at constant surface moisture (Crank's
series, the thin-layer limit of kernelDiffusion: kernel at the air's
temperature, negligible film resistance) is fitted to MR(t) over
MR 0.95 .. 0.1, and ln D against 1/T gives D_0 and E_a.  The fit is a
calibration, so the thin-layer comparison of the coupled runs then checks
the solver and the model's form, not the diffusivity.

    python3 -m spoutlab.thinlayer     # prints the fit (protocols/drying keeps it)
"""
import math

GAS_CONSTANT = 8.314462618   # J/(mol K), CODATA 2018
RADIUS = 4e-3                # the papers' 8 mm corn kernel [m]
FIT_TEMPERATURES_C = (40.0, 50.0, 60.0, 70.0, 80.0)


def _ab(T_C):
    T_F = 1.8 * T_C + 32.0
    return -1.862 + 0.00488 * T_F, 427.4 * math.exp(-0.033 * T_F)


def thompson_time(mr, T_C):
    """Drying time [s] to moisture ratio mr in (0, 1] at air temperature T [C]."""
    A, B = _ab(T_C)
    ln = math.log(mr)
    return 3600.0 * (A * ln + B * ln * ln)


def thompson_ratio(t, T_C):
    """Moisture ratio after t [s] at air temperature T [C]."""
    A, B = _ab(T_C)
    hours = t / 3600.0
    return math.exp((-A - math.sqrt(A * A + 4.0 * B * hours)) / (2.0 * B))


def crank_ratio(fourier, terms=200):
    """Mean moisture ratio of a sphere at constant surface moisture after
    the Fourier number D t/R^2 (Crank, The Mathematics of Diffusion, 6.20)."""
    if fourier <= 0:
        return 1.0
    return 6.0 / math.pi ** 2 * sum(math.exp(-(n * math.pi) ** 2 * fourier) / n ** 2
                                    for n in range(1, terms + 1))


def fitted_diffusivity(T_C, radius=RADIUS, points=60, curve=None):
    """D [m2/s] of the sphere whose MR(t) is nearest Thompson's at T (least
    squares in MR over MR 0.95 .. 0.1, equally spaced in MR), and the rms
    misfit in MR; curve(mr, T_C) -> t replaces Thompson's equation."""
    from scipy.optimize import minimize_scalar
    curve = curve or thompson_time
    ratios = [0.95 - k * (0.95 - 0.1) / (points - 1) for k in range(points)]
    times = [curve(mr, T_C) for mr in ratios]

    def misfit(log_d):
        d = math.exp(log_d)
        return sum((crank_ratio(d * t / radius ** 2) - mr) ** 2 for t, mr in zip(times, ratios))

    best = minimize_scalar(misfit, bounds=(math.log(1e-13), math.log(1e-8)), method='bounded',
                           options={'xatol': 1e-10})
    rms = math.sqrt(best.fun / points)
    return math.exp(best.x), rms


def arrhenius_fit(temperatures_C=FIT_TEMPERATURES_C, radius=RADIUS, curve=None):
    """(D_0 [m2/s], E_a [J/mol], worst relative D misfit, worst MR rms) of
    ln D = ln D_0 - E_a/(R T) over the fitted temperatures."""
    xs, ys, rms = [], [], 0.0
    for T in temperatures_C:
        d, r = fitted_diffusivity(T, radius, curve=curve)
        xs.append(1.0 / (T + 273.15))
        ys.append(math.log(d))
        rms = max(rms, r)
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    d0 = math.exp(my - slope * mx)
    ea = -slope * GAS_CONSTANT
    worst = max(abs(math.exp(math.log(d0) + slope * x - y) - 1.0) for x, y in zip(xs, ys))
    return d0, ea, worst, rms


def main():
    d0, ea, worst, rms = arrhenius_fit()
    print('kernel diffusivity fitted to Thompson et al. (1968), %g-%g C, sphere of R = %g mm:'
          % (FIT_TEMPERATURES_C[0], FIT_TEMPERATURES_C[-1], 1000 * RADIUS))
    print('  D0 = %.4g m2/s, Ea = %.5g J/mol; D within %.1f %% of each temperature\'s own fit,'
          ' MR within %.3f rms' % (d0, ea, 100 * worst, rms))
    for T in FIT_TEMPERATURES_C:
        print('  %g C: D = %.4g m2/s, t(MR 0.5) = %.3f h' % (T, d0 * math.exp(-ea / (GAS_CONSTANT * (T + 273.15))),
                                                          thompson_time(0.5, T) / 3600))


if __name__ == '__main__':
    main()
