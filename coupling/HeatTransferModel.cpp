#include "HeatTransferModel.hpp"

#include "Gunn.hpp"
#include "InputError.hpp"
#include "RanzMarshall.hpp"
#include "Sartori.hpp"
#include "SpoutDowncomer.hpp"

#include <functional>
#include <utility>

namespace spoutlab {

namespace {

using HeatTransferFactory = std::function<std::unique_ptr<HeatTransferModel>(const Parameters&)>;

template <class Model>
std::pair<const char*, HeatTransferFactory> entry(const char* name) {
  return {name, [](const Parameters& p) { return std::unique_ptr<HeatTransferModel>(new Model(p)); }};
}

// An explicit table for the same reason as the drag laws' table: registration
// objects in a static library are dropped by the linker when nothing else
// references their translation unit.
const std::vector<std::pair<const char*, HeatTransferFactory>>& heatTransferTable() {
  static const std::vector<std::pair<const char*, HeatTransferFactory>> table = {
      entry<RanzMarshall>("RanzMarshall"),
      entry<Sartori>("Sartori"),
      entry<Gunn>("Gunn"),
      entry<SpoutDowncomer>("spoutDowncomer"),
  };
  return table;
}

}  // namespace

double heatTransferReynolds(const HeatTransferCell& cell, const GasThermalProperties& gas) {
  return cell.voidFraction * gas.rho * cell.slip * cell.diameter / gas.mu;
}

HeatTransferModel::~HeatTransferModel() = default;

int HeatTransferModel::region(const HeatTransferCell&) const { return -1; }

std::vector<std::string> HeatTransferModel::available() {
  std::vector<std::string> names;
  for (const auto& e : heatTransferTable()) names.emplace_back(e.first);
  return names;
}

std::unique_ptr<HeatTransferModel> HeatTransferModel::New(const std::string& typeName,
                                                          const Parameters& props) {
  for (const auto& e : heatTransferTable()) {
    if (typeName == e.first) return e.second(props);
  }
  std::string known;
  for (const auto& n : available()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("heatTransferModel '" + typeName + "' unknown; expected one of: " + known);
}

}  // namespace spoutlab
