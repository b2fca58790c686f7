#include "kinetics/Corona.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <iomanip>

#include "common/Csv.hpp"
#include "common/YamlInput.hpp"
#include "kinetics/Case.hpp"

namespace procsim::kinetics::corona
{

double numberDensity(double p, double t) { return p / (boltzmann * t); }

double field(double v, double r, double anodeR, double wireR) { return v / (r * std::log(anodeR / wireR)); }

double meanEOverN(double v, double anodeR, double wireR, double n)
{
    return 2.0 * v / (n * (anodeR + wireR) * std::log(anodeR / wireR));
}

double removalEfficiency(double c0, double c) { return (c0 - c) / c0; }

double residenceCorrected(double psi, double t, double tRef) { return psi * t / tRef; }

double energeticEfficiency(double qIn, double qOut, double i, double v) { return (qIn - qOut) / (i * v); }

} // namespace procsim::kinetics::corona

namespace procsim::kinetics
{

const char* coronaHelp()
{
    return R"(usage: procsim kinetics corona FILE.yaml [-o DIR]

Gas-side formulas of the dry corona-discharge papers, evaluated for lists of
operating points. Each section is optional; every item may carry a 'label'.

  mean_en:                        toluene paper eqs 1-2: mean E/N over the annulus
    - voltage_kV: 14.8            applied voltage V
      wire_diameter_mm: 0.3       cathode wire diameter (2 R0)
      anode_diameter_mm: 37       anode inner diameter (2 R)
      temperature_C: 25           gas temperature (N = p / (k_B T))
      pressure_kPa: 101.325       gas pressure
    -> E at the wire and at the anode (kV/cm), N (1/m3), <E/N> in Td (1 Td = 1e-21 V m2)
  removal:                        acetaldehyde paper eqs 1-2
    - outlet_ppm_no_discharge: 600   C_out at 0 mA (same temperature)
      outlet_ppm_discharge: 150      C_out with discharge
      temperature_C: 200             reactor temperature T
      reference_temperature_C: 25    optional (default 25); residence time scales as 1/T(K)
    -> psi and psi' = psi * theta(T_ref)/theta(T) = psi * T/T_ref (fixed molar flow, pressure)
  energetic:                      toluene paper eq 4
    - inlet_ppm: 2000             target gas at the inlet
      outlet_ppm: 1000            target gas at the outlet
      gas_flow_m3_per_s: 1.67e-6  volumetric flow at the temperature/pressure below
      temperature_C: 25
      pressure_kPa: 101.325
      current_mA: 0.5
      voltage_kV: 14.8
    -> molar flows q_in, q_out (mol/s) and J = (q_in - q_out)/(I V) in mol/J

Writes corona_mean_en.csv, corona_removal.csv, corona_energetic.csv into DIR
(default: <file name>_out) and prints them.
)";
}

namespace
{

std::string label(const YamlInput& item, std::size_t i)
{
    return item.text("label", "point " + std::to_string(i + 1));
}

double kelvin(const YamlInput& item, const std::string& key)
{
    const double t = item.number(key, "degC");
    if (!(t > -273.15 && t <= 5000)) throw item.error(key, "a temperature above absolute zero and up to 5000 [degC]");
    return t + 273.15;
}

std::string num(double v) { return formatNumber(v); }

} // namespace

