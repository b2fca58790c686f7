#pragma once
// Gas-particle drag laws, expressed as the momentum-exchange coefficient beta.
//
// Convention (fixed by the solver, Tsuji "model A"):
//   gas:      d(eps rho u)/dt + ... = -eps grad(p) + beta (Us - u) + ...
//   particle: F_i = V_i beta/(1 - eps) (u - v_i)  - V_i grad(p)
// so beta [kg m^-3 s^-1] is the drag per unit mixture volume and unit slip.
// In a packed bed at rest this gives -grad(p) = beta u_s/eps^2 for the
// superficial velocity u_s, which every law below must turn into Ergun (or its
// own packed-bed limit); as eps -> 1 the force on one particle must become the
// single-sphere drag C_d (pi d^2/4) rho w^2/2.

#include "ModelRegistry.hpp"
#include "Parameters.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spoutlab
{

struct GasProperties
{
    double rho; // density [kg/m^3]
    double mu;  // dynamic viscosity [Pa s]
};

// Local state the drag law needs. Preconditions: 0 < voidFraction <= 1,
// diameter > 0, slip >= 0.
struct DragState
{
    double voidFraction; // eps, gas volume fraction
    double diameter;     // d_p [m] (Sauter mean for a mixture)
    double slip;         // |u - Us| [m/s], interstitial gas velocity minus particle velocity
};

// Particle Reynolds number on the superficial slip, Re = eps rho |w| d / mu,
// the definition shared by Gidaspow, Di Felice and Beetstra.
double particleReynolds(const DragState& s, const GasProperties& gas);

class DragModel
{
public:
    virtual ~DragModel();

    virtual double beta(const DragState& state, const GasProperties& gas) const = 0;
    virtual std::string name() const = 0;

    // Run-time selection by name (the couplingProperties entry "dragModel"); a
    // law joins the registry from its own .cpp (ModelRegistry.hpp).
    static ModelRegistry<DragModel>& registry();
    static std::unique_ptr<DragModel> New(const std::string& typeName, const Parameters& props);
    static std::vector<std::string> available();
};

} // namespace spoutlab
