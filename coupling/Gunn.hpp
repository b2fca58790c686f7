#pragma once
// Gunn (1978) heat transfer to particles in fixed and fluidised beds, the
// usual dense-bed correlation of CFD-DEM codes:
//   Nu = (7 - 10 eps + 5 eps^2)(1 + 0.7 Re^0.2 Pr^(1/3))
//      + (1.33 - 2.4 eps + 1.2 eps^2) Re^0.7 Pr^(1/3),   h = Nu k_c / d
// with Re = eps rho |Us - u| d / mu on the superficial slip. Fitted for
// 0.35 <= eps <= 1 and Re up to 1e5; at eps = 1 and Re = 0 it gives the
// single-sphere Nu = 2, and unlike Sartori it stays positive at zero slip.
// Those are its stated ranges (Gunn, Int. J. Heat Mass Transfer 21 (1978)
// 467-476); a run beyond them is warned once (StatedRange.hpp).
// No parameters.

#include "HeatTransferModel.hpp"

namespace spoutlab
{

class Gunn : public HeatTransferModel
{
public:
    explicit Gunn(const Parameters& props);

    double nusselt(const HeatTransferCell& cell, double re, double pr) const override;
    std::vector<StatedRange> statedRanges() const override;
    std::string name() const override { return "Gunn"; }
};

} // namespace spoutlab
