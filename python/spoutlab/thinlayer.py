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
kernel-diffusion model's D_0 and E_a are calibrated on Thompson's equation,
two ways:
  - the idealised thin layer: the sphere at constant surface moisture
    (Crank's series: kernel at the air's temperature, no film) fitted to
    MR(t) over MR 0.95 .. 0.1 at each air temperature, ln D against 1/T;
  - the model as the solver runs it (the one the cases use): the kernel of
    openfoam_cases/singleKernel, heating from its initial temperature,
    cooled by evaporation, behind its film (spoutlab.kerneldrying), fitted
    over MR 0.95 .. 0.1 at 40, 60 and 80 C at once.
The first leaves the time to MR 0.5 of the coupled kernel 16-23 % longer
than Thompson's, as the heating it ignores slows the start; the second
7-13 %, what a Fickian sphere can do against the equation's shape.  A
calibration: the thin-layer comparison of the coupled runs then checks the
solver and the model's form, not the diffusivity.

    python3 -m spoutlab.thinlayer     # prints both fits (about a minute)
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


def singlekernel_conditions(case=None):
    """The kernels of openfoam_cases/singleKernel (system/singleKernelDict) in
    each air of its airTable: {T [C]: kerneldrying.Kernel}."""
    import os
    from spoutlab import foamfile, kerneldrying, moistair
    from spoutlab.spoutedbed import read_dict
    case = case or os.path.join(os.environ.get('SPOUTLAB_DIR', '../..'), 'openfoam_cases', 'singleKernel')
    path = os.path.join(case, 'system', 'singleKernelDict')
    v = read_dict(path, [])
    number = lambda key: float(v[key])
    d, rhop, X0, p = number('dp'), number('rhop'), number('X0'), number('pressure')
    model = v['heatTransferModel']
    eps = 1 - math.pi * d ** 3 / 6 / 0.3 ** 3          # the kernel in its 0.3 m cell
    kernels = {}
    for T, rho, mu, cp, kappa in foamfile.parse_value(v['airTable'], path, 'airTable'):
        gas = {'rho': rho, 'mu': mu, 'Cp': cp, 'kappa': kappa,
               'Dv': moistair.vapour_diffusivity(T + 273.15, p)}
        h, km = kerneldrying.film_coefficients(model, eps, number('velocity'), d, gas)
        kernels[T] = kerneldrying.Kernel(d, rhop * math.pi * d ** 3 / 6 / (1 + X0),
                                         number('kernelHeatCapacity'), X0, number('Tp0') + 273.15,
                                         T + 273.15, number('inletHumidityRatio'), p, h, km)
    return kernels


def kernel_fit(kernels, start, points=20, nodes=60, curve=None):
    """(D_0, E_a, rms misfit in MR) of the kernel-diffusion model as the
    solver runs it -- the kernel heating from T_0, cooled by evaporation,
    behind its film -- fitted to Thompson's MR(t) over MR 0.95 .. 0.1 at
    every temperature of `kernels` at once; start = (D_0, E_a);
    curve(mr, T_C) -> t replaces Thompson's equation."""
    from scipy.optimize import minimize
    curve = curve or thompson_time
    ratios = [0.95 - k * (0.95 - 0.1) / (points - 1) for k in range(points)]

    def misfit(x):
        d0, ea = math.exp(x[0]), 1e4 * x[1]
        total = 0.0
        for T_C, kernel in kernels.items():
            times = [curve(mr, T_C) for mr in ratios]
            X, _ = kernel.kernel_diffusion(d0, ea, times[-1], times, nodes=nodes)
            total += sum(((x - kernel.Xeq) / (kernel.X0 - kernel.Xeq) - mr) ** 2 for x, mr in zip(X, ratios))
        return total
    best = minimize(misfit, [math.log(start[0]), start[1] / 1e4], method='Nelder-Mead',
                    options={'xatol': 1e-5, 'fatol': 1e-12})
    return math.exp(best.x[0]), 1e4 * best.x[1], math.sqrt(best.fun / (points * len(kernels)))


def main():
    d0, ea, worst, rms = arrhenius_fit()
    print('kernel diffusivity fitted to Thompson et al. (1968), %g-%g C, sphere of R = %g mm:'
          % (FIT_TEMPERATURES_C[0], FIT_TEMPERATURES_C[-1], 1000 * RADIUS))
    print('  D0 = %.4g m2/s, Ea = %.5g J/mol; D within %.1f %% of each temperature\'s own fit,'
          ' MR within %.3f rms' % (d0, ea, 100 * worst, rms))
    for T in FIT_TEMPERATURES_C:
        print('  %g C: D = %.4g m2/s, t(MR 0.5) = %.3f h' % (T, d0 * math.exp(-ea / (GAS_CONSTANT * (T + 273.15))),
                                                          thompson_time(0.5, T) / 3600))
    kernels = singlekernel_conditions()
    d0, ea, rms = kernel_fit(kernels, (d0, ea))
    print('the model as the solver runs it (openfoam_cases/singleKernel: the kernel heating from '
          'its initial temperature, evaporative cooling, the film), fitted at %s C:'
          % ', '.join('%g' % T for T in kernels))
    print('  D0 = %.4g m2/s, Ea = %.5g J/mol, MR within %.3f rms' % (d0, ea, rms))


if __name__ == '__main__':
    main()
