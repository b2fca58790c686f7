#pragma once
// Circulation statistics of a draft-plate spouted bed (issue 24 item 1): each
// particle's sequence of regions, the residence time in each and the time of a
// whole cycle, and what a particle sees in each.
//
// Regions (x across, z up, origin at the centre of the inlet slot; SI):
//   spout        |x| <= Wd/2,                 He <= z < Hd
//   fountain     z >= Hd (at any x)
//   downcomer    |x| >= Wd/2 + plateThickness, He <= z < Hd
//   entrainment  z < He (at any x)
// and none inside a plate (Wd/2 < |x| < Wd/2 + plateThickness, He <= z < Hd),
// where no particle can be. Two states hold two gases each, one in the
// state's core over or under the spout (|x| <= Wd/2) and one beside it (the
// gas's compartments, not particle states): the jet is the entrainment
// state's core, z < He, where the inlet gas rises hot and dry, while beside
// it the kernels sliding off the downcomers meet the little gas that seeps
// towards them; the fountain's core is the spout's gas rising above the
// plates (and a fountain particle fallen back into the spout), beside it the
// gas that seeped up the downcomers.
//
// A particle's state advances only in the cycle order
//   spout -> fountain -> downcomer -> entrainment -> spout:
// it enters the next state when it is first found in that region; found in any
// other region (flicker at a boundary, a fountain particle falling back into
// the spout) the state stays. The residence time of a state is the time from
// entering it to entering the next; the cycle time the time between two
// successive entries into the spout. Tracking starts at the averaging start:
// the state a particle is first found in there is an incomplete visit and not
// counted, nor the first cycle until its first entry into the spout.
//
// Each particle's track is trackWidth doubles kept with the particle (in the
// solver a LIGGGHTS per-atom property, so it follows the atom across ranks and
// into restarts): the state (-1 before the particle is first seen), the time
// it entered the state (-1: an incomplete visit), the time of its last
// entry into the spout (-1: none yet), and the samples of the visit so far,
// all and those in its state's core. An incomplete visit keeps the time t it
// was first seen as -1 - t. Each completed visit of a state with a core adds
// the share of its samples found in the core to that core's histogram
// (coreFractions, bins of 1/nCoreFractionBins): how much of its time in the
// zone a kernel spends in the core varies from visit to visit.
//
// Little's law over the finite window, with its boundary terms, holds exactly
// per state: holdup x window = the completed residences + the time of the
// incomplete first visits that ended in the window (openAtStart) + the time
// in the window of the visits still open at its end (openAtEnd, from the
// tracks), each sample counting one sampling interval. The visits open at the
// end whose entry is known are also binned by their time so far
// (censoredAtEnd): with the completed ones, every entry into a state in the
// window, so that a window shorter than the longest visits still gives
// their distribution (Kaplan-Meier) where the completed ones alone would
// keep only the short.
//
// Per state, over every sample (particle in the state at a sampling time):
// the holdup (particles per sampling time) and the mean of what the particle
// sees (ParticleSample). Residence times go into a histogram (bin i covers
// [i w, (i + 1) w)) and into the moments of the whole window and of its two
// halves, each half taken as a window of its own: a visit counts in the half
// in which it begins and ends (one straddling the split in neither), so that
// both halves cut long visits off alike and agree for a steady bed. Each
// half's moments are kept in batchesPerHalf batches of equal length, a visit
// in the batch it ends in: successive visits are not independent (a slug
// carries many particles through the spout together), and the scatter of the
// batch means gives the half's mean an error that counts that (batch means).
//
// Everything the statistics hold is a sum: pack() gives it as one vector
// whose element-wise sum over the ranks (packed to the same number of bins)
// is the statistics of the whole bed (add), and unpack() restores a packed
// vector (restarts).

