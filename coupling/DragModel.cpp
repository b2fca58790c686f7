#include "DragModel.hpp"

#include "Beetstra.hpp"
#include "DiFelice.hpp"
#include "Gidaspow.hpp"
#include "InputError.hpp"

#include <functional>
#include <utility>

namespace spoutlab {

namespace {

using DragFactory = std::function<std::unique_ptr<DragModel>(const Parameters&)>;

template <class Model>
std::pair<const char*, DragFactory> entry(const char* name) {
  return {name, [](const Parameters& p) { return std::unique_ptr<DragModel>(new Model(p)); }};
}

// An explicit table rather than static self-registration: registration objects
// in a static library are silently dropped by the linker when nothing else
// references their translation unit.
const std::vector<std::pair<const char*, DragFactory>>& dragTable() {
  static const std::vector<std::pair<const char*, DragFactory>> table = {
      entry<Gidaspow>("Gidaspow"),
      entry<DiFelice>("DiFelice"),
      entry<Beetstra>("Beetstra"),
  };
  return table;
}

}  // namespace

double particleReynolds(const DragState& s, const GasProperties& gas) {
  return s.voidFraction * gas.rho * s.slip * s.diameter / gas.mu;
}

DragModel::~DragModel() = default;

std::vector<std::string> DragModel::available() {
  std::vector<std::string> names;
  for (const auto& e : dragTable()) names.emplace_back(e.first);
  return names;
}

std::unique_ptr<DragModel> DragModel::New(const std::string& typeName, const Parameters& props) {
  for (const auto& e : dragTable()) {
    if (typeName == e.first) return e.second(props);
  }
  std::string known;
  for (const auto& n : available()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("dragModel '" + typeName + "' unknown; expected one of: " + known);
}

}  // namespace spoutlab
