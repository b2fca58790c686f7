#pragma once
// Sartori et al., heat transfer in downward moving beds, the draft-plate
// paper's correlation for the downcomer (eq 6b):
//   Nu = 1.54 Pr^(1/3) Re^0.57,   h = Nu k_c / d
// with Re = eps rho |Us - u| d / mu. Unlike Ranz-Marshall it has no
// conduction term, so h = 0 at Re = 0: a cell whose particles move with the
// gas exchanges no heat. That is the correlation as published, not clipped
// here; use Gunn where the bed may stall.
// No parameters.

#include "HeatTransferModel.hpp"

namespace spoutlab
{

class Sartori : public HeatTransferModel
{
public:
    explicit Sartori(const Parameters& props);

    double nusselt(const HeatTransferCell& cell, double re, double pr) const override;
    std::string name() const override { return "Sartori"; }
};

} // namespace spoutlab
