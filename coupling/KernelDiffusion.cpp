#include "KernelDiffusion.hpp"

#include "Arrhenius.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

// Eigenvalues and orthonormal eigenvectors of the symmetric n x n matrix a
// (row-major, destroyed) by cyclic Jacobi rotations; vectors[k n + i] is
// component i of vector k. An off-diagonal entry is dropped once it is below
// round-off of the geometric mean of its two diagonal entries, which keeps
// the small eigenvalues of a graded matrix to their relative precision.
void symmetricEigen(std::vector<double> a, int n, std::vector<double>& values, std::vector<double>& vectors)
{
    vectors.assign(static_cast<std::size_t>(n) * n, 0.0);
    for (int i = 0; i < n; ++i) vectors[i * n + i] = 1.0;
    auto at = [&](int i, int j) -> double& { return a[static_cast<std::size_t>(i) * n + j]; };
    for (int sweep = 0; sweep < 100; ++sweep)
    {
        bool rotated = false;
        for (int p = 0; p < n; ++p)
        {
            for (int q = p + 1; q < n; ++q)
            {
                const double apq = at(p, q);
                if (std::fabs(apq) <= 1e-17 * std::sqrt(std::fabs(at(p, p) * at(q, q))))
                {
                    at(p, q) = at(q, p) = 0.0;
                    continue;
                }
                rotated = true;
                const double theta = (at(q, q) - at(p, p)) / (2.0 * apq);
                const double t =
                    (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), sn = t * c;
                for (int k = 0; k < n; ++k) // columns p and q
                {
                    const double kp = at(k, p), kq = at(k, q);
                    at(k, p) = c * kp - sn * kq;
                    at(k, q) = sn * kp + c * kq;
                }
                for (int k = 0; k < n; ++k) // rows p and q
                {
                    const double pk = at(p, k), qk = at(q, k);
                    at(p, k) = c * pk - sn * qk;
                    at(q, k) = sn * pk + c * qk;
                }
                for (int k = 0; k < n; ++k)
                {
                    double& vp = vectors[static_cast<std::size_t>(p) * n + k];
                    double& vq = vectors[static_cast<std::size_t>(q) * n + k];
                    const double op = vp, oq = vq;
                    vp = c * op - sn * oq;
                    vq = sn * op + c * oq;
                }
            }
        }
        if (!rotated) break;
    }
    values.resize(n);
    for (int i = 0; i < n; ++i) values[i] = at(i, i);
}

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
    const long blocks = props.getInteger("kernelSteps", 1);
    if (blocks < 1 || blocks > 1000)
        throw props.badValue("kernelSteps", "a number of coupling steps from 1 to 1000");
    kernelSteps_ = static_cast<int>(blocks);
    offset_ = kernelSteps_ > 1 ? 2 : 0;
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
    modes(static_cast<int>(n));
}

