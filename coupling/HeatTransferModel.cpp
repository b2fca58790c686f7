#include "HeatTransferModel.hpp"

#include "Gunn.hpp"
#include "ModelTable.hpp"
#include "RanzMarshall.hpp"
#include "Sartori.hpp"
#include "SpoutDowncomer.hpp"

namespace spoutlab {

namespace {

const ModelTable<HeatTransferModel>& heatTransferTable() {
  using T = ModelTable<HeatTransferModel>;
  static const T table("heatTransferModel", {
      T::entry<RanzMarshall>("RanzMarshall"),
      T::entry<Sartori>("Sartori"),
      T::entry<Gunn>("Gunn"),
      T::entry<SpoutDowncomer>("spoutDowncomer"),
  });
  return table;
}

}  // namespace

double heatTransferReynolds(const HeatTransferCell& cell, const GasThermalProperties& gas) {
  return cell.voidFraction * gas.rho * cell.slip * cell.diameter / gas.mu;
}

HeatTransferModel::~HeatTransferModel() = default;

int HeatTransferModel::region(const HeatTransferCell&) const { return -1; }

std::vector<std::string> HeatTransferModel::available() { return heatTransferTable().names(); }

std::unique_ptr<HeatTransferModel> HeatTransferModel::New(const std::string& typeName,
                                                          const Parameters& props) {
  return heatTransferTable().create(typeName, props);
}

}  // namespace spoutlab
