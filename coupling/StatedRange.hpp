#pragma once
// Where a correlation holds: the ranges of its inputs stated by its source,
// and a watch that tells a run, once per quantity, that it went beyond them.
//
// A model states a range only where its source gives one (Gunn 1978 for its
// Nusselt correlation, ASAE D245.5 for the corn isotherms); Ranz-Marshall and
// Sartori et al. state none here, as no stated range of theirs could be
// checked against the source. Outside its range a correlation is an
// extrapolation: the run goes on, and says so in one line.

#include <string>
#include <vector>

namespace spoutlab
{

struct StatedRange
{
    std::string quantity; // as the warning names it, e.g. "Re", "voidage"
    double low;           // bounds, in the units the model sees the quantity in
    double high;
    std::string source; // where the range is stated
};

// The extremes a run has seen of each watched quantity. The slots are the same
// on every rank (models and ranges are fixed at set-up), so the extremes of a
// parallel run merge by one element-wise maximum of extremes() (the minima are
// kept negated).
class RangeWatch
{
public:
    // Watch a model's ranges; its quantities are then seen through slot().
    void add(const std::string& model, const std::vector<StatedRange>& ranges);

    // The slot of a model's quantity, -1 if it states no range for it.
    int slot(const std::string& model, const std::string& quantity) const;

    void see(int slot, double value)
    {
        if (slot < 0) return;
        if (-value > extremes_[2 * slot]) extremes_[2 * slot] = -value;
        if (value > extremes_[2 * slot + 1]) extremes_[2 * slot + 1] = value;
    }

    // Two values per slot, -min and max (for the merge across ranks).
    std::vector<double>& extremes() { return extremes_; }

    // One line for each quantity that went beyond its range and was not
    // reported before (it is not reported again), with the extremes seen so
    // far beyond the range.
    std::vector<std::string> newWarnings();

    bool empty() const { return slots_.empty(); }

private:
    struct Slot
    {
        std::string model;
        StatedRange range;
        bool reported;
    };
    std::vector<Slot> slots_;
    std::vector<double> extremes_;
};

} // namespace spoutlab
