#pragma once
// Liquid diffusion in the kernel, the classic falling-rate model of cereal
// grains: Fick's law in a sphere of radius R = d/2 at uniform temperature,
//   dX/dt = r^-2 d/dr (r^2 D_eff(T_p) dX/dr),   dX/dr = 0 at r = 0,
//   D_eff(T) = D_0 exp(-E_a/(R T))             (Arrhenius)
// and at the surface the flux the water carries to r = R leaves through the
// gas film, the surface vapour in equilibrium with the surface moisture X_s:
//   -rho_d D_eff dX/dr |_R A = k_m A (a_w(X_s, T_p) rho_v,sat(T_p) - rho_v,inf)
// (a_w from the isotherm, rho_d the kernel's dry density). With a negligible
// film resistance this is the classical X_s = X_eq at the air's vapour
// pressure; with k_m = 0 nothing leaves.
//
// Discretisation: N shells of dry mass m_d w_i, face radii
// r_i = R (1 - (1 - i/N)^2) (thin shells at the surface, where the early
// gradients are, wider ones inside), finite volumes with the shells' volume
// centroids as nodes, backward Euler in time. The shells' linear equations
// are solved in their diffusion modes (K v_k = lambda_k W v_k, computed once
// per model; KernelDiffusion.cpp), in which a backward-Euler step is one
// division per mode: the outer shell is P + Q j in the surface flux j, and
// the one nonlinear equation left, for X_s, is solved by Newton from the last
// step's X_s (two isotherm evaluations per coupling step; it is monotone in
// X_s: a unique root, bracketed where Newton would leave it). The same
// discrete equations as a tridiagonal solve of the shells, to round-off
// (the shells agree to 1e-13 after 300 bed-like steps), without its chain of
// dependent divisions. The scheme is an M-matrix: stable and monotone for any
// dt, X >= min(X, X_s) >= 0; a step longer than D_eff dt/R^2 = 5e-5 is cut
// into equal sub-steps so that long steps (a drying-time predictor's minutes)
// are as accurate as short ones; water is conserved to round-off (the mean
// moisture, the uniform mode's amplitude, loses exactly what crosses the
// surface). Against Crank's series for a sphere at constant surface moisture
// the mean X and the moisture ratio agree within 0.5 % down to 10 % of the
// way to X_eq from N = 13 shells on (0.46 %; 12 give 0.53 %, 10 0.75 %); the
// default 15 gives 0.36 %, 20 0.22 %, whether the steps are a minute or ten
// (unit.KernelDiffusion.MatchesCranksSeriesAtConstantSurfaceMoisture).
//
// State: the N mode amplitudes a_k (a_0 the mean moisture X, the shells
// X_i = sum_k a_k v_k,i: shellMoistures()), then X_s (stateSize() = N + 1);
// with kernelSteps M > 1 first the calls left in the block and its latent
// heat, then the amplitudes and X_s (N + 3): a step inside a block reads
// and writes only the row's first three values (the calls left, the latent
// heat, a_0), one cache line of it in three rows of four, and needs no gas
// (needsGas). A row of the layout before (the block's values last) stops
// the run with one line (its first value, X, is not a whole number of calls).
// Latent heat: the grain's at the surface moisture X_s.
//
// Parameters:
//   D0                 D_0 [m^2/s], > 0 (required)
//   activationEnergy   E_a [J/mol], >= 0 (required)
//     No Arrhenius fit of D_eff for shelled corn could be checked against its
//     source here, so there are no defaults: give a published fit for the
//     kernels of the case and cite it beside the case.
//   nShells            N, 2..200, default 15
//   kernelSteps        M, 1..1000, default 1: the kernel (shells, surface,
//     latent heat) advanced once per M calls over M dt, with the gas, k_m
//     and T_p of the first, and its water released over the M calls in
//     equal shares (the last lands X on the kernel's mean again), at the
//     latent heat of the block's start. An approximation for coupling steps
//     far shorter than the times over which a particle's surroundings
//     change: it holds them for M dt. Conservative step by step and over a
//     block; the block's progress is part of the state (stateSize() =
//     N + 3), so a restart continues it exactly. In the spouted bed (3e-4 s
//     steps, M = 10: 3 ms) a kernel crossing between spout and downcomer
//     every 0.1 s loses within 1e-3 of the resolved kernel's water from 1 s
//     on and 2.5e-4 after 20 s (unit.KernelDiffusion.KernelStepsFollow...).
//   isotherm           modifiedHenderson (default) | modifiedChungPfost

