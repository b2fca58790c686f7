#pragma once
// Particle -> cell mapping and the solid volume per cell (docs/DESIGN.md
// §3 step 3). A model decides how one particle's volume is shared among cells;
// the base class does the bookkeeping every model needs: locating the centre,
// reporting particles outside the mesh, and summing solid volume per cell, so
// that sum over cells of solidVolume = sum of particle volumes to round-off.
//
// Parameters common to all models:
//   voidFractionMin   lower bound on eps used by the drag (default 0.3)

#include "CellLocator.hpp"
#include "ModelRegistry.hpp"
#include "Parameters.hpp"
#include "Particle.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace spoutlab
{

struct CellWeight
{
    label cell;
    double weight; // fraction of the particle's volume in this cell
};

// Compressed rows: for each particle, the cells it overlaps with weights that
// sum to 1 (an empty row for a lost particle).
class ParticleCellMap
{
public:
    struct Row
    {
        const CellWeight* first;
        const CellWeight* last;
        const CellWeight* begin() const { return first; }
        const CellWeight* end() const { return last; }
        std::size_t size() const { return static_cast<std::size_t>(last - first); }
    };

    std::size_t nParticles() const { return offsets_.size() - 1; }
    Row cells(std::size_t particle) const;

    void clear();
    void appendRow(const std::vector<CellWeight>& row);

private:
    std::vector<std::size_t> offsets_{0};
    std::vector<CellWeight> entries_;
};

// Where a particle's row was made and how far it may move from there before
// any of its cells could change (the model's promise; 0: none).
struct RowOrigin
{
    long id = -1;
    Vec3 x;
    double radius = 0.0;
    double clearance = 0.0;
};

struct VoidFractionResult
{
    ParticleCellMap map;
    std::vector<double> solidVolume;        // per cell [m^3]
    std::vector<label> centreCell;          // per particle, -1 if its centre is outside the mesh
    std::vector<std::size_t> lostParticles; // indices (into the particle vector) with centreCell -1
    std::vector<RowOrigin> origin;          // per particle
    std::size_t rowsKept = 0;               // rows taken over from the previous mapping
};

// eps = 1 - solidVolume/V per cell, bounded below by voidFractionMin. The bound
// only protects the drag law from eps -> 0 in overfilled cells (a particle
// whose volume lands in a cell smaller than itself); solidVolume itself, and
// with it the solid mass, is never clipped.
std::vector<double> clippedVoidFraction(const CellLocator& mesh, const std::vector<double>& solidVolume,
                                        double voidFractionMin);

class VoidFractionModel
{
public:
    explicit VoidFractionModel(const Parameters& props);
    virtual ~VoidFractionModel();

    virtual std::string name() const = 0;

    // Every particle located and distributed afresh.
    VoidFractionResult compute(const CellLocator& mesh, const std::vector<Particle>& particles) const;
    // The same, from previous (last step's mapping; particles matched by
    // id, in any order): a particle that has moved less than
    // its row's clearance since the row was made keeps the row, since its
    // pieces are all still in the same cells and distribute() would make the
    // same row to the bit; the others search from last step's centre cell.
    // Most particles of a bed are slow: their rows last.
    VoidFractionResult compute(const CellLocator& mesh, const std::vector<Particle>& particles,
                               const VoidFractionResult& previous) const;

    double voidFractionMin() const { return voidFractionMin_; }
    std::vector<double> voidFraction(const CellLocator& mesh, const std::vector<double>& solidVolume) const;

    // Run-time selection by name (the couplingProperties entry "voidFractionModel");
    // a model joins the registry from its own .cpp (ModelRegistry.hpp).
    static ModelRegistry<VoidFractionModel>& registry();
    static std::unique_ptr<VoidFractionModel> New(const std::string& typeName, const Parameters& props);
    static std::vector<std::string> available();

protected:
    // Fill row with this particle's (cell, weight) pairs, weights summing to 1.
    // Called only for particles whose centre lies in centreCell (>= 0).
    // Returns how far the particle may move before the row could change
    // (CellLocator::clearance of what the row depends on); 0: no promise.
    virtual double distribute(const CellLocator& mesh, const Particle& p, label centreCell,
                              std::vector<CellWeight>& row) const = 0;

private:
    double voidFractionMin_;

    VoidFractionResult map(const CellLocator& mesh, const std::vector<Particle>& particles,
                           const VoidFractionResult* previous) const;
};

} // namespace spoutlab
