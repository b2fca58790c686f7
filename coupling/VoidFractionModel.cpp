#include "VoidFractionModel.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace spoutlab
{

ParticleCellMap::Row ParticleCellMap::cells(std::size_t particle) const
{
    const CellWeight* base = entries_.data();
    return {base + offsets_[particle], base + offsets_[particle + 1]};
}

void ParticleCellMap::clear()
{
    offsets_.assign(1, 0);
    entries_.clear();
}

void ParticleCellMap::appendRow(const std::vector<CellWeight>& row)
{
    entries_.insert(entries_.end(), row.begin(), row.end());
    offsets_.push_back(entries_.size());
}

std::vector<double> clippedVoidFraction(const CellLocator& mesh, const std::vector<double>& solidVolume,
                                        double voidFractionMin)
{
    std::vector<double> eps(solidVolume.size());
    for (std::size_t c = 0; c < eps.size(); ++c)
    {
        const double raw = 1.0 - solidVolume[c] / mesh.cellVolume(static_cast<label>(c));
        eps[c] = std::max(raw, voidFractionMin);
    }
    return eps;
}

VoidFractionModel::VoidFractionModel(const Parameters& props)
    : voidFractionMin_(props.getScalar("voidFractionMin", 0.3))
{
    if (!(voidFractionMin_ > 0.0 && voidFractionMin_ < 1.0))
    {
        throw props.badValue("voidFractionMin", "a void fraction in (0, 1)");
    }
}

VoidFractionModel::~VoidFractionModel() = default;

std::vector<double> VoidFractionModel::voidFraction(const CellLocator& mesh,
                                                    const std::vector<double>& solidVolume) const
{
    return clippedVoidFraction(mesh, solidVolume, voidFractionMin_);
}

VoidFractionResult VoidFractionModel::compute(const CellLocator& mesh,
                                              const std::vector<Particle>& particles) const
{
    return map(mesh, particles, nullptr);
}

VoidFractionResult VoidFractionModel::compute(const CellLocator& mesh, const std::vector<Particle>& particles,
                                              const VoidFractionResult& previous) const
{
    return map(mesh, particles, &previous);
}

namespace
{

// Whether the particle may keep the row made at origin: the same particle,
// the same size, moved less than the clearance (less a margin far above the
// round-off of positions, so that no piece can have reached a face).
bool rowLasts(const RowOrigin& origin, const Particle& p)
{
    const double margin = 1e-9 * p.radius;
    return origin.id == p.id && origin.radius == p.radius && origin.clearance > margin
           && mag(p.x - origin.x) < origin.clearance - margin;
}

// Where each particle's row of the last step is: at the same place while
// the particles keep their order (the DEM keeps its atoms in place between
// its sorts), else found by id.
class PreviousSlots
{
public:
    explicit PreviousSlots(const VoidFractionResult* previous)
        : previous_(previous),
          n_(previous ? std::min(previous->origin.size(), previous->map.nParticles()) : 0)
    {}

    // the slot of the particle with this id, now at place n; -1 if new
    std::ptrdiff_t of(std::size_t n, long id)
    {
        if (n < n_ && previous_->origin[n].id == id) return static_cast<std::ptrdiff_t>(n);
        if (n_ == 0) return -1;
        if (byId_.empty())
        {
            byId_.reserve(n_);
            for (std::size_t m = 0; m < n_; ++m) byId_.emplace_back(previous_->origin[m].id, m);
            std::sort(byId_.begin(), byId_.end());
        }
        const auto it = std::lower_bound(byId_.begin(), byId_.end(), std::make_pair(id, std::size_t(0)));
        return it != byId_.end() && it->first == id ? static_cast<std::ptrdiff_t>(it->second) : -1;
    }

private:
    const VoidFractionResult* previous_;
    std::size_t n_;
    std::vector<std::pair<long, std::size_t>> byId_; // built on the first particle out of place
};

} // namespace

VoidFractionResult VoidFractionModel::map(const CellLocator& mesh, const std::vector<Particle>& particles,
                                          const VoidFractionResult* previous) const
{
    PreviousSlots slots(previous);
    VoidFractionResult result;
    result.solidVolume.assign(static_cast<std::size_t>(mesh.nCells()), 0.0);
    result.centreCell.resize(particles.size());
    result.origin.resize(particles.size());
    std::vector<CellWeight> row;
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        const Particle& p = particles[n];
        const std::ptrdiff_t slot = slots.of(n, p.id);
        const bool seen = slot >= 0;
        const std::size_t m = seen ? static_cast<std::size_t>(slot) : 0;
        row.clear();
        if (seen && rowLasts(previous->origin[m], p))
        {
            const ParticleCellMap::Row last = previous->map.cells(m);
            row.assign(last.begin(), last.end());
            result.centreCell[n] = previous->centreCell[m];
            result.origin[n] = previous->origin[m];
            ++result.rowsKept;
        }
        else
        {
            const label hint = seen ? previous->centreCell[m] : -1;
            const label centre = mesh.findCell(p.x, hint);
            result.centreCell[n] = centre;
            result.origin[n] = RowOrigin{p.id, p.x, p.radius, 0.0};
            if (centre < 0)
            {
                result.lostParticles.push_back(n);
            }
            else
            {
                result.origin[n].clearance = distribute(mesh, p, centre, row);
            }
        }
        const double volume = p.volume();
        for (const CellWeight& cw : row) result.solidVolume[cw.cell] += cw.weight * volume;
        result.map.appendRow(row);
    }
    mesh.complete(result.solidVolume, 1);
    return result;
}

// Built on first use, before any model's registration object adds to it.
ModelRegistry<VoidFractionModel>& VoidFractionModel::registry()
{
    static ModelRegistry<VoidFractionModel> models("voidFractionModel");
    return models;
}

std::vector<std::string> VoidFractionModel::available()
{
    return registry().names();
}

std::unique_ptr<VoidFractionModel> VoidFractionModel::New(const std::string& typeName,
                                                          const Parameters& props)
{
    return registry().create(typeName, props);
}

} // namespace spoutlab