int coronaMain(int argc, char** argv)
{
    std::string file, dir;
    for (int i = 2; i < argc; ++i)
    {
        const std::string s = argv[i];
        if (s == "-o" || s == "--output")
        {
            if (i + 1 >= argc) throw InputError("kinetics corona: -o needs a directory");
            if (!dir.empty()) throw InputError("kinetics corona: option -o given twice");
            dir = argv[++i];
        }
        else if (!s.empty() && s[0] == '-') throw InputError("kinetics corona: unknown option '" + s + "'");
        else if (file.empty()) file = s;
        else throw InputError("kinetics corona: expected one input file");
    }
    if (file.empty()) throw InputError("kinetics corona: expected one input file");
    const YamlInput in = YamlInput::load(file);
    in.rejectUnknown({"title", "mean_en", "removal", "energetic"});
    if (dir.empty()) dir = std::filesystem::path(file).stem().string() + "_out";
    std::filesystem::create_directories(dir);
    using namespace corona;
    if (in.has("mean_en"))
    {
        CsvWriter csv(dir + "/corona_mean_en.csv", {"label", "voltage_kV", "wire_diameter_mm", "anode_diameter_mm", "temperature_C",
                                                    "pressure_kPa", "E_wire_kV_per_cm", "E_anode_kV_per_cm", "N_per_m3", "mean_E_over_N_Td"});
        std::cout << "mean E/N (toluene paper eq 2)\n";
        const auto items = in.child("mean_en").items();
        for (std::size_t i = 0; i < items.size(); ++i)
        {
            const auto& it = items[i];
            it.rejectUnknown({"label", "voltage_kV", "wire_diameter_mm", "anode_diameter_mm", "temperature_C", "pressure_kPa"});
            const double v = it.within("voltage_kV", 1e-6, 1e4, "kV") * 1e3;
            const double r0 = it.within("wire_diameter_mm", 1e-6, 1e4, "mm") * 0.5e-3;
            const double r = it.within("anode_diameter_mm", 1e-6, 1e5, "mm") * 0.5e-3;
            if (r <= r0) throw it.error("anode_diameter_mm", "a diameter larger than the wire's [mm]");
            const double tK = kelvin(it, "temperature_C");
            const double p = it.within("pressure_kPa", 1e-3, 1e6, "kPa") * 1e3;
            const double n = numberDensity(p, tK);
            const double en = meanEOverN(v, r, r0, n) / townsend;
            csv.row(std::vector<std::string>{label(it, i), num(v / 1e3), num(2e3 * r0), num(2e3 * r), num(tK - 273.15), num(p / 1e3),
                                             num(field(v, r0, r, r0) / 1e5), num(field(v, r, r, r0) / 1e5), num(n), num(en)});
            std::cout << "  " << label(it, i) << ": <E/N> = " << num(en) << " Td (N = " << num(n) << " 1/m3)\n";
        }
        csv.close();
    }
    if (in.has("removal"))
    {
        CsvWriter csv(dir + "/corona_removal.csv", {"label", "outlet_ppm_no_discharge", "outlet_ppm_discharge", "temperature_C",
                                                    "reference_temperature_C", "psi", "psi_prime"});
        std::cout << "removal efficiency (acetaldehyde paper eqs 1-2)\n";
        const auto items = in.child("removal").items();
        for (std::size_t i = 0; i < items.size(); ++i)
        {
            const auto& it = items[i];
            it.rejectUnknown({"label", "outlet_ppm_no_discharge", "outlet_ppm_discharge", "temperature_C", "reference_temperature_C"});
            const double c0 = it.within("outlet_ppm_no_discharge", 1e-12, 1e6, "ppm");
            const double c = it.within("outlet_ppm_discharge", 0, 1e6, "ppm");
            const double tK = kelvin(it, "temperature_C");
            const double tRef = it.has("reference_temperature_C") ? kelvin(it, "reference_temperature_C") : 298.15;
            const double psi = removalEfficiency(c0, c);
            const double psiP = residenceCorrected(psi, tK, tRef);
            csv.row(std::vector<std::string>{label(it, i), num(c0), num(c), num(tK - 273.15), num(tRef - 273.15), num(psi), num(psiP)});
            std::cout << "  " << label(it, i) << ": psi = " << num(psi) << ", psi' = " << num(psiP) << '\n';
        }
        csv.close();
    }
    if (in.has("energetic"))
    {
        CsvWriter csv(dir + "/corona_energetic.csv", {"label", "inlet_ppm", "outlet_ppm", "q_in_mol_per_s", "q_out_mol_per_s",
                                                      "current_mA", "voltage_kV", "J_mol_per_J"});
        std::cout << "energetic efficiency (toluene paper eq 4)\n";
        const auto items = in.child("energetic").items();
        for (std::size_t i = 0; i < items.size(); ++i)
        {
            const auto& it = items[i];
            it.rejectUnknown({"label", "inlet_ppm", "outlet_ppm", "gas_flow_m3_per_s", "temperature_C", "pressure_kPa", "current_mA",
                              "voltage_kV"});
            const double cin = it.within("inlet_ppm", 0, 1e6, "ppm");
            const double cout = it.within("outlet_ppm", 0, 1e6, "ppm");
            const double q = it.within("gas_flow_m3_per_s", 1e-12, 1e6, "m3/s");
            const double tK = kelvin(it, "temperature_C");
            const double p = it.within("pressure_kPa", 1e-3, 1e6, "kPa") * 1e3;
            const double i_mA = it.within("current_mA", 1e-9, 1e6, "mA");
            const double v_kV = it.within("voltage_kV", 1e-6, 1e4, "kV");
            const double molar = p * q / (gasConstant * tK);
            const double qin = molar * cin * 1e-6, qout = molar * cout * 1e-6;
            const double j = energeticEfficiency(qin, qout, i_mA * 1e-3, v_kV * 1e3);
            csv.row(std::vector<std::string>{label(it, i), num(cin), num(cout), num(qin), num(qout), num(i_mA), num(v_kV), num(j)});
            std::cout << "  " << label(it, i) << ": J = " << num(j) << " mol/J\n";
        }
        csv.close();
    }
    std::cout << "  output: " << dir << "/\n";
    return 0;
}

} // namespace procsim::kinetics
