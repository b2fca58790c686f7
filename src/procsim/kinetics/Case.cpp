#include "kinetics/Case.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/Checked.hpp"
#include "common/Csv.hpp"

namespace procsim::kinetics
{

namespace
{

constexpr long maxReportTimes = 1000000; // rows of timeseries.csv

std::vector<std::string> splitDots(const std::string& key)
{
    std::vector<std::string> parts;
    std::stringstream ss(key);
    std::string p;
    while (std::getline(ss, p, '.')) parts.push_back(p);
    return parts;
}

void applyYamlOverride(YAML::Node& root, const std::string& file, const std::string& key, double value)
{
    const auto parts = splitDots(key);
    YAML::Node cur;
    cur.reset(root);
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
    {
        if (!cur.IsMap() || !cur[parts[i]] || !cur[parts[i]].IsMap())
        {
            throw InputError(file + ": cannot set '" + key + "': section '" + parts[i]
                             + "' is not in the case file");
        }
        YAML::Node next = cur[parts[i]];
        cur.reset(next);
    }
    if (!cur.IsMap()) throw InputError(file + ": cannot set '" + key + "'");
    const std::string last = parts.back();
    if (cur[last] && !cur[last].IsScalar())
    {
        throw InputError(file + ": cannot set '" + key + "': it is a section, not a number");
    }
    std::ostringstream os;
    os.precision(17);
    os << value;
    cur[last] = os.str();
}

void readSpeciesMap(const YamlInput& in, const std::string& key, const Mechanism& mech,
                    std::vector<double>& target, double factorPerMolarMass, bool perMolarMass,
                    const std::string& unit, double maxValue)
{
    if (!in.has(key)) return;
    const YamlInput m = in.child(key);
    if (!m.node().IsMap()) throw in.error(key, "a map of species to values [" + unit + "]");
    for (const auto& name : m.keys())
    {
        const std::size_t i = mech.index(name, in.file() + ": key '" + m.path() + "'");
        const double v = m.within(name, 0, maxValue, unit);
        target[i] = perMolarMass ? v * factorPerMolarMass / mech.species[i].molarMass : v;
    }
}

} // namespace

std::string expandAlias(const std::string& key)
{
    if (key == "I") return "corona.current_mA";
    if (key == "V") return "corona.voltage_kV";
    return key;
}

SweepDim parseSweep(const std::string& arg)
{
    const auto eq = arg.find('=');
    if (eq == std::string::npos || eq == 0)
    {
        throw InputError("--sweep expected KEY=v1,v2,... (e.g. I=0.1,0.3,0.5), got '" + arg + "'");
    }
    SweepDim d;
    d.key = expandAlias(arg.substr(0, eq));
    std::stringstream ss(arg.substr(eq + 1));
    std::string v;
    while (std::getline(ss, v, ','))
    {
        const auto x = parseFinite(v);
        if (!x)
            throw InputError("--sweep " + d.key + ": expected finite numbers separated by commas, got '" + v
                             + "'");
        d.values.push_back(*x);
    }
    if (d.values.empty()) throw InputError("--sweep " + d.key + ": no values given");
    return d;
}

double Case::radicalConcentration() const
{
    if (!radicalFixed()) return 0;
    const double mw = mech.species[mech.radicalIndex()].molarMass;
    double mgPerL = 0;
    if (oh.kind == "constant")
        mgPerL = oh.concentration;
    else if (oh.kind == "linear_current")
        mgPerL = oh.intercept + oh.slope * current;
    return mgPerL / 1000.0 / mw;
}

std::vector<double> Case::feedRate() const
{
    std::vector<double> f(mech.species.size(), 0.0);
    for (std::size_t i = 0; i < f.size(); ++i)
    {
        f[i] = gasFlow * (inletPpm[i] - effluentPpm[i]) * 1e-6 / volume;
    }
    return f;
}

CaseSource CaseSource::load(const std::string& path)
{
    const YamlInput in = YamlInput::load(path);
    CaseSource s;
    s.file_ = path;
    s.node_ = in.node();
    const std::string mechFile = in.text("mechanism");
    std::filesystem::path mp(mechFile);
    if (mp.is_relative()) mp = std::filesystem::path(path).parent_path() / mp;
    if (!std::filesystem::exists(mp))
    {
        throw InputError(path + ": key 'mechanism': file '" + mp.string() + "' not found");
    }
    s.mech_ = Mechanism::load(mp.string());
    return s;
}

namespace
{

// A rate-constant override "k.<reaction id>" changes the mechanism; any
// other key is written into (a copy of) the case file before it is read.
void applyOverrides(const Overrides& overrides, const std::string& file, Mechanism& mech, YAML::Node& node)
{
    for (const auto& [keyIn, value] : overrides)
    {
        const std::string key = expandAlias(keyIn);
        if (key.rfind("k.", 0) != 0)
        {
            applyYamlOverride(node, file, key, value);
            continue;
        }
        const std::string id = key.substr(2);
        const std::size_t r = mech.reaction(id);
        if (r == std::string::npos)
            throw InputError(mech.file + ": no reaction with id '" + id + "' (from '" + key + "')");
        if (!(value >= 0 && value <= maxRateConstant))
            throw InputError(key + ": a rate constant must be from 0 to " + formatNumber(maxRateConstant)
                             + ", got " + formatNumber(value));
        mech.reactions[r].k = value;
    }
}

void readReactor(const YamlInput& in, Case& c)
{
    const YamlInput reactor = in.child("reactor");
    reactor.rejectUnknown({"liquid_volume_L"});
    c.volume = reactor.within("liquid_volume_L", 1e-9, 1e9, "L");
    if (!(c.volume > 0)) throw reactor.error("liquid_volume_L", "a positive number [L]");
}

// The feed gas: its molar flow from the volumetric flow at T and p (ideal
// gas), and what each species leaves of its inlet concentration.
void readGas(const YamlInput& in, Case& c)
{
    const std::size_t n = c.mech.species.size();
    c.inletPpm.assign(n, 0.0);
    c.effluentPpm.assign(n, 0.0);
    if (!in.has("gas")) return;
    const YamlInput gas = in.child("gas");
    gas.rejectUnknown({"flow_mL_per_min", "temperature_C", "pressure_kPa", "inlet_ppm", "effluent_ppm"});
    const double flow = gas.within("flow_mL_per_min", 0, 1e9, "mL/min");
    const double tC = gas.number("temperature_C", "degC");
    if (!(tC > -273.15 && tC <= 5000))
        throw gas.error("temperature_C", "a temperature above absolute zero and up to 5000 [degC]");
    const double pKPa = gas.within("pressure_kPa", 1e-3, 1e6, "kPa");
    c.gasFlow = pKPa * 1e3 * flow * 1e-6 / 60.0 / (gasConstant * (tC + 273.15));
    readSpeciesMap(gas, "inlet_ppm", c.mech, c.inletPpm, 1, false, "ppm by mol", 1e6);
    readSpeciesMap(gas, "effluent_ppm", c.mech, c.effluentPpm, 1, false, "ppm by mol", 1e6);
    for (std::size_t i = 0; i < n; ++i)
        if (c.effluentPpm[i] > c.inletPpm[i])
            throw InputError(c.file + ": key 'gas.effluent_ppm." + c.mech.species[i].name
                             + "' expected a value <= the inlet concentration");
}

// Initial liquid concentrations, by mass and by mole; both add up.
void readInitial(const YamlInput& in, Case& c)
{
    const std::size_t n = c.mech.species.size();
    c.initial.assign(n, 0.0);
    readSpeciesMap(in, "initial_mg_per_L", c.mech, c.initial, 1e-3, true, "mg/L", 1e6);
    if (!in.has("initial_mol_per_L")) return;
    std::vector<double> molar(n, 0.0);
    readSpeciesMap(in, "initial_mol_per_L", c.mech, molar, 1, false, "mol/L", 1e3);
    for (std::size_t i = 0; i < n; ++i) c.initial[i] += molar[i];
}

void readCorona(const YamlInput& in, Case& c)
{
    if (!in.has("corona")) return;
    const YamlInput co = in.child("corona");
    co.rejectUnknown({"current_mA", "voltage_kV"});
    c.current = co.within("current_mA", 0, 1e6, "mA");
    c.voltage = co.has("voltage_kV") ? co.within("voltage_kV", 1e-6, 1e6, "kV") : 0.0;
}

// The [OH] model: a mechanism with a radical needs one, and a fixed [OH]
// must not be negative at the case's current.
void readOh(const YamlInput& in, Case& c)
{
    if (!in.has("oh"))
    {
        if (c.mech.hasRadical())
            throw in.error("oh", "a section 'oh' (the mechanism has radical " + c.mech.radical + ")");
        return;
    }
    const YamlInput oh = in.child("oh");
    c.oh.kind = oh.text("model");
    if (!c.mech.hasRadical())
        throw InputError(c.file + ": key 'oh' needs a mechanism with 'radical: <species>' (" + c.mech.file
                         + " has none)");
    if (c.oh.kind == "constant")
    {
        oh.rejectUnknown({"model", "concentration_mg_per_L"});
        c.oh.concentration = oh.within("concentration_mg_per_L", 0, 1e6, "mg/L");
    }
    else if (c.oh.kind == "linear_current")
    {
        oh.rejectUnknown({"model", "slope_mg_per_L_per_mA", "intercept_mg_per_L"});
        c.oh.slope = oh.within("slope_mg_per_L_per_mA", 0, 1e6, "mg/L per mA");
        c.oh.intercept = oh.within("intercept_mg_per_L", 0.0, -1e6, 1e6, "mg/L");
        if (!in.has("corona"))
            throw in.error("corona", "a section with current_mA (oh.model is linear_current)");
    }
    else if (c.oh.kind == "dynamic")
        oh.rejectUnknown({"model"});
    else
        throw oh.error("model", "one of constant, linear_current, dynamic");
    if (c.radicalFixed() && c.radicalConcentration() < 0)
        throw InputError(c.file + ": key 'oh' gives a negative [OH] at the current "
                         + std::to_string(c.current) + " mA");
}

// Duration and output interval, each in either of two units, and a number
// of report times the run can write.
void readTime(const YamlInput& in, Case& c)
{
    const YamlInput time = in.child("time");
    time.rejectUnknown({"duration_h", "output_interval_min", "duration_s", "output_interval_s"});
    for (const auto& [a, b] : {std::pair<const char*, const char*>{"duration_h", "duration_s"},
                               {"output_interval_min", "output_interval_s"}})
        if (time.has(a) && time.has(b))
            throw InputError(c.file + ": keys 'time." + a + "' and 'time." + b
                             + "' both given (expected one of them)");
    if (time.has("duration_h"))
        c.duration = 3600.0 * time.within("duration_h", 1e-9, 1e9, "h");
    else if (time.has("duration_s"))
        c.duration = time.within("duration_s", 1e-9, 3.6e12, "s");
    else
        throw time.error("duration_h", "a positive number [h] (or duration_s)");
    if (time.has("output_interval_min"))
        c.outputInterval = 60.0 * time.positive("output_interval_min", "min");
    else if (time.has("output_interval_s"))
        c.outputInterval = time.positive("output_interval_s", "s");
    else
        throw time.error("output_interval_min", "a positive number [min] (or output_interval_s)");
    if (c.outputInterval > c.duration)
        throw time.error("output_interval_min", "an interval no longer than the duration");
    stepCount(c.duration, c.outputInterval, maxReportTimes, c.file + ": key 'time'",
              "a run of " + formatNumber(c.duration / 3600.0) + " h reported every "
                  + formatNumber(c.outputInterval / 60.0) + " min",
              "use a longer output interval or a shorter duration");
}

void readSolver(const YamlInput& in, Case& c)
{
    if (!in.has("solver")) return;
    const YamlInput so = in.child("solver");
    so.rejectUnknown({"method", "rk4_step_s", "rtol", "atol_mol_per_L"});
    c.solver.method = so.text("method", "expm");
    if (c.solver.method != "expm" && c.solver.method != "rk4" && c.solver.method != "cvode")
        throw so.error("method", "one of expm, rk4, cvode");
    if (so.has("rk4_step_s")) c.solver.rk4Step = so.positive("rk4_step_s", "s");
    if (so.has("rtol")) c.solver.rtol = so.positive("rtol");
    if (so.has("atol_mol_per_L")) c.solver.atol = so.positive("atol_mol_per_L", "mol/L");
}

// The scalar items of a list, each checked by `check` (which throws).
template <class Check>
std::vector<std::string> readNames(const YamlInput& list, const std::string& file,
                                   const std::string& expected, Check check)
{
    std::vector<std::string> names;
    for (const auto& item : list.items())
    {
        if (!item.node().IsScalar())
            throw InputError(file + ": key '" + item.path() + "' expected " + expected);
        names.push_back(item.node().as<std::string>());
        check(names.back(), file + ": key '" + item.path() + "'");
    }
    return names;
}

void readReport(const YamlInput& in, Case& c)
{
    if (!in.has("report")) return;
    const YamlInput rep = in.child("report");
    rep.rejectUnknown({"times_h", "plot_species"});
    if (rep.has("times_h"))
        for (double t : rep.increasingNumbers("times_h", "h"))
        {
            if (t < 0 || t * 3600.0 > c.duration * (1 + 1e-12))
                throw rep.error("times_h", "times within the run [h]");
            c.reportTimes.push_back(t * 3600.0);
        }
    if (rep.has("plot_species"))
        c.plotSpecies =
            readNames(rep.child("plot_species"), c.file, "a species name",
                      [&](const std::string& name, const std::string& where) { c.mech.index(name, where); });
}

void readSweep(const YamlInput& in, Case& c)
{
    if (!in.has("sweep")) return;
    for (const auto& d : in.child("sweep").items())
    {
        d.rejectUnknown({"key", "values"});
        SweepDim s;
        s.key = expandAlias(d.text("key"));
        s.values = d.numbers("values");
        if (s.values.empty()) throw d.error("values", "a non-empty list of numbers");
        c.sweep.push_back(s);
    }
    if (c.sweep.size() > 2) throw InputError(c.file + ": key 'sweep' expected at most two swept keys");
    rejectDuplicates(c.sweep, &SweepDim::key, c.file + ": key 'sweep'", "swept key");
}

// The defaults of `kinetics sensitivity`: which rate constants, which
// outputs, at what time, by how much.
void readSensitivity(const YamlInput& in, Case& c)
{
    if (!in.has("sensitivity")) return;
    const YamlInput se = in.child("sensitivity");
    se.rejectUnknown({"parameters", "outputs", "time_h", "change_percent"});
    if (se.has("parameters"))
        c.sensParameters = readNames(se.child("parameters"), c.file, "a reaction id",
                                     [&](const std::string& id, const std::string& where) {
                                         if (c.mech.reaction(id) == std::string::npos)
                                             throw InputError(where + ": no reaction with id '" + id + "'");
                                     });
    if (se.has("outputs"))
        c.sensOutputs = readNames(se.child("outputs"), c.file, "a species name or TOC",
                                  [&](const std::string& o, const std::string& where) {
                                      if (o != "TOC") c.mech.index(o, where);
                                  });
    if (se.has("time_h"))
    {
        c.sensTime = 3600.0 * se.positive("time_h", "h");
        if (c.sensTime > c.duration * (1 + 1e-12)) throw se.error("time_h", "a time within the run [h]");
    }
    if (se.has("change_percent")) c.sensChange = se.positive("change_percent", "%") / 100.0;
}

} // namespace

Case CaseSource::build(const Overrides& overrides) const
{
    Case c;
    c.file = file_;
    c.mech = mech_;
    YAML::Node node = YAML::Clone(node_);
    applyOverrides(overrides, file_, c.mech, node);
    const YamlInput in(node, file_, "");
    in.rejectUnknown({"title", "mechanism", "reactor", "gas", "initial_mg_per_L", "initial_mol_per_L",
                      "corona", "oh", "time", "solver", "report", "sweep", "sensitivity"});
    c.title = in.text("title", std::filesystem::path(file_).stem().string());
    readReactor(in, c);
    readGas(in, c);
    readInitial(in, c);
    readCorona(in, c);
    readOh(in, c);
    readTime(in, c);
    readSolver(in, c);
    readReport(in, c);
    readSweep(in, c);
    readSensitivity(in, c);
    return c;
}

} // namespace procsim::kinetics
