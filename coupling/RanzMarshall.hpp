#pragma once
// Ranz-Marshall (1952) single-sphere heat transfer, the draft-plate paper's
// correlation for the dilute spout (eq 6a):
//   Nu = 2 + 0.6 Pr^(1/3) Re^(1/2),   h = Nu k_c / d
// with Re = eps rho |Us - u| d / mu. At zero slip Nu = 2, conduction into
// still gas around an isolated sphere.
// No parameters.

#include "HeatTransferModel.hpp"

namespace spoutlab
{

class RanzMarshall : public HeatTransferModel
{
public:
    explicit RanzMarshall(const Parameters& props);

    double nusselt(const HeatTransferCell& cell, double re, double pr) const override;
    std::string name() const override { return "RanzMarshall"; }
};

} // namespace spoutlab
