// The region rule of the draft-plate bed at hand-placed points, and the state
// machine of the circulation statistics on hand-made tracks, whose residence
// and cycle times, holdups, halves and histogram bins are counted by hand.
//
// Geometry of the draft-plate paper's bed (spoutedBedDict, SI): Wd 0.055
// (inner faces at |x| = 0.0275), plates 0.011 thick (outer faces at
// |x| = 0.0385), He 0.095, Hd 0.912.

#include "Circulation.hpp"
#include "InputError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

using namespace spoutlab;

namespace
{

const DraftPlateRegions bed(0.055, 0.095, 0.912, 0.011);

// a point of each region, on the axis or in the right downcomer
const Vec3 inSpout{0.0, 0.02, 0.5};
const Vec3 inFountain{0.0, 0.02, 1.0};
const Vec3 inDowncomer{0.2, 0.02, 0.5};
const Vec3 inEntrainment{0.0, 0.02, 0.05};

std::vector<double> freshTrack()
{
    return std::vector<double>(CirculationStatistics::trackWidth, -1.0);
}

// One particle followed through `places` at t = t0, t0 + dt, ...; the
// statistics count one sampling time per place.
void follow(CirculationStatistics& stats, std::vector<double>& track, const std::vector<Vec3>& places,
            double t0, double dt, const ParticleSample& seen = {})
{
    for (std::size_t k = 0; k < places.size(); ++k)
    {
        const double t = t0 + double(k) * dt;
        stats.observe(t, places[k], track.data(), seen);
        stats.endSample(t);
    }
}

std::vector<Vec3> repeat(const Vec3& place, int n)
{
    return std::vector<Vec3>(std::size_t(n), place);
}

std::vector<Vec3> operator+(std::vector<Vec3> a, const std::vector<Vec3>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

} // namespace

TEST(DraftPlateRegions, PointsOfEachRegion)
{
    EXPECT_EQ(bed.region(0.0, 0.5), spoutRegion);
    EXPECT_EQ(bed.region(0.0275, 0.5), spoutRegion);     // on the inner face: spout (|x| <= Wd/2)
    EXPECT_EQ(bed.region(-0.0275, 0.095), spoutRegion);  // lower edge belongs to the spout
    EXPECT_EQ(bed.region(0.0, 0.912), fountainRegion);   // upper edge: fountain (z >= Hd)
    EXPECT_EQ(bed.region(0.2, 0.95), fountainRegion);    // above a downcomer too
    EXPECT_EQ(bed.region(0.0385, 0.5), downcomerRegion); // on the outer face
    EXPECT_EQ(bed.region(-0.24, 0.3), downcomerRegion);
    EXPECT_EQ(bed.region(0.0, 0.0949), entrainmentRegion);
    EXPECT_EQ(bed.region(0.2, 0.05), entrainmentRegion); // below a downcomer
    EXPECT_EQ(bed.region(0.03, 0.5), noRegion);          // inside a plate
    EXPECT_EQ(bed.region(-0.0384, 0.9119), noRegion);
}

TEST(DraftPlateRegions, BadGeometryIsOneLine)
{
    EXPECT_THROW(DraftPlateRegions(0.0, 0.095, 0.912, 0.011), InputError);
    EXPECT_THROW(DraftPlateRegions(0.055, 0.912, 0.095, 0.011), InputError);
    EXPECT_THROW(DraftPlateRegions(0.055, 0.095, 0.912, -0.001), InputError);
    try
    {
        DraftPlateRegions(0.055, 0.095, 0.912, -0.001, "constant/couplingProperties: circulation");
    }
    catch (const InputError& e)
    {
        EXPECT_NE(std::string(e.what()).find("constant/couplingProperties: circulation"), std::string::npos);
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
}

// One full cycle with steps of 0.1 s from t = 0: spout 3 samples (incomplete,
// tracking starts there), fountain 2, downcomer 5, entrainment 1, spout 4,
// fountain 1. Entries: fountain at 0.3, downcomer 0.5, entrainment 1.0,
// spout 1.1, fountain 1.5. Completed visits: fountain 0.2, downcomer 0.5,
// entrainment 0.1, spout 0.4 (the first spout visit is incomplete); no cycle
// (only one entry into the spout).
static void followOneCycle(CirculationStatistics& stats, std::vector<double>& track)
{
    follow(stats, track,
           repeat(inSpout, 3) + repeat(inFountain, 2) + repeat(inDowncomer, 5) + repeat(inEntrainment, 1)
               + repeat(inSpout, 4) + repeat(inFountain, 1),
           0.0, 0.1);
}

// Its visits, entries, holdups and Little's law's boundary terms
TEST(CirculationStatistics, OneCycleByHand)
{
    CirculationStatistics stats(bed, 0.0, 10.0, 0.05);
    std::vector<double> track = freshTrack();
    followOneCycle(stats, track);
    EXPECT_EQ(stats.residence(spoutRegion).all.samples, 1);
    EXPECT_NEAR(stats.residence(spoutRegion).all.mean(), 0.4, 1e-12);
    EXPECT_NEAR(stats.residence(fountainRegion).all.mean(), 0.2, 1e-12);
    EXPECT_NEAR(stats.residence(downcomerRegion).all.mean(), 0.5, 1e-12);
    EXPECT_NEAR(stats.residence(entrainmentRegion).all.mean(), 0.1, 1e-12);
    EXPECT_EQ(stats.residence(CirculationStatistics::cycle).all.samples, 0);
    EXPECT_EQ(stats.entries(spoutRegion), 1);
    EXPECT_EQ(stats.entries(fountainRegion), 2);
    EXPECT_EQ(stats.sampleTimes(), 16);
    // holdup: samples in the state over 16 sampling times
    EXPECT_NEAR(stats.holdup(spoutRegion), 7.0 / 16, 1e-15);
    EXPECT_NEAR(stats.holdup(fountainRegion), 3.0 / 16, 1e-15);
    EXPECT_NEAR(stats.holdup(downcomerRegion), 5.0 / 16, 1e-15);
    EXPECT_NEAR(stats.holdup(entrainmentRegion), 1.0 / 16, 1e-15);
    EXPECT_EQ(track[0], fountainRegion);
    EXPECT_NEAR(track[1], 1.5, 1e-12);
    EXPECT_NEAR(track[2], 1.1, 1e-12);
    // Little's law with its boundary terms: the incomplete first spout visit
    // 0 .. 0.3 s, the fountain visit open at the last sample (1.5 s) 0.1 s;
    // holdup x 16 samples x 0.1 s = completed + open at start + open at end
    EXPECT_NEAR(stats.openAtStart(spoutRegion), 0.3, 1e-12);
    const auto open = CirculationStatistics::openAtEnd({track.data()}, 1.5, 0.1);
    EXPECT_NEAR(open[fountainRegion], 0.1, 1e-12);
    EXPECT_EQ(open[spoutRegion], 0.0);
    for (int s = 0; s < nCirculationRegions; ++s)
    {
        const double completed = stats.residence(s).all.sum;
        EXPECT_NEAR(stats.holdup(s) * 16 * 0.1, completed + stats.openAtStart(s) + open[std::size_t(s)],
                    1e-12)
            << circulationRegionName(s);
    }
}

// A particle seen in one state for the whole window: all its time is open.
TEST(CirculationStatistics, VisitSpanningTheWindowIsOpenAtEnd)
{
    CirculationStatistics stats(bed, 1.0, 100.0, 0.05);
    std::vector<double> track = freshTrack();
    follow(stats, track, repeat(inDowncomer, 30), 0.0, 0.1); // samples 1.0 .. 2.9 in the window
    const auto open = CirculationStatistics::openAtEnd({track.data()}, 2.9, 0.1);
    EXPECT_NEAR(open[downcomerRegion], 2.0, 1e-12);
    EXPECT_NEAR(stats.holdup(downcomerRegion) * stats.sampleTimes() * 0.1, 2.0, 1e-12);
    EXPECT_EQ(stats.openAtStart(downcomerRegion), 0.0);
}

// Two cycles: the cycle time is between spout entries at 1.0 and 2.0
// (steps of 0.25 s from 0.0 entering the spout at 1.0 from entrainment).
TEST(CirculationStatistics, CycleBetweenSpoutEntries)
{
    CirculationStatistics stats(bed, 0.0, 100.0, 0.1);
    std::vector<double> track = freshTrack();
    const std::vector<Vec3> loop = {inSpout, inFountain, inDowncomer, inEntrainment};
    // t = 0 downcomer (incomplete), 0.25 .. 0.75 entrainment, then
    // 1.0 spout, 1.25 fountain, 1.5 downcomer, 1.75 entrainment, 2.0 spout,
    // ... 2.75 entrainment, 3.0 spout
    follow(stats, track,
           std::vector<Vec3>{inDowncomer} + repeat(inEntrainment, 3) + loop + loop
               + std::vector<Vec3>{inSpout},
           0.0, 0.25);
    const ResidenceDistribution& c = stats.residence(CirculationStatistics::cycle);
    ASSERT_EQ(c.all.samples, 2); // 1.0 -> 2.0, 2.0 -> 3.0
    EXPECT_NEAR(c.all.mean(), 1.0, 1e-12);
    EXPECT_NEAR(c.all.std(), 0.0, 1e-12);
    // entrainment: from 0.25 (entered from the incomplete downcomer) to 1.0
    const ResidenceDistribution& e = stats.residence(entrainmentRegion);
    ASSERT_EQ(e.all.samples, 3);
    EXPECT_NEAR(e.all.sum, 0.75 + 0.25 + 0.25, 1e-12);
}

// The visits open at the end of that cycle, by their time so far: the
// fountain entered at the last sample (1.5 s, so 0.1 s so far) and the cycle from the spout entry
// at 1.1 s (0.5 s); the incomplete first visit of a particle seen in one
// state all the window long has no known entry and is not among them.
TEST(CirculationStatistics, CensoredAtEndByHand)
{
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    std::vector<double> track = freshTrack();
    followOneCycle(stats, track);
    ASSERT_NEAR(track[1], 1.5, 1e-12);
    ASSERT_NEAR(track[2], 1.1, 1e-12);
    std::vector<double> spanning = freshTrack();
    follow(stats, spanning, repeat(inDowncomer, 16), 0.0, 0.1);
    const auto open =
        CirculationStatistics::censoredAtEnd({track.data(), spanning.data()}, 1.5, 0.1, 0.05, 40);
    for (std::size_t k = 0; k < open.size(); ++k)
    {
        ASSERT_EQ(open[k].size(), 40u);
        const double n = std::accumulate(open[k].begin(), open[k].end(), 0.0);
        const bool expected = k == fountainRegion || k == CirculationStatistics::cycle;
        EXPECT_EQ(n, expected ? 1.0 : 0.0) << k;
    }
    EXPECT_EQ(open[fountainRegion][2], 1.0);                // 0.1 s: [0.10, 0.15)
    EXPECT_EQ(open[CirculationStatistics::cycle][10], 1.0); // 0.5 s: [0.50, 0.55)
    // an age beyond the bins counts in the last
    const auto few = CirculationStatistics::censoredAtEnd({track.data()}, 1.5, 0.1, 0.05, 4);
    EXPECT_EQ(few[CirculationStatistics::cycle][3], 1.0);
}

// Every entry into a state in the window is either a completed visit or
// one still open at the end: per state, completed + censored = entries,
// whatever the phases of the particles against the window.
TEST(CirculationStatistics, EveryEntryIsCompletedOrCensored)
{
    CirculationStatistics stats(bed, 0.35, 100.0, 0.1);
    const std::vector<Vec3> loop =
        repeat(inSpout, 3) + repeat(inFountain, 2) + repeat(inDowncomer, 7) + repeat(inEntrainment, 2);
    std::vector<std::vector<double>> tracks;
    for (int phase = 0; phase < 11; ++phase)
    {
        std::vector<Vec3> places;
        for (int k = 0; k < 40; ++k) places.push_back(loop[std::size_t(k + phase) % loop.size()]);
        tracks.push_back(freshTrack());
        for (std::size_t k = 0; k < places.size(); ++k)
            stats.observe(0.05 * double(k), places[k], tracks.back().data(), {});
    }
    std::vector<double*> pointers;
    for (std::vector<double>& t : tracks) pointers.push_back(t.data());
    const auto open = CirculationStatistics::censoredAtEnd(pointers, 0.05 * 39, 0.05, 0.1, 30);
    for (int s = 0; s < nCirculationRegions; ++s)
    {
        const double censored =
            std::accumulate(open[std::size_t(s)].begin(), open[std::size_t(s)].end(), 0.0);
        EXPECT_EQ(stats.residence(s).all.samples + censored, stats.entries(s)) << circulationRegionName(s);
    }
    // a cycle begins at each spout entry: completed or open, one per entry
    const auto& c = open[CirculationStatistics::cycle];
    const double cycles = std::accumulate(c.begin(), c.end(), 0.0);
    EXPECT_EQ(stats.residence(CirculationStatistics::cycle).all.samples + cycles, stats.entries(spoutRegion));
}

// Flicker at the plates' upper edge and a fountain particle falling back
// into the spout do not change the state; neither do the plate (no region)
// nor a fall out of the spout's bottom into the entrainment zone.
TEST(CirculationStatistics, FlickerAndFallBackKeepTheState)
{
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    std::vector<double> track = freshTrack();
    const Vec3 justBelow{0.0, 0.02, 0.9119}, justAbove{0.0, 0.02, 0.9121};
    // 0.0 spout (incomplete), 0.1 spout, 0.2 entrainment (fall out of the
    // bottom: previous, kept), 0.3 spout, 0.4 fountain (entered), 0.5 spout
    // (fall-back), 0.6 fountain, 0.7 just below (spout), 0.8 just above,
    // 0.9 downcomer (entered), 1.0 the plate (no region), 1.1 fountain
    // (previous), 1.2 downcomer, 1.3 entrainment (entered), 1.4 downcomer
    // (previous), 1.5 spout (entered)
    const Vec3 inPlate{0.03, 0.02, 0.5};
    follow(stats, track,
           {inSpout, inSpout, inEntrainment, inSpout, justAbove, inSpout, inFountain, justBelow, justAbove,
            inDowncomer, inPlate, inFountain, inDowncomer, inEntrainment, inDowncomer, inSpout},
           0.0, 0.1);
    EXPECT_EQ(stats.entries(fountainRegion), 1);
    EXPECT_EQ(stats.entries(downcomerRegion), 1);
    EXPECT_EQ(stats.entries(entrainmentRegion), 1);
    EXPECT_EQ(stats.entries(spoutRegion), 1);
    EXPECT_NEAR(stats.residence(fountainRegion).all.mean(), 0.5, 1e-12);
    EXPECT_NEAR(stats.residence(downcomerRegion).all.mean(), 0.4, 1e-12);
    EXPECT_NEAR(stats.residence(entrainmentRegion).all.mean(), 0.2, 1e-12);
    EXPECT_EQ(stats.residence(spoutRegion).all.samples, 0); // the first, incomplete visit
    EXPECT_EQ(stats.skippedSamples(), 0);
    // holdup counts the state, not the region: the fountain state held the
    // particle at 0.4 .. 0.8 (5 sampling times) of 16
    EXPECT_NEAR(stats.holdup(fountainRegion), 5.0 / 16, 1e-15);
}

// Found two regions ahead (spout state, found in the downcomer) is counted
// as a skipped sample and changes nothing.
TEST(CirculationStatistics, SkippedRegionIsCountedNotFollowed)
{
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    std::vector<double> track = freshTrack();
    follow(stats, track, {inSpout, inDowncomer, inDowncomer}, 0.0, 0.1);
    EXPECT_EQ(stats.skippedSamples(), 2);
    EXPECT_EQ(track[0], spoutRegion);
}

// Before the averaging start nothing is tracked or summed: a particle seen
// first at the start in the downcomer counts that visit as incomplete.
TEST(CirculationStatistics, NothingBeforeTheAveragingStart)
{
    CirculationStatistics stats(bed, 1.0, 100.0, 0.05);
    std::vector<double> track = freshTrack();
    // 0.0 .. 0.9 spout, fountain, downcomer (before the start); from 1.0 downcomer
    // (incomplete), 1.1 entrainment (entered), 1.3 spout (entered)
    follow(stats, track,
           repeat(inSpout, 4) + repeat(inFountain, 3) + repeat(inDowncomer, 4) + repeat(inEntrainment, 2)
               + repeat(inSpout, 1),
           0.0, 0.1);
    EXPECT_EQ(stats.sampleTimes(), 4); // 1.0, 1.1, 1.2, 1.3
    EXPECT_EQ(stats.residence(downcomerRegion).all.samples, 0);
    ASSERT_EQ(stats.residence(entrainmentRegion).all.samples, 1);
    EXPECT_NEAR(stats.residence(entrainmentRegion).all.mean(), 0.2, 1e-12);
    EXPECT_NEAR(stats.holdup(downcomerRegion), 1.0 / 4, 1e-15);
}

// Bins cover [i w, (i + 1) w): with w = 0.1, residences 0.05 (bin 0),
// 0.1 (bin 1), 0.25 (bin 2), 0.3 (bin 3); visits ending before the split
// (t = 2) go to the first half, those beginning after it to the second. 0.65 - 0.55 is 0.0999... in doubles:
// a residence on a bin edge, a whole number of sampling intervals, must still count in the upper bin.
TEST(CirculationStatistics, HistogramBinsAndHalves)
{
    CirculationStatistics stats(bed, 0.0, 2.0, 0.1);
    // four particles, each one completed fountain visit of its own length,
    // sampled every 0.05 s: enter the fountain at t0 + 0.05, leave after tau
    struct Visit
    {
        double t0, tau;
    };
    // the fifth enters at 1.95 and leaves at 2.05: it straddles the split
    // and counts in neither half
    const std::vector<Visit> visits = {{0.0, 0.05}, {0.5, 0.1}, {2.0, 0.25}, {3.0, 0.3}, {1.9, 0.1}};
    for (const Visit& v : visits)
    {
        std::vector<double> track = freshTrack();
        const int inFountainSteps = int(std::lround(v.tau / 0.05));
        follow(stats, track,
               std::vector<Vec3>{inSpout} + repeat(inFountain, inFountainSteps) + repeat(inDowncomer, 1),
               v.t0, 0.05);
    }
    const ResidenceDistribution& f = stats.residence(fountainRegion);
    ASSERT_EQ(f.all.samples, 5);
    ASSERT_GE(f.counts.size(), 4u);
    EXPECT_EQ(f.counts[0], 1);
    EXPECT_EQ(f.counts[1], 2);
    EXPECT_EQ(f.counts[2], 1);
    EXPECT_EQ(f.counts[3], 1);
    EXPECT_EQ(f.half(0).samples, 2);
    EXPECT_EQ(f.half(1).samples, 2);
    EXPECT_NEAR(f.half(0).mean(), 0.075, 1e-12);
    EXPECT_NEAR(f.half(1).mean(), 0.275, 1e-12);
    // sample standard deviation of 0.25 and 0.3: 0.05/sqrt(2)
    EXPECT_NEAR(f.half(1).std(), 0.05 / std::sqrt(2.0), 1e-12);
    // the halves of 2 s in batches of 0.5 s, a visit in the one it ends in:
    // 0.1 and 0.65 s in the first half's first two, 2.3 s in the second
    // half's first, 3.35 s in its third
    const std::vector<double> batchSamples = {1, 1, 0, 0, 1, 0, 1, 0};
    for (std::size_t b = 0; b < batchSamples.size(); ++b)
        EXPECT_EQ(f.batches[b].samples, batchSamples[b]) << b;
    EXPECT_NEAR(f.batches[6].sum, 0.3, 1e-12);
}

// A pack written before the halves had batches (all, first half, second
// half per distribution) unpacks to the same statistics, each half's
// moments in its first batch.
TEST(CirculationStatistics, PackWithoutBatchesUpgrades)
{
    CirculationStatistics stats(bed, 0.0, 1.0, 0.05);
    std::vector<double> a = freshTrack(), b = freshTrack();
    follow(stats, a,
           repeat(inSpout, 2) + repeat(inFountain, 3) + repeat(inDowncomer, 2) + repeat(inEntrainment, 2)
               + repeat(inSpout, 3) + repeat(inFountain, 2) + repeat(inDowncomer, 6),
           0.0, 0.1);
    follow(stats, b,
           repeat(inFountain, 14) + repeat(inDowncomer, 1) + repeat(inEntrainment, 1) + repeat(inSpout, 4),
           0.0, 0.1);
    // the old layout: the new one with each distribution's batches summed
    // into its halves
    const std::vector<double> now = stats.pack();
    const std::size_t perDistribution = 3 * (1 + 2 * ResidenceDistribution::batchesPerHalf);
    const std::size_t distributions = CirculationStatistics::cycle + 1;
    std::size_t momentsAt = now.size() - 1 - distributions * stats.bins() - distributions * perDistribution;
    std::vector<double> old(now.begin(), now.begin() + long(momentsAt));
    for (int i = 0; i <= CirculationStatistics::cycle; ++i)
    {
        const ResidenceDistribution& d = stats.residence(i);
        for (const Moments& m : {d.all, d.half(0), d.half(1)})
            old.insert(old.end(), {m.samples, m.sum, m.sumSquares});
    }
    old.insert(old.end(), now.begin() + long(momentsAt + distributions * perDistribution), now.end());
    CirculationStatistics restored(bed, 0.0, 1.0, 0.05);
    restored.unpack(CirculationStatistics::withoutBatchesUpgraded(old));
    for (int i = 0; i <= CirculationStatistics::cycle; ++i)
    {
        const ResidenceDistribution &d = stats.residence(i), &r = restored.residence(i);
        EXPECT_EQ(r.all.sum, d.all.sum) << i;
        std::vector<double> counts = d.counts;
        counts.resize(r.counts.size(), 0.0); // packed to the longest histogram
        EXPECT_EQ(r.counts, counts) << i;
        for (int h = 0; h < 2; ++h)
        {
            EXPECT_EQ(r.half(h).samples, d.half(h).samples) << i;
            EXPECT_EQ(r.half(h).sumSquares, d.half(h).sumSquares) << i;
            EXPECT_EQ(r.batches[std::size_t(h * ResidenceDistribution::batchesPerHalf)].samples,
                      d.half(h).samples);
        }
    }
    EXPECT_GT(stats.residence(fountainRegion).half(0).samples, 0);
    EXPECT_GT(stats.residence(fountainRegion).half(1).samples, 0);
    EXPECT_EQ(restored.entries(spoutRegion), stats.entries(spoutRegion));
    EXPECT_EQ(restored.pack().size(), now.size());
    EXPECT_THROW(CirculationStatistics::withoutBatchesUpgraded(std::vector<double>(3, 0.0)),
                 std::invalid_argument);
}

// What a particle sees is averaged per state over its samples.
TEST(CirculationStatistics, ConditionsPerState)
{
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    std::vector<double> a = freshTrack(), b = freshTrack();
    ParticleSample hot;
    hot.voidage = 0.9;
    hot.Tgas = 400;
    ParticleSample cool;
    cool.voidage = 0.5;
    cool.Tgas = 300;
    stats.observe(0.0, inSpout, a.data(), hot);
    stats.observe(0.0, inSpout, b.data(), cool);
    stats.endSample(0.0);
    stats.observe(0.1, inSpout, a.data(), cool);
    stats.observe(0.1, inDowncomer, b.data(), hot); // b: spout state still
    stats.endSample(0.1);
    EXPECT_NEAR(stats.holdup(spoutRegion), 2.0, 1e-15);
    EXPECT_NEAR(stats.meanSeen(spoutRegion, 0), (0.9 + 0.5 + 0.5 + 0.9) / 4, 1e-15);
    EXPECT_NEAR(stats.meanSeen(spoutRegion, 4), 350.0, 1e-12);
    EXPECT_EQ(stats.meanSeen(downcomerRegion, 4), 0.0);
}

// The jet: samples of the entrainment state under the spout (|x| <= Wd/2,
// z < He), not those beside it, nor a spout particle fallen back into it.
TEST(CirculationStatistics, JetIsTheEntrainmentStateUnderTheSpout)
{
    EXPECT_TRUE(bed.inJet(0.0275, 0.094));
    EXPECT_FALSE(bed.inJet(0.0276, 0.094));
    EXPECT_FALSE(bed.inJet(0.0, 0.095));
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    std::vector<double> jet = freshTrack(), beside = freshTrack(), fallen = freshTrack();
    ParticleSample hot;
    hot.Tgas = 420;
    ParticleSample cool;
    cool.Tgas = 350;
    const Vec3 besideJet{0.1, 0.02, 0.05};
    stats.observe(0.0, inEntrainment, jet.data(), hot);
    stats.observe(0.0, besideJet, beside.data(), cool);
    stats.observe(0.0, inSpout, fallen.data(), cool);
    stats.endSample(0.0);
    stats.observe(0.1, inEntrainment, jet.data(), hot);
    stats.observe(0.1, inEntrainment, beside.data(), hot);  // beside moved into the jet
    stats.observe(0.1, inEntrainment, fallen.data(), cool); // spout state still
    stats.endSample(0.1);
    EXPECT_NEAR(stats.holdup(entrainmentRegion), 2.0, 1e-15);
    EXPECT_NEAR(stats.coreHoldup(entrainmentRegion), 1.5, 1e-15);
    EXPECT_NEAR(stats.meanSeenInCore(entrainmentRegion, 4), 420.0, 1e-12);
    EXPECT_NEAR(stats.meanSeen(entrainmentRegion, 4), (420.0 * 3 + 350) / 4, 1e-12);
}

// Each completed entrainment visit: the share of its samples in the jet.
TEST(CirculationStatistics, JetFractionPerVisit)
{
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    const Vec3 besideJet{0.1, 0.02, 0.05};
    std::vector<double> a = freshTrack(), b = freshTrack(), c = freshTrack();
    follow(stats, a,
           repeat(inDowncomer, 1) + repeat(besideJet, 3) + repeat(inEntrainment, 1) + repeat(inSpout, 1), 0.0,
           0.1);
    follow(stats, b, repeat(inDowncomer, 1) + repeat(inEntrainment, 2) + repeat(inSpout, 1), 0.0, 0.1);
    // first seen in the zone: an incomplete visit, not counted
    follow(stats, c, repeat(inEntrainment, 2) + repeat(inSpout, 1), 0.0, 0.1);
    const auto& f = stats.coreFractions(entrainmentRegion);
    EXPECT_EQ(f[5], 1.0);  // 1 of 4 samples: 0.25
    EXPECT_EQ(f[19], 1.0); // all: the last bin, closed
    EXPECT_EQ(std::accumulate(f.begin(), f.end(), 0.0), 2.0);
    CirculationStatistics restored(bed, 0.0, 100.0, 0.05);
    restored.unpack(stats.pack());
    EXPECT_EQ(restored.coreFractions(entrainmentRegion), f);
}

// The fountain's core: its samples over the spout (|x| <= Wd/2) and those
// fallen back into the spout, not those over the downcomers; each completed
// fountain visit's share in it. The jet's sums stay apart.
TEST(CirculationStatistics, FountainCoreIsTheFountainStateOverTheSpout)
{
    EXPECT_TRUE(bed.inCore(fountainRegion, 0.0275, 1.0));
    EXPECT_FALSE(bed.inCore(fountainRegion, 0.0276, 1.0));
    EXPECT_TRUE(bed.inCore(fountainRegion, 0.0, 0.5)); // fallen back into the spout
    EXPECT_FALSE(bed.inCore(spoutRegion, 0.0, 0.5));
    EXPECT_FALSE(bed.inCore(downcomerRegion, 0.0, 0.5));
    EXPECT_EQ(bed.inCore(entrainmentRegion, 0.0, 0.05), bed.inJet(0.0, 0.05));
    CirculationStatistics stats(bed, 0.0, 100.0, 0.05);
    const Vec3 overAnnulus{0.1, 0.02, 1.0};
    ParticleSample hot, cool;
    hot.Tgas = 390;
    cool.Tgas = 355;
    std::vector<double> a = freshTrack(), b = freshTrack();
    follow(stats, a, repeat(inSpout, 1), 0.0, 0.1);
    follow(stats, a, repeat(inFountain, 1), 0.1, 0.1, hot);
    follow(stats, a, repeat(overAnnulus, 3), 0.2, 0.1, cool);
    follow(stats, a, repeat(inDowncomer, 1), 0.5, 0.1);
    follow(stats, b, repeat(inSpout, 1) + repeat(inFountain, 2) + repeat(inDowncomer, 1), 0.0, 0.1, hot);
    const auto& f = stats.coreFractions(fountainRegion);
    EXPECT_EQ(f[5], 1.0);  // a: 1 of 4 samples over the spout
    EXPECT_EQ(f[19], 1.0); // b: all
    EXPECT_EQ(std::accumulate(f.begin(), f.end(), 0.0), 2.0);
    EXPECT_EQ(std::accumulate(stats.coreFractions(entrainmentRegion).begin(),
                              stats.coreFractions(entrainmentRegion).end(), 0.0),
              0.0);
    // 3 core samples of 6 fountain samples, over the sampling times counted
    EXPECT_NEAR(stats.coreHoldup(fountainRegion) / stats.holdup(fountainRegion), 0.5, 1e-15);
    EXPECT_NEAR(stats.meanSeenInCore(fountainRegion, 4), 390.0, 1e-12);
    EXPECT_EQ(stats.coreHoldup(entrainmentRegion), 0.0);
    CirculationStatistics restored(bed, 0.0, 100.0, 0.05);
    restored.unpack(stats.pack());
    EXPECT_EQ(restored.coreFractions(fountainRegion), f);
    EXPECT_EQ(restored.coreHoldup(fountainRegion), stats.coreHoldup(fountainRegion));
}

// Packed statistics add up over ranks and restore exactly.
TEST(CirculationStatistics, PackAddUnpack)
{
    CirculationStatistics one(bed, 0.0, 1.0, 0.05), two(bed, 0.0, 1.0, 0.05), both(bed, 0.0, 1.0, 0.05);
    std::vector<double> a = freshTrack(), b = freshTrack(), a2 = freshTrack(), b2 = freshTrack();
    const std::vector<Vec3> pathA = repeat(inSpout, 2) + repeat(inFountain, 3) + repeat(inDowncomer, 2);
    const std::vector<Vec3> pathB =
        repeat(inDowncomer, 1) + repeat(inEntrainment, 2) + repeat(inSpout, 20) + repeat(inFountain, 1);
    for (std::size_t k = 0; k < pathB.size(); ++k)
    {
        const double t = 0.1 * double(k);
        const Vec3& pa = pathA[std::min(k, pathA.size() - 1)];
        one.observe(t, pa, a.data(), {});
        two.observe(t, pathB[k], b.data(), {});
        both.observe(t, pa, a2.data(), {});
        both.observe(t, pathB[k], b2.data(), {});
        one.endSample(t);
        two.endSample(t);
        both.endSample(t);
    }
    // the sampling times are the bed's: add counts them once per rank, so
    // the solver adds them on one rank only; here both hold the same count
    std::vector<double> sum = one.pack();
    two.add(sum);
    CirculationStatistics restored(bed, 0.0, 1.0, 0.05);
    restored.unpack(two.pack());
    for (int s = 0; s <= CirculationStatistics::cycle; ++s)
    {
        EXPECT_EQ(restored.residence(s).all.sum, both.residence(s).all.sum) << s;
        EXPECT_EQ(restored.residence(s).counts.size() >= both.residence(s).counts.size(), true);
    }
    EXPECT_EQ(restored.entries(fountainRegion), both.entries(fountainRegion));
    EXPECT_GT(both.coreHoldup(entrainmentRegion), 0.0);
    EXPECT_EQ(restored.coreHoldup(entrainmentRegion) * restored.sampleTimes(),
              both.coreHoldup(entrainmentRegion) * both.sampleTimes());
    EXPECT_EQ(restored.pack().size(), two.pack().size());
    EXPECT_THROW(restored.unpack(std::vector<double>(3, 0.0)), std::invalid_argument);
}

// The solver sums the ranks' packed vectors element by element (MPI_Reduce
// with MPI_SUM) and the master unpacks the sum: that must give what adding
// them one by one gives, the bins' count included.
TEST(CirculationStatistics, ElementWiseSumOfPacksIsTheirAdd)
{
    CirculationStatistics one(bed, 0.0, 1.0, 0.05), two(bed, 0.0, 1.0, 0.05);
    std::vector<double> a = freshTrack(), b = freshTrack();
    const std::vector<Vec3> pathA = repeat(inSpout, 2) + repeat(inFountain, 3) + repeat(inDowncomer, 5);
    const std::vector<Vec3> pathB = repeat(inDowncomer, 1) + repeat(inEntrainment, 2) + repeat(inSpout, 7);
    for (std::size_t k = 0; k < pathA.size(); ++k)
    {
        const double t = 0.1 * double(k);
        one.observe(t, pathA[k], a.data(), {});
        two.observe(t, pathB[k], b.data(), {});
        one.endSample(t);
        two.endSample(t);
    }
    const std::size_t bins = std::max(one.bins(), two.bins());
    ASSERT_GT(bins, 0u);
    std::vector<double> sum = one.pack(bins);
    const std::vector<double> other = two.pack(bins);
    ASSERT_EQ(sum.size(), other.size());
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += other[k];
    CirculationStatistics reduced(bed, 0.0, 1.0, 0.05);
    reduced.unpack(sum);
    one.add(two.pack(bins));
    EXPECT_EQ(reduced.pack(bins), one.pack(bins));
}

// Two ranks holding one particle each of a two-particle bed sample it at the
// same times: their reduced statistics are those of one rank holding both,
// the holdups included (each time counted once, not once per rank).
TEST(CirculationStatistics, RanksSharingSamplingTimesReduceToTheWholeBed)
{
    CirculationStatistics whole(bed, 0.0, 1.0, 0.05), rankA(bed, 0.0, 1.0, 0.05), rankB(bed, 0.0, 1.0, 0.05);
    std::vector<double> a = freshTrack(), b = freshTrack(), wa = freshTrack(), wb = freshTrack();
    const std::vector<Vec3> pathA = repeat(inSpout, 2) + repeat(inFountain, 3) + repeat(inDowncomer, 5);
    const std::vector<Vec3> pathB = repeat(inDowncomer, 6) + repeat(inEntrainment, 2) + repeat(inSpout, 2);
    for (std::size_t k = 0; k < pathA.size(); ++k)
    {
        const double t = 0.1 * double(k);
        rankA.observe(t, pathA[k], a.data(), {});
        rankB.observe(t, pathB[k], b.data(), {});
        whole.observe(t, pathA[k], wa.data(), {});
        whole.observe(t, pathB[k], wb.data(), {});
        rankA.endSample(t);
        rankB.endSample(t);
        whole.endSample(t);
    }
    const std::size_t bins = std::max(rankA.bins(), rankB.bins());
    std::vector<double> sum = rankA.pack(bins, true);
    const std::vector<double> other = rankB.pack(bins, false);
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += other[k];
    CirculationStatistics reduced(bed, 0.0, 1.0, 0.05);
    reduced.unpack(sum);
    EXPECT_EQ(reduced.sampleTimes(), 10.0);
    // by hand: A is 5 of 10 times in the downcomer, B 6; 2 and 2 in the spout
    EXPECT_NEAR(reduced.holdup(downcomerRegion), (5.0 + 6.0) / 10, 1e-15);
    EXPECT_NEAR(reduced.holdup(spoutRegion), (2.0 + 2.0) / 10, 1e-15);
    EXPECT_EQ(reduced.pack(bins), whole.pack(bins));
}