// The shells' equations without the surface, W dY/dtau = -K Y (W = diag w_i,
// K the conductances' symmetric Laplacian, K 1 = 0), decouple in the modes
// K v_k = lambda_k W v_k, v_k' W v_l = delta_kl: from the eigenvectors u_k of
// S = W^-1/2 K W^-1/2, v_k = W^-1/2 u_k. Mode 0 is the uniform v_0 = 1 at
// lambda_0 = 0, set exactly (its amplitude is the mean moisture), the others
// made orthogonal to it.
void KernelDiffusion::modes(int n)
{
    const std::vector<double>& w = weights_;
    const std::vector<double>& g = conductance_;
    std::vector<double> sym(static_cast<std::size_t>(n) * n, 0.0);
    for (int i = 0; i < n; ++i)
    {
        sym[i * n + i] = (g[i] + (i + 1 < n ? g[i + 1] : 0.0)) / w[i];
        if (i > 0) sym[i * n + i - 1] = sym[(i - 1) * n + i] = -g[i] / std::sqrt(w[i] * w[i - 1]);
    }
    std::vector<double> values, vectors;
    symmetricEigen(sym, n, values, vectors);
    std::vector<int> order(n);
    for (int k = 0; k < n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
    double norm = 0.0;
    for (int i = 0; i < n; ++i) norm += w[i];
    lambda_.assign(n, 0.0);
    modes_.assign(static_cast<std::size_t>(n) * n, 0.0);
    for (int i = 0; i < n; ++i) modes_[i] = 1.0; // v_0 (sum w_i = 1 to round-off)
    std::vector<double> v(n);
    for (int k = 1; k < n; ++k)
    {
        const double* u = &vectors[static_cast<std::size_t>(order[k]) * n];
        double along = 0.0, length = 0.0;
        for (int i = 0; i < n; ++i) along += u[i] * std::sqrt(w[i] / norm);
        for (int i = 0; i < n; ++i)
        {
            v[i] = u[i] - along * std::sqrt(w[i] / norm);
            length += v[i] * v[i];
        }
        for (int i = 0; i < n; ++i) modes_[k * n + i] = v[i] / std::sqrt(length * w[i]);
        lambda_[k] = values[order[k]];
    }
    outer_.resize(n);
    outerSquared_.resize(n);
    for (int k = 0; k < n; ++k)
    {
        outer_[k] = modes_[k * n + n - 1];
        outerSquared_[k] = outer_[k] * outer_[k];
    }
}

void KernelDiffusion::shellMoistures(const double* full, double* shells) const
{
    const double* state = full + offset_;
    const int n = this->shells();
    for (int i = 0; i < n; ++i)
    {
        double x = 0.0;
        for (int k = 0; k < n; ++k) x += state[k] * modes_[k * n + i];
        shells[i] = x;
    }
}

double KernelDiffusion::diffusivity(double temperature) const
{
    // D_0 exp(-E_a/(R T)): the Arrhenius law about an infinite reference temperature
    return arrhenius(d0_, activationEnergy_, temperature, std::numeric_limits<double>::infinity());
}

void KernelDiffusion::initialise(double moisture, double* state) const
{
    // uniform: mode 0 alone
    std::fill(state, state + stateSize(), 0.0); // and no block under way
    state[offset_] = moisture;
    state[offset_ + shells()] = moisture;
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

// One backward-Euler step of D_eff dt/R^2 = dTau of the mode amplitudes a_k
// (decay_k = 1/(1 + dTau lambda_k)); returns X_s. With the surface flux j
// leaving the outer shell, (W/dTau + K) Y = W X/dTau - j e_N-1 gives per mode
//   a_k' = (a_k - dTau j v_k,N-1) decay_k
// and the outer shell Y_N-1 = sum a_k' v_k,N-1 = P + Q j,
//   P = sum a_k v_k,N-1 decay_k,   Q = -dTau sum v_k,N-1^2 decay_k.
// The mean moisture a_0 loses dTau j exactly (v_0 = 1, lambda_0 = 0).
double KernelDiffusion::subStep(const Surface& s, double* amplitude, double dTau, const double* decay,
                                double surfaceGuess, SorptionIsotherm::Activity atGuess) const
{
    const int n = shells();
    double p = 0.0, q = 0.0;
    for (int k = 0; k < n; ++k)
    {
        p += amplitude[k] * outer_[k] * decay[k];
        q += outerSquared_[k] * decay[k];
    }
    q *= -dTau;
    double drop;
    const double surface = surfaceMoisture(s, p, q, surfaceGuess, atGuess, drop);
    const double gs = conductance_.back();
    const double flux = dTau * (gs / (1.0 - gs * q) * drop);
    amplitude[0] -= flux;
    for (int k = 1; k < n; ++k) amplitude[k] = (amplitude[k] - flux * outer_[k]) * decay[k];
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

double KernelDiffusion::rate(const Kernel& kernel, double, const double* full, const MoistAir& air,
                             double massTransferCoefficient) const
{
    const double* state = full + offset_;
    const int n = shells();
    const double d = diffusivity(kernel.temperature);
    const Surface s = surfaceOf(kernel, air, massTransferCoefficient, d);
    // the outer shell as it is (Q = 0): j = g_s (X_N-1 - X_s)
    double outer = 0.0, drop;
    for (int k = 0; k < n; ++k) outer += state[k] * outer_[k];
    surfaceMoisture(s, outer, 0.0, state[n], isotherm().activity(state[n], kernel.temperature), drop);
    const double j = conductance_.back() * drop;
    const double radius = 0.5 * kernel.diameter;
    return j * kernel.dryMass * d / (radius * radius);
}

double KernelDiffusion::advance(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                                double massTransferCoefficient, double dt) const
{
    double latent;
    return advanceWithLatentHeat(kernel, moisture, state, air, massTransferCoefficient, dt, latent);
}

double KernelDiffusion::advanceWithLatentHeat(const Kernel& kernel, double& moisture, double* state,
                                              const MoistAir& air, double massTransferCoefficient, double dt,
                                              double& latentHeat) const
{
    if (kernelSteps_ == 1)
        return step(kernel, moisture, state, air, massTransferCoefficient, dt, &latentHeat);
    checkStep(moisture, massTransferCoefficient, dt);
    // state: the calls left in the block, its latent heat, then the kernel
    if (state[0] == 0.0)
    {
        // a block starts: the kernel over kernelSteps steps of this dt, its
        // water then released in equal shares (the last lands X on a_0)
        double x = moisture;
        step(kernel, x, state + 2, air, massTransferCoefficient, kernelSteps_ * dt, &state[1]);
        state[0] = kernelSteps_;
        return nextShare(kernel.dryMass, moisture, state, latentHeat);
    }
    return release(kernel.dryMass, moisture, state, latentHeat);
}

double KernelDiffusion::release(double dryMass, double& moisture, double* state, double& latentHeat) const
{
    if (kernelSteps_ == 1) return DryingModel::release(dryMass, moisture, state, latentHeat);
    const double left = state[0];
    if (!(left >= 1.0 && left < kernelSteps_ && left == std::floor(left)))
    {
        throw std::domain_error("dryingModel kernelDiffusion: expected a particle state whose first value "
                                "is the calls left in a block of kernelSteps "
                                + std::to_string(kernelSteps_) + ", got " + std::to_string(left)
                                + " (a state of another layout, such as a restart written before "
                                  "the block's values came first)");
    }
    return nextShare(dryMass, moisture, state, latentHeat);
}

// The block's next equal share of its water (the last lands X on a_0).
double KernelDiffusion::nextShare(double dryMass, double& moisture, double* state, double& latentHeat) const
{
    double& left = state[0];
    latentHeat = state[1];
    const double old = moisture;
    moisture = left == 1.0 ? state[2] : moisture - (moisture - state[2]) / left;
    left -= 1.0;
    return dryMass * (old - moisture);
}

double KernelDiffusion::step(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                             double massTransferCoefficient, double dt, double* latentHeat) const
{
    checkStep(moisture, massTransferCoefficient, dt);
    const int n = shells();
    if (state[0] != moisture)
    {
        // the mean moisture is the uniform mode's amplitude, kept equal to X
        throw std::domain_error("dryingModel kernelDiffusion: expected a particle state whose first value "
                                "is its moisture X = "
                                + std::to_string(moisture) + ", got " + std::to_string(state[0])
                                + " (a state of another layout, such as the shell moistures of a "
                                  "restart written before the state held the shells' modes)");
    }
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
    if (steps == 0) return 0.0;
    const double dTau = tau / steps;
    double decay[kMaxShells];
    for (int k = 0; k < n; ++k) decay[k] = 1.0 / (1.0 + dTau * lambda_[k]);
    for (long k = 0; k < steps; ++k)
    {
        if (k > 0) atSurface = isotherm().activity(state[n], kernel.temperature);
        state[n] = subStep(s, state, dTau, decay, state[n], atSurface);
    }
    moisture = state[0];
    return kernel.dryMass * (old - moisture);
}

double KernelDiffusion::latentHeat(const Kernel& kernel, double, const double* state) const
{
    // within a block, the block's (taken at its start)
    if (kernelSteps_ > 1 && state[0] > 0.0) return state[1];
    return isotherm().latentHeat(state[offset_ + shells()], kernel.temperature);
}

} // namespace spoutlab
