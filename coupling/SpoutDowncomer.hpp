#pragma once
// A region rule: one correlation in the spout, another in the downcomer, as in
// the draft-plate paper (Ranz-Marshall, eq 6a, in the dilute spout and
// fountain; Sartori, eq 6b, in the moving bed of the downcomer):
//   h = h_spout(cell)      where the cell is spout
//   h = h_downcomer(cell)  elsewhere
// Parameters:
//   spout      correlation in the spout, default RanzMarshall
//   downcomer  correlation in the downcomer, default Sartori
//   region     geometry | voidage (required), how a cell is classified:
//     geometry  a vessel with draft plates: spout where
//               |x - spoutAxis| <= spoutHalfWidth (between the plates' inner
//               faces, at any height) or z >= fountainBase (the fountain above
//               the plates' upper edge). Keys spoutAxis [m] (default 0),
//               spoutHalfWidth [m] (> 0, required), fountainBase [m] (required).
//     voidage   a bed without plates, where the spout has no fixed wall: spout
//               where eps >= spoutVoidage (in (0, 1), required).
// The sub-models get an empty Parameters named "<context>/spout" and
// "<context>/downcomer"; none of the single correlations has settings.

#include "HeatTransferModel.hpp"

namespace spoutlab
{

class SpoutDowncomer : public HeatTransferModel
{
public:
    explicit SpoutDowncomer(const Parameters& props);

    double nusselt(const HeatTransferCell& cell, double re, double pr) const override;
    int region(const HeatTransferCell& cell) const override;
    // {spout, downcomer}
    std::vector<const HeatTransferModel*> correlations() const override;
    int correlationIndex(const HeatTransferCell& cell) const override;
    std::string name() const override { return "spoutDowncomer"; }

private:
    std::unique_ptr<HeatTransferModel> spout_;
    std::unique_ptr<HeatTransferModel> downcomer_;
    bool byGeometry_;
    double spoutAxis_ = 0.0;
    double spoutHalfWidth_ = 0.0;
    double fountainBase_ = 0.0;
    double spoutVoidage_ = 0.0;
};

} // namespace spoutlab
