#include "dryer/Metrics.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "common/YamlInput.hpp"
#include "Psychrometrics.hpp" // coupling/: the one psychrometrics of the project

namespace procsim::dryer
{

namespace psy = spoutlab::psy;

double LatentHeatConvention::perKg(double hotAirC, double ambientC) const
{
    if (kind == Kind::Constant) return constant;
    return psy::kHfg0 + psy::kCpVapour * hotAirC - psy::kCpWater * ambientC;
}

std::string LatentHeatConvention::describe() const
{
    std::ostringstream os;
    if (kind == Kind::Constant)
        os << "constant " << constant / 1e3 << " kJ/kg";
    else
        os << "liquid at ambient -> vapour at hot-air temperature: "
              "2501 + 1.86 T_hot - 4.186 T_amb kJ/kg";
    return os.str();
}

double parseHoursMinutes(const std::string& text)
{
    const auto colon = text.find(':');
    if (colon == std::string::npos) throw std::invalid_argument("no ':'");
    std::size_t used = 0;
    const std::string hs = text.substr(0, colon), ms = text.substr(colon + 1);
    const long h = std::stol(hs, &used);
    if (used != hs.size() || h < 0) throw std::invalid_argument("hours");
    const long m = std::stol(ms, &used);
    if (used != ms.size() || m < 0 || m >= 60) throw std::invalid_argument("minutes");
    return 3600.0 * h + 60.0 * m;
}

BatchMetrics computeMetrics(const BatchRecord& b, const LatentHeatConvention& lh)
{
    BatchMetrics m;
    m.id = b.id;
    const double dx = b.x1 - b.x2;
    m.rateWaterKg = std::nan("");
    if (b.rateKgPerS) m.rateWaterKg = *b.rateKgPerS * b.timeS;
    if (b.waterKg)
    {
        m.waterKg = *b.waterKg;
        m.waterFrom = "evaporated_water";
    }
    else if (b.dryMassKg)
    {
        m.waterKg = *b.dryMassKg * dx;
        m.waterFrom = "dry_mass x (X1 - X2)";
    }
    else
    {
        m.waterKg = m.rateWaterKg;
        m.waterFrom = "rate x time";
    }
    m.dryMassKg = b.dryMassKg ? *b.dryMassKg : m.waterKg / dx;
    m.rateKgPerH = m.waterKg / (b.timeS / 3600.0);
    m.electricityKWh = b.electricityJ / 3.6e6;
    m.latentJPerKg = lh.perKg(b.hotAirC, b.ambientC);
    m.specificEnergy = b.electricityJ / m.waterKg;
    m.eta = m.waterKg * m.latentJPerKg / b.electricityJ;
    m.rateDisagrees = std::isfinite(m.rateWaterKg) && m.waterFrom != "rate x time"
                      && std::fabs(m.rateWaterKg / m.waterKg - 1.0) > 0.01;
    return m;
}

void validate(const BatchRecord& b, const std::string& where)
{
    auto fail = [&](const std::string& key, const std::string& what) {
        throw InputError(b.source + ": key '" + where + key + "' expected " + what);
    };
    std::ostringstream x1;
    x1 << b.x1 * 100;
    auto bounded = [&](double v, double lo, double hi, const std::string& key, const std::string& unit) {
        if (!(v >= lo && v <= hi))
        {
            std::ostringstream os;
            os << "a number from " << lo << " to " << hi << " [" << unit << "], got " << v;
            fail(key, os.str());
        }
    };
    // bounds that keep a record physical (and its arithmetic finite)
    bounded(b.hotAirC, -50, 500, "hot_air_temperature_C", "degC");
    bounded(b.ambientC, -50, 60, "ambient_temperature_C", "degC");
    bounded(b.x1 * 100, 0, 10000, "initial_moisture_percent_db", "% dry basis");
    bounded(b.timeS / 3600, 0, 1e4, "drying_time_h", "h");
    bounded(b.electricityJ / 3.6e6, 0, 1e9, "electricity_kWh", "kWh");
    if (b.rateKgPerS) bounded(*b.rateKgPerS * 3600, 0, 1e7, "evaporation_rate_kg_per_h", "kg/h");
    if (b.dryMassKg) bounded(*b.dryMassKg, 0, 1e9, "dry_mass_kg", "kg");
    if (b.waterKg) bounded(*b.waterKg, 0, 1e9, "evaporated_water_kg", "kg");
    if (b.paperEta && !(*b.paperEta > 0 && *b.paperEta <= 1))
        fail("paper_energy_efficiency_percent", "a percentage above 0 and up to 100");
    if (b.paperE && !(*b.paperE > 0 && *b.paperE <= 1e12))
        fail("paper_specific_energy_kJ_per_kg", "a positive energy up to 1e9 [kJ/kg]");
    if (!(b.x1 > 0)) fail("initial_moisture_percent_db", "a positive moisture content [% dry basis]");
    if (!(b.x2 >= 0)) fail("final_moisture_percent_db", "a moisture content >= 0 [% dry basis]");
    if (!(b.x2 < b.x1))
    {
        std::ostringstream os;
        os << "a final moisture below the initial " << b.x1 * 100 << " % (dry basis), got " << b.x2 * 100;
        fail("final_moisture_percent_db", os.str());
    }
    if (!(b.timeS > 0)) fail("drying_time", "a positive drying time");
    if (!(b.electricityJ > 0)) fail("electricity_kWh", "a positive energy [kWh]");
    if (b.rateKgPerS && !(*b.rateKgPerS > 0)) fail("evaporation_rate_kg_per_h", "a positive rate [kg/h]");
    if (b.dryMassKg && !(*b.dryMassKg > 0)) fail("dry_mass_kg", "a positive mass [kg]");
    if (b.waterKg && !(*b.waterKg > 0)) fail("evaporated_water_kg", "a positive mass [kg]");
    if (!b.rateKgPerS && !b.dryMassKg && !b.waterKg)
        fail("evaporation_rate_kg_per_h",
             "one of evaporation_rate_kg_per_h, dry_mass_kg or evaporated_water_kg");
    if (!(b.hotAirC > b.ambientC))
    {
        std::ostringstream os;
        os << "a hot-air set-point above the ambient " << b.ambientC << " degC, got " << b.hotAirC;
        fail("hot_air_temperature_C", os.str());
    }
}

namespace
{

bool endsWith(const std::string& s, const std::string& tail)
{
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

LatentHeatConvention readConvention(const YamlInput& in)
{
    LatentHeatConvention lh;
    if (!in.has("latent_heat")) return lh;
    const YamlInput l = in.child("latent_heat");
    l.rejectUnknown({"convention", "value_kJ_per_kg"});
    const std::string c = l.text("convention");
    if (c == "ambient-liquid-to-hot-air-vapour")
        lh.kind = LatentHeatConvention::Kind::AmbientLiquidToHotAirVapour;
    else if (c == "constant")
    {
        lh.kind = LatentHeatConvention::Kind::Constant;
        lh.constant = l.positive("value_kJ_per_kg", "kJ/kg") * 1e3;
    }
    else
        throw l.error("convention", "'ambient-liquid-to-hot-air-vapour' or 'constant'");
    return lh;
}

BatchFile readYaml(const std::string& path)
{
    const YamlInput in = YamlInput::load(path);
    in.rejectUnknown({"batches", "latent_heat", "ambient_temperature_C"});
    BatchFile f;
    f.latentHeat = readConvention(in);
    const bool haveAmbient = in.has("ambient_temperature_C");
    const double ambient = haveAmbient ? in.number("ambient_temperature_C", "degC") : 0.0;
    const YamlInput list = in.child("batches");
    for (const YamlInput& b : list.items())
    {
        b.rejectUnknown({"id", "dryer", "material", "hot_air_temperature_C", "ambient_temperature_C",
                         "initial_moisture_percent_db", "final_moisture_percent_db", "drying_time",
                         "drying_time_h", "electricity_kWh", "evaporation_rate_kg_per_h", "dry_mass_kg",
                         "evaporated_water_kg", "paper_energy_efficiency_percent",
                         "paper_specific_energy_kJ_per_kg", "note"});
        BatchRecord r;
        r.source = path;
        r.id = b.text("id");
        r.dryer = b.text("dryer", "");
        r.material = b.text("material", "");
        r.hotAirC = b.number("hot_air_temperature_C", "degC");
        if (b.has("ambient_temperature_C"))
            r.ambientC = b.number("ambient_temperature_C", "degC");
        else if (haveAmbient)
            r.ambientC = ambient;
        else
            throw b.error("ambient_temperature_C", "a number [degC] (here or at the top level)");
        r.x1 = b.number("initial_moisture_percent_db", "% dry basis") / 100.0;
        r.x2 = b.number("final_moisture_percent_db", "% dry basis") / 100.0;
        if (b.has("drying_time"))
        {
            try
            {
                r.timeS = parseHoursMinutes(b.text("drying_time"));
            }
            catch (const std::invalid_argument&)
            {
                throw b.error("drying_time", "hours:minutes such as '11:50'");
            }
        }
        else
            r.timeS = b.number("drying_time_h", "h") * 3600.0;
        r.electricityJ = b.number("electricity_kWh", "kWh") * 3.6e6;
        if (b.has("evaporation_rate_kg_per_h"))
            r.rateKgPerS = b.number("evaporation_rate_kg_per_h", "kg/h") / 3600.0;
        if (b.has("dry_mass_kg")) r.dryMassKg = b.number("dry_mass_kg", "kg");
        if (b.has("evaporated_water_kg")) r.waterKg = b.number("evaporated_water_kg", "kg");
        if (b.has("paper_energy_efficiency_percent"))
            r.paperEta = b.number("paper_energy_efficiency_percent", "%") / 100.0;
        if (b.has("paper_specific_energy_kJ_per_kg"))
            r.paperE = b.number("paper_specific_energy_kJ_per_kg", "kJ/kg") * 1e3;
        validate(r, b.path() + ".");
        f.batches.push_back(r);
    }
    if (f.batches.empty()) throw list.error("batches", "a non-empty list of batch records");
    return f;
}

BatchFile readCsvFile(const std::string& path)
{
    const CsvTable t = readCsv(path, true); // "nan" = not given
    auto col = [&](const std::string& name) -> long {
        for (std::size_t i = 0; i < t.header.size(); ++i)
            if (t.header[i] == name) return static_cast<long>(i);
        return -1;
    };
    const std::vector<std::string> required = {"batch",
                                               "hot_air_temperature_C",
                                               "ambient_temperature_C",
                                               "initial_moisture_percent_db",
                                               "final_moisture_percent_db",
                                               "drying_time_h",
                                               "electricity_kWh"};
    std::vector<std::string> known = required;
    known.insert(known.end(), {"evaporation_rate_kg_per_h", "dry_mass_kg", "evaporated_water_kg",
                               "paper_energy_efficiency_percent", "paper_specific_energy_kJ_per_kg"});
    t.rejectUnknownColumns(known, path);                    // a misspelt optional column would be ignored
    for (const auto& name : required) t.column(name, path); // throws with the column name if missing
    BatchFile f;
    std::size_t line = 0;
    for (const auto& row : t.rows)
    {
        ++line;
        auto get = [&](const std::string& name) -> std::optional<double> {
            const long c = col(name);
            if (c < 0 || std::isnan(row[static_cast<std::size_t>(c)])) return std::nullopt;
            return row[static_cast<std::size_t>(c)];
        };
        auto need = [&](const std::string& name) {
            const auto v = get(name);
            if (!v)
                throw InputError(path + ": row " + std::to_string(line) + " column '" + name
                                 + "' expected a number, got nan");
            return *v;
        };
        BatchRecord r;
        r.source = path;
        std::ostringstream id;
        id << need("batch");
        r.id = id.str();
        r.hotAirC = need("hot_air_temperature_C");
        r.ambientC = need("ambient_temperature_C");
        r.x1 = need("initial_moisture_percent_db") / 100.0;
        r.x2 = need("final_moisture_percent_db") / 100.0;
        r.timeS = need("drying_time_h") * 3600.0;
        r.electricityJ = need("electricity_kWh") * 3.6e6;
        if (auto v = get("evaporation_rate_kg_per_h")) r.rateKgPerS = *v / 3600.0;
        if (auto v = get("dry_mass_kg")) r.dryMassKg = *v;
        if (auto v = get("evaporated_water_kg")) r.waterKg = *v;
        if (auto v = get("paper_energy_efficiency_percent")) r.paperEta = *v / 100.0;
        if (auto v = get("paper_specific_energy_kJ_per_kg")) r.paperE = *v * 1e3;
        validate(r, "row " + std::to_string(line) + " column ");
        f.batches.push_back(r);
    }
    if (f.batches.empty()) throw InputError(path + ": no batch rows");
    return f;
}

} // namespace

BatchFile readBatchFile(const std::string& path)
{
    BatchFile f = endsWith(path, ".csv") ? readCsvFile(path) : readYaml(path);
    rejectDuplicates(f.batches, &BatchRecord::id, path, "batch id");
    return f;
}

} // namespace procsim::dryer
