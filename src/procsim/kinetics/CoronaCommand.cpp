// procsim kinetics corona: the dry corona papers' gas-side formulas for
// lists of operating points: mean E/N, removal efficiency psi and psi',
// energetic efficiency J.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/YamlInput.hpp"
#include "kinetics/Case.hpp"
#include "kinetics/Commands.hpp"
#include "kinetics/Corona.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

using namespace corona;

struct CoronaArgs
{
    std::string file;
    std::string output; // empty: <file name>_out
};

std::optional<CoronaArgs> parse(int argc, char** argv)
{
    CoronaArgs a;
    CommandLine cl("kinetics corona", std::string(texts::help::corona));
    cl.input(a.file, "input file");
    cl.text("-o,--output", a.output);
    if (!cl.parse(argc, argv)) return std::nullopt;
    return a;
}

std::string label(const YamlInput& item, std::size_t i)
{
    return item.text("label", "point " + std::to_string(i + 1));
}

double kelvin(const YamlInput& item, const std::string& key)
{
    const double t = item.number(key, "degC");
    if (!(t > -273.15 && t <= 5000))
        throw item.error(key, "a temperature above absolute zero and up to 5000 [degC]");
    return t + 273.15;
}

std::string num(double v)
{
    return formatNumber(v);
}

// One operating point evaluated: its CSV row and the line printed for it.
struct Point
{
    std::vector<std::string> row;
    std::string line;
};

// Toluene paper eqs 1-2: the field at wire and anode, N and the area-mean E/N.
Point meanEn(const YamlInput& it, std::size_t i)
{
    it.rejectUnknown(
        {"label", "voltage_kV", "wire_diameter_mm", "anode_diameter_mm", "temperature_C", "pressure_kPa"});
    const double v = it.within("voltage_kV", 1e-6, 1e4, "kV") * 1e3;
    const double r0 = it.within("wire_diameter_mm", 1e-6, 1e4, "mm") * 0.5e-3;
    const double r = it.within("anode_diameter_mm", 1e-6, 1e5, "mm") * 0.5e-3;
    if (r <= r0) throw it.error("anode_diameter_mm", "a diameter larger than the wire's [mm]");
    const double tK = kelvin(it, "temperature_C");
    const double p = it.within("pressure_kPa", 1e-3, 1e6, "kPa") * 1e3;
    const double n = numberDensity(p, tK);
    const double en = meanEOverN(v, r, r0, n) / townsend;
    return {{label(it, i), num(v / 1e3), num(2e3 * r0), num(2e3 * r), num(tK - 273.15), num(p / 1e3),
             num(field(v, r0, r, r0) / 1e5), num(field(v, r, r, r0) / 1e5), num(n), num(en)},
            fmt::format("  {}: <E/N> = {} Td (N = {} 1/m3)\n", label(it, i), num(en), num(n))};
}

// Acetaldehyde paper eqs 1-2: psi and the residence-time corrected psi'.
Point removal(const YamlInput& it, std::size_t i)
{
    it.rejectUnknown({"label", "outlet_ppm_no_discharge", "outlet_ppm_discharge", "temperature_C",
                      "reference_temperature_C"});
    const double c0 = it.within("outlet_ppm_no_discharge", 1e-12, 1e6, "ppm");
    const double c = it.within("outlet_ppm_discharge", 0, 1e6, "ppm");
    if (c > c0)
        throw it.error("outlet_ppm_discharge",
                       "a concentration up to outlet_ppm_no_discharge " + num(c0) + " [ppm]");
    const double tK = kelvin(it, "temperature_C");
    const double tRef = it.has("reference_temperature_C") ? kelvin(it, "reference_temperature_C") : 298.15;
    const double psi = removalEfficiency(c0, c);
    const double psiP = residenceCorrected(psi, tK, tRef);
    return {{label(it, i), num(c0), num(c), num(tK - 273.15), num(tRef - 273.15), num(psi), num(psiP)},
            fmt::format("  {}: psi = {}, psi' = {}\n", label(it, i), num(psi), num(psiP))};
}

