#include "kinetics/Main.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "kinetics/Case.hpp"
#include "kinetics/Corona.hpp"
#include "kinetics/Fit.hpp"
#include "kinetics/Run.hpp"
#include "kinetics/Study.hpp"

namespace procsim::kinetics
{

namespace
{

const char* mainHelp = R"(usage: procsim kinetics <command> [options]      (procsim kinetics <command> --help)

Liquid-phase kinetics of the wetted-wall corona reactor (simultaneous
acetaldehyde-laden air / phenol-containing water treatment) for any
mass-action mechanism given in YAML.

commands:
  run CASE.yaml          solve a case (or a sweep over any input): CSV, summary, PNG
  sensitivity CASE.yaml  +-10 % change of every rate constant -> table of output deviations
  fit FIT.yaml           estimate rate constants / the [OH]-current slope from measured CSV
  corona FILE.yaml       gas-side corona formulas: mean E/N, psi, psi', energetic efficiency J
  format                 the YAML formats of mechanism and case files, key by key

Shipped cases: process_cases/kinetics/ (the paper's Figs 4-8); see its README.
)";

const char* formatHelp = R"(INPUT FORMATS (units are part of every key name; concentrations inside are mol/L, time s)

MECHANISM file (referenced by the case's 'mechanism:' key)
  name: text                      label for summaries
  radical: OH                     species whose concentration the case's 'oh' model sets
                                  (omit for mechanisms without a pseudo-steady radical)
  check_carbon: true              every reaction must conserve carbon (default true); the
                                  CO2 formed must then appear as a product
  species:                        list; each item:
    - name: PH                    identifier used in equations and output columns
      description: phenol         free text
      molar_mass_g_per_mol: 94.11 converts mg/L <-> mol/L
      carbon: 6                   carbon atoms per molecule (TOC, carbon balance)
      organic: true               counted in TOC (default: true if carbon > 0; CO2: false)
  reactions:                      list; each item:
    - id: k5                      name used by sweeps (k.k5), sensitivity and fitting
      equation: "PH + OH -> CC"   mass action: rate = k * prod(c_i ^ nu_i) over the left side;
                                  terms are 'NAME' or 'COEF NAME', separated by ' + '; an empty
                                  left side is a zero-order source
      k: 7.0e9                    rate constant, >= 0, in 'units'
      units: L/mol/s              must match the order: mol/L/s (0), 1/s (1), L/mol/s (2),
                                  L2/mol2/s (3)
      source: text                optional reference

CASE file
  title: text                     label (default: the file name)
  mechanism: file.yaml            path, relative to the case file
  reactor:
    liquid_volume_L: 1.0          W, total circulating water volume [L]
  gas:                            optional: continuous gas feed absorbed into the liquid
    flow_mL_per_min: 100          volumetric gas flow at the temperature/pressure below
    temperature_C: 25
    pressure_kPa: 101.3
    inlet_ppm: {AD: 30}           inlet mole fractions [ppm] of mechanism species
    effluent_ppm: {AD: 0}         optional outlet ppm (default 0: all absorbed, paper assumption 5);
                                  the liquid receives q_g (C_in - C_eff) 1e-6 / W mol/(L s)
  initial_mg_per_L: {PH: 30}      initial liquid concentrations [mg/L] (others 0)
  initial_mol_per_L: {A: 1}       alternative/additional initial concentrations [mol/L]
  corona:
    current_mA: 0.3               corona current I [mA]
    voltage_kV: 10                applied voltage V [kV] (only for the energetic efficiencies)
  oh:                             the model of the mechanism's radical
    model: linear_current         [OH] = intercept + slope * I (pseudo-steady, paper: 8.77e-10 I)
    slope_mg_per_L_per_mA: 8.77e-10
    intercept_mg_per_L: 0         optional
    # model: constant  with  concentration_mg_per_L: ...   (fixed [OH])
    # model: dynamic   the radical is integrated like any species (needs its production and
    #                  loss reactions in the mechanism; use solver cvode)
  time:
    duration_h: 10                (or duration_s)
    output_interval_min: 5        (or output_interval_s) spacing of the CSV rows
  solver:                         optional
    method: expm                  expm: exact matrix exponential (linear mechanisms, default);
                                  rk4: classic Runge-Kutta (the paper's method);
                                  cvode: SUNDIALS CVODE BDF (stiff / nonlinear mechanisms)
    rk4_step_s: 10                RK4 step [s]
    rtol: 1e-8                    CVODE relative tolerance
    atol_mol_per_L: 1e-16         CVODE absolute tolerance [mol/L]
  report:                         optional
    times_h: [3, 8, 10]           times listed in the summary and sweep tables
    plot_species: [PH, AD, AA]    species in the plots/summary (default: organics present)
  sweep:                          optional family of runs (like --sweep); at most two keys
    - key: corona.current_mA      any numeric case key path, 'k.<reaction id>', or I / V
      values: [0.1, 0.3, 0.5]
  sensitivity:                    optional defaults of 'procsim kinetics sensitivity'
    parameters: [k1, k2, k3]      reaction ids (default: all)
    outputs: [PH, AD, AA, TOC]    species names or TOC
    time_h: 8                     time at which deviations are tabulated (default: end)
    change_percent: 10

The paper's [OH] correlation is in mg/L with I in mA; it is divided by the
radical's molar mass (17.007 g/mol) for mol/L before the L/mol/s rate constants apply.
)";

const char* runHelp = R"(usage: procsim kinetics run CASE.yaml [options]

Solves the species balances built from the mechanism's reactions and writes, in
the output directory:
  timeseries.csv   time_h, time_s, every species in mg/L and mol/L, TOC (mg C/L from
                   carbon counts of organic species), TOC without discharge, CO2 formed
                   (mol in the liquid), carbon fed (mol), carbon-balance relative error
  summary.txt      the one-screen summary (also printed): values at report times, the TOC
                   half time t_1/2 (TOC = half of TOC without discharge), J_TOC, J_P, J_A
                   (paper eqs 18-20, mol/J; need corona.voltage_kV), carbon balance
  summary.csv      the same numbers as quantity,value,unit
  species.png, toc.png
With a sweep (from --sweep or the case's 'sweep:'), one subdirectory per run plus
  sweep_summary.csv, family_<quantity>.png (curves over the swept values) and
  sweep_<quantity>_at_<t>h.png (value at a report time vs the swept key).

options:
  -o, --output DIR         output directory (default: <case name>_out)
  --sweep KEY=v1,v2,...    run the case for each value; KEY is a case key path
                           (corona.current_mA, gas.inlet_ppm.AD, initial_mg_per_L.PH, ...),
                           k.<reaction id>, or the shorthands I (current), V (voltage);
                           give --sweep twice for a two-way table
  --set KEY=VALUE          change one input for this run (same keys as --sweep)
  --solver expm|rk4|cvode  override solver.method
  --no-sweep               ignore the case's own 'sweep:' section
  --no-plots               CSV and summary only
  -q, --quiet              do not print summaries of sweep members
Input format: procsim kinetics format
)";

const char* sensHelp = R"(usage: procsim kinetics sensitivity CASE.yaml [options]

Changes each chosen rate constant by +change and -change (default 10 %), reruns the
case, and tabulates the relative deviation of each output at a chosen time and the
largest deviation over the run (the paper's Table S1). Writes sensitivity.csv:
parameter, change_percent, output, base_value, perturbed_value, deviation_percent,
max_deviation_percent, max_deviation_time_h.

options:
  -o, --output DIR           output directory (default: <case name>_sensitivity)
  --params k1,k2,...         reaction ids (default: case 'sensitivity.parameters' or all)
  --outputs PH,AA,TOC        species or TOC (default: case list or organics present + TOC)
  --time-h T                 tabulation time [h] (default: case 'sensitivity.time_h' or end)
  --change-percent P         relative change [%] (default 10)
  --set KEY=VALUE            change an input first (as in run)
)";

struct Args
{
    std::vector<std::string> positional;
    std::string output;
    Overrides set;
    std::vector<SweepDim> sweeps;
    std::string solver;
    bool noPlots = false, quiet = false, noSweep = false;
    std::string params, outputs;
    double timeH = 0, changePercent = 0;   // 0: not given (the case's value or the default)
};

double parseNumber(const std::string& opt, const std::string& v)
{
    if (const auto x = parseFinite(v)) return *x;
    throw InputError(opt + " expected a finite number, got '" + v + "'");
}

std::vector<std::string> splitCommas(const std::string& s)
{
    std::vector<std::string> out;
    std::string cur;
    for (char ch : s)
    {
        if (ch == ',')
        {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        }
        else cur += ch;
    }
    if (!cur.empty()) out.push_back(cur);
    return out;
}

Args parseArgs(int argc, char** argv, const std::string& cmd)
{
    Args a;
    std::set<std::string> seen;
    for (int i = 2; i < argc; ++i)
    {
        const std::string s = argv[i];
        // an option given twice would silently replace the first value (--sweep and --set add up)
        if (!s.empty() && s[0] == '-' && s != "--sweep" && s != "--set" && !seen.insert(s == "--output" ? "-o" : s).second)
            throw InputError("kinetics " + cmd + ": option " + s + " given twice");
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw InputError("kinetics " + cmd + ": option " + s + " needs a value");
            return argv[++i];
        };
        if (s == "-o" || s == "--output") a.output = value();
        else if (s == "--sweep") a.sweeps.push_back(parseSweep(value()));
        else if (s == "--set")
        {
            const SweepDim d = parseSweep(value());
            if (d.values.size() != 1) throw InputError("--set expected KEY=VALUE (one value)");
            a.set.emplace_back(d.key, d.values[0]);
        }
        else if (s == "--solver") a.solver = value();
        else if (s == "--no-plots") a.noPlots = true;
        else if (s == "--no-sweep") a.noSweep = true;
        else if (s == "-q" || s == "--quiet") a.quiet = true;
        else if (s == "--params") a.params = value();
        else if (s == "--outputs") a.outputs = value();
        else if (s == "--time-h")
        {
            a.timeH = parseNumber(s, value());
            if (!(a.timeH > 0)) throw InputError("kinetics " + cmd + ": option --time-h expected a time above 0 [h], got " + argv[i]);
        }
        else if (s == "--change-percent")
        {
            a.changePercent = parseNumber(s, value());
            if (!(a.changePercent > 0 && a.changePercent < 100))
                throw InputError("kinetics " + cmd + ": option --change-percent expected a number above 0 and below 100 [%], got "
                                 + argv[i]);
        }
        else if (!s.empty() && s[0] == '-') throw InputError("kinetics " + cmd + ": unknown option '" + s + "' (see --help)");
        else a.positional.push_back(s);
    }
    if (a.positional.size() != 1)
        throw InputError("kinetics " + cmd + ": expected one input file (see procsim kinetics " + cmd + " --help)");
    std::vector<std::string> setKeys;
    for (const auto& kv : a.set) setKeys.push_back(kv.first);
    rejectDuplicates(setKeys, "kinetics " + cmd, "--set key");
    rejectDuplicates(a.sweeps, &SweepDim::key, "kinetics " + cmd, "--sweep key");
    return a;
}

std::string defaultDir(const std::string& file, const std::string& suffix)
{
    return std::filesystem::path(file).stem().string() + suffix;
}

int cmdRun(int argc, char** argv)
{
    Args a = parseArgs(argc, argv, "run");
    const CaseSource src = CaseSource::load(a.positional[0]);
    if (!a.solver.empty())
    {
        if (a.solver != "expm" && a.solver != "rk4" && a.solver != "cvode")
            throw InputError("--solver expected expm, rk4 or cvode, got '" + a.solver + "'");
    }
    Case c = src.build(a.set);
    const std::string dir = a.output.empty() ? defaultDir(src.file(), "_out") : a.output;
    std::vector<SweepDim> sweeps = a.sweeps;
    if (sweeps.empty() && !a.noSweep) sweeps = c.sweep;
    if (!a.solver.empty()) c.solver.method = a.solver;
    if (sweeps.empty())
    {
        const Model model(c);
        const auto times = outputTimes(c.duration, c.outputInterval);
        const Results r = analyse(model, solve(model, times, c.solver));
        const Efficiency e = efficiency(r);
        writeRun(r, e, dir, !a.noPlots);
        std::cout << summaryText(r, e) << "  output: " << dir << "/\n";
        return 0;
    }
    if (sweeps.size() > 2) throw InputError("kinetics run: at most two --sweep keys");
    const auto runs = runSweep(src, a.set, sweeps, dir, !a.noPlots, a.quiet, a.solver);
    // one-screen table: swept values, then every plotted quantity at the last report time
    const Results& r0 = runs.front().results;
    const double tEnd = r0.cas.reportTimes.empty() ? r0.t.back() : r0.cas.reportTimes.back();
    auto names = plotSpecies(r0);
    names.push_back("TOC");
    std::cout << "sweep of " << r0.cas.title << ": values at " << tEnd / 3600.0 << " h (mg/L; TOC mg C/L)\n ";
    for (const auto& d : sweeps) std::cout << std::setw(16) << shortKey(d.key);
    for (const auto& n : names) std::cout << std::setw(10) << n;
    std::cout << std::setw(10) << "t_1/2 h" << '\n';
    for (const auto& run : runs)
    {
        std::cout << ' ';
        for (const auto& kv : run.values) std::cout << std::setw(16) << kv.second;
        for (const auto& n : names) std::cout << std::setw(10) << std::setprecision(4) << run.results.value(n, tEnd);
        if (run.eff.halfReached) std::cout << std::setw(10) << std::setprecision(4) << run.eff.tHalf / 3600.0;
        else std::cout << std::setw(10) << "-";
        std::cout << std::setprecision(6) << '\n';
    }
    std::cout << runs.size() << " runs; table: " << dir << "/sweep_summary.csv";
    if (!a.noPlots) std::cout << ", plots: " << dir << "/family_*.png, " << dir << "/sweep_*.png";
    std::cout << '\n';
    return 0;
}

int cmdSensitivity(int argc, char** argv)
{
    Args a = parseArgs(argc, argv, "sensitivity");
    const CaseSource src = CaseSource::load(a.positional[0]);
    const auto rows = sensitivity(src, a.set, splitCommas(a.params), splitCommas(a.outputs), a.timeH * 3600.0,
                                  a.changePercent / 100.0);
    const std::string dir = a.output.empty() ? defaultDir(src.file(), "_sensitivity") : a.output;
    writeSensitivity(rows, dir);
    std::cout << sensitivityTable(rows) << "  output: " << dir << "/sensitivity.csv\n";
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || isHelp(argv[1]))
    {
        std::cout << mainHelp;
        return argc < 2 ? 2 : 0;
    }
    const std::string cmd = argv[1];
    const bool help = argc > 2 && isHelp(argv[2]);
    if (cmd == "format")
    {
        std::cout << formatHelp;
        return 0;
    }
    if (cmd == "run")
    {
        if (help || argc == 2) return std::cout << runHelp << "\n" << formatHelp, help ? 0 : 2;
        return cmdRun(argc, argv);
    }
    if (cmd == "sensitivity")
    {
        if (help || argc == 2) return std::cout << sensHelp, help ? 0 : 2;
        return cmdSensitivity(argc, argv);
    }
    if (cmd == "fit")
    {
        if (help || argc == 2) return std::cout << fitHelp(), help ? 0 : 2;
        return fitMain(argc, argv);
    }
    if (cmd == "corona")
    {
        if (help || argc == 2) return std::cout << coronaHelp(), help ? 0 : 2;
        return coronaMain(argc, argv);
    }
    std::cerr << "procsim: kinetics: unknown command '" << cmd << "' (see procsim kinetics --help)\n";
    return 2;
}

} // namespace procsim::kinetics
