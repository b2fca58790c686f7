#include "KernelDiffusion.hpp"

#include "Arrhenius.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spoutlab
{

// selected by "dryingModel kernelDiffusion;"
const Registration<DryingModel, KernelDiffusion> registeredKernelDiffusion("kernelDiffusion");

// The surface film over a step, in the units of the shell equations (moisture
// per unit of the dimensionless time D_eff t/R^2): the flux through the film
// is kappa (a_w(X_s) rho_v,sat - rho_v,inf), kappa = k_m A R^2/(m_d D_eff).
struct KernelDiffusion::Surface
{
    double kappa;
    double saturatedVapour; // rho_v,sat(T_p)
    double farVapour;       // rho_v,inf
    double temperature;     // T_p
};

namespace
{

long requireShells(const Parameters& props)
{
    const long n = props.getInteger("nShells", 15);
    if (n < 2 || n > KernelDiffusion::kMaxShells)
    {
        throw props.badValue("nShells", "a number of shells from 2 to 200");
    }
    return n;
}

} // namespace

KernelDiffusion::KernelDiffusion(const Parameters& props)
    : DryingModel(isothermOf(props)), d0_(props.getScalar("D0")),
      activationEnergy_(props.getScalar("activationEnergy"))
{
    if (!(d0_ > 0.0)) throw props.badValue("D0", "a diffusivity > 0 in m^2/s");
    if (!(activationEnergy_ >= 0.0)) throw props.badValue("activationEnergy", "an energy >= 0 in J/mol");
    const long n = requireShells(props);
    // faces s_i = r_i/R, volume fractions and volume centroids of the shells
    std::vector<double> face(n + 1), centroid(n);
    for (long i = 0; i <= n; ++i)
    {
        const double u = 1.0 - static_cast<double>(i) / n;
        face[i] = 1.0 - u * u;
    }
    weights_.resize(n);
    for (long i = 0; i < n; ++i)
    {
        const double a = face[i], b = face[i + 1];
        weights_[i] = b * b * b - a * a * a;
        centroid[i] = 0.75 * (b * b * b * b - a * a * a * a) / weights_[i];
    }
    // flux 4 pi r^2 D rho_d dX/dr in units of m_d D/R^2: 3 s_f^2 / (distance of the nodes)
    conductance_.assign(n + 1, 0.0);
    for (long f = 1; f < n; ++f) conductance_[f] = 3.0 * face[f] * face[f] / (centroid[f] - centroid[f - 1]);
    conductance_[n] = 3.0 / (1.0 - centroid[n - 1]);
}

double KernelDiffusion::diffusivity(double temperature) const
{
    // D_0 exp(-E_a/(R T)): the Arrhenius law about an infinite reference temperature
    return arrhenius(d0_, activationEnergy_, temperature, std::numeric_limits<double>::infinity());
}

void KernelDiffusion::initialise(double moisture, double* state) const
{
    std::fill(state, state + stateSize(), moisture);
}

// X_s with the outer shell at P + Q j and j = g_s (Y_N-1 - X_s): eliminating
// Y_N-1 gives j = G (P - X_s), G = g_s/(1 - g_s Q) (Q <= 0), and the film
// condition kappa (a_w(X_s) rho_sat - rho_inf) = G (P - X_s), which rises with
// X_s: one root, in [0, P + kappa rho_inf/G]. Solved for the drop
// u = P - X_s across the outer half-shell (j = G u without cancellation):
// Newton from the guess (the last step's X_s, whose a_w the caller has
// already evaluated: atGuess), which in a coupling step is within a step's
// change of the root and converges in two evaluations; should an iterate
// leave the bracket or not settle, the bracketed iteration in X_s.
double KernelDiffusion::surfaceMoisture(const Surface& s, double p, double q, double guess,
                                        SorptionIsotherm::Activity atGuess, double& drop) const
{
    drop = 0.0;
    if (s.kappa == 0.0) return p; // no film: no flux, X_s = the outer shell's
    const double gs = conductance_.back();
    const double g = gs / (1.0 - gs * q);
    const SorptionIsotherm& iso = isotherm();
    const double lowest = -s.kappa * s.farVapour / g; // u at X_s = P + kappa rho_inf/G
    double u = p - guess, last = 0.0;
    SorptionIsotherm::Activity a = atGuess;
    for (int k = 0; k < 8 && u > lowest && u < p; ++k)
    {
        if (k > 0) a = iso.activity(p - u, s.temperature);
        const double f = g * u - s.kappa * (a.value * s.saturatedVapour - s.farVapour);
        const double du = f / (g + s.kappa * s.saturatedVapour * a.derivative);
        u -= du;
        // Converged when this step is at round-off, or when it is so far
        // below the last that the convergence is quadratic (the slope is
        // exact) and the error it leaves, about |du| (du/last)^2, is below
        // round-off: from the last step's X_s, two evaluations.
        const double scale = 1e-16 * (std::fabs(u) + std::fabs(p - u));
        const double ratio = k > 0 ? du / last : 1.0;
        last = du;
        const bool quadratic = std::fabs(ratio) < 1e-3 && std::fabs(du) * ratio * ratio < scale;
        if (!quadratic && std::fabs(du) > 1e-14 * std::fabs(u) + 1e-15 * std::fabs(p - u)) continue;
        if (!(u > lowest && u < p)) break;
        drop = u;
        return p - u;
    }
    auto film = [&](double x) {
        return s.kappa * (iso.waterActivity(x, s.temperature) * s.saturatedVapour - s.farVapour)
               - g * (p - x);
    };
    auto slope = [&](double x) {
        return s.kappa * s.saturatedVapour * iso.waterActivityDerivative(x, s.temperature) + g;
    };
    const double hi = p - lowest;
    double x = 0.0; // a bone-dry surface: the water limits the flux
    if (hi > 0.0 && film(0.0) < 0.0) x = increasingRoot(film, slope, 0.0, hi, guess);
    drop = p - x;
    return x;
}

// One backward-Euler step of D_eff dt/R^2 = dTau; returns X_s. The shells'
// equations (w_i/dTau + g_i + g_i+1) Y_i - g_i Y_i-1 - g_i+1 Y_i+1 = w_i/dTau X_i,
// the outer one less the surface flux j, are eliminated once from the centre
// out (Thomas): the outer shell is then Y_N-1 = P + Q j, Q = -1/(its pivot).
// With X_s and j known, the back substitution from Y_N-1 inwards gives the
// shells (the same as solving for the two right-hand sides P and Q apart).
double KernelDiffusion::subStep(const Surface& s, double* shells, double dTau, double surfaceGuess,
                                SorptionIsotherm::Activity atGuess) const
{
    const int n = static_cast<int>(weights_.size());
    const double* w = weights_.data();
    const double* g = conductance_.data(); // g[0] = 0: no flux at the centre
    const double perTau = 1.0 / dTau;
    double upper[kMaxShells];   // the eliminated upper diagonal -g_i+1/pivot_i
    double reduced[kMaxShells]; // the eliminated right-hand side
    double pivot = w[0] * perTau + g[1];
    double previous = w[0] * perTau * shells[0] / pivot;
    reduced[0] = previous;
    for (int i = 1; i < n; ++i)
    {
        upper[i - 1] = -g[i] / pivot;
        pivot = w[i] * perTau + g[i] + (i + 1 < n ? g[i + 1] : 0.0) + g[i] * upper[i - 1];
        previous = (w[i] * perTau * shells[i] + g[i] * previous) / pivot;
        reduced[i] = previous;
    }
    const double q = -1.0 / pivot, p = reduced[n - 1];
    double drop;
    const double surface = surfaceMoisture(s, p, q, surfaceGuess, atGuess, drop);
    const double gs = g[n];
    const double j = gs / (1.0 - gs * q) * drop;
    shells[n - 1] = p + q * j;
    for (int i = n - 1; i-- > 0;) shells[i] = reduced[i] - upper[i] * shells[i + 1];
    return surface;
}

namespace
{

// d: D_eff at the kernel's temperature
KernelDiffusion::Surface surfaceOf(const Kernel& kernel, const MoistAir& air, double massTransferCoefficient,
                                   double d)
{
    const double radius = 0.5 * kernel.diameter;
    return {massTransferCoefficient * surfaceArea(kernel) * radius * radius / (kernel.dryMass * d),
            saturationVapourDensity(kernel.temperature), vapourDensity(air), kernel.temperature};
}

} // namespace

double KernelDiffusion::rate(const Kernel& kernel, double, const double* state, const MoistAir& air,
                             double massTransferCoefficient) const
{
    const int n = shells();
    const double d = diffusivity(kernel.temperature);
    const Surface s = surfaceOf(kernel, air, massTransferCoefficient, d);
    // the outer shell as it is (Q = 0): j = g_s (X_N-1 - X_s)
    double drop;
    surfaceMoisture(s, state[n - 1], 0.0, state[n], isotherm().activity(state[n], kernel.temperature), drop);
    const double j = conductance_.back() * drop;
    const double radius = 0.5 * kernel.diameter;
    return j * kernel.dryMass * d / (radius * radius);
}

double KernelDiffusion::advance(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                                double massTransferCoefficient, double dt) const
{
    return step(kernel, moisture, state, air, massTransferCoefficient, dt, nullptr);
}

double KernelDiffusion::advanceWithLatentHeat(const Kernel& kernel, double& moisture, double* state,
                                              const MoistAir& air, double massTransferCoefficient, double dt,
                                              double& latentHeat) const
{
    return step(kernel, moisture, state, air, massTransferCoefficient, dt, &latentHeat);
}

double KernelDiffusion::step(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                             double massTransferCoefficient, double dt, double* latentHeat) const
{
    checkStep(moisture, massTransferCoefficient, dt);
    const int n = shells();
    const double old = moisture;
    const double radius = 0.5 * kernel.diameter;
    const double d = diffusivity(kernel.temperature);
    const double tau = d * dt / (radius * radius);
    const Surface s = surfaceOf(kernel, air, massTransferCoefficient, d);
    // the isotherm at the surface as the step finds it: the latent heat and
    // the surface root's first iterate
    SorptionIsotherm::Activity atSurface = isotherm().activity(state[n], kernel.temperature);
    if (latentHeat) *latentHeat = SorptionIsotherm::latentHeat(kernel.temperature, atSurface);
    const long steps = static_cast<long>(std::ceil(tau / kMaxStep));
    for (long k = 0; k < steps; ++k)
    {
        if (k > 0) atSurface = isotherm().activity(state[n], kernel.temperature);
        state[n] = subStep(s, state, tau / steps, state[n], atSurface);
    }
    if (steps == 0) return 0.0;
    double mean = 0.0;
    for (int i = 0; i < n; ++i) mean += weights_[i] * state[i];
    moisture = mean;
    return kernel.dryMass * (old - moisture);
}

double KernelDiffusion::latentHeat(const Kernel& kernel, double, const double* state) const
{
    return isotherm().latentHeat(state[shells()], kernel.temperature);
}

} // namespace spoutlab