// Toluene paper eq 4: J = (q_in - q_out) / (I V) from molar flows.
Point energetic(const YamlInput& it, std::size_t i)
{
    it.rejectUnknown({"label", "inlet_ppm", "outlet_ppm", "gas_flow_m3_per_s", "temperature_C",
                      "pressure_kPa", "current_mA", "voltage_kV"});
    const double cin = it.within("inlet_ppm", 0, 1e6, "ppm");
    const double cout = it.within("outlet_ppm", 0, 1e6, "ppm");
    if (cout > cin)
        throw it.error("outlet_ppm", "an outlet concentration up to inlet_ppm " + num(cin) + " [ppm]");
    const double q = it.within("gas_flow_m3_per_s", 1e-12, 1e6, "m3/s");
    const double tK = kelvin(it, "temperature_C");
    const double p = it.within("pressure_kPa", 1e-3, 1e6, "kPa") * 1e3;
    const double mA = it.within("current_mA", 1e-9, 1e6, "mA");
    const double kV = it.within("voltage_kV", 1e-6, 1e4, "kV");
    const double molar = p * q / (gasConstant * tK);
    const double qin = molar * cin * 1e-6, qout = molar * cout * 1e-6;
    const double j = energeticEfficiency(qin, qout, mA * 1e-3, kV * 1e3);
    return {{label(it, i), num(cin), num(cout), num(qin), num(qout), num(mA), num(kV), num(j)},
            fmt::format("  {}: J = {} mol/J\n", label(it, i), num(j))};
}

// One optional section of the input: every item evaluated, then printed and written.
struct Section
{
    const char* key;
    const char* heading;
    const char* file;
    std::vector<std::string> header;
    Point (*evaluate)(const YamlInput&, std::size_t);
};

// Every point of a section that is there, checked before anything is written.
std::vector<Point> evaluateSection(const YamlInput& in, const Section& s)
{
    if (!in.has(s.key)) return {};
    const auto items = in.child(s.key).items();
    if (items.empty()) throw in.error(s.key, "a non-empty list of operating points");
    std::vector<Point> points;
    for (std::size_t i = 0; i < items.size(); ++i) points.push_back(s.evaluate(items[i], i));
    return points;
}

void writeSection(const Section& s, const std::vector<Point>& points, const std::string& dir)
{
    CsvWriter csv(dir + "/" + s.file, s.header);
    fmt::print("{}\n", s.heading);
    for (const auto& p : points)
    {
        fmt::print("{}", p.line);
        csv.row(p.row);
    }
    csv.close();
}

const std::vector<Section> sections = {
    {"mean_en",
     "mean E/N (toluene paper eq 2)",
     "corona_mean_en.csv",
     {"label", "voltage_kV", "wire_diameter_mm", "anode_diameter_mm", "temperature_C", "pressure_kPa",
      "E_wire_kV_per_cm", "E_anode_kV_per_cm", "N_per_m3", "mean_E_over_N_Td"},
     meanEn},
    {"removal",
     "removal efficiency (acetaldehyde paper eqs 1-2)",
     "corona_removal.csv",
     {"label", "outlet_ppm_no_discharge", "outlet_ppm_discharge", "temperature_C", "reference_temperature_C",
      "psi", "psi_prime"},
     removal},
    {"energetic",
     "energetic efficiency (toluene paper eq 4)",
     "corona_energetic.csv",
     {"label", "inlet_ppm", "outlet_ppm", "q_in_mol_per_s", "q_out_mol_per_s", "current_mA", "voltage_kV",
      "J_mol_per_J"},
     energetic},
};

} // namespace

int coronaCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    const YamlInput in = YamlInput::load(args->file);
    in.rejectUnknown({"title", "mean_en", "removal", "energetic"});
    std::vector<std::vector<Point>> points;
    for (const auto& s : sections) points.push_back(evaluateSection(in, s));
    if (!in.has("mean_en") && !in.has("removal") && !in.has("energetic"))
        throw InputError(args->file
                         + ": no section to evaluate (expected one or more of: mean_en, removal, energetic)");
    const std::string dir =
        args->output.empty() ? std::filesystem::path(args->file).stem().string() + "_out" : args->output;
    createOutputDirectory(dir);
    for (std::size_t k = 0; k < sections.size(); ++k)
        if (!points[k].empty()) writeSection(sections[k], points[k], dir);
    fmt::print("  output: {}/\n", dir);
    return 0;
}

} // namespace procsim::kinetics
