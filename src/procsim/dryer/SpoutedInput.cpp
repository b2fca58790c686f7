#include "dryer/SpoutedInput.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include "CornProperties.hpp"
#include "InputError.hpp" // coupling/'s
#include "MoistAir.hpp"
#include "Psychrometrics.hpp"
#include "SorptionIsotherm.hpp"
#include "common/Checked.hpp"
#include "common/Csv.hpp"
#include "common/Format.hpp"
#include "common/YamlInput.hpp"

namespace procsim::dryer::spouted
{

namespace
{

namespace psy = spoutlab::psy;

// the four regions of the statistics
const std::set<std::string> kRegions = {"entrainment", "spout", "downcomer", "fountain"};
const char* const kGeometry[] = {"Wd", "He", "Hd", "plateThickness", "width", "depth"};

// a physics-core input error (model settings) as procsim's
template <class F>
auto physics(F f) -> decltype(f())
{
    try
    {
        return f();
    }
    catch (const spoutlab::InputError& e)
    {
        throw InputError(e.what());
    }
}

spoutlab::Parameters props(const YamlInput& in, const std::string& key)
{
    spoutlab::Parameters p(in.file() + ": " + key);
    if (!in.has(key)) return p;
    const YamlInput sub = in.child(key);
    for (const std::string& k : sub.keys())
    {
        if (!sub.node()[k].IsScalar()) throw sub.error(k, "a value");
        p.set(k, sub.node()[k].Scalar());
    }
    return p;
}

// r's list `counts` into res.counts (each an integer >= 0); their sum
long readCounts(const YamlInput& r, Residence& res)
{
    const YAML::Node n = r.node()["counts"];
    long sum = 0;
    for (std::size_t i = 0; n && n.IsSequence() && i < n.size(); ++i)
    {
        const auto v = n[i].IsScalar() ? parseInteger(n[i].Scalar(), 0, 2000000000L) : std::nullopt;
        if (!v)
            throw InputError(r.file() + ": key '" + r.path() + ".counts[" + std::to_string(i)
                             + "]' expected a count (an integer >= 0)");
        res.counts.push_back(static_cast<double>(*v));
        sum += *v;
    }
    return sum;
}

// The visits open at the window's end (open) into res, by Kaplan-Meier with
// the tail past the window whose mean makes the whole mean Little's: holdup
// of `states` / entry rate into `entering`.
void censorByLittle(Residence& res, const Residence& open, const YamlInput& r, const YamlInput& conditions,
                    const std::vector<std::string>& states, const std::string& entering)
{
    double holdup = 0;
    for (const std::string& s : states) holdup += conditions.child(s).within("holdup", 0, 1e12);
    const YamlInput into = conditions.child(entering);
    const double rate = into.within("entryRate", 0, 1e12, "1/s");
    if (!(rate > 0)) throw into.error("entryRate", "entries per second above 0");
    // Little's mean is as good as the entry rate, whose count scatters by
    // its square root
    const double entries = into.within("entries", 1, 1e15);
    try
    {
        res.censor(open.counts, holdup / rate, holdup / rate / std::sqrt(entries));
    }
    catch (const std::invalid_argument& e)
    {
        throw r.child("censored").error("counts", std::string(e.what()) + " (a bed not yet stationary?)");
    }
}

// Residence r (residence.<key>): its completed visits and, where the file
// has them, the visits still open at the window's end (censored) by
// Kaplan-Meier, with the tail past the window from Little's law: holdup /
// entryRate of the states `states` (one region; for the cycle all of them
// over the entries into `entering`, the spout). The mean must be known
// within 5 %: from n completed visits at cv = std/mean that takes
// n >= (cv/0.05)^2; by Little's law, whose error is 1/sqrt(entries), 400
// entries, completed or open -- the full bed's downcomer visits outlast a
// window of 20 s, and none may have ended in it.
Residence readResidence(const YamlInput& r, const YamlInput& conditions,
                        const std::vector<std::string>& states, const std::string& entering)
{
    Residence res;
    res.binWidth = r.within("binWidth", 1e-9, 1e6, "s");
    if (!(res.binWidth > 0)) throw r.error("binWidth", "a positive bin width [s]");
    const YAML::Node n = r.node()["counts"];
    if (!n || !n.IsSequence() || n.size() == 0) throw r.error("counts", "a non-empty list of counts");
    const long sum = readCounts(r, res);
    res.samples = r.integer("samples", 0, 2000000000L);
    res.mean = r.within("mean", 0, 1e6, "s");
    res.std = r.within("std", 0, 1e6, "s");
    if (sum != res.samples) throw r.error("samples", "the sum of the counts, " + std::to_string(sum));
    Residence open;
    long opened = 0;
    if (r.has("censored"))
    {
        const YamlInput c = r.child("censored");
        opened = readCounts(c, open);
        if (opened != c.integer("samples", 0, 2000000000L))
            throw c.error("samples", "the sum of the counts, " + std::to_string(opened));
    }
    const double cv = res.mean > 0 ? res.std / res.mean : 0;
    const long need =
        opened > 0 ? kMinResidences
                   : std::max<long>(kMinResidences, static_cast<long>(std::ceil(std::pow(cv / 0.05, 2))));
    if (res.samples + opened < need)
    {
        const std::string which =
            opened > 0 ? " residence times, completed or open at the window's end ("
                             + std::to_string(res.samples) + " + " + std::to_string(opened) + ")"
                       : " residence times (the mean within 5 % at cv " + formatNumber(cv, 3) + ")";
        throw r.error("samples", "at least " + std::to_string(need) + which
                                     + ": too few cycles for a distribution; average over a longer run");
    }
    if (res.samples > 0 || opened == 0)
    {
        if (!(res.mean > 0)) throw r.error("mean", "a positive mean residence time [s]");
        // the bins' midpoints put the mean within half a bin of the exact one
        if (std::fabs(res.histogramMean() - res.mean) > 0.5 * res.binWidth * (1 + 1e-9))
            throw r.error("mean",
                          "the counts' mean " + formatNumber(res.histogramMean()) + " s within half a bin");
    }
    if (opened > 0) censorByLittle(res, open, r, conditions, states, entering);
    return res;
}

void same(const YamlInput& stats, const std::string& key, double theirs, double ours, const std::string& what,
          const std::string& caseFile)
{
    if (std::fabs(theirs - ours) <= kSameRel * std::max(std::fabs(ours), 1e-12)) return;
    throw stats.error(key, "the " + what + " of " + caseFile + ", " + formatNumber(ours, 8)
                               + " (statistics of another bed or operating point)");
}

struct CaseGeometry
{
    std::map<std::string, double> geometry;
    bool hasVelocity = false;
    double velocity = 0, massFlow = 0;
};

// A core's share of each visit of its region: a histogram over [0, 1].
Residence readVisitFractions(const YamlInput& f)
{
    Residence res;
    res.binWidth = f.within("binWidth", 1e-6, 1);
    const YAML::Node n = f.node()["counts"];
    const double bins = n && n.IsSequence() ? static_cast<double>(n.size()) : 0;
    if (std::fabs(bins * res.binWidth - 1) > 1e-9)
        throw f.error("counts",
                      "1/binWidth = " + formatNumber(1 / res.binWidth) + " counts (bins over [0, 1])");
    const long sum = readCounts(f, res);
    if (sum < kMinResidences)
        throw f.error("counts",
                      "at least " + std::to_string(kMinResidences)
                          + " visits: too few cycles for a distribution; average over a longer run");
    res.samples = sum;
    res.mean = res.histogramMean();
    return res;
}

// A core's exchangeShare from what spoutFoam measured its side flows carry
// (gas.carried: the flow-weighted T of the gas going out and coming in);
// 1 without the measurement.
double carriedShare(const YamlInput& gas, const std::string& into, const std::string& outOf, double coreT,
                    double restT)
{
    if (!gas.has("carried")) return 1;
    const YamlInput carried = gas.child("carried");
    if (!carried.has(into) || !carried.has(outOf)) return 1;
    return exchangeShare(carried.child(outOf).within("T", 0, 2000, "K"),
                         carried.child(into).within("T", 0, 2000, "K"), coreT, restT);
}

// A region's core, where the statistics have it as spoutFoam's do
// (conditions.entrainment.jet, conditions.fountain.core): a gas compartment
// of the region (spouted::addCore), with its flows across its sides (gas.into,
// gas.outOf: dry-air shares of the inlet's; 0 where the file has none).
void readCore(const YamlInput& cond, const YamlInput& gas, Case& c, const std::string& region,
              const std::string& key, const std::string& name, const std::string& into,
              const std::string& outOf)
{
    const YamlInput zone = cond.child(region);
    if (!zone.has(key)) return;
    const YamlInput j = zone.child(key);
    const double share = j.within("holdup", 0, zone.number("holdup")) / zone.number("holdup");
    if (!(share > 0 && share < 1)) return; // all or none of its kernels in the core: one compartment
    Region core;
    core.slipReynolds = j.within("slipRe", 0, 1e6);
    core.voidage = j.within("voidage", 1e-3, 1);
    core.hFile = j.within("h", 0, 1e6, "W/m2/K");
    core.kmFile = j.within("km", 0, 1e3, "m/s");
    core.gasTemperatureFile = j.within("Tgas", 0, 2000, "K");
    core.gasHumidityFile = j.within("humidityRatio", -1, 0, 1);
    if (j.has("visitFractions")) core.visitFractions = readVisitFractions(j.child("visitFractions"));
    if (gas.has(into)) core.intoCore = gas.within(into, 0, 10);
    if (gas.has(outOf)) core.outOfCore = gas.within(outOf, 0, 10);
    const double regionT = zone.within("Tgas", 0, 2000, "K");
    core.exchangeShare = carriedShare(gas, into, outOf, core.gasTemperatureFile,
                                      meanBeside(regionT, core.gasTemperatureFile, share));
    addCore(c, region, name, share, core);
    const Region& rest = c.regions[static_cast<std::size_t>(c.regions.back().partOf)];
    const std::pair<const char*, double> beside[] = {
        {"slipRe", rest.slipReynolds}, {"voidage", rest.voidage}, {"h", rest.hFile}, {"km", rest.kmFile}};
    for (const auto& [k, v] : beside)
        if (!(v >= 0))
            throw j.error(k, "a mean the region's can hold (the rest beside the " + name + " came out "
                                 + formatNumber(v) + ")");
}

// The statistics: checked against the case, their regions into c.
void readStatistics(const std::string& file, Case& c, const CaseGeometry& g, const YamlInput& caseRegions)
{
    const YamlInput s = YamlInput::load(file);
    if (s.text("format") != "spoutlab-circulation 1")
        throw s.error("format", "'spoutlab-circulation 1' (a circulation.json of spoutFoam)");
    const YamlInput run = s.child("run");
    c.statisticsRun = run.text("case");
    c.statisticsInletC = run.within("inletTemperature", 0, 2000, "K") - 273.15;
    c.statisticsInletW = run.within("inletHumidityRatio", 0, 1);
    if (g.hasVelocity)
        same(run, "u_s", run.number("u_s", "m/s"), g.velocity, "superficial velocity [m/s]", c.file);
    else
        same(s.child("gas"), "inletMassFlow", s.child("gas").number("inletMassFlow"), g.massFlow,
             "gas mass flow [kg/s]", c.file);
    const YamlInput geo = run.child("geometry");
    for (const char* k : kGeometry)
        same(geo, k, geo.number(k, "m"), g.geometry.at(k), std::string(k) + " [m]", c.file);
    same(run, "particleDiameter", run.number("particleDiameter", "m"), c.diameter, "kernel diameter [m]",
         c.file);
    const double particles = run.positive("particles");
    const YamlInput regions = s.child("regions");
    std::vector<std::string> order;
    for (const YamlInput& r : regions.items()) order.push_back(r.node().IsScalar() ? r.node().Scalar() : "");
    if (order.size() != kRegions.size())
        throw s.error("regions", "the four regions spout, fountain, downcomer, entrainment");
    rejectDuplicates(order, file + ": key 'regions'", "region");
    const YamlInput res = s.child("residence"), cond = s.child("conditions");
    const Residence cycle = readResidence(res.child("cycle"), cond, order, "spout");
    c.cycleMean = cycle.mean;
    for (const std::string& name : order)
    {
        if (!kRegions.count(name)) throw s.error("regions", "spout, fountain, downcomer and entrainment");
        if (!caseRegions.has(name))
            throw caseRegions.error(name, "the heat-transfer model of region '" + name + "' of " + file);
        Region r;
        r.name = name;
        r.residence = readResidence(res.child(name), cond, {name}, name);
        const YamlInput k = cond.child(name);
        r.slipReynolds = k.within("slipRe", 0, 1e6);
        r.voidage = k.within("voidage", 1e-3, 1);
        r.hFile = k.within("h", 0, 1e6, "W/m2/K");
        r.kmFile = k.within("km", 0, 1e3, "m/s");
        if (c.measuredTransfer && !(r.hFile > 0 && r.kmFile > 0))
            throw k.error(r.hFile > 0 ? "km" : "h",
                          "a measured value above 0 (the case's transfer_coefficients: measured)");
        r.gasTemperatureFile = k.within("Tgas", 0, 2000, "K");
        r.gasHumidityFile = k.within("humidityRatio", -1, 0, 1);
        r.holdupShare = k.within("holdup", 0, particles) / particles;
        r.measured = true;
        c.regions.push_back(r);
    }
    const YamlInput gas = s.child("gas");
    c.spoutShare = gas.within("spoutShare", 0, 1);
    const double seep = gas.within("downcomerShare", 0, 1);
    if (std::fabs(c.spoutShare + seep - 1) > 1e-3)
        throw gas.error("downcomerShare",
                        "1 - spoutShare = " + formatNumber(1 - c.spoutShare) + " within 1e-3");
    if (!c.circulating) return;
    readCore(cond, gas, c, "entrainment", "jet", "jet", "intoJet", "outOfJet");
    readCore(cond, gas, c, "fountain", "core", "fountainCore", "intoFountainCore", "outOfFountainCore");
    const Region& core = c.regions.back();
    if (core.name != "fountainCore") return;
    // the core's net outflow across its sides: at most the spout's gas, at
    // least minus the seepage, or a compartment would lose more than it takes
    const double net = core.outOfCore - core.intoCore;
    if (net > c.spoutShare || net < -seep)
        throw gas.error("outOfFountainCore", "outOfFountainCore - intoFountainCore (" + formatNumber(net)
                                                 + ") between -downcomerShare (" + formatNumber(-seep)
                                                 + ") and spoutShare (" + formatNumber(c.spoutShare) + ")");
}

// The case's regions: correlation and optional overrides of the measured.
void readRegions(const YamlInput& in, Case& c, const std::string& still)
{
    const YamlInput regs = in.child("regions");
    if (!c.circulating)
    {
        // the one region: from the statistics if they have it, else the case's
        std::vector<Region> kept;
        for (const Region& r : c.regions)
            if (r.name == still) kept.push_back(r);
        if (kept.empty()) kept.push_back(Region{});
        kept[0].name = still;
        kept[0].residence = Residence{};
        kept[0].core = -1;
        c.regions = kept;
        c.spoutShare = 1;
        for (const std::string& k : regs.keys())
            if (k != still) throw regs.error(k, "only the still region '" + still + "' (circulation none)");
    }
    else
        for (const std::string& k : regs.keys())
            if (!kRegions.count(k)) throw regs.error(k, "a region of the statistics");
    for (Region& r : c.regions)
    {
        if (r.partOf >= 0) continue; // a compartment: its region's correlation, below
        const YamlInput one = regs.child(r.name);
        one.rejectUnknown({"heatTransferModel", "slipRe", "voidage"});
        r.correlation = one.text("heatTransferModel");
        auto known = spoutlab::HeatTransferModel::available();
        // a region rule picks a correlation by cell; here each region names its own
        known.erase(std::remove(known.begin(), known.end(), "spoutDowncomer"), known.end());
        if (std::find(known.begin(), known.end(), r.correlation) == known.end())
            throw one.error(
                "heatTransferModel", "one of " + [&] {
                    std::string s;
                    for (const auto& n : known) s += (s.empty() ? "" : ", ") + n;
                    return s;
                }());
        const bool measured = r.measured;
        if (!measured && c.measuredTransfer)
            throw in.error("transfer_coefficients", "correlation: region '" + r.name
                                                        + "' has no measured h and k_m in the statistics");
        for (const char* key : {"slipRe", "voidage"})
            if (c.measuredTransfer && one.has(key))
                throw one.error(key, std::string("no override with transfer_coefficients measured (its "
                                                 "kernels exchange with the measured h and k_m)"));
        r.slipReynolds =
            measured ? one.within("slipRe", r.slipReynolds, 0, 1e6) : one.within("slipRe", 0, 1e6);
        r.voidage = measured ? one.within("voidage", r.voidage, 1e-3, 1) : one.within("voidage", 1e-3, 1);
    }
    for (Region& r : c.regions)
        if (r.partOf >= 0) r.correlation = c.regions[static_cast<std::size_t>(r.partOf)].correlation;
    physics([&] {
        transferCoefficients(c);
        return 0;
    });
}

void readOperation(const YamlInput& in, Case& c, CaseGeometry& g)
{
    const YamlInput op = in.child("operation");
    op.rejectUnknown({"inlet_temperature_C", "inlet_humidity_ratio", "superficial_velocity_m_per_s",
                      "air_mass_flow_kg_per_s", "pressure_Pa", "ambient_temperature_C", "fan_power_kW"});
    c.inletC = op.within("inlet_temperature_C", -20, 200, "degC");
    c.pressure = op.within("pressure_Pa", 101325, 5e4, 2e5, "Pa");
    c.inletW = op.within("inlet_humidity_ratio", 0, 0.5, "kg/kg dry air");
    if (!(psy::relativeHumidity(c.inletC, c.inletW, c.pressure) <= 1))
        throw op.error("inlet_humidity_ratio", "air at or below saturation at the inlet temperature");
    c.ambientC = op.within("ambient_temperature_C", -40, 60, "degC");
    if (!(c.inletC > c.ambientC))
        throw op.error("inlet_temperature_C", "an inlet temperature above the ambient "
                                                  + formatNumber(c.ambientC) + " degC (heated air)");
    c.fanPower = op.within("fan_power_kW", 0, 0, 1e4, "kW") * 1e3;
    g.hasVelocity = op.has("superficial_velocity_m_per_s");
    if (in.has("geometry") || g.hasVelocity || c.circulating)
    {
        // the statistics' bed is compared with it; u_s flows through width x depth
        const YamlInput geo = in.child("geometry");
        geo.rejectUnknown({"Wd", "He", "Hd", "plateThickness", "width", "depth"});
        for (const char* k : kGeometry) g.geometry[k] = geo.within(k, 0, 100, "m");
    }
    if (g.hasVelocity == op.has("air_mass_flow_kg_per_s"))
        throw op.error("superficial_velocity_m_per_s", "one of superficial_velocity_m_per_s and "
                                                       "air_mass_flow_kg_per_s");
    if (g.hasVelocity)
    {
        g.velocity = op.within("superficial_velocity_m_per_s", 1e-4, 100, "m/s");
        const double area = g.geometry["width"] * g.geometry["depth"];
        if (!(area > 0)) throw in.child("geometry").error("width", "a cross-section width x depth above 0");
        c.airFlow = psy::density(c.inletC, c.inletW, c.pressure) * g.velocity * area / (1 + c.inletW);
    }
    else
        c.airFlow = g.massFlow = op.within("air_mass_flow_kg_per_s", 1e-9, 1e4, "kg/s");
}

// bed.initial_state: a CSV of one kernel a row, columns moisture_db [kg/kg
// d.b.] and temperature_C (and an optional particle id, not used), as the
// protocol dryingTime exports a CFD-DEM particle file
void readInitialState(const std::string& path, Case& c)
{
    const CsvTable t = readCsv(path);
    t.rejectUnknownColumns({"id", "moisture_db", "temperature_C"}, path);
    const std::size_t cx = t.column("moisture_db", path), ct = t.column("temperature_C", path);
    if (t.rows.empty()) throw InputError(path + ": no kernel rows (expected one row per kernel)");
    double sx = 0, st = 0;
    for (std::size_t r = 0; r < t.rows.size(); ++r)
    {
        const double x = t.rows[r][cx], tc = t.rows[r][ct];
        const std::string where = path + ": line " + std::to_string(t.lines[r]);
        if (!(x >= 0 && x <= 5))
            throw InputError(where
                             + ": column 'moisture_db' expected a moisture from 0 to 5 kg/kg dry "
                               "basis, got '"
                             + formatNumber(x) + "'");
        if (!(tc >= -20 && tc <= 200))
            throw InputError(where
                             + ": column 'temperature_C' expected a temperature from -20 to 200 "
                               "degC, got '"
                             + formatNumber(tc) + "'");
        c.initialStateX.push_back(x);
        c.initialStateT.push_back(tc + 273.15);
        sx += x;
        st += tc;
    }
    c.initialStateFile = path;
    c.initialX = sx / static_cast<double>(t.rows.size());
    c.initialC = st / static_cast<double>(t.rows.size());
}

void readBed(const YamlInput& in, Case& c)
{
    const YamlInput bed = in.child("bed");
    bed.rejectUnknown({"particles", "kernel_diameter_m", "kernel_dry_mass_kg", "initial_moisture_db",
                       "initial_temperature_C", "initial_state", "kernelHeatCapacity"});
    c.bedParticles = bed.within("particles", 1, 1e10);
    c.diameter = bed.within("kernel_diameter_m", 1e-5, 0.1, "m");
    c.dryMass = bed.within("kernel_dry_mass_kg", 1e-12, 1, "kg");
    if (bed.has("initial_state"))
    {
        for (const char* k : {"initial_moisture_db", "initial_temperature_C"})
            if (bed.has(k))
                throw bed.error(k, "no uniform initial state beside initial_state (its kernels' own)");
        readInitialState(
            relativeTo(std::filesystem::path(in.file()).parent_path().string(), bed.text("initial_state")),
            c);
    }
    else
    {
        c.initialX = bed.within("initial_moisture_db", 0, 5, "kg/kg dry basis");
        c.initialC = bed.within("initial_temperature_C", -20, 200, "degC");
    }
    c.dryHeatCapacity =
        bed.within("kernelHeatCapacity", spoutlab::corn::kDrySpecificHeat, 100, 1e4, "J/kg/K");
    const YamlInput gas = in.child("gas");
    gas.rejectUnknown({"rho", "mu", "Cp", "kappa", "Dv"});
    c.gas = GasProperties{gas.within("rho", 1e-3, 100, "kg/m3"), gas.within("mu", 1e-7, 1, "Pa s"),
                          gas.within("Cp", 100, 1e5, "J/kg/K"), gas.within("kappa", 1e-4, 10, "W/m/K"),
                          gas.within("Dv", 1e-8, 1, "m2/s")};
}

// The target against the kernels' equilibrium with the inlet air.
void checkTarget(const YamlInput& in, const Case& c, const spoutlab::Parameters& modelProps)
{
    if (c.dryingName == "freeWater") return; // no isotherm: free water dries to 0
    const std::string name = physics([&] { return modelProps.getWord("isotherm", "modifiedHenderson"); });
    const auto isotherm =
        physics([&] { return spoutlab::SorptionIsotherm::New(name, spoutlab::Parameters()); });
    const double T = c.inletC + 273.15;
    const double rh = spoutlab::relativeHumidity(spoutlab::MoistAir{T, c.inletW, c.pressure});
    const double xeq = isotherm->equilibriumMoisture(rh, T);
    if (c.targetX > xeq) return;
    throw in.error("target_moisture_wb_percent",
                   "a moisture above the kernels' equilibrium " + formatNumber(100 * xeq / (1 + xeq), 4)
                       + " % (wet basis) with the inlet air (" + formatNumber(c.inletC) + " degC, RH "
                       + formatNumber(100 * rh, 3) + " %, " + name + ")");
}

void readBatch(const YamlInput& in, Case& c)
{
    const double wb = in.within("target_moisture_wb_percent", 0, 99, "% wet basis") / 100;
    c.targetX = wb / (1 - wb);
    c.stopAtTarget = in.text("stop_at_target", "yes") == "yes";
    if (in.has("stop_at_target") && in.text("stop_at_target") != "yes" && in.text("stop_at_target") != "no")
        throw in.error("stop_at_target", "yes or no");
    c.limitC = in.within("kernel_temperature_limit_C", 0, 300, "degC");
    c.duration = in.within("duration_h", 1e-6, 1000, "h") * 3600;
    c.outputInterval = in.within("output_interval_s", 60, 1e-3, 1e6, "s");
    stepCount(c.duration, c.outputInterval, 1000000, in.file(), "output_interval_s",
              "a longer output interval");
    c.samples = in.has("samples") ? in.integer("samples", 1, 10000000) : 10000;
    c.seed = static_cast<std::uint64_t>(in.has("seed") ? in.integer("seed", 0, 2147483647L) : 1);
    if (in.has("time_step"))
    {
        const YamlInput s = in.child("time_step");
        s.rejectUnknown({"max_s", "initial_s", "kernel_temperature_change_K", "bed_moisture_change"});
        c.step.maxStep = s.within("max_s", 5, 1e-6, 3600, "s");
        c.step.initialStep = s.within("initial_s", std::min(0.1, c.step.maxStep), 1e-6, 3600, "s");
        c.step.kernelTemperatureChange = s.within("kernel_temperature_change_K", 1, 1e-6, 1e3, "K");
        c.step.bedMoistureChange = s.within("bed_moisture_change", 2e-3, 1e-9, 10, "kg/kg dry basis");
    }
}

} // namespace

Case readCase(const std::string& path)
{
    const YamlInput in = YamlInput::load(path);
    in.rejectUnknown({"statistics",
                      "circulation",
                      "still_region",
                      "operation",
                      "geometry",
                      "bed",
                      "gas",
                      "dryingModel",
                      "regions",
                      "gasModel",
                      "transfer_coefficients",
                      "target_moisture_wb_percent",
                      "stop_at_target",
                      "kernel_temperature_limit_C",
                      "duration_h",
                      "output_interval_s",
                      "samples",
                      "seed",
                      "time_step",
                      "freeWaterProps",
                      "reactionEngineeringProps",
                      "kernelDiffusionProps"});
    Case c;
    c.file = path;
    CaseGeometry g;
    const std::string mode = in.text("circulation", "measured");
    if (mode != "measured" && mode != "none") throw in.error("circulation", "measured or none");
    c.circulating = mode == "measured";
    readOperation(in, c, g);
    readBed(in, c);
    c.dryingName = in.text("dryingModel");
    const spoutlab::Parameters modelProps = props(in, c.dryingName + "Props");
    c.drying = physics([&] { return spoutlab::DryingModel::New(c.dryingName, modelProps); });
    const std::string gasModel = in.text("gasModel", "compartments");
    if (gasModel != "compartments" && gasModel != "plugFlow" && gasModel != "inlet")
        throw in.error("gasModel", "compartments, plugFlow or inlet");
    c.gasAtInlet = gasModel == "inlet";
    c.plugFlow = gasModel == "plugFlow";
    const bool withStatistics = c.circulating || in.has("statistics");
    const std::string transfer =
        in.text("transfer_coefficients", withStatistics ? "measured" : "correlation");
    if (transfer != "measured" && transfer != "correlation")
        throw in.error("transfer_coefficients", "measured or correlation");
    if (transfer == "measured" && !withStatistics)
        throw in.error("transfer_coefficients",
                       "correlation without statistics (measured h and k_m are theirs)");
    c.measuredTransfer = transfer == "measured";
    if (withStatistics)
    {
        c.statistics = relativeTo(std::filesystem::path(path).parent_path().string(), in.text("statistics"));
        readStatistics(c.statistics, c, g, in.child("regions"));
    }
    const std::string still = c.circulating ? "" : in.text("still_region");
    readRegions(in, c, still);
    readBatch(in, c);
    checkTarget(in, c, modelProps);
    if (c.circulating && !c.gasAtInlet)
        for (const auto& [key, share, region] : {std::tuple{"spoutShare", c.spoutShare, "spout"},
                                                 std::tuple{"downcomerShare", 1 - c.spoutShare, "downcomer"}})
            if (share < 1e-3)
                throw InputError(c.statistics + ": key 'gas." + key + "' expected at least 0.001 (region '"
                                 + region + "' holds particles: its compartment needs gas)");
    checkMemory(static_cast<double>(c.samples), 8.0 * (c.drying->stateSize() + 6), path, "samples");
    return c;
}

} // namespace procsim::dryer::spouted
