#include "Circulation.hpp"

#include "InputError.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spoutlab
{

const char* circulationRegionName(int region)
{
    static const char* const names[nCirculationRegions] = {"spout", "fountain", "downcomer", "entrainment"};
    if (region < 0 || region >= nCirculationRegions) return "none";
    return names[region];
}

DraftPlateRegions::DraftPlateRegions(double Wd, double He, double Hd, double plateThickness,
                                     const std::string& context)
    : Wd_(Wd), He_(He), Hd_(Hd), thickness_(plateThickness)
{
    if (!(Wd > 0 && plateThickness >= 0 && He < Hd && std::isfinite(He) && std::isfinite(Hd)))
    {
        throw InputError(context + ": expected a draft-plate geometry with Wd > 0, plateThickness >= 0 and "
                         + "He < Hd, got Wd " + std::to_string(Wd) + ", He " + std::to_string(He) + ", Hd "
                         + std::to_string(Hd) + ", plateThickness " + std::to_string(plateThickness) + " m");
    }
}

int DraftPlateRegions::region(double x, double z) const
{
    if (z >= Hd_) return fountainRegion;
    if (z < He_) return entrainmentRegion;
    const double ax = std::fabs(x);
    if (ax <= 0.5 * Wd_) return spoutRegion;
    if (ax >= 0.5 * Wd_ + thickness_) return downcomerRegion;
    return noRegion;
}

void Moments::add(double value)
{
    samples += 1;
    sum += value;
    sumSquares += value * value;
}

double Moments::mean() const
{
    return samples > 0 ? sum / samples : 0.0;
}

Moments& Moments::operator+=(const Moments& other)
{
    samples += other.samples;
    sum += other.sum;
    sumSquares += other.sumSquares;
    return *this;
}

Moments ResidenceDistribution::half(int h) const
{
    Moments m;
    for (int b = 0; b < batchesPerHalf; ++b) m += batches[std::size_t(h * batchesPerHalf + b)];
    return m;
}

double Moments::std() const
{
    if (samples < 2) return 0.0;
    const double m = mean();
    return std::sqrt(std::max(0.0, (sumSquares - samples * m * m) / (samples - 1)));
}

CirculationStatistics::CirculationStatistics(const DraftPlateRegions& regions, double averageStart,
                                             double halfSplit, double binWidth)
    : regions_(regions), averageStart_(averageStart), halfSplit_(halfSplit), binWidth_(binWidth)
{
    if (!(binWidth > 0)) throw std::invalid_argument("CirculationStatistics: bin width must be > 0");
}

namespace
{

// The histogram bin of a residence tau: residences are whole numbers of
// sampling intervals, often on a bin edge, which round-off would put on
// either side: within 1e-9 of a bin below an edge counts in the upper bin
std::size_t residenceBin(double tau, double binWidth)
{
    return std::size_t(std::max(0.0, std::floor(tau / binWidth + 1e-9)));
}

} // namespace

void CirculationStatistics::addResidence(int index, double tau, double t)
{
    ResidenceDistribution& d = residence_[std::size_t(index)];
    const std::size_t bin = residenceBin(tau, binWidth_);
    if (d.counts.size() <= bin) d.counts.resize(bin + 1, 0.0);
    d.counts[bin] += 1;
    d.all.add(tau);
    // each half a window of its own: a visit counts in the half it begins
    // and ends in, so both halves cut off long visits alike (by the end of
    // the visit alone, the first half would hold only the visits short
    // enough to end in it); one straddling the split counts in neither
    const double begin = t - tau;
    const int half = t < halfSplit_ ? 0 : begin >= halfSplit_ ? 1 : -1;
    if (half < 0) return;
    // its batch by when it ends, counted from the half's start
    const double length = (halfSplit_ - averageStart_) / ResidenceDistribution::batchesPerHalf;
    const double from = half == 0 ? averageStart_ : halfSplit_;
    const int batch = length > 0 ? std::clamp(int(std::floor((t - from) / length)), 0,
                                              ResidenceDistribution::batchesPerHalf - 1)
                                 : 0;
    d.batches[std::size_t(half * ResidenceDistribution::batchesPerHalf + batch)].add(tau);
}

void CirculationStatistics::enter(double t, int state, double* track)
{
    const int left = int(track[0]);
    if (track[1] >= 0)
    {
        addResidence(left, t - track[1], t);
        if (coreOf(left) >= 0 && track[4] > 0)
        {
            const auto bin = std::min(int(track[3] / track[4] * nCoreFractionBins), nCoreFractionBins - 1);
            cores_[std::size_t(coreOf(left))].fractions[std::size_t(bin)] += 1;
        }
    }
    else
        openStart_[std::size_t(left)] += t - (-track[1] - 1);
    track[0] = state;
    track[1] = t;
    track[3] = track[4] = 0;
    entries_[std::size_t(state)] += 1;
    if (state != spoutRegion) return;
    if (track[2] >= 0) addResidence(cycle, t - track[2], t);
    track[2] = t;
}

void CirculationStatistics::observe(double t, const Vec3& x, double* track, const ParticleSample& seen)
{
    if (t < averageStart_) return;
    const int region = regions_.region(x.x, x.z);
    int state = int(track[0]);
    if (state < 0)
    {
        if (region == noRegion) return;
        // first seen: an incomplete visit, its time kept as -1 - t
        track[0] = state = region;
        track[1] = -1 - t;
        track[2] = -1;
        track[3] = track[4] = 0;
    }
    else if (region == (state + 1) % nCirculationRegions)
    {
        enter(t, region, track);
        state = region;
    }
    else if (region == (state + 2) % nCirculationRegions)
    {
        skipped_ += 1;
    }
    const auto s = std::size_t(state);
    occupancy_[s] += 1;
    const double values[nSampleQuantities] = {seen.voidage, seen.slipRe, seen.h,        seen.km,
                                              seen.Tgas,    seen.Y,      seen.Tparticle};
    for (int q = 0; q < nSampleQuantities; ++q) seen_[s][std::size_t(q)] += values[q];
    track[4] += 1;
    if (!regions_.inCore(state, x.x, x.z)) return;
    track[3] += 1;
    Core& core = cores_[std::size_t(coreOf(state))];
    core.occupancy += 1;
    for (int q = 0; q < nSampleQuantities; ++q) core.seen[std::size_t(q)] += values[q];
}

void CirculationStatistics::endSample(double t)
{
    if (t >= averageStart_) sampleTimes_ += 1;
}

double CirculationStatistics::holdup(int state) const
{
    return sampleTimes_ > 0 ? occupancy_[std::size_t(state)] / sampleTimes_ : 0.0;
}

double CirculationStatistics::meanSeen(int state, int quantity) const
{
    const double n = occupancy_[std::size_t(state)];
    return n > 0 ? seen_[std::size_t(state)][std::size_t(quantity)] / n : 0.0;
}

double CirculationStatistics::coreHoldup(int state) const
{
    const double n = cores_[std::size_t(coreOf(state))].occupancy;
    return sampleTimes_ > 0 ? n / sampleTimes_ : 0.0;
}

double CirculationStatistics::meanSeenInCore(int state, int quantity) const
{
    const Core& core = cores_[std::size_t(coreOf(state))];
    return core.occupancy > 0 ? core.seen[std::size_t(quantity)] / core.occupancy : 0.0;
}

std::array<double, nCirculationRegions> CirculationStatistics::openAtEnd(const std::vector<double*>& tracks,
                                                                         double tLast, double dt)
{
    std::array<double, nCirculationRegions> open{};
    for (const double* track : tracks)
    {
        if (track[0] < 0) continue;
        const double entry = track[1] >= 0 ? track[1] : -track[1] - 1;
        open[std::size_t(track[0])] += tLast - entry + dt;
    }
    return open;
}

std::array<std::vector<double>, nCirculationRegions + 1>
CirculationStatistics::censoredAtEnd(const std::vector<double*>& tracks, double tLast, double dt,
                                     double binWidth, std::size_t bins)
{
    std::array<std::vector<double>, nCirculationRegions + 1> open;
    for (std::vector<double>& h : open) h.assign(std::max<std::size_t>(bins, 1), 0.0);
    const auto add = [&](std::size_t index, double entry) {
        const std::size_t bin = residenceBin(tLast - entry + dt, binWidth); // as a completed one
        open[index][std::min(bin, open[index].size() - 1)] += 1;
    };
    for (const double* track : tracks)
    {
        if (track[0] < 0) continue;
        if (track[1] >= 0) add(std::size_t(track[0]), track[1]);
        if (track[2] >= 0) add(std::size_t(cycle), track[2]);
    }
    return open;
}

// Layout: sampleTimes, skipped, entries[4], occupancy[4], openStart[4], seen[4][7],
// per core (entrainment's, fountain's) occupancy, seen[7], fractions[20], per
// distribution (5) the moments all, first, second (3 each), then the number
// of bins n and the 5 histograms of n bins each.
std::size_t CirculationStatistics::bins() const
{
    std::size_t n = 0;
    for (const ResidenceDistribution& d : residence_) n = std::max(n, d.counts.size());
    return n;
}

std::vector<double> CirculationStatistics::pack(std::size_t minBins, bool countsSampleTimes) const
{
    std::vector<double> p = {countsSampleTimes ? sampleTimes_ : 0.0, skipped_};
    p.insert(p.end(), entries_.begin(), entries_.end());
    p.insert(p.end(), occupancy_.begin(), occupancy_.end());
    p.insert(p.end(), openStart_.begin(), openStart_.end());
    for (const auto& row : seen_) p.insert(p.end(), row.begin(), row.end());
    for (const Core& core : cores_)
    {
        p.push_back(core.occupancy);
        p.insert(p.end(), core.seen.begin(), core.seen.end());
        p.insert(p.end(), core.fractions.begin(), core.fractions.end());
    }
    const std::size_t bins = std::max(minBins, this->bins());
    for (const ResidenceDistribution& d : residence_)
    {
        p.insert(p.end(), {d.all.samples, d.all.sum, d.all.sumSquares});
        for (const Moments& m : d.batches) p.insert(p.end(), {m.samples, m.sum, m.sumSquares});
    }
    p.push_back(double(bins));
    for (const ResidenceDistribution& d : residence_)
    {
        for (std::size_t b = 0; b < bins; ++b) p.push_back(b < d.counts.size() ? d.counts[b] : 0.0);
    }
    return p;
}

namespace
{

constexpr std::size_t distributions = nCirculationRegions + 1;
// the pack up to the distributions' moments
constexpr std::size_t momentsAt = 2 + 3 * nCirculationRegions + nCirculationRegions * nSampleQuantities
                                  + CirculationStatistics::coreStates.size()
                                        * (1 + nSampleQuantities + CirculationStatistics::nCoreFractionBins);
// a distribution's moments (samples, sum, sum of squares of all, then of
// each batch), and before the halves had batches (all, first, second half)
constexpr std::size_t momentsPerDistribution = 3 * (1 + 2 * ResidenceDistribution::batchesPerHalf);
constexpr std::size_t momentsWithoutBatches = 9;
constexpr std::size_t fixedPackSize = momentsAt + distributions * momentsPerDistribution;

} // namespace

void CirculationStatistics::add(const std::vector<double>& packed)
{
    if (packed.size() < fixedPackSize + 1)
        throw std::invalid_argument("CirculationStatistics: packed data too short");
    // the bins from the length: the count's slot is, like every other, a
    // sum when the ranks' vectors were summed element by element
    const std::size_t histograms = packed.size() - fixedPackSize - 1;
    const std::size_t bins = histograms / residence_.size();
    if (histograms != bins * residence_.size())
    {
        throw std::invalid_argument("CirculationStatistics: packed data of the wrong size");
    }
    std::size_t k = 0;
    sampleTimes_ += packed[k++];
    skipped_ += packed[k++];
    for (double& e : entries_) e += packed[k++];
    for (double& o : occupancy_) o += packed[k++];
    for (double& o : openStart_) o += packed[k++];
    for (auto& row : seen_)
    {
        for (double& v : row) v += packed[k++];
    }
    for (Core& core : cores_)
    {
        core.occupancy += packed[k++];
        for (double& v : core.seen) v += packed[k++];
        for (double& v : core.fractions) v += packed[k++];
    }
    for (ResidenceDistribution& d : residence_)
    {
        auto addMoments = [&](Moments& m) {
            m.samples += packed[k++];
            m.sum += packed[k++];
            m.sumSquares += packed[k++];
        };
        addMoments(d.all);
        for (Moments& m : d.batches) addMoments(m);
    }
    ++k;
    for (ResidenceDistribution& d : residence_)
    {
        if (d.counts.size() < bins) d.counts.resize(bins, 0.0);
        for (std::size_t b = 0; b < bins; ++b) d.counts[b] += packed[k++];
    }
}

void CirculationStatistics::clear()
{
    residence_ = {};
    entries_ = {};
    occupancy_ = {};
    openStart_ = {};
    seen_ = {};
    cores_ = {};
    sampleTimes_ = 0;
    skipped_ = 0;
}

void CirculationStatistics::unpack(const std::vector<double>& packed)
{
    clear();
    add(packed);
}

std::vector<double> CirculationStatistics::withoutBatchesUpgraded(const std::vector<double>& packed)
{
    if (packed.size() < momentsAt + distributions * momentsWithoutBatches + 1)
        throw std::invalid_argument("CirculationStatistics: packed data too short");
    std::vector<double> p(packed.begin(), packed.begin() + long(momentsAt));
    const double* old = packed.data() + momentsAt;
    for (std::size_t d = 0; d < distributions; ++d, old += momentsWithoutBatches)
    {
        p.insert(p.end(), old, old + 3); // all
        for (int h = 0; h < 2; ++h)
        {
            p.insert(p.end(), old + 3 * (h + 1), old + 3 * (h + 2));
            p.insert(p.end(), 3 * (ResidenceDistribution::batchesPerHalf - 1), 0.0);
        }
    }
    p.insert(p.end(), old, packed.data() + packed.size()); // bins and histograms
    return p;
}

} // namespace spoutlab
