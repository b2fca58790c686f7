#pragma once
// The run-time selection of a model family (drag laws, void-fraction models,
// heat-transfer correlations): an explicit table of names and constructors.
// Explicit rather than static self-registration, because registration objects
// in a static library are dropped by the linker when nothing else references
// their translation unit.

#include "InputError.hpp"
#include "Parameters.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace spoutlab {

template <class Base>
class ModelTable {
 public:
  using Factory = std::function<std::unique_ptr<Base>(const Parameters&)>;
  using Entry = std::pair<std::string, Factory>;

  // family names the dictionary key in errors, e.g. "dragModel"
  ModelTable(std::string family, std::vector<Entry> entries)
      : family_(std::move(family)), entries_(std::move(entries)) {}

  template <class Model>
  static Entry entry(const char* name) {
    return {name, [](const Parameters& p) { return std::unique_ptr<Base>(new Model(p)); }};
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.first);
    return out;
  }

  std::unique_ptr<Base> create(const std::string& name, const Parameters& props) const {
    for (const Entry& e : entries_) {
      if (name == e.first) return e.second(props);
    }
    std::string known;
    for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.first;
    throw InputError(family_ + " '" + name + "' unknown; expected one of: " + known);
  }

 private:
  std::string family_;
  std::vector<Entry> entries_;
};

}  // namespace spoutlab
