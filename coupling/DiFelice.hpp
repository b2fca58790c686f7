#pragma once
// Di Felice (1994) drag: the single-sphere force on the superficial slip,
// corrected by eps^-chi for the surrounding particles.
//   F_i = C_d (pi d^2/4) rho (eps w)^2/2 eps^-chi
//   C_d = (0.63 + 4.8/sqrt(Re))^2 (Dallavalle), Re = eps rho |w| d/mu
//   chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2)
// In this library's convention (F_i = V_i beta/(1-eps) w) that is
//   beta = 3/4 C_d rho (1-eps) eps^(2-chi) |w|/d.
// No parameters.

#include "DragModel.hpp"

namespace spoutlab
{

class DiFelice : public DragModel
{
public:
    explicit DiFelice(const Parameters& props);

    double beta(const DragState& state, const GasProperties& gas) const override;
    std::string name() const override { return "DiFelice"; }
};

} // namespace spoutlab
