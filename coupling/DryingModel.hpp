#pragma once
// Drying of one grain kernel in moist air: how fast it loses water, and its
// advance over a time step with the gas, the kernel temperature and the
// mass-transfer coefficient held for the step (the coupling's explicit
// exchange, docs/DESIGN.md §3.8).
//
// Every model is a gas-film law for the vapour leaving the kernel's surface,
//   m_dot = k_m A (rho_v,s - rho_v,inf)   [kg/s, > 0 evaporating],  A = pi d^2
// and differs in the surface vapour density rho_v,s: saturated at T_p
// (freeWater), reduced by a relative activation energy (reactionEngineering),
// or in equilibrium with the surface moisture of a kernel resolved in radial
// shells (kernelDiffusion). k_m is the Sherwood form of the cell's heat
// correlation (HeatTransferModel::massTransferCoefficient).
//
// A model holds only its parameters. The per-particle state is the mean
// moisture X [kg water / kg dry solid] plus stateSize() more doubles, which the
// caller stores per particle, fills with initialise() and hands back every
// step. advance() moves X (and the state) over dt and returns the water that
// left, exactly m_dry (X_old - X_new), for the gas to receive; it keeps X >= 0
// and is stable for any dt >= 0 (implicit where the law is stiff).
//
// Run-time selection by name, the couplingProperties entry "dryingModel",
// with settings in "<name>Props".

#include "ModelRegistry.hpp"
#include "MoistAir.hpp"
#include "Parameters.hpp"
#include "SorptionIsotherm.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace spoutlab
{

// What a drying model sees of one particle.
struct Kernel
{
    double diameter;    // d [m]
    double dryMass;     // m_d [kg], constant while drying
    double temperature; // T_p [K], held over a step
};

// Surface area of the kernel, pi d^2 [m^2].
double surfaceArea(const Kernel& kernel);

class DryingModel
{
public:
    virtual ~DryingModel();

    // Doubles of per-particle state beyond X (0 unless the model says so).
    virtual int stateSize() const;

    // The state of a kernel at uniform moisture X0.
    virtual void initialise(double moisture, double* state) const;

    // Drying rate m_dot [kg/s] (> 0 evaporating, < 0 condensing) now.
    virtual double rate(const Kernel& kernel, double moisture, const double* state, const MoistAir& air,
                        double massTransferCoefficient) const = 0;

    // Advance the kernel over dt [s]; updates X and the state, returns the
    // water evaporated [kg], m_d (X_old - X_new).
    virtual double advance(const Kernel& kernel, double& moisture, double* state, const MoistAir& air,
                           double massTransferCoefficient, double dt) const = 0;

    // latentHeat() of the kernel as it is, then advance(): what a coupling
    // step asks of every particle (MoistureExchange), in one call so that a
    // model can share what the two evaluate. The same values as the two
    // calls (the default makes them).
    virtual double advanceWithLatentHeat(const Kernel& kernel, double& moisture, double* state,
                                         const MoistAir& air, double massTransferCoefficient, double dt,
                                         double& latentHeat) const;

    // Whether the next advance() of this state uses the gas, k_m and T_p
    // (true unless the model says otherwise). Where it does not (a step
    // inside a kernelSteps block of KernelDiffusion, which only releases the
    // block's water), the caller may skip gathering the gas and hand any
    // finite air and k_m = 0: the same water, state and latent heat.
    virtual bool needsGas(const double* state) const;

    // The step of a state whose advance needs no gas (needsGas() false),
    // taken without it: X and the state move, the latent heat is set, and
    // the water released [kg] returned, all as advanceWithLatentHeat() with
    // any gas would give them for a kernel of dry mass m_d. A model whose
    // every step needs the gas has none (logic_error).
    virtual double release(double dryMass, double& moisture, double* state, double& latentHeat) const;

    // Heat the kernel gives up per kg of water evaporated [J/kg]: the grain's
    // heat of vaporisation at the moisture where the water leaves
    // (SorptionIsotherm::latentHeat), free water's for freeWater.
    virtual double latentHeat(const Kernel& kernel, double moisture, const double* state) const;

    virtual std::string name() const = 0;

    // The model's isotherm and its stated ranges (StatedRange.hpp), for the
    // run's range warnings; null and none for a model without an isotherm.
    const SorptionIsotherm* sorptionIsotherm() const { return isotherm_.get(); }

    // Run-time selection; a model joins the registry from its own .cpp.
    static ModelRegistry<DryingModel>& registry();
    static std::unique_ptr<DryingModel> New(const std::string& typeName, const Parameters& props);
    static std::vector<std::string> available();

protected:
    // isotherm: the model's "isotherm" setting (default modifiedHenderson);
    // null for a model without one.
    explicit DryingModel(std::unique_ptr<SorptionIsotherm> isotherm);

    const SorptionIsotherm& isotherm() const { return *isotherm_; }

    // The isotherm named by props' "isotherm" entry.
    static std::unique_ptr<SorptionIsotherm> isothermOf(const Parameters& props);

    // One line naming the model for a call outside its preconditions
    // (X >= 0, k_m >= 0, dt >= 0, all finite), as std::domain_error.
    void checkStep(double moisture, double massTransferCoefficient, double dt) const;

private:
    std::unique_ptr<SorptionIsotherm> isotherm_;
};

// The root of a function increasing in x with f(lo) <= 0 <= f(hi), by Newton
// steps from x0 kept inside the bracket (bisection where a step would leave
// it), to the last bits of x. df is f's derivative, or any positive estimate
// of it; a Newton step that stops moving is accepted only if f changes sign
// across it, so a poor slope costs iterations, never accuracy.
template <class F, class DF>
double increasingRoot(F f, DF df, double lo, double hi, double x0)
{
    double x = (x0 > lo && x0 < hi) ? x0 : 0.5 * (lo + hi);
    for (int i = 0; i < 400; ++i)
    {
        const double fx = f(x);
        if (fx == 0.0) return x;
        if (fx > 0.0)
            hi = x;
        else
            lo = x;
        const double tol = 4e-16 * (1.0 + std::fabs(x));
        if (hi - lo <= tol) return 0.5 * (lo + hi);
        double next = x - fx / df(x);
        if (!(next > lo && next < hi))
        {
            next = 0.5 * (lo + hi);
        }
        else if (std::fabs(next - x) <= tol)
        {
            if (f(std::max(lo, next - tol)) <= 0.0 && f(std::min(hi, next + tol)) >= 0.0) return next;
            next = 0.5 * (lo + hi);
        }
        x = next;
    }
    return x;
}

} // namespace spoutlab
