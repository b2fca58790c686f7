// The stated ranges of the correlations that have them, and the watch that
// warns once per quantity a run takes beyond its range.

#include "DryingModel.hpp"
#include "HeatTransferModel.hpp"
#include "SorptionIsotherm.hpp"
#include "StatedRange.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace spoutlab;

namespace
{

const StatedRange unitRange{"Re", 1.0, 2.0, "a source"};

} // namespace

TEST(RangeWatch, InsideGivesNoWarning)
{
    RangeWatch w;
    w.add("model", {unitRange});
    const int s = w.slot("model", "Re");
    ASSERT_EQ(s, 0);
    w.see(s, 1.0);
    w.see(s, 2.0);
    EXPECT_TRUE(w.newWarnings().empty());
}

TEST(RangeWatch, OutsideWarnsOnceWithTheExtreme)
{
    RangeWatch w;
    w.add("model", {unitRange, {"voidage", 0.35, 1.0, "b"}});
    w.see(w.slot("model", "Re"), 3.5);
    w.see(w.slot("model", "Re"), 2.5);
    w.see(w.slot("model", "voidage"), 0.5);
    const std::vector<std::string> lines = w.newWarnings();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "warning: model used beyond its stated range of Re, 1 to 2 (a source), first at 3.5: "
                        "an extrapolation (reported once)");
    w.see(w.slot("model", "Re"), 9.0);
    EXPECT_TRUE(w.newWarnings().empty());
}

TEST(RangeWatch, BothSidesInOneLine)
{
    RangeWatch w;
    w.add("model", {unitRange});
    w.see(0, 0.25);
    w.see(0, 4.0);
    const std::vector<std::string> lines = w.newWarnings();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("first at 0.25 and 4:"), std::string::npos) << lines[0];
}

TEST(RangeWatch, ExtremesMergeByOneMaximum)
{
    // two ranks' watches, merged element-wise as MPI's MAX would
    RangeWatch a, b;
    a.add("model", {unitRange});
    b.add("model", {unitRange});
    a.see(0, 0.5);
    b.see(0, 1.5);
    std::vector<double>& ea = a.extremes();
    const std::vector<double>& eb = b.extremes();
    for (std::size_t i = 0; i < ea.size(); ++i) ea[i] = std::max(ea[i], eb[i]);
    const std::vector<std::string> lines = a.newWarnings();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("first at 0.5:"), std::string::npos) << lines[0];
}

TEST(RangeWatch, UnknownQuantityIsNotWatched)
{
    RangeWatch w;
    w.add("model", {unitRange});
    EXPECT_EQ(w.slot("model", "Pr"), -1);
    EXPECT_EQ(w.slot("other", "Re"), -1);
    w.see(-1, 1e9);
    EXPECT_TRUE(w.newWarnings().empty());
}

TEST(StatedRanges, GunnAsPublished)
{
    // Gunn (1978): 0.35 <= eps <= 1, Re up to 1e5
    const auto gunn = HeatTransferModel::New("Gunn", Parameters("test"));
    const std::vector<StatedRange> r = gunn->statedRanges();
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0].quantity, "Re");
    EXPECT_DOUBLE_EQ(r[0].high, 1e5);
    EXPECT_EQ(r[1].quantity, "voidage");
    EXPECT_DOUBLE_EQ(r[1].low, 0.35);
    EXPECT_DOUBLE_EQ(r[1].high, 1.0);
}

TEST(StatedRanges, RegionRuleListsItsTwoCorrelations)
{
    Parameters p("test");
    p.set("region", "geometry");
    p.set("spoutHalfWidth", "0.0275");
    p.set("fountainBase", "0.912");
    p.set("spout", "RanzMarshall");
    p.set("downcomer", "Gunn");
    const auto rule = HeatTransferModel::New("spoutDowncomer", p);
    const auto c = rule->correlations();
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0]->name(), "RanzMarshall");
    EXPECT_EQ(c[1]->name(), "Gunn");
    EXPECT_EQ(rule->correlationIndex(HeatTransferCell{{0.0, 0, 0.5}, 0.9, 8e-3, 1.0}), 0);
    EXPECT_EQ(rule->correlationIndex(HeatTransferCell{{0.1, 0, 0.5}, 0.4, 8e-3, 1.0}), 1);
    EXPECT_TRUE(c[0]->statedRanges().empty());
    EXPECT_EQ(c[1]->statedRanges().size(), 2u);
}

TEST(StatedRanges, HendersonAsAsae)
{
    // ASAE D245.5: about 0-50 degC, 10-90 % RH
    const auto drying = DryingModel::New("kernelDiffusion", [] {
        Parameters p("test");
        p.set("D0", "4.81e-4");
        p.set("activationEnergy", "44748");
        return p;
    }());
    ASSERT_NE(drying->sorptionIsotherm(), nullptr);
    const std::vector<StatedRange> r = drying->sorptionIsotherm()->statedRanges();
    ASSERT_EQ(r.size(), 2u);
    EXPECT_DOUBLE_EQ(r[0].low, 273.15);
    EXPECT_DOUBLE_EQ(r[0].high, 323.15);
    EXPECT_DOUBLE_EQ(r[1].low, 0.10);
    EXPECT_DOUBLE_EQ(r[1].high, 0.90);
    EXPECT_EQ(DryingModel::New("freeWater", Parameters("test"))->sorptionIsotherm(), nullptr);
}
