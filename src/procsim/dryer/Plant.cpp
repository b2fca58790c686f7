#include "dryer/Plant.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "common/YamlInput.hpp"
#include "dryer/Metrics.hpp"
#include "Psychrometrics.hpp" // coupling/: the one psychrometrics of the project

namespace procsim::dryer
{

namespace psy = spoutlab::psy;

namespace
{

std::string fmt(double v)
{
    return formatNumber(v, 10);
}

std::vector<double> positiveList(const YamlInput& in, const std::string& key, std::size_t size,
                                 const std::string& what)
{
    const auto v = in.numbers(key);
    if (v.size() != size) throw in.error(key, "a list of " + std::to_string(size) + " " + what);
    for (double x : v)
        if (!(x >= 0.01 && x <= 100)) throw in.error(key, "relative air shares from 0.01 to 100");
    return v;
}

double fraction(const YamlInput& in, const std::string& key, double lo, double hi, const std::string& what)
{
    const double v = in.number(key);
    if (!(v >= lo && v <= hi)) throw in.error(key, what);
    return v;
}

void readDryer(const YamlInput& d, DryerCase& c)
{
    d.rejectUnknown({"carts", "trays_per_cart", "pieces_per_tray", "air_holdup_kg", "wall_UA_W_per_K",
                     "heater_power_kW", "fan_power_kW", "circulation_kg_per_s",
                     "heat_transfer_coefficient_W_per_m2K", "velocity_exponent", "air_distribution"});
    auto count = [&](const std::string& key) {
        const long v = d.integer(key);
        if (v < 1 || v > 1000) throw d.error(key, "an integer from 1 to 1000");
        return static_cast<int>(v);
    };
    c.carts = count("carts");
    c.traysPerCart = count("trays_per_cart");
    c.piecesPerTray = count("pieces_per_tray");
    if (c.carts * c.traysPerCart > 2000) // the dense implicit solve grows with the cube of the trays
        throw d.error("trays_per_cart", "at most 2000 trays in all (carts x trays_per_cart), got "
                                            + std::to_string(c.carts * c.traysPerCart));
    c.airHoldup = d.within("air_holdup_kg", 1e-06, 10000000.0, "kg");
    c.wallUA = d.within("wall_UA_W_per_K", 0, 100000000.0, "W/K");
    c.heaterPower = d.within("heater_power_kW", 1e-06, 1000000.0, "kW") * 1e3;
    c.fanPower = d.within("fan_power_kW", 0, 1000000.0, "kW") * 1e3;
    c.circulation = d.within("circulation_kg_per_s", 1e-06, 100000.0, "kg dry air/s");
    c.hConv = d.within("heat_transfer_coefficient_W_per_m2K", 1e-06, 100000.0, "W/(m2 K)");
    c.velocityExponent = d.within("velocity_exponent", 0, 10);
    c.cartFactors.clear();
    c.trayFactors.clear();
    if (d.has("air_distribution"))
    {
        const YamlInput a = d.child("air_distribution");
        a.rejectUnknown({"cart_factors", "tray_factors"});
        if (a.has("cart_factors"))
            c.cartFactors = positiveList(a, "cart_factors", static_cast<std::size_t>(c.carts),
                                         "air shares, one per cart");
        if (a.has("tray_factors"))
            c.trayFactors = positiveList(a, "tray_factors", static_cast<std::size_t>(c.traysPerCart),
                                         "air shares, one per tray (top first)");
    }
}

void readProduct(const YamlInput& p, DryerCase& c)
{
    p.rejectUnknown(
        {"piece_diameter_mm", "piece_length_m", "specific_heat_dry_J_per_kgK", "scorch_temperature_C"});
    c.pieceDiameter = p.within("piece_diameter_mm", 0.001, 10000.0, "mm") / 1e3;
    c.pieceLength = p.within("piece_length_m", 1e-06, 100, "m");
    c.cpDry = p.within("specific_heat_dry_J_per_kgK", 1, 100000.0, "J/(kg K)");
    c.scorchC = p.within("scorch_temperature_C", -50, 500, "degC");
}

void readKinetics(const YamlInput& k, DryerCase& c)
{
    k.rejectUnknown({"model", "rate_constant_per_h", "reference_temperature_C",
                     "activation_energy_kJ_per_mol", "critical_moisture_percent_db", "falling_rate_exponent",
                     "oswin_A_percent_db", "oswin_B"});
    const std::string model = k.text("model");
    if (model == "thin-layer")
    {
        c.kinetics = DryerCase::Kinetics::ThinLayer;
        c.rateConstant = k.within("rate_constant_per_h", 1e-09, 1000000.0, "1/h") / 3600.0;
        c.referenceC = k.within("reference_temperature_C", -50, 500, "degC");
        c.activationEnergy = k.within("activation_energy_kJ_per_mol", 0, 10000.0, "kJ/mol") * 1e3;
    }
    else if (model == "characteristic-curve")
    {
        c.kinetics = DryerCase::Kinetics::CharacteristicCurve;
        c.xCritical = k.within("critical_moisture_percent_db", 1e-06, 10000.0, "% dry basis") / 100.0;
        c.fallingExponent = k.within("falling_rate_exponent", 1e-06, 100);
    }
    else
        throw k.error("model", "'thin-layer' or 'characteristic-curve'");
    c.oswinA = k.within("oswin_A_percent_db", 0, 10000.0, "% dry basis") / 100.0;
    c.oswinB = k.within("oswin_B", 0, 10);
    if (!(c.oswinB < 1.0)) throw k.error("oswin_B", "an exponent from 0 to 1");
}

void readOperation(const YamlInput& o, DryerCase& c)
{
    o.rejectUnknown({"ambient_temperature_C", "ambient_relative_humidity_percent", "pressure_kPa"});
    c.pressure = o.within("pressure_kPa", 1, 10000.0, "kPa") * 1e3;
    c.ambientC = o.number("ambient_temperature_C", "degC");
    if (!(c.ambientC >= 0 && c.ambientC <= 60))
        throw o.error("ambient_temperature_C", "an ambient temperature from 0 to 60 degC");
    c.ambientRH =
        fraction(o, "ambient_relative_humidity_percent", 0, 100, "a relative humidity from 0 to 100 %")
        / 100.0;
    if (c.ambientRH * psy::saturationPressure(c.ambientC) >= c.pressure)
        throw o.error("pressure_kPa", "a pressure above the ambient vapour pressure");
}

Venting readVenting(const YamlInput& v)
{
    v.rejectUnknown({"vented_fraction", "vent_short_circuit_fraction"});
    Venting out;
    out.ventedFraction = fraction(v, "vented_fraction", 0, 1, "a fraction of the circulated air from 0 to 1");
    out.shortCircuit =
        fraction(v, "vent_short_circuit_fraction", 0, 1, "a fraction of the vented air from 0 to 1");
    return out;
}

// Two parameter names for one model quantity: the same name, or
// vented_fraction_all and the vented fraction of one arrangement.
bool sameQuantity(const std::string& a, const std::string& b)
{
    const auto oneVent = [](const std::string& n) {
        return n.rfind("venting.", 0) == 0 && n.size() > 16 && n.substr(n.size() - 16) == ".vented_fraction";
    };
    return a == b || (a == "vented_fraction_all" && oneVent(b)) || (b == "vented_fraction_all" && oneVent(a));
}

// The parameter named under 'parameter', checked against the plant.
std::string knownParameter(const Plant& p, const YamlInput& f)
{
    const std::string name = f.text("parameter");
    try
    {
        p.get(name);
    }
    catch (const std::invalid_argument&)
    {
        std::string list;
        for (const auto& n : Plant::parameterNames()) list += (list.empty() ? "" : ", ") + n;
        throw f.error("parameter", "one of " + list);
    }
    return name;
}

// The values a fitted or held parameter may take: those its plant key accepts.
std::pair<double, double> parameterRange(const std::string& name)
{
    if (name == "heat_transfer_coefficient_W_per_m2K") return {1e-6, 1e5};
    if (name == "falling_rate_exponent") return {1e-6, 100};
    if (name == "rate_constant_per_h") return {1e-9, 1e6};
    if (name == "activation_energy_kJ_per_mol") return {0, 1e4};
    if (name == "critical_moisture_percent_db") return {1e-6, 1e4};
    if (name == "oswin_A_percent_db") return {0, 1e4};
    if (name == "wall_UA_W_per_K") return {0, 1e8};
    return {0, 1}; // the vented and short-circuit fractions
}

void checkParameterValue(const YamlInput& f, const std::string& key, const std::string& name, double v)
{
    const auto [lo, hi] = parameterRange(name);
    if (!(v >= lo && v <= hi))
        throw f.error(key, "values of " + name + " from " + formatNumber(lo) + " to " + formatNumber(hi));
}

void readProfile(const YamlInput& pr, Plant& p)
{
    pr.rejectUnknown({"hold", "time_tolerance_percent", "electricity_tolerance_percent"});
    for (const YamlInput& h : pr.child("hold").items())
    {
        h.rejectUnknown({"parameter", "values"});
        ProfileAxis axis;
        axis.name = knownParameter(p, h);
        axis.values = h.increasingNumbers("values");
        for (double v : axis.values) checkParameterValue(h, "values", axis.name, v);
        for (const auto& other : p.profile)
            if (sameQuantity(other.name, axis.name)) throw h.error("parameter", "each parameter held once");
        p.profile.push_back(axis);
    }
    if (p.profile.empty()) throw pr.error("hold", "a non-empty list of {parameter, values}");
    p.timeTolerance = pr.within("time_tolerance_percent", 1e-06, 10000.0, "%") / 100;
    p.electricityTolerance = pr.within("electricity_tolerance_percent", 1e-06, 10000.0, "%") / 100;
}

// How long a batch may run and how often its state is written.
void readRun(const YamlInput& r, DryerCase& c)
{
    r.rejectUnknown({"max_time_h", "output_interval_min"});
    c.maxTime = r.within("max_time_h", 1e-06, 10000.0, "h") * 3600;
    c.outputInterval = r.within("output_interval_min", 0.001, 1000000.0, "min") * 60;
}

// The named venting arrangements, at least one.
void readVentings(const YamlInput& in, Plant& p)
{
    const YamlInput v = in.child("venting");
    for (const auto& name : v.keys()) p.venting[name] = readVenting(v.child(name));
    if (p.venting.empty()) throw in.error("venting", "at least one named venting arrangement");
}

// What was measured on a batch: drying time, electricity and the moisture
// spreads f1, f2.
void readMeasured(const YamlInput& m, BatchSpec& s)
{
    m.rejectUnknown({"drying_time", "electricity_kWh", "f1_percent", "f2_percent"});
    if (m.has("drying_time"))
    {
        try
        {
            s.measuredTime = parseHoursMinutes(m.text("drying_time"));
        }
        catch (const std::invalid_argument&)
        {
            throw m.error("drying_time", "hours:minutes such as '11:50'");
        }
    }
    if (m.has("electricity_kWh"))
        s.measuredElectricity = m.within("electricity_kWh", 1e-06, 1000000000.0, "kWh") * 3.6e6;
    if (m.has("f1_percent")) s.measuredF1 = m.within("f1_percent", 0, 100, "%");
    if (m.has("f2_percent")) s.measuredF2 = m.within("f2_percent", 0, 100, "%");
}

// One batch: its venting, the hot-air set-point between the ambient and
// 150 degC, the dry mass and the moisture it starts from and must reach.
BatchSpec readBatch(const YamlInput& b, const Plant& p)
{
    b.rejectUnknown({"id", "venting", "hot_air_temperature_C", "dry_mass_kg", "initial_moisture_percent_db",
                     "target_moisture_percent_db", "initial_moisture_spread_percent", "pattern_seed",
                     "measured", "note"});
    BatchSpec s;
    s.id = b.text("id");
    checkFileNamePart(s.id, b.file() + ": key '" + b.path() + ".id'"); // names the batch's result files
    s.venting = b.text("venting");
    if (!p.venting.count(s.venting)) throw b.error("venting", "the name of an arrangement under 'venting'");
    s.hotAirC = b.within("hot_air_temperature_C", -50, 500, "degC");
    if (!(s.hotAirC > p.base.ambientC))
        throw b.error("hot_air_temperature_C",
                      "a set-point above the ambient " + fmt(p.base.ambientC) + " degC");
    if (!(s.hotAirC <= 150)) throw b.error("hot_air_temperature_C", "a set-point of at most 150 degC");
    s.dryMass = b.within("dry_mass_kg", 1e-06, 1000000000.0, "kg");
    s.x0 = b.within("initial_moisture_percent_db", 1e-06, 10000.0, "% dry basis") / 100;
    s.xTarget = b.within("target_moisture_percent_db", 1e-06, 10000.0, "% dry basis") / 100;
    if (!(s.xTarget < s.x0))
        throw b.error("target_moisture_percent_db",
                      "a value below initial_moisture_percent_db (" + fmt(s.x0 * 100) + ")");
    s.x0Spread = b.has("initial_moisture_spread_percent")
                     ? b.within("initial_moisture_spread_percent", 0, 10000.0, "%") / 100
                     : 0.0;
    s.seed = static_cast<unsigned>(b.has("pattern_seed") ? b.integer("pattern_seed") : 1);
    if (b.has("measured")) readMeasured(b.child("measured"), s);
    return s;
}

// The batches, at least one, each with its own id.
void readBatches(const YamlInput& in, Plant& p)
{
    for (const YamlInput& b : in.child("batches").items()) p.batches.push_back(readBatch(b, p));
    if (p.batches.empty()) throw in.error("batches", "a non-empty list of batches");
    rejectDuplicates(p.batches, &BatchSpec::id, in.file() + ": key 'batches'", "batch id");
}

// Batch ids listed under calibration.<key>, each once.
std::vector<std::string> readBatchIds(const YamlInput& c, const std::string& key)
{
    std::vector<std::string> ids;
    for (const YamlInput& id : c.child(key).items())
    {
        if (!id.node().IsScalar())
            throw InputError(c.file() + ": key '" + id.path() + "' expected a batch id");
        ids.push_back(id.node().as<std::string>());
    }
    rejectDuplicates(ids, c.file() + ": key '" + c.path() + "." + key + "'", "batch id");
    return ids;
}

// What calibration fits (each parameter once, within its bounds), on which
// batches, and which batches it predicts with which venting.
void readCalibration(const YamlInput& c, Plant& p)
{
    c.rejectUnknown({"fit", "calibrate_on", "predict", "predict_venting", "profile"});
    for (const YamlInput& f : c.child("fit").items())
    {
        f.rejectUnknown({"parameter", "lower", "upper"});
        FitParameter fp;
        fp.name = knownParameter(p, f);
        for (const auto& other : p.fit)
            if (sameQuantity(other.name, fp.name)) throw f.error("parameter", "each parameter fitted once");
        fp.lower = f.number("lower");
        fp.upper = f.number("upper");
        checkParameterValue(f, "lower", fp.name, fp.lower);
        checkParameterValue(f, "upper", fp.name, fp.upper);
        if (!(fp.lower < fp.upper)) throw f.error("upper", "a value above 'lower'");
        p.fit.push_back(fp);
    }
    p.calibrateOn = readBatchIds(c, "calibrate_on");
    p.predict = readBatchIds(c, "predict");
    p.predictVenting = c.text("predict_venting");
    if (!p.venting.count(p.predictVenting))
        throw c.error("predict_venting", "the name of an arrangement under 'venting'");
    for (const auto& id : p.calibrateOn) p.batch(id);
    for (const auto& id : p.predict) p.batch(id);
    if (c.has("profile")) readProfile(c.child("profile"), p);
}

// The what-if grid: one batch and venting, hot-air set-points above the
// ambient and up to 150 degC, vented fractions from 0 to 1, each list
// non-empty and increasing.
void readWhatif(const YamlInput& w, Plant& p)
{
    w.rejectUnknown({"batch", "venting", "hot_air_temperatures_C", "vented_fractions"});
    p.whatifBatch = w.text("batch");
    p.batch(p.whatifBatch);
    p.whatifVenting = w.text("venting");
    if (!p.venting.count(p.whatifVenting))
        throw w.error("venting", "the name of an arrangement under 'venting'");
    p.whatifTemperatures = w.increasingNumbers("hot_air_temperatures_C", "degC");
    for (double t : p.whatifTemperatures)
        if (!(t > p.base.ambientC && t <= 150))
            throw w.error("hot_air_temperatures_C", "set-points above ambient and <= 150 degC");
    p.whatifVentedFractions = w.increasingNumbers("vented_fractions");
    for (double f : p.whatifVentedFractions)
        if (!(f >= 0 && f <= 1)) throw w.error("vented_fractions", "fractions from 0 to 1");
}

} // namespace

std::vector<std::string> Plant::parameterNames()
{
    return {"heat_transfer_coefficient_W_per_m2K",
            "rate_constant_per_h",
            "activation_energy_kJ_per_mol",
            "falling_rate_exponent",
            "critical_moisture_percent_db",
            "oswin_A_percent_db",
            "wall_UA_W_per_K",
            "vented_fraction_all (same in every venting)",
            "venting.<name>.vented_fraction",
            "venting.<name>.vent_short_circuit_fraction"};
}

double Plant::get(const std::string& name) const
{
    if (name == "heat_transfer_coefficient_W_per_m2K") return base.hConv;
    if (name == "falling_rate_exponent") return base.fallingExponent;
    if (name == "rate_constant_per_h") return base.rateConstant * 3600;
    if (name == "vented_fraction_all")
    {
        // one vent flow shared by every arrangement (same fans and ducts)
        const double v = venting.begin()->second.ventedFraction;
        for (const auto& kv : venting)
            if (kv.second.ventedFraction != v) throw std::invalid_argument(name);
        return v;
    }
    if (name == "activation_energy_kJ_per_mol") return base.activationEnergy / 1e3;
    if (name == "critical_moisture_percent_db") return base.xCritical * 100;
    if (name == "oswin_A_percent_db") return base.oswinA * 100;
    if (name == "wall_UA_W_per_K") return base.wallUA;
    if (name.rfind("venting.", 0) == 0)
    {
        const auto dot = name.find('.', 8);
        const std::string v = name.substr(8, dot - 8), field = name.substr(dot + 1);
        const auto it = venting.find(v);
        if (it != venting.end() && dot != std::string::npos)
        {
            if (field == "vented_fraction") return it->second.ventedFraction;
            if (field == "vent_short_circuit_fraction") return it->second.shortCircuit;
        }
    }
    throw std::invalid_argument(name);
}

void Plant::set(const std::string& name, double value)
{
    if (name == "heat_transfer_coefficient_W_per_m2K")
        base.hConv = value;
    else if (name == "falling_rate_exponent")
        base.fallingExponent = value;
    else if (name == "rate_constant_per_h")
        base.rateConstant = value / 3600;
    else if (name == "vented_fraction_all")
        for (auto& kv : venting) kv.second.ventedFraction = value;
    else if (name == "activation_energy_kJ_per_mol")
        base.activationEnergy = value * 1e3;
    else if (name == "critical_moisture_percent_db")
        base.xCritical = value / 100;
    else if (name == "oswin_A_percent_db")
        base.oswinA = value / 100;
    else if (name == "wall_UA_W_per_K")
        base.wallUA = value;
    else
    {
        get(name); // validates
        const auto dot = name.find('.', 8);
        Venting& v = venting[name.substr(8, dot - 8)];
        if (name.substr(dot + 1) == "vented_fraction")
            v.ventedFraction = value;
        else
            v.shortCircuit = value;
    }
}

const BatchSpec& Plant::batch(const std::string& id) const
{
    for (const auto& b : batches)
        if (b.id == id) return b;
    std::string ids;
    for (const auto& b : batches) ids += (ids.empty() ? "" : ", ") + b.id;
    throw InputError(file + ": no batch '" + id + "' (batches: " + ids + ")");
}

DryerCase Plant::caseFor(const BatchSpec& b) const
{
    return caseFor(b, b.venting);
}

DryerCase Plant::caseFor(const BatchSpec& b, const std::string& ventingName) const
{
    DryerCase c = base;
    c.name = b.id;
    const auto it = venting.find(ventingName);
    if (it == venting.end())
        throw InputError(file + ": venting '" + ventingName + "' is not defined under 'venting'");
    c.ventedFraction = it->second.ventedFraction;
    c.ventShortCircuit = it->second.shortCircuit;
    c.hotAirC = b.hotAirC;
    c.dryMass = b.dryMass;
    c.x0 = b.x0;
    c.xTarget = b.xTarget;
    c.x0Spread = b.x0Spread;
    c.seed = b.seed;
    return c;
}

Plant readPlant(const std::string& path)
{
    const YamlInput in = YamlInput::load(path);
    in.rejectUnknown(
        {"dryer", "product", "kinetics", "operation", "venting", "batches", "calibration", "whatif", "run"});
    Plant p;
    p.file = path;
    readDryer(in.child("dryer"), p.base);
    readProduct(in.child("product"), p.base);
    readKinetics(in.child("kinetics"), p.base);
    readOperation(in.child("operation"), p.base);
    if (in.has("run")) readRun(in.child("run"), p.base);
    readVentings(in, p);
    readBatches(in, p);
    if (in.has("calibration")) readCalibration(in.child("calibration"), p);
    if (in.has("whatif")) readWhatif(in.child("whatif"), p);
    return p;
}

void writePlant(const Plant& p, const std::string& path, const std::string& comment)
{
    OutputFile file(path);
    std::ostream& o = file.out();
    const DryerCase& c = p.base;
    auto list = [](const std::vector<double>& v) {
        std::string s = "[";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + fmt(v[i]);
        return s + "]";
    };
    o << "# " << comment << "\n";
    o << "dryer:\n  carts: " << c.carts << "\n  trays_per_cart: " << c.traysPerCart
      << "\n  pieces_per_tray: " << c.piecesPerTray << "\n  air_holdup_kg: " << fmt(c.airHoldup)
      << "\n  wall_UA_W_per_K: " << fmt(c.wallUA) << "\n  heater_power_kW: " << fmt(c.heaterPower / 1e3)
      << "\n  fan_power_kW: " << fmt(c.fanPower / 1e3) << "\n  circulation_kg_per_s: " << fmt(c.circulation)
      << "\n  heat_transfer_coefficient_W_per_m2K: " << fmt(c.hConv)
      << "\n  velocity_exponent: " << fmt(c.velocityExponent) << "\n";
    if (!c.cartFactors.empty() || !c.trayFactors.empty())
    {
        o << "  air_distribution:\n";
        if (!c.cartFactors.empty()) o << "    cart_factors: " << list(c.cartFactors) << "\n";
        if (!c.trayFactors.empty()) o << "    tray_factors: " << list(c.trayFactors) << "\n";
    }
    o << "product:\n  piece_diameter_mm: " << fmt(c.pieceDiameter * 1e3)
      << "\n  piece_length_m: " << fmt(c.pieceLength) << "\n  specific_heat_dry_J_per_kgK: " << fmt(c.cpDry)
      << "\n  scorch_temperature_C: " << fmt(c.scorchC) << "\n";
    o << "kinetics:\n";
    if (c.kinetics == DryerCase::Kinetics::ThinLayer)
        o << "  model: thin-layer\n  rate_constant_per_h: " << fmt(c.rateConstant * 3600)
          << "\n  reference_temperature_C: " << fmt(c.referenceC)
          << "\n  activation_energy_kJ_per_mol: " << fmt(c.activationEnergy / 1e3) << "\n";
    else
        o << "  model: characteristic-curve\n  critical_moisture_percent_db: " << fmt(c.xCritical * 100)
          << "\n  falling_rate_exponent: " << fmt(c.fallingExponent) << "\n";
    o << "  oswin_A_percent_db: " << fmt(c.oswinA * 100) << "\n  oswin_B: " << fmt(c.oswinB) << "\n";
    o << "operation:\n  ambient_temperature_C: " << fmt(c.ambientC)
      << "\n  ambient_relative_humidity_percent: " << fmt(c.ambientRH * 100)
      << "\n  pressure_kPa: " << fmt(c.pressure / 1e3) << "\n";
    o << "run:\n  max_time_h: " << fmt(c.maxTime / 3600)
      << "\n  output_interval_min: " << fmt(c.outputInterval / 60) << "\n";
    o << "venting:\n";
    for (const auto& [name, v] : p.venting)
        o << "  " << name << ": {vented_fraction: " << fmt(v.ventedFraction)
          << ", vent_short_circuit_fraction: " << fmt(v.shortCircuit) << "}\n";
    o << "batches:\n";
    for (const auto& b : p.batches)
    {
        o << "  - id: \"" << b.id << "\"\n    venting: " << b.venting
          << "\n    hot_air_temperature_C: " << fmt(b.hotAirC) << "\n    dry_mass_kg: " << fmt(b.dryMass)
          << "\n    initial_moisture_percent_db: " << fmt(b.x0 * 100)
          << "\n    target_moisture_percent_db: " << fmt(b.xTarget * 100)
          << "\n    initial_moisture_spread_percent: " << fmt(b.x0Spread * 100)
          << "\n    pattern_seed: " << b.seed << "\n";
        if (b.measuredTime || b.measuredElectricity || b.measuredF1 || b.measuredF2)
        {
            o << "    measured:\n";
            if (b.measuredTime)
            {
                const long m = std::lround(*b.measuredTime / 60);
                o << "      drying_time: \"" << m / 60 << ":" << std::setw(2) << std::setfill('0') << m % 60
                  << std::setfill(' ') << "\"\n";
            }
            if (b.measuredElectricity)
                o << "      electricity_kWh: " << fmt(*b.measuredElectricity / 3.6e6) << "\n";
            if (b.measuredF1) o << "      f1_percent: " << fmt(*b.measuredF1) << "\n";
            if (b.measuredF2) o << "      f2_percent: " << fmt(*b.measuredF2) << "\n";
        }
    }
    if (!p.whatifBatch.empty())
    {
        o << "whatif:\n  batch: \"" << p.whatifBatch << "\"\n  venting: " << p.whatifVenting
          << "\n  hot_air_temperatures_C: " << list(p.whatifTemperatures)
          << "\n  vented_fractions: " << list(p.whatifVentedFractions) << "\n";
    }
    file.close();
}

} // namespace procsim::dryer