#include "Vec3.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace spoutlab
{

enum CirculationRegion : int
{
    noRegion = -1,
    spoutRegion = 0,
    fountainRegion = 1,
    downcomerRegion = 2,
    entrainmentRegion = 3
};
constexpr int nCirculationRegions = 4;

// "spout", "fountain", "downcomer", "entrainment"
const char* circulationRegionName(int region);

class DraftPlateRegions
{
public:
    // lengths in m; throws InputError naming `context` unless
    // 0 < Wd, 0 <= plateThickness, He < Hd
    DraftPlateRegions(double Wd, double He, double Hd, double plateThickness,
                      const std::string& context = "draft-plate regions");

    int region(double x, double z) const;
    bool inJet(double x, double z) const { return z < He_ && std::fabs(x) <= 0.5 * Wd_; }
    // a particle of `state` at (x, z) in that state's core (the jet, the
    // fountain's core); false for the states without one
    bool inCore(int state, double x, double z) const
    {
        return state == entrainmentRegion ? inJet(x, z)
                                          : state == fountainRegion && std::fabs(x) <= 0.5 * Wd_;
    }

    double Wd() const { return Wd_; }
    double He() const { return He_; }
    double Hd() const { return Hd_; }
    double plateThickness() const { return thickness_; }

private:
    double Wd_, He_, Hd_, thickness_;
};

// What one particle sees at a sampling time (weighted over its cells).
struct ParticleSample
{
    double voidage = 0;   // eps
    double slipRe = 0;    // Re = eps rho |u - Us| d/mu
    double h = 0;         // [W m^-2 K^-1]
    double km = 0;        // [m/s]
    double Tgas = 0;      // [K]
    double Y = 0;         // vapour mass fraction
    double Tparticle = 0; // [K]
};
constexpr int nSampleQuantities = 7;

struct Moments
{
    double samples = 0, sum = 0, sumSquares = 0;

    void add(double value);
    double mean() const;
    double std() const; // sample standard deviation (n - 1); 0 below two samples
    Moments& operator+=(const Moments& other);
};

struct ResidenceDistribution
{
    static constexpr int batchesPerHalf = 4;
    std::vector<double> counts; // per bin
    Moments all;
    // the first half's batches, then the second's
    std::array<Moments, 2 * batchesPerHalf> batches;

    Moments half(int h) const; // h = 0, 1: the sum of its batches
};

class CirculationStatistics
{
public:
    static constexpr int trackWidth = 5;
    static constexpr int nCoreFractionBins = 20;
    // the states with a core, in the order of the core index
    static constexpr std::array<int, 2> coreStates = {entrainmentRegion, fountainRegion};
    // a state's core index, -1 without a core
    static constexpr int coreOf(int state)
    {
        return state == entrainmentRegion ? 0 : state == fountainRegion ? 1 : -1;
    }
    static constexpr int cycle = nCirculationRegions; // index of the cycle's distribution

    // averageStart: tracking and sums start at samples t >= averageStart;
    // halfSplit: the time between the window's two halves; binWidth > 0 [s]
    CirculationStatistics(const DraftPlateRegions& regions, double averageStart, double halfSplit,
                          double binWidth);

    // One particle at sampling time t: its track advanced, its sample added
    // to its state's sums. Nothing before averageStart.
    void observe(double t, const Vec3& x, double* track, const ParticleSample& seen);
    // After the particles of a sampling time: one more sampling time.
    void endSample(double t);

    const DraftPlateRegions& regions() const { return regions_; }
    double averageStart() const { return averageStart_; }
    double binWidth() const { return binWidth_; }
    double sampleTimes() const { return sampleTimes_; }

    // index 0..3 a state, cycle the cycle
    const ResidenceDistribution& residence(int index) const { return residence_[index]; }
    // entries into a state (transitions observed into it)
    double entries(int state) const { return entries_[state]; }
    // mean particles in the state per sampling time
    double holdup(int state) const;
    // mean of a ParticleSample quantity (0..nSampleQuantities-1, in the
    // struct's order) over the samples in the state; 0 without samples
    double meanSeen(int state, int quantity) const;
    // the same over the samples of a state (with a core) found in its core
    double coreHoldup(int state) const;
    double meanSeenInCore(int state, int quantity) const;
    // its completed visits by the share of their samples in the core
    // (bin i: [i, i + 1) / nCoreFractionBins, the last closed)
    const std::array<double, nCoreFractionBins>& coreFractions(int state) const
    {
        return cores_[std::size_t(coreOf(state))].fractions;
    }
    // samples of particles found in the region two steps ahead of their state
    // (a skipped region: the sampling was too coarse), over all states
    double skippedSamples() const { return skipped_; }
    // time of the incomplete first visits in the state that ended [s]
    double openAtStart(int state) const { return openStart_[std::size_t(state)]; }
    // time in the window of the visits open at the last sample tLast, per
    // state, over the tracks given (one rank's particles) [s]
    static std::array<double, nCirculationRegions> openAtEnd(const std::vector<double*>& tracks, double tLast,
                                                             double dt);
    // The visits open at tLast whose entry lies in the window, per
    // distribution (the states, then the cycle: since the last spout entry),
    // by their time so far, tLast - entry + dt, in `bins` bins of binWidth
    // (longer ones in the last): residences known only to last at least that
    // long (right-censored), which a window shorter than the longest visits
    // leaves out of the completed ones and Kaplan-Meier puts back.
    static std::array<std::vector<double>, nCirculationRegions + 1>
    censoredAtEnd(const std::vector<double*>& tracks, double tLast, double dt, double binWidth,
                  std::size_t bins);

    // the packed histograms hold at least `bins` bins each (ranks pack to
    // the same length); bins() is this one's longest histogram. Ranks that
    // hold parts of one bed sample it at the same times: only one of them
    // (countsSampleTimes) may count those times in its pack, or the sum
    // over the ranks would count every time once per rank.
    std::vector<double> pack(std::size_t bins = 0, bool countsSampleTimes = true) const;
    std::size_t bins() const;
    void unpack(const std::vector<double>& packed); // throws std::invalid_argument on a size mismatch
    // A pack written before the halves had batches (each distribution's
    // moments: all, first half, second half) in today's layout, each half's
    // moments in its first batch
    static std::vector<double> withoutBatchesUpgraded(const std::vector<double>& packed);
    void add(const std::vector<double>& packed);
    void clear();

private:
    DraftPlateRegions regions_;
    double averageStart_, halfSplit_, binWidth_;
    std::array<ResidenceDistribution, nCirculationRegions + 1> residence_;
    std::array<double, nCirculationRegions> entries_{};
    std::array<double, nCirculationRegions> occupancy_{}; // particle samples per state
    std::array<double, nCirculationRegions> openStart_{};
    std::array<std::array<double, nSampleQuantities>, nCirculationRegions> seen_{};
    struct Core
    {
        double occupancy = 0;
        std::array<double, nSampleQuantities> seen{};
        std::array<double, nCoreFractionBins> fractions{};
    };
    std::array<Core, coreStates.size()> cores_{};
    double sampleTimes_ = 0;
    double skipped_ = 0;

    void addResidence(int index, double tau, double t);
    void enter(double t, int state, double* track);
};

} // namespace spoutlab
