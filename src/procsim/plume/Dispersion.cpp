#include "plume/Dispersion.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

namespace procsim::plume
{

namespace
{

void checkClass(int cls)
{
    if (cls < 1 || cls > 6) throw std::invalid_argument("stability class must be 1..6");
}

// One distance range of sigma_z = a x^b: valid for x below `below` [km].
struct PowerLawRange
{
    double below, a, b;
};

// ISC3 vol. II Table 1-2 (rural), ranges in increasing distance; the last
// range of each class is open-ended.
const std::vector<PowerLawRange>& isc3SigmaZRanges(int cls)
{
    constexpr double open = HUGE_VAL;
    static const std::vector<PowerLawRange> table[6] = {
        {{0.10, 122.800, 0.94470},
         {0.15, 158.080, 1.05420},
         {0.20, 170.220, 1.09320},
         {0.25, 179.520, 1.12620},
         {0.30, 217.410, 1.26440},
         {0.40, 258.890, 1.40940},
         {0.50, 346.750, 1.72830},
         {open, 453.850, 2.11660}},
        {{0.20, 90.673, 0.93198}, {0.40, 98.483, 0.98332}, {open, 109.300, 1.09710}},
        {{open, 61.141, 0.91465}},
        {{0.30, 34.459, 0.86974},
         {1.00, 32.093, 0.81066},
         {3.00, 32.093, 0.64403},
         {10.00, 33.504, 0.60486},
         {30.00, 36.650, 0.56589},
         {open, 44.053, 0.51179}},
        {{0.10, 24.260, 0.83660},
         {0.30, 23.331, 0.81956},
         {1.00, 21.628, 0.75660},
         {2.00, 21.628, 0.63077},
         {4.00, 22.534, 0.57154},
         {10.00, 24.703, 0.50527},
         {20.00, 26.970, 0.46713},
         {40.00, 35.420, 0.37615},
         {open, 47.618, 0.29592}},
        {{0.20, 15.209, 0.81558},
         {0.70, 14.457, 0.78407},
         {1.00, 13.953, 0.68465},
         {2.00, 13.953, 0.63227},
         {3.00, 14.823, 0.54503},
         {7.00, 16.187, 0.46490},
         {15.00, 17.836, 0.41507},
         {30.00, 22.651, 0.32681},
         {60.00, 27.074, 0.27436},
         {open, 34.219, 0.21716}}};
    return table[cls - 1];
}

// Table 1-2 ends the unstable curves at 5000 m (class A reaches it near 3.1 km)
constexpr double unstableSigmaZCap = 5000.0;

using Factory = std::function<std::unique_ptr<DispersionCurves>()>;

// the known curves by name, the default first
const std::vector<std::pair<std::string, Factory>>& registry()
{
    static const std::vector<std::pair<std::string, Factory>> known = {
        {"isc3_rural", [] { return std::make_unique<Isc3RuralCurves>(); }},
        {"briggs_rural", [] { return std::make_unique<BriggsRuralCurves>(); }}};
    return known;
}

} // namespace

std::unique_ptr<DispersionCurves> DispersionCurves::create(const std::string& name)
{
    for (const auto& [known, make] : registry())
        if (known == name) return make();
    return nullptr;
}

const std::vector<std::string>& DispersionCurves::curveNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& entry : registry()) n.push_back(entry.first);
        return n;
    }();
    return names;
}

// ISC3 vol. II Table 1-1 (rural): TH = c - d ln x [deg], x in km, is the
// half-angle at which the concentration falls to a tenth of the axis value,
// 2.15 sigma_y off the axis: hence 465.11628 = 1000 m/km / 2.15.
double Isc3RuralCurves::sigmaY(int cls, double x) const
{
    checkClass(cls);
    static const double c[6] = {24.1670, 18.3330, 12.5000, 8.3330, 6.2500, 4.1667};
    static const double d[6] = {2.5334, 1.8096, 1.0857, 0.72382, 0.54287, 0.36191};
    const double km = x / 1000;
    const double th = 0.017453293 * (c[cls - 1] - d[cls - 1] * std::log(km));
    return 465.11628 * km * std::tan(th);
}

double Isc3RuralCurves::sigmaZ(int cls, double x) const
{
    checkClass(cls);
    const double km = x / 1000;
    const auto& ranges = isc3SigmaZRanges(cls);
    std::size_t r = 0;
    while (km >= ranges[r].below) ++r; // the last range is open-ended
    const double s = ranges[r].a * std::pow(km, ranges[r].b);
    return cls <= 3 ? std::min(s, unstableSigmaZCap) : s;
}

double BriggsRuralCurves::sigmaY(int cls, double x) const
{
    checkClass(cls);
    static const double a[6] = {0.22, 0.16, 0.11, 0.08, 0.06, 0.04};
    return a[cls - 1] * x / std::sqrt(1 + 1e-4 * x);
}

double BriggsRuralCurves::sigmaZ(int cls, double x) const
{
    checkClass(cls);
    switch (cls)
    {
    case 1: return 0.20 * x;
    case 2: return 0.12 * x;
    case 3: return 0.08 * x / std::sqrt(1 + 2e-4 * x);
    case 4: return 0.06 * x / std::sqrt(1 + 1.5e-3 * x);
    case 5: return 0.03 * x / (1 + 3e-4 * x);
    default: return 0.016 * x / (1 + 3e-4 * x);
    }
}

} // namespace procsim::plume
