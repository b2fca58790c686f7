#pragma once
// Beetstra, van der Hoef & Kuipers (2007), AIChE J. 53:489, monodisperse law
// fitted to lattice-Boltzmann simulations of random sphere arrays (Re <= 1000):
//   F = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi))
//     + 0.413 Re/(24 eps^2) (1/eps + 3 eps phi + 8.4 Re^-0.343)
//                          / (1 + 10^(3 phi) Re^-(1 + 4 phi)/2)
// with phi = 1 - eps and Re = eps rho |w| d/mu. F is the drag force on one
// particle, excluding the mean pressure gradient (i.e. the model-A drag),
// divided by the Stokes drag 3 pi mu d (eps w) on the superficial slip. Setting
// V_i beta/(1-eps) w = 3 pi mu d eps w F gives
//   beta = 18 mu eps (1-eps) F / d^2.
// No parameters.

#include "DragModel.hpp"

namespace spoutlab
{

class Beetstra : public DragModel
{
public:
    explicit Beetstra(const Parameters& props);

    double beta(const DragState& state, const GasProperties& gas) const override;
    std::string name() const override { return "Beetstra"; }
};

} // namespace spoutlab
