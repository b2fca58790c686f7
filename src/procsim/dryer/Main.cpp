// procsim dryer: batch hot-air tray dryer (the tray-dryer paper): energy
// metrics from batch records, psychrometrics, a physical batch simulation,
// calibration on measured batches and what-if sweeps.
#include "dryer/Main.hpp"

#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "dryer/Calibrate.hpp"
#include "dryer/Metrics.hpp"
#include "dryer/Model.hpp"
#include "dryer/Plant.hpp"
#include "dryer/Psychrometrics.hpp"

namespace procsim::dryer
{

namespace
{

const char* kUsage =
    "usage: procsim dryer <command> [options]   (procsim dryer <command> --help)\n"
    "\n"
    "Batch hot-air tray dryer with recirculation and partial venting (the\n"
    "dog-chew tray-dryer paper, Tables 1 and 2).\n"
    "\n"
    "commands:\n"
    "  metrics    E, eta, water evaporated and dry mass from batch records (Table 1)\n"
    "  psychro    moist-air properties at one state (0..200 degC)\n"
    "  simulate   simulate batches of a plant file: air, moisture per tray, energy\n"
    "  calibrate  fit uncertain parameters on measured batches, predict others\n"
    "  whatif     sweep hot-air temperature and vented fraction, flag scorching\n"
    "\n"
    "Definitions (paper): X = kg water / kg bone-dry material (dry basis, %);\n"
    "eta = energy used for evaporating water / energy used for operating dryer;\n"
    "E = energy used for operating dryer / mass of evaporated water.\n";

const char* kMetricsHelp =
    "usage: procsim dryer metrics RECORDS.{yaml,csv} [--out DIR] [--latent-heat-kJ-per-kg L]\n"
    "\n"
    "Computes, per batch: evaporated water W, dry mass, average evaporation\n"
    "rate, specific energy E = Q/W [kJ/kg] and energy efficiency eta = W L / Q,\n"
    "with Q the electricity used. Writes DIR/metrics.csv (default DIR '.').\n"
    "\n"
    "Evaporated water comes from, in order of preference: evaporated_water_kg;\n"
    "dry_mass_kg x (X1 - X2); evaporation_rate_kg_per_h x drying time. If a\n"
    "rate is given as well, rate x time is cross-checked (warning if > 1 % off).\n"
    "\n"
    "Latent heat L per kg (\"energy used for evaporating water\"):\n"
    "  default  liquid at ambient -> vapour at the hot-air temperature,\n"
    "           L = 2501 + 1.86 T_hot - 4.186 T_amb kJ/kg\n"
    "  --latent-heat-kJ-per-kg L   a constant instead (e.g. 2501, at 0 degC)\n"
    "\n"
    "YAML records:\n"
    "  latent_heat:            (optional) convention: ambient-liquid-to-hot-air-vapour\n"
    "                          | constant, with value_kJ_per_kg for 'constant'\n"
    "  ambient_temperature_C:  default ambient for all batches [degC]\n"
    "  batches: list of\n"
    "    id                              batch name (text)\n"
    "    dryer, material, note           free text (optional)\n"
    "    hot_air_temperature_C           hot-air set-point [degC], above ambient\n"
    "    ambient_temperature_C           (optional) overrides the top-level value\n"
    "    initial_moisture_percent_db     X1, average before drying [% dry basis]\n"
    "    final_moisture_percent_db       X2, average after drying [% dry basis], < X1\n"
    "    drying_time                     'hours:minutes', or drying_time_h [h]\n"
    "    electricity_kWh                 electricity for the batch [kWh]\n"
    "    evaporation_rate_kg_per_h       average rate [kg/h]     } at least\n"
    "    dry_mass_kg                     bone-dry mass [kg]      } one of\n"
    "    evaporated_water_kg             weighed water loss [kg] } these\n"
    "    paper_energy_efficiency_percent (optional) published eta, for comparison\n"
    "    paper_specific_energy_kJ_per_kg (optional) published E, for comparison\n"
    "CSV records: the same names as columns (drying_time_h, not 'h:min'; 'batch'\n"
    "for the id; 'nan' for a missing optional value).\n";

const char* kPsychroHelp =
    "usage: procsim dryer psychro --t T_C (--rh RH_% | --w W | --twb T_C | --tdew T_C)\n"
    "                             [--p P_kPa]\n"
    "\n"
    "Moist-air state at dry bulb T (-100..200 degC) and total pressure P\n"
    "(default 101.325 kPa), given one of: relative humidity [%], humidity ratio\n"
    "[kg water/kg dry air], thermodynamic wet bulb [degC] or dew point [degC].\n"
    "Prints saturation pressure, humidity ratio, relative humidity, enthalpy,\n"
    "dew point, thermodynamic wet bulb, specific volume and density.\n"
    "Formulation: ASHRAE Fundamentals ch. 1 (Hyland-Wexler saturation pressure,\n"
    "ideal mixing); the wet bulb is found by bisection and always converges.\n";

const char* kPlantHelp =
    "Plant file (YAML; every key is required unless marked optional):\n"
    "  dryer:\n"
    "    carts, trays_per_cart, pieces_per_tray   layout (paper: 9 carts, 15 trays, ~160 pieces)\n"
    "    air_holdup_kg                  dry air inside the dryer [kg]\n"
    "    wall_UA_W_per_K                heat loss through walls, roof, doors [W/K]\n"
    "    heater_power_kW                installed heater power (cap) [kW]\n"
    "    fan_power_kW                   electrical power of all fans, heats the air [kW]\n"
    "    circulation_kg_per_s           dry air through the fans G [kg/s]\n"
    "    heat_transfer_coefficient_W_per_m2K  air -> product h at the mean air share\n"
    "    velocity_exponent              h ~ (local air share)^n (0.8 turbulent, 0.5 laminar)\n"
    "    air_distribution:              (optional) relative air shares, normalised to mean 1\n"
    "      cart_factors                 one per cart\n"
    "      tray_factors                 one per tray position, top tray first\n"
    "  product:\n"
    "    piece_diameter_mm, piece_length_m   rod-shaped pieces; area = pieces x pi d L\n"
    "    specific_heat_dry_J_per_kgK    bone-dry product\n"
    "    scorch_temperature_C           product temperature that scorches\n"
    "  kinetics:\n"
    "    model                          thin-layer | characteristic-curve\n"
    "    thin-layer: internal rate m_dry k (X - X_eq) in series with the gas film\n"
    "      rate_constant_per_h          k at the reference temperature [1/h]\n"
    "      reference_temperature_C      [degC]\n"
    "      activation_energy_kJ_per_mol k = k_ref exp(-Ea/R (1/T - 1/T_ref)), T product\n"
    "    characteristic-curve: gas-film rate x f(X)\n"
    "      critical_moisture_percent_db X_cr: constant rate above, falling rate below\n"
    "      falling_rate_exponent        n in f = ((X - X_eq)/(X_cr - X_eq))^n\n"
    "    oswin_A_percent_db, oswin_B    equilibrium moisture X_eq = A (a/(1-a))^B at the\n"
    "                                   air's relative humidity a: rate zero at and below\n"
    "  operation:\n"
    "    ambient_temperature_C, ambient_relative_humidity_percent, pressure_kPa\n"
    "  run: (optional) max_time_h (30), output_interval_min (10)\n"
    "  venting: named arrangements, each\n"
    "    vented_fraction                vented air G_v / G, replaced by ambient air\n"
    "    vent_short_circuit_fraction    share of the make-up air that is heated and\n"
    "                                   vented without reaching the trays\n"
    "  batches: list of\n"
    "    id, venting (a name above), hot_air_temperature_C (set-point at the louvres)\n"
    "    dry_mass_kg, initial_moisture_percent_db, target_moisture_percent_db\n"
    "    initial_moisture_spread_percent (optional, relative std dev over trays)\n"
    "    pattern_seed (optional integer)\n"
    "    measured: (optional) drying_time 'h:min', electricity_kWh, f1_percent, f2_percent\n"
    "  calibration: (optional)\n"
    "    fit: list of {parameter, lower, upper}; parameter one of\n"
    "         heat_transfer_coefficient_W_per_m2K, rate_constant_per_h,\n"
    "         activation_energy_kJ_per_mol, falling_rate_exponent,\n"
    "         critical_moisture_percent_db, oswin_A_percent_db, wall_UA_W_per_K,\n"
    "         vented_fraction_all (one value shared by every venting arrangement),\n"
    "         venting.<name>.vented_fraction, venting.<name>.vent_short_circuit_fraction\n"
    "    calibrate_on: batch ids; predict: batch ids; predict_venting: a venting name\n"
    "    profile: (optional)\n"
    "      hold: list of {parameter (as in fit), values: [..]}: grid, last one fastest\n"
    "      time_tolerance_percent, electricity_tolerance_percent: a refit fits the\n"
    "                                   calibration batches if every error is within\n"
    "  whatif: (optional)\n"
    "    batch, venting, hot_air_temperatures_C: [..], vented_fractions: [..]\n";

std::string simulateHelp()
{
    return std::string(
               "usage: procsim dryer simulate PLANT.yaml [--batch ID] [--out DIR]\n"
               "\n"
               "Simulates each batch (or only ID) until the batch-average moisture reaches\n"
               "its target. Writes to DIR (default '.'):\n"
               "  <id>_series.csv   time [h], supply/return air temperature [degC] and\n"
               "                    humidity, moisture mean/min/max, product temperature,\n"
               "                    heater power [kW], evaporation [kg/h], electricity [kWh]\n"
               "  <id>_trays.csv    per tray: cart, tray, air share, X initial/final [%],\n"
               "                    deviation from the mean [%], product temperature\n"
               "  <id>_tray_moisture.csv  moisture of every tray over time\n"
               "  <id>_batch.png    air temperatures and moisture over time\n"
               "  simulate_summary.csv  drying time, electricity, E, eta, f1, f2, wall\n"
               "                    condensate [kg], water and energy balance residuals\n"
               "\n")
           + kPlantHelp;
}

std::string calibrateHelp()
{
    return std::string(
               "usage: procsim dryer calibrate PLANT.yaml [--out DIR] [--max-iterations N]\n"
               "                                          [--profile on|off]\n"
               "\n"
               "Fits calibration.fit on the batches calibration.calibrate_on (least squares\n"
               "on the relative errors of drying time and electricity, Ceres), then runs\n"
               "calibration.predict with their own venting changed to\n"
               "calibration.predict_venting.\n"
               "\n"
               "With calibration.profile, it then holds the listed parameters on every\n"
               "point of their grid, refits the other fit parameters on the same batches,\n"
               "keeps the refits whose every time and electricity error is within the\n"
               "tolerances (the batches' scatter) and predicts with each: the band of\n"
               "predictions over the parameter sets those batches cannot tell apart.\n"
               "\n"
               "Writes DIR/calibration.csv (per batch: time, electricity, E, eta measured,\n"
               "central fit, band min/max, whether the measurement lies in the band),\n"
               "DIR/calibration.png, DIR/profile.csv (every grid point: held and refitted\n"
               "values, errors, accepted, predictions) and DIR/calibrated.yaml (the plant\n"
               "file with the central fit).\n"
               "--max-iterations N caps the Levenberg-Marquardt iterations per fit (default 50).\n"
               "--profile off skips the profile (default on when the plant file has one).\n"
               "\n")
           + kPlantHelp;
}

std::string whatifHelp()
{
    return std::string(
               "usage: procsim dryer whatif PLANT.yaml [--out DIR]\n"
               "\n"
               "Runs whatif.batch with whatif.venting at every hot-air temperature x vented\n"
               "fraction; flags settings whose highest product temperature exceeds\n"
               "product.scorch_temperature_C; reports the settings with the lowest E\n"
               "and the shortest drying time that do not scorch. Writes DIR/whatif.csv, DIR/whatif_time.png and\n"
               "DIR/whatif_energy.png.\n"
               "\n")
           + kPlantHelp;
}

struct Args
{
    std::vector<std::string> positional;
    std::map<std::string, std::string> options;
};

Args parse(int argc, char** argv, const std::vector<std::string>& valued)
{
    Args a;
    for (int i = 1; i < argc; ++i)
    {
        const std::string s = argv[i];
        if (s.rfind("--", 0) == 0)
        {
            bool known = false;
            for (const auto& v : valued)
                if (v == s) known = true;
            if (!known) throw InputError(std::string("dryer ") + argv[0] + ": unknown option '" + s + "'");
            if (i + 1 >= argc) throw InputError(std::string("dryer ") + argv[0] + ": option '" + s + "' needs a value");
            if (a.options.count(s)) throw InputError(std::string("dryer ") + argv[0] + ": option '" + s + "' given twice");
            a.options[s] = argv[++i];
        }
        else
            a.positional.push_back(s);
    }
    return a;
}

double optNumber(const Args& a, const std::string& key, const std::string& cmd)
{
    const std::string& v = a.options.at(key);
    const auto x = parseFinite(v);
    if (!x) throw InputError("dryer " + cmd + ": option '" + key + "' expected a finite number, got '" + v + "'");
    return *x;
}

std::string outDir(const Args& a)
{
    const auto it = a.options.find("--out");
    const std::string d = it == a.options.end() ? "." : it->second;
    for (std::size_t pos = d.find('/', 1); ; pos = d.find('/', pos + 1))
    {
        ::mkdir(d.substr(0, pos).c_str(), 0755);   // parents first; errors show below
        if (pos == std::string::npos) break;
    }
    struct stat st;
    if (::stat(d.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw InputError("dryer: --out '" + d + "' is not a directory and cannot be created");
    return d;
}

std::string hm(double seconds)
{
    const long m = std::lround(seconds / 60);
    std::ostringstream os;
    os << m / 60 << ":" << std::setw(2) << std::setfill('0') << m % 60;
    return os.str();
}

std::string num(double v, int prec = 2)
{
    std::ostringstream os;
    os << std::fixed << std::setprecision(prec) << v;
    return os.str();
}

bool wantsHelp(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        if (isHelp(argv[i])) return true;
    return false;
}

// ---------------------------------------------------------------- metrics
int runMetrics(int argc, char** argv)
{
    if (wantsHelp(argc, argv))
    {
        std::cout << kMetricsHelp;
        return 0;
    }
    const Args a = parse(argc, argv, {"--out", "--latent-heat-kJ-per-kg"});
    if (a.positional.size() != 1)
        throw InputError("dryer metrics: expected one records file (see --help)");
    BatchFile f = readBatchFile(a.positional[0]);
    if (a.options.count("--latent-heat-kJ-per-kg"))
    {
        const double l = optNumber(a, "--latent-heat-kJ-per-kg", "metrics");
        if (!(l > 0))
            throw InputError("dryer metrics: option '--latent-heat-kJ-per-kg' expected a positive number");
        f.latentHeat.kind = LatentHeatConvention::Kind::Constant;
        f.latentHeat.constant = l * 1e3;
    }
    const std::string dir = outDir(a);
    CsvWriter csv(dir + "/metrics.csv",
                  {"batch", "hot_air_temperature_C", "X1_percent_db", "X2_percent_db",
                   "drying_time_h", "electricity_kWh", "evaporated_water_kg", "dry_mass_kg",
                   "evaporation_rate_kg_per_h", "latent_heat_kJ_per_kg", "eta_percent",
                   "E_kJ_per_kg", "paper_eta_percent", "paper_E_kJ_per_kg", "eta_dev_percent",
                   "E_dev_percent"});
    std::cout << "latent heat: " << f.latentHeat.describe() << "\n\n";
    std::cout << std::left << std::setw(7) << "batch" << std::right << std::setw(10) << "water kg"
              << std::setw(10) << "dry kg" << std::setw(9) << "kg/h" << std::setw(9) << "L kJ/kg"
              << std::setw(9) << "eta %" << std::setw(9) << "paper" << std::setw(10) << "E kJ/kg"
              << std::setw(10) << "paper" << std::setw(9) << "dE %" << "\n";
    for (const auto& b : f.batches)
    {
        const BatchMetrics m = computeMetrics(b, f.latentHeat);
        const double pe = b.paperEta ? *b.paperEta * 100 : std::nan("");
        const double pE = b.paperE ? *b.paperE / 1e3 : std::nan("");
        const double dEta = (m.eta * 100 / pe - 1) * 100, dE = (m.specificEnergy / 1e3 / pE - 1) * 100;
        std::cout << std::left << std::setw(7) << b.id << std::right << std::setw(10)
                  << num(m.waterKg, 1) << std::setw(10) << num(m.dryMassKg, 1) << std::setw(9)
                  << num(m.rateKgPerH) << std::setw(9) << num(m.latentJPerKg / 1e3, 1)
                  << std::setw(9) << num(m.eta * 100) << std::setw(9) << num(pe) << std::setw(10)
                  << num(m.specificEnergy / 1e3) << std::setw(10) << num(pE) << std::setw(9)
                  << num(dE, 3) << "\n";
        if (m.rateDisagrees)
        {
            std::cout << "        warning: the reported rate x drying time gives "
                      << num(m.rateWaterKg, 1) << " kg, not " << num(m.waterKg, 1) << " kg ("
                      << m.waterFrom << "); " << num(m.waterKg / (*b.rateKgPerS * 3600), 2)
                      << " h would match\n";
        }
        csv.row(std::vector<std::string>{
            b.id, num(b.hotAirC, 2), num(b.x1 * 100, 4), num(b.x2 * 100, 4), num(b.timeS / 3600, 6),
            num(m.electricityKWh, 4), num(m.waterKg, 4), num(m.dryMassKg, 4), num(m.rateKgPerH, 4),
            num(m.latentJPerKg / 1e3, 4), num(m.eta * 100, 4), num(m.specificEnergy / 1e3, 4),
            num(pe, 4), num(pE, 4), num(dEta, 4), num(dE, 4)});
    }
    csv.close();
    std::cout << "\nwrote " << dir << "/metrics.csv\n";
    return 0;
}

// ---------------------------------------------------------------- psychro
int runPsychro(int argc, char** argv)
{
    if (wantsHelp(argc, argv))
    {
        std::cout << kPsychroHelp;
        return 0;
    }
    const Args a = parse(argc, argv, {"--t", "--rh", "--w", "--twb", "--tdew", "--p"});
    if (!a.positional.empty()) throw InputError("dryer psychro: unexpected argument '" + a.positional[0] + "'");
    if (!a.options.count("--t")) throw InputError("dryer psychro: option '--t' (dry bulb, degC) is required");
    const double t = optNumber(a, "--t", "psychro");
    if (!(t >= -100 && t <= 200))
        throw InputError("dryer psychro: option '--t' expected a dry bulb from -100 to 200 degC");
    const double p = a.options.count("--p") ? optNumber(a, "--p", "psychro") * 1e3 : psy::kAtm;
    if (!(p > 0)) throw InputError("dryer psychro: option '--p' expected a positive pressure [kPa]");
    int given = 0;
    for (const char* k : {"--rh", "--w", "--twb", "--tdew"}) given += a.options.count(k);
    if (given != 1)
        throw InputError("dryer psychro: give exactly one of --rh, --w, --twb, --tdew");
    double W = 0;
    try
    {
        if (a.options.count("--rh"))
        {
            const double rh = optNumber(a, "--rh", "psychro");
            if (!(rh >= 0 && rh <= 100))
                throw InputError("dryer psychro: option '--rh' expected 0 to 100 %, got " + a.options.at("--rh"));
            if (rh / 100 * psy::saturationPressure(t) >= p)
                throw InputError("dryer psychro: option '--rh' gives a vapour pressure at or above the total pressure");
            W = psy::humidityRatioFromRH(t, rh / 100, p);
        }
        else if (a.options.count("--w"))
        {
            W = optNumber(a, "--w", "psychro");
            if (!(W >= 0)) throw InputError("dryer psychro: option '--w' expected a humidity ratio >= 0");
            if (psy::relativeHumidity(t, W, p) > 1 + 1e-12)
                throw InputError("dryer psychro: option '--w' is above saturation at this dry bulb (relative humidity over 100 %)");
        }
        else if (a.options.count("--twb"))
        {
            const double twb = optNumber(a, "--twb", "psychro");
            if (!(twb <= t && twb >= -100))
                throw InputError("dryer psychro: option '--twb' expected a wet bulb at or below the dry bulb");
            W = psy::humidityRatioFromWetBulb(t, twb, p);
            if (!(W >= 0))
                throw InputError("dryer psychro: option '--twb' is too low for any humidity at this dry bulb");
        }
        else
        {
            const double td = optNumber(a, "--tdew", "psychro");
            if (!(td <= t && td >= -100))
                throw InputError("dryer psychro: option '--tdew' expected a dew point at or below the dry bulb");
            W = psy::humidityRatioFromPw(psy::saturationPressure(td), p);
        }
    }
    catch (const std::domain_error& e)
    {
        throw InputError(std::string("dryer psychro: ") + e.what());
    }
    const double pws = psy::saturationPressure(t);
    std::cout << std::setprecision(6) << "dry bulb                " << t << " degC\n"
              << "pressure                " << p / 1e3 << " kPa\n"
              << "saturation pressure     " << pws / 1e3 << " kPa\n"
              << "humidity ratio          " << W << " kg/kg dry air\n"
              << "relative humidity       " << psy::relativeHumidity(t, W, p) * 100 << " %\n"
              << "enthalpy                " << psy::enthalpy(t, W) / 1e3 << " kJ/kg dry air\n"
              << "dew point               " << (W > 0 ? num(psy::dewPoint(W, p), 3) : std::string("-inf")) << " degC\n"
              << "thermodynamic wet bulb  " << psy::wetBulb(t, W, p) << " degC\n"
              << "specific volume         " << psy::specificVolume(t, W, p) << " m3/kg dry air\n"
              << "density                 " << psy::density(t, W, p) << " kg/m3\n";
    return 0;
}

// ---------------------------------------------------------------- simulate
void writeBatchOutputs(const std::string& dir, const DryerCase& c, const BatchResult& r)
{
    const std::string base = dir + "/" + c.name;
    {
        CsvWriter s(base + "_series.csv",
                    {"time_h", "T_supply_C", "T_return_C", "W_supply_kg_per_kg",
                     "W_return_kg_per_kg", "RH_return_percent", "X_mean_percent_db",
                     "X_min_percent_db", "X_max_percent_db", "T_product_mean_C",
                     "T_product_max_C", "heater_kW", "evaporation_kg_per_h",
                     "electricity_kWh"});
        for (const auto& p : r.series)
            s.row(std::vector<double>{p.t / 3600, p.tSupply, p.tReturn, p.wSupply, p.wReturn,
                                      p.rhReturn * 100, p.xAvg * 100, p.xMin * 100, p.xMax * 100,
                                      p.tProductMean, p.tProductMax, p.heaterW / 1e3,
                                      p.evaporationKgPerS * 3600, p.electricityJ / 3.6e6});
        s.close();
    }
    {
        const auto phi = c.airShares();
        double mean = 0;
        for (double x : r.trayX) mean += x / r.trayX.size();
        CsvWriter t(base + "_trays.csv", {"cart", "tray", "air_share", "X_initial_percent_db",
                                          "X_final_percent_db", "deviation_percent",
                                          "T_product_final_C"});
        for (int ci = 0; ci < c.carts; ++ci)
            for (int k = 0; k < c.traysPerCart; ++k)
            {
                const std::size_t i = static_cast<std::size_t>(ci * c.traysPerCart + k);
                t.row(std::vector<double>{double(ci + 1), double(k + 1), phi[i], r.trayX0[i] * 100,
                                          r.trayX[i] * 100, (r.trayX[i] / mean - 1) * 100,
                                          r.trayT[i]});
            }
        t.close();
    }
    {
        std::vector<std::string> h{"time_h"};
        for (int ci = 0; ci < c.carts; ++ci)
            for (int k = 0; k < c.traysPerCart; ++k)
                h.push_back("X_cart" + std::to_string(ci + 1) + "_tray" + std::to_string(k + 1)
                            + "_percent_db");
        CsvWriter m(base + "_tray_moisture.csv", h);
        for (std::size_t j = 0; j < r.series.size(); ++j)
        {
            std::vector<double> row{r.series[j].t / 3600};
            for (double x : r.trayXSeries[j]) row.push_back(x * 100);
            m.row(row);
        }
        m.close();
    }
    const std::string csv = base + "_series.csv";
    plotPng(base + "_batch.png",
            "set termoption noenhanced\nset datafile separator ','\n"
            "set key autotitle columnhead outside right\nset grid\n"
            "set multiplot layout 3,1 title 'batch " + c.name + "'\n"
            "set ylabel 'temperature [degC]'\n"
            "plot '" + csv + "' u 1:2 w l lw 2, '' u 1:3 w l lw 2, '' u 1:10 w l, '' u 1:11 w l\n"
            "set ylabel 'return air RH [%]'\nset y2label 'heater [kW]'\nset y2tics\n"
            "plot '" + csv + "' u 1:6 w l lw 2, '' u 1:12 axes x1y2 w l\n"
            "unset y2label\nunset y2tics\n"
            "set ylabel 'moisture [% dry basis]'\nset xlabel 'time [h]'\n"
            "plot '" + csv + "' u 1:7 w l lw 2, '' u 1:8 w l, '' u 1:9 w l\n"
            "unset multiplot\n",
            1000, 1000);
}

int runSimulate(int argc, char** argv)
{
    if (wantsHelp(argc, argv))
    {
        std::cout << simulateHelp();
        return 0;
    }
    const Args a = parse(argc, argv, {"--out", "--batch"});
    if (a.positional.size() != 1)
        throw InputError("dryer simulate: expected one plant file (see --help)");
    const Plant plant = readPlant(a.positional[0]);
    const std::string dir = outDir(a);
    std::vector<const BatchSpec*> todo;
    if (a.options.count("--batch"))
        todo.push_back(&plant.batch(a.options.at("--batch")));
    else
        for (const auto& b : plant.batches) todo.push_back(&b);
    CsvWriter sum(dir + "/simulate_summary.csv",
                  {"batch", "reached_target", "drying_time_h", "electricity_kWh",
                   "evaporated_water_kg", "E_kJ_per_kg", "eta_percent", "T_product_max_C",
                   "scorched", "f1_percent", "f2_percent", "condensate_kg", "water_balance_rel",
                   "energy_balance_rel"});
    std::cout << std::left << std::setw(7) << "batch" << std::right << std::setw(8) << "time"
              << std::setw(10) << "kWh" << std::setw(10) << "water kg" << std::setw(10) << "E kJ/kg"
              << std::setw(8) << "eta %" << std::setw(8) << "Tp max" << std::setw(7) << "f1 %"
              << std::setw(7) << "f2 %" << std::setw(11) << "water bal" << std::setw(11)
              << "energy bal" << "\n";
    for (const BatchSpec* b : todo)
    {
        const DryerCase c = plant.caseFor(*b);
        const BatchResult r = simulate(c);
        writeBatchOutputs(dir, c, r);
        std::ostringstream wb, eb;
        wb << std::scientific << std::setprecision(1) << r.waterBalanceRel;
        eb << std::scientific << std::setprecision(1) << r.energyBalanceRel;
        std::cout << std::left << std::setw(7) << b->id << std::right << std::setw(8)
                  << (r.reachedTarget ? hm(r.dryingTime) : ">" + hm(r.dryingTime)) << std::setw(10)
                  << num(r.electricityJ / 3.6e6, 1) << std::setw(10) << num(r.waterEvaporated, 1)
                  << std::setw(10) << num(r.specificEnergy / 1e3, 0) << std::setw(8)
                  << num(r.eta * 100, 1) << std::setw(8) << num(r.tProductMax, 1) << std::setw(7)
                  << num(r.f1, 1) << std::setw(7) << num(r.f2, 1) << std::setw(11) << wb.str()
                  << std::setw(11) << eb.str() << (r.scorched ? "  SCORCHED" : "") << "\n";
        sum.row(std::vector<std::string>{
            b->id, r.reachedTarget ? "1" : "0", num(r.dryingTime / 3600, 4),
            num(r.electricityJ / 3.6e6, 3), num(r.waterEvaporated, 3), num(r.specificEnergy / 1e3, 3),
            num(r.eta * 100, 3), num(r.tProductMax, 3), r.scorched ? "1" : "0", num(r.f1, 2),
            num(r.f2, 2), num(r.condensateKg, 3), wb.str(), eb.str()});
    }
    sum.close();
    std::cout << "\nwrote " << dir << "/simulate_summary.csv and per-batch CSV/PNG\n";
    return 0;
}

// ---------------------------------------------------------------- calibrate
// The four quantities the paper reports per batch, from a model run and
// from the batch record (E and eta with the measured electricity and the
// water dry mass x (X1 - X2), eta with the model's latent-heat convention).
struct Quantity
{
    std::string name, unit, csvUnit;
    std::function<double(const BatchResult&)> model;
    std::function<double(const BatchSpec&, double latent)> measured;
    std::function<std::string(double)> show;
};

std::vector<Quantity> quantities()
{
    auto water = [](const BatchSpec& b) { return b.dryMass * (b.x0 - b.xTarget); };
    auto q = [](const BatchSpec& b) {
        return b.measuredElectricity ? *b.measuredElectricity : std::nan("");
    };
    return {
        {"time", "h:min", "h", [](const BatchResult& r) { return r.dryingTime / 3600; },
         [](const BatchSpec& b, double) { return b.measuredTime ? *b.measuredTime / 3600 : std::nan(""); },
         [](double h) { return std::isnan(h) ? std::string("-") : hm(h * 3600); }},
        {"electricity", "kWh", "kWh", [](const BatchResult& r) { return r.electricityJ / 3.6e6; },
         [q](const BatchSpec& b, double) { return q(b) / 3.6e6; },
         [](double v) { return num(v, 0); }},
        {"E", "kJ/kg", "kJ_per_kg", [](const BatchResult& r) { return r.specificEnergy / 1e3; },
         [q, water](const BatchSpec& b, double) { return q(b) / water(b) / 1e3; },
         [](double v) { return num(v, 0); }},
        {"eta", "%", "percent", [](const BatchResult& r) { return r.eta * 100; },
         [q, water](const BatchSpec& b, double L) { return water(b) * L / q(b) * 100; },
         [](double v) { return num(v, 1); }},
    };
}

void printFit(const Plant& plant, const CalibrationResult& cr)
{
    std::cout << "calibration on batches";
    for (const auto& id : plant.calibrateOn) std::cout << " " << id;
    std::cout << ": " << cr.report << "\n";
    for (std::size_t i = 0; i < plant.fit.size(); ++i)
        std::cout << "  " << std::left << std::setw(46) << plant.fit[i].name << std::right
                  << " start " << std::setw(10) << num(cr.start[i], 4) << "  fitted "
                  << std::setw(10) << num(cr.fitted[i], 4) << "\n";
}

// profile.csv: one row per grid point, the held and refitted values, the
// errors on the calibration batches and the predictions.
void writeProfileCsv(const std::string& path, const Plant& plant,
                     const std::vector<ProfilePoint>& points)
{
    std::vector<std::string> head;
    for (const auto& a : plant.profile) head.push_back("held:" + a.name);
    std::vector<std::string> refit;
    for (const auto& pt : points)
        if (!pt.failed && refit.empty()) refit = pt.refitNames;
    for (const auto& n : refit) head.push_back("refitted:" + n);
    for (const auto& n : {"cost", "worst_time_error_percent", "worst_electricity_error_percent",
                          "accepted", "failed"})
        head.push_back(n);
    for (const auto& id : plant.calibrateOn)
        for (const auto& n : {"time_error_percent_", "electricity_error_percent_"})
            head.push_back(n + id);
    const auto qs = quantities();
    for (const auto& id : plant.predict)
        for (const auto& q : qs) head.push_back(q.name + "_" + q.csvUnit + "_" + id);
    CsvWriter csv(path, head);
    for (const auto& pt : points)
    {
        std::vector<double> row(pt.held);
        for (std::size_t i = 0; i < refit.size(); ++i)
            row.push_back(pt.failed ? std::nan("") : pt.refitted[i]);
        row.insert(row.end(), {pt.cost, pt.worstTimeError * 100, pt.worstElectricityError * 100,
                               pt.accepted ? 1.0 : 0.0, pt.failed ? 1.0 : 0.0});
        for (std::size_t i = 0; i < plant.calibrateOn.size(); ++i)
        {
            row.push_back(pt.failed ? std::nan("") : pt.fitted[i].timeError * 100);
            row.push_back(pt.failed ? std::nan("") : pt.fitted[i].electricityError * 100);
        }
        for (std::size_t i = 0; i < plant.predict.size(); ++i)
            for (const auto& q : qs)
                row.push_back(pt.failed ? std::nan("") : q.model(pt.predicted[i].result));
        csv.row(row);
    }
    csv.close();
}

void printProfilePoint(const Plant& plant, const ProfilePoint& pt)
{
    for (std::size_t a = 0; a < pt.held.size(); ++a)
        std::cout << "  " << plant.profile[a].name << " = " << num(pt.held[a], 4);
    if (pt.failed)
    {
        std::cout << "  -> a run did not integrate\n";
        return;
    }
    std::cout << "  -> worst error time " << num(pt.worstTimeError * 100, 1) << " %, electricity "
              << num(pt.worstElectricityError * 100, 1) << " %"
              << (pt.accepted ? "  fits" : "  rejected");
    for (const auto& c : pt.predicted)
        std::cout << "  | " << c.id << ": " << hm(c.result.dryingTime)
                  << (c.result.reachedTarget ? "" : "+") << " h "
                  << num(c.result.electricityJ / 3.6e6, 0) << " kWh";
    std::cout << std::endl;   // a profile takes minutes: show each point as it ends
}

// The calibrate-then-predict table: per batch and quantity, measured,
// central fit and the band over the profile fits that reproduce the
// calibration batches; written to calibration.csv and printed.
void reportCalibration(const std::string& path, const Plant& plant,
                       const std::vector<ProfilePoint>& points)
{
    const auto qs = quantities();
    std::vector<std::string> head{"batch", "role", "venting"};
    for (const auto& q : qs)
        for (const auto& n : {"measured", "central", "band_min", "band_max", "measured_in_band"})
            head.push_back(q.name + "_" + n + (std::string(n) == "measured_in_band" ? "" : "_" + q.csvUnit));
    head.push_back("band_members");
    CsvWriter csv(path, head);
    std::cout << "\n" << std::left << std::setw(7) << "batch" << std::setw(11) << "role"
              << std::setw(13) << "quantity" << std::right << std::setw(10) << "measured"
              << std::setw(10) << "central" << std::setw(22) << "band (profile fits)"
              << "  measured in band\n";
    auto one = [&](const std::string& id, const std::string& role, const std::string& vent) {
        const BatchSpec& b = plant.batch(id);
        const BatchResult r = simulate(plant.caseFor(b, vent));
        std::vector<std::string> row{id, role, vent};
        int members = 0;
        for (const auto& q : qs)
        {
            const double m = q.measured(b, r.latentPerKg), c = q.model(r);
            const Band bd = band(points, id, q.model);
            members = bd.members;
            const std::string in = bd.members == 0 || std::isnan(m) ? "-" : bd.contains(m) ? "yes" : "no";
            row.insert(row.end(), {num(m, 4), num(c, 4), bd.members ? num(bd.lo, 4) : "nan",
                                   bd.members ? num(bd.hi, 4) : "nan", in == "yes" ? "1" : in == "no" ? "0" : "nan"});
            std::cout << std::left << std::setw(7) << id << std::setw(11) << role << std::setw(13)
                      << (q.name + " " + q.unit) << std::right << std::setw(10) << q.show(m)
                      << std::setw(10) << (q.show(c) + (r.reachedTarget || q.name != "time" ? "" : "+"))
                      << std::setw(22)
                      << (bd.members ? q.show(bd.lo) + " .. " + q.show(bd.hi) : std::string("-"))
                      << "  " << in << "\n";
        }
        row.push_back(std::to_string(members));
        csv.row(row);
    };
    for (const auto& id : plant.calibrateOn) one(id, "fitted", plant.batch(id).venting);
    for (const auto& id : plant.predict) one(id, "predicted", plant.predictVenting);
    csv.close();
}

// calibration.png: one panel per quantity; measured points, the central
// fit and the profile band as an interval.
void plotCalibration(const std::string& png, const std::string& csv)
{
    std::string script =
        "set termoption noenhanced\nset datafile separator ','\n"
        "set multiplot layout 2,2 title 'fitted on the old-dryer batches, predicted with the "
        "modified venting: measured, central fit, band of fits within the scatter'\n"
        "set key outside bottom center horizontal\nset grid\nset offsets 0.5, 0.5, 0, 0\n"
        "set xlabel 'batch'\n";
    const char* labels[] = {"drying time [h]", "electricity [kWh]", "E [kJ/kg water]", "eta [%]"};
    for (int k = 0; k < 4; ++k)
    {
        const int c = 4 + 5 * k;   // measured, central, band min, band max
        const auto col = [&](int i) { return std::to_string(c + i); };
        script += std::string("set ylabel '") + labels[k] + "'\n" + "plot '" + csv + "' u 0:"
                  + col(1) + ":" + col(2) + ":" + col(3)
                  + ":xtic(1) w yerrorbars pt 4 ps 1.5 lw 2 lc rgb '#1f77b4' t 'central, band', "
                  + "'' u 0:" + col(0) + " w p pt 7 ps 1.5 lc rgb 'black' t 'measured'\n";
    }
    plotPng(png, script + "unset multiplot\n", 1200, 900);
}

int runCalibrate(int argc, char** argv)
{
    if (wantsHelp(argc, argv))
    {
        std::cout << calibrateHelp();
        return 0;
    }
    const Args a = parse(argc, argv, {"--out", "--max-iterations", "--profile"});
    if (a.positional.size() != 1)
        throw InputError("dryer calibrate: expected one plant file (see --help)");
    bool runProfile = true;
    if (a.options.count("--profile"))
    {
        const std::string v = a.options.at("--profile");
        if (v != "on" && v != "off")
            throw InputError("dryer calibrate: option '--profile' expected 'on' or 'off', got '" + v + "'");
        runProfile = v == "on";
    }
    int maxIterations = 50;
    if (a.options.count("--max-iterations"))
    {
        const double n = optNumber(a, "--max-iterations", "calibrate");
        if (!(n >= 1 && n <= 1000 && n == std::floor(n)))
            throw InputError("dryer calibrate: option '--max-iterations' expected an integer from 1 to 1000");
        maxIterations = static_cast<int>(n);
    }
    Plant plant = readPlant(a.positional[0]);
    if (plant.fit.empty())
        throw InputError(plant.file + ": key 'calibration' is missing (needed by calibrate)");
    const std::string dir = outDir(a);
    printFit(plant, calibrate(plant, maxIterations));
    writePlant(plant, dir + "/calibrated.yaml",
               "plant file with parameters fitted by 'procsim dryer calibrate'");
    std::vector<ProfilePoint> points;
    if (runProfile && !plant.profile.empty())
    {
        std::cout << "\nprofile: hold, refit the rest on the calibration batches (fits: every "
                     "time error within "
                  << num(plant.timeTolerance * 100, 1) << " %, electricity within "
                  << num(plant.electricityTolerance * 100, 1) << " %)\n";
        points = profile(plant, maxIterations, [&](const ProfilePoint& pt) { printProfilePoint(plant, pt); });
        writeProfileCsv(dir + "/profile.csv", plant, points);
    }
    reportCalibration(dir + "/calibration.csv", plant, points);
    plotCalibration(dir + "/calibration.png", dir + "/calibration.csv");
    std::cout << "\nwrote " << dir << "/calibration.csv, calibration.png, calibrated.yaml"
              << (points.empty() ? "" : ", profile.csv") << "\n";
    return 0;
}

// ---------------------------------------------------------------- whatif
int runWhatif(int argc, char** argv)
{
    if (wantsHelp(argc, argv))
    {
        std::cout << whatifHelp();
        return 0;
    }
    const Args a = parse(argc, argv, {"--out"});
    if (a.positional.size() != 1)
        throw InputError("dryer whatif: expected one plant file (see --help)");
    const Plant plant = readPlant(a.positional[0]);
    if (plant.whatifBatch.empty())
        throw InputError(plant.file + ": key 'whatif' is missing (needed by whatif)");
    const std::string dir = outDir(a);
    const BatchSpec& b = plant.batch(plant.whatifBatch);
    CsvWriter csv(dir + "/whatif.csv",
                  {"hot_air_temperature_C", "vented_fraction", "reached_target", "drying_time_h",
                   "electricity_kWh", "E_kJ_per_kg", "eta_percent", "T_product_max_C",
                   "scorched"});
    double bestE = 1e300, bestT = 1e300;
    std::string best, fastest;
    std::cout << std::setw(8) << "T_hot" << std::setw(9) << "vented" << std::setw(9) << "time"
              << std::setw(10) << "E kJ/kg" << std::setw(9) << "Tp max" << "\n";
    for (double v : plant.whatifVentedFractions)
    {
        for (double T : plant.whatifTemperatures)
        {
            DryerCase c = plant.caseFor(b, plant.whatifVenting);
            c.hotAirC = T;
            c.ventedFraction = v;
            const BatchResult r = simulate(c);
            std::cout << std::setw(8) << num(T, 1) << std::setw(9) << num(v, 3) << std::setw(9)
                      << (r.reachedTarget ? hm(r.dryingTime) : ">" + hm(r.dryingTime))
                      << std::setw(10) << num(r.specificEnergy / 1e3, 0) << std::setw(9)
                      << num(r.tProductMax, 1) << (r.scorched ? "  SCORCHED" : "") << "\n";
            csv.row(std::vector<double>{T, v, r.reachedTarget ? 1.0 : 0.0, r.dryingTime / 3600,
                                        r.electricityJ / 3.6e6, r.specificEnergy / 1e3,
                                        r.eta * 100, r.tProductMax, r.scorched ? 1.0 : 0.0});
            if (r.reachedTarget && !r.scorched && r.dryingTime < bestT)
            {
                bestT = r.dryingTime;
                fastest = "hot air " + num(T, 1) + " degC, vented fraction " + num(v, 3) + ": "
                          + hm(r.dryingTime) + " h, E = " + num(r.specificEnergy / 1e3, 0)
                          + " kJ/kg, highest product temperature " + num(r.tProductMax, 1) + " degC";
            }
            if (r.reachedTarget && !r.scorched && r.specificEnergy < bestE)
            {
                bestE = r.specificEnergy;
                best = "hot air " + num(T, 1) + " degC, vented fraction " + num(v, 3) + ": "
                       + hm(r.dryingTime) + " h, E = " + num(r.specificEnergy / 1e3, 0)
                       + " kJ/kg, highest product temperature " + num(r.tProductMax, 1) + " degC";
            }
        }
        csv.row(std::vector<std::string>{});   // two blank lines: one gnuplot data
        csv.row(std::vector<std::string>{});   // block per vented fraction
    }
    csv.close();
    const std::string f = dir + "/whatif.csv";
    const std::string common =
        "set termoption noenhanced\nset datafile separator ','\n"
        "set key outside right title 'vented fraction'\n"
        "set xlabel 'hot-air temperature [degC]'\nset grid\n";
    // one line per vented fraction (CSV data blocks), scorched points filled red
    auto curves = [&](int column) {
        std::string cmd = "plot ";
        for (std::size_t i = 0; i < plant.whatifVentedFractions.size(); ++i)
        {
            const std::string idx = std::to_string(i), col = std::to_string(column);
            cmd += (i ? ", " : "") + std::string("'") + f + "' index " + idx + " u 1:" + col
                   + " w lp pt 6 lw 2 lc " + std::to_string(i + 1) + " t '"
                   + num(plant.whatifVentedFractions[i], 3) + "', '' index " + idx
                   + " u 1:($9>0.5?$" + col + ":1/0) w p pt 7 ps 2 lc rgb 'red' notitle";
        }
        return cmd + "\n";
    };
    const std::string title = "set title 'batch " + b.id + ", venting " + plant.whatifVenting
                              + " (red: scorched, product above "
                              + num(plant.base.scorchC, 0) + " degC)'\n";
    plotPng(dir + "/whatif_time.png",
            common + title + "set ylabel 'drying time [h]'\n" + curves(4));
    plotPng(dir + "/whatif_energy.png",
            common + title + "set ylabel 'specific energy E [kJ/kg water]'\n" + curves(6));
    std::cout << "\nscorch limit: product temperature " << num(plant.base.scorchC, 1) << " degC\n";
    if (best.empty())
        std::cout << "best setting: none reaches the target without scorching\n";
    else
    {
        std::cout << "best setting (lowest E without scorching): " << best << "\n";
        std::cout << "fastest setting without scorching:         " << fastest << "\n";
    }
    std::cout << "wrote " << dir << "/whatif.csv, whatif_time.png, whatif_energy.png\n";
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || isHelp(argv[1]))
    {
        std::cout << kUsage;
        return argc < 2 ? 2 : 0;
    }
    const std::string cmd = argv[1];
    if (cmd == "metrics") return runMetrics(argc - 1, argv + 1);
    if (cmd == "psychro") return runPsychro(argc - 1, argv + 1);
    if (cmd == "simulate") return runSimulate(argc - 1, argv + 1);
    if (cmd == "calibrate") return runCalibrate(argc - 1, argv + 1);
    if (cmd == "whatif") return runWhatif(argc - 1, argv + 1);
    throw InputError("dryer: unknown command '" + cmd + "' (metrics, psychro, simulate, calibrate, whatif; see procsim dryer --help)");
}

} // namespace procsim::dryer
