#include "SpoutDowncomer.hpp"

#include <cmath>

namespace spoutlab
{

// selected by "heatTransferModel spoutDowncomer;"
const Registration<HeatTransferModel, SpoutDowncomer> registeredSpoutDowncomer("spoutDowncomer");

namespace
{

// The sub-model named by `key`. Checked here rather than left to New so that a
// bad name is reported against the entry the user has to fix, and so that the
// rule cannot nest itself.
std::unique_ptr<HeatTransferModel> subModel(const Parameters& props, const std::string& key,
                                            const std::string& defaultName)
{
    const std::string chosen = props.getWord(key, defaultName);
    std::string known;
    bool found = false;
    for (const auto& n : HeatTransferModel::available())
    {
        if (n == "spoutDowncomer") continue;
        known += (known.empty() ? "" : ", ") + n;
        found = found || n == chosen;
    }
    if (!found) throw props.badValue(key, "a single correlation, one of: " + known);
    return HeatTransferModel::New(chosen, Parameters(props.context() + "/" + key));
}

} // namespace

SpoutDowncomer::SpoutDowncomer(const Parameters& props)
    : spout_(subModel(props, "spout", "RanzMarshall")), downcomer_(subModel(props, "downcomer", "Sartori")),
      byGeometry_(false)
{
    const std::string rule = props.getWord("region");
    if (rule == "geometry")
    {
        byGeometry_ = true;
        spoutAxis_ = props.getScalar("spoutAxis", 0.0);
        spoutHalfWidth_ = props.getScalar("spoutHalfWidth");
        if (!(spoutHalfWidth_ > 0.0)) throw props.badValue("spoutHalfWidth", "a half-width > 0 in m");
        fountainBase_ = props.getScalar("fountainBase");
    }
    else if (rule == "voidage")
    {
        spoutVoidage_ = props.getScalar("spoutVoidage");
        if (!(spoutVoidage_ > 0.0 && spoutVoidage_ < 1.0))
        {
            throw props.badValue("spoutVoidage", "a void fraction in (0, 1)");
        }
    }
    else
    {
        throw props.badValue("region", "one of: geometry, voidage");
    }
}

int SpoutDowncomer::region(const HeatTransferCell& cell) const
{
    if (!byGeometry_) return cell.voidFraction >= spoutVoidage_ ? 1 : 0;
    const bool inBand = std::fabs(cell.centre.x - spoutAxis_) <= spoutHalfWidth_;
    return inBand || cell.centre.z >= fountainBase_ ? 1 : 0;
}

std::vector<const HeatTransferModel*> SpoutDowncomer::correlations() const
{
    return {spout_.get(), downcomer_.get()};
}

int SpoutDowncomer::correlationIndex(const HeatTransferCell& cell) const
{
    return region(cell) == 1 ? 0 : 1;
}

double SpoutDowncomer::nusselt(const HeatTransferCell& cell, double re, double pr) const
{
    return (region(cell) == 1 ? spout_ : downcomer_)->nusselt(cell, re, pr);
}

} // namespace spoutlab
