#pragma once
// Gidaspow drag: Ergun in dense regions, Wen-Yu in dilute ones (the source
// papers' model, docs/DESIGN.md §3.3).
//   eps <  eps_s: beta = 150 (1-eps)^2 mu/(eps d^2) + 1.75 (1-eps) rho |w|/d
//   eps >= eps_s: beta = 3/4 C_d rho eps (1-eps) |w|/d eps^-2.65,
//                 C_d = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), 0.44 (Re >= 1000)
// Parameters:
//   switch         sharp (default) | smooth
//   epsilonSwitch  eps_s, default 0.8
// "sharp" is the papers' model and jumps at eps_s: for 8 mm particles in air at
// 1 m/s slip, beta falls by a factor of about 2.8 when eps crosses 0.8, which
// can make a cell's drag chatter as its void fraction wanders across the
// switch. "smooth" blends the two with the Huilin-Gidaspow weight
// phi = 1/2 + atan(262.5 (eps - eps_s))/pi, beta = (1-phi) Ergun + phi WenYu.

#include "DragModel.hpp"

namespace spoutlab
{

class Gidaspow : public DragModel
{
public:
    explicit Gidaspow(const Parameters& props);

    double beta(const DragState& state, const GasProperties& gas) const override;
    std::string name() const override { return "Gidaspow"; }

private:
    bool smooth_;
    double epsilonSwitch_;
};

} // namespace spoutlab
