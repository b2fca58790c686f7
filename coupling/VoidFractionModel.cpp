#include "VoidFractionModel.hpp"

#include "CentreVoidFraction.hpp"
#include "DividedVoidFraction.hpp"
#include "InputError.hpp"

#include <algorithm>
#include <functional>
#include <utility>

namespace spoutlab {

namespace {

using VoidFractionFactory = std::function<std::unique_ptr<VoidFractionModel>(const Parameters&)>;

template <class Model>
std::pair<const char*, VoidFractionFactory> entry(const char* name) {
  return {name,
          [](const Parameters& p) { return std::unique_ptr<VoidFractionModel>(new Model(p)); }};
}

// Explicit table for the same reason as the drag models: self-registering
// statics in a static library get dropped by the linker.
const std::vector<std::pair<const char*, VoidFractionFactory>>& voidFractionTable() {
  static const std::vector<std::pair<const char*, VoidFractionFactory>> table = {
      entry<DividedVoidFraction>("divided"),
      entry<CentreVoidFraction>("centre"),
  };
  return table;
}

}  // namespace

ParticleCellMap::Row ParticleCellMap::cells(std::size_t particle) const {
  const CellWeight* base = entries_.data();
  return {base + offsets_[particle], base + offsets_[particle + 1]};
}

void ParticleCellMap::clear() {
  offsets_.assign(1, 0);
  entries_.clear();
}

void ParticleCellMap::appendRow(const std::vector<CellWeight>& row) {
  entries_.insert(entries_.end(), row.begin(), row.end());
  offsets_.push_back(entries_.size());
}

std::vector<double> clippedVoidFraction(const CellLocator& mesh,
                                        const std::vector<double>& solidVolume,
                                        double voidFractionMin) {
  std::vector<double> eps(solidVolume.size());
  for (std::size_t c = 0; c < eps.size(); ++c) {
    const double raw = 1.0 - solidVolume[c] / mesh.cellVolume(static_cast<label>(c));
    eps[c] = std::max(raw, voidFractionMin);
  }
  return eps;
}

VoidFractionModel::VoidFractionModel(const Parameters& props)
    : voidFractionMin_(props.getScalar("voidFractionMin", 0.3)) {
  if (!(voidFractionMin_ > 0.0 && voidFractionMin_ < 1.0)) {
    throw props.badValue("voidFractionMin", "a void fraction in (0, 1)");
  }
}

VoidFractionModel::~VoidFractionModel() = default;

std::vector<double> VoidFractionModel::voidFraction(const CellLocator& mesh,
                                                    const std::vector<double>& solidVolume) const {
  return clippedVoidFraction(mesh, solidVolume, voidFractionMin_);
}

VoidFractionResult VoidFractionModel::compute(const CellLocator& mesh,
                                              const std::vector<Particle>& particles,
                                              const std::vector<label>& centreHints) const {
  const bool hinted = centreHints.size() == particles.size();
  VoidFractionResult result;
  result.solidVolume.assign(static_cast<std::size_t>(mesh.nCells()), 0.0);
  result.centreCell.resize(particles.size());
  std::vector<CellWeight> row;
  for (std::size_t n = 0; n < particles.size(); ++n) {
    const Particle& p = particles[n];
    const label centre = mesh.findCell(p.x, hinted ? centreHints[n] : -1);
    result.centreCell[n] = centre;
    row.clear();
    if (centre < 0) {
      result.lostParticles.push_back(n);
    } else {
      distribute(mesh, p, centre, row);
    }
    const double volume = p.volume();
    for (const CellWeight& cw : row) result.solidVolume[cw.cell] += cw.weight * volume;
    result.map.appendRow(row);
  }
  return result;
}

std::vector<std::string> VoidFractionModel::available() {
  std::vector<std::string> names;
  for (const auto& e : voidFractionTable()) names.emplace_back(e.first);
  return names;
}

std::unique_ptr<VoidFractionModel> VoidFractionModel::New(const std::string& typeName,
                                                          const Parameters& props) {
  for (const auto& e : voidFractionTable()) {
    if (typeName == e.first) return e.second(props);
  }
  std::string known;
  for (const auto& n : available()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("voidFractionModel '" + typeName + "' unknown; expected one of: " + known);
}

}  // namespace spoutlab
