#include "DragModel.hpp"

#include "Beetstra.hpp"
#include "DiFelice.hpp"
#include "Gidaspow.hpp"
#include "ModelTable.hpp"

namespace spoutlab {

namespace {

const ModelTable<DragModel>& dragTable() {
  using T = ModelTable<DragModel>;
  static const T table("dragModel", {
      T::entry<Gidaspow>("Gidaspow"),
      T::entry<DiFelice>("DiFelice"),
      T::entry<Beetstra>("Beetstra"),
  });
  return table;
}

}  // namespace

double particleReynolds(const DragState& s, const GasProperties& gas) {
  return s.voidFraction * gas.rho * s.slip * s.diameter / gas.mu;
}

DragModel::~DragModel() = default;

std::vector<std::string> DragModel::available() { return dragTable().names(); }

std::unique_ptr<DragModel> DragModel::New(const std::string& typeName, const Parameters& props) {
  return dragTable().create(typeName, props);
}

}  // namespace spoutlab
