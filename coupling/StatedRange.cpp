#include "StatedRange.hpp"

#include <limits>
#include <sstream>

namespace spoutlab
{

void RangeWatch::add(const std::string& model, const std::vector<StatedRange>& ranges)
{
    const double none = -std::numeric_limits<double>::infinity();
    for (const StatedRange& r : ranges)
    {
        slots_.push_back(Slot{model, r, false});
        extremes_.push_back(none);
        extremes_.push_back(none);
    }
}

int RangeWatch::slot(const std::string& model, const std::string& quantity) const
{
    for (std::size_t i = 0; i < slots_.size(); ++i)
    {
        if (slots_[i].model == model && slots_[i].range.quantity == quantity) return static_cast<int>(i);
    }
    return -1;
}

std::vector<std::string> RangeWatch::newWarnings()
{
    std::vector<std::string> lines;
    for (std::size_t i = 0; i < slots_.size(); ++i)
    {
        Slot& s = slots_[i];
        const double lowest = -extremes_[2 * i], highest = extremes_[2 * i + 1];
        const bool below = lowest<s.range.low, above = highest> s.range.high;
        if (s.reported || !(below || above)) continue;
        s.reported = true;
        std::ostringstream line;
        line.precision(6);
        line << "warning: " << s.model << " used beyond its stated range of " << s.range.quantity << ", "
             << s.range.low << " to " << s.range.high << " (" << s.range.source << "), first at ";
        if (below) line << lowest << (above ? " and " : "");
        if (above) line << highest;
        line << ": an extrapolation (reported once)";
        lines.push_back(line.str());
    }
    return lines;
}

} // namespace spoutlab