#include "DryingModel.hpp"

#include <vector>

namespace spoutlab
{

class KernelDiffusion : public DryingModel
{
public:
    explicit KernelDiffusion(const Parameters& props);

    int stateSize() const override { return static_cast<int>(weights_.size()) + (kernelSteps_ > 1 ? 3 : 1); }
    void initialise(double moisture, double* state) const override;
    double rate(const Kernel& kernel, double moisture, const double* state, const MoistAir& air,
                double massTransferCoefficient) const override;
    double advance(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                   double massTransferCoefficient, double dt) const override;
    double advanceWithLatentHeat(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                                 double massTransferCoefficient, double dt,
                                 double& latentHeat) const override;
    double latentHeat(const Kernel& kernel, double moisture, const double* state) const override;
    // false inside a kernelSteps block (its kernel already advanced)
    bool needsGas(const double* state) const override { return kernelSteps_ == 1 || state[0] == 0.0; }
    // a step inside a block: the next of its equal shares of water
    double release(double dryMass, double& moisture, double* state, double& latentHeat) const override;
    std::string name() const override { return "kernelDiffusion"; }
    // The mean moisture a_0 held in a state (X at the end of a block).
    double meanMoisture(const double* state) const { return state[offset_]; }

    // D_eff(T) [m^2/s].
    double diffusivity(double temperature) const;
    int shells() const { return static_cast<int>(weights_.size()); }
    // Dry-mass fraction of shell i (they sum to 1).
    double weight(int i) const { return weights_[i]; }
    // The N shell moistures of a state, from the centre out.
    void shellMoistures(const double* state, double* shells) const;
    // lambda_k, mode k's decay rate in D_eff t/R^2 (0 for the mean, k = 0).
    double decayRate(int k) const { return lambda_[k]; }
    // Largest D_eff dt/R^2 of one backward-Euler sub-step.
    static constexpr double kMaxStep = 5e-5;
    // Coupling steps per step of the kernel (kernelSteps).
    int kernelSteps() const { return kernelSteps_; }
    // Most shells (nShells).
    static constexpr int kMaxShells = 200;

    struct Surface; // what a step holds fixed at the surface (KernelDiffusion.cpp)

private:
    // X_s with the outer shell's moisture given as P + Q j, and the drop
    // P - X_s (the surface flux j is G times it, KernelDiffusion.cpp);
    // atGuess: the isotherm at X_s = guess.
    double surfaceMoisture(const Surface& s, double p, double q, double guess,
                           SorptionIsotherm::Activity atGuess, double& drop) const;
    double subStep(const Surface& s, double* amplitude, double dTau, const double* decay, double surfaceGuess,
                   SorptionIsotherm::Activity atGuess) const;
    void modes(int n);
    // release() without its check of the block's count (also at a block's start)
    double nextShare(double dryMass, double& moisture, double* state, double& latentHeat) const;
    // advance(), and with latentHeat non-null the latent heat before it
    double step(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                double massTransferCoefficient, double dt, double* latentHeat) const;

    double d0_;
    double activationEnergy_;
    int kernelSteps_ = 1;              // coupling steps per kernel step (kernelSteps)
    int offset_ = 0;                   // where the amplitudes start in a state (2 with blocks)
    std::vector<double> weights_;      // w_i, dry-mass fraction of shell i
    std::vector<double> conductance_;  // g_f of face f (1..N-1) and g_s of the surface (index N), per unit R
    std::vector<double> lambda_;       // lambda_k, the modes' decay rates in tau, lambda_0 = 0
    std::vector<double> modes_;        // v_k,i (k n + i), v_0 = 1
    std::vector<double> outer_;        // v_k,N-1, the outer shell's
    std::vector<double> outerSquared_; // v_k,N-1^2
};

} // namespace spoutlab
