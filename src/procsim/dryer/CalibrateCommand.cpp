// procsim dryer calibrate: fit the uncertain plant parameters on measured
// batches, profile the fit along what those batches cannot resolve, and
// predict other batches with a band over the fits that reproduce them.
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "dryer/Calibrate.hpp"
#include "dryer/Commands.hpp"
#include "dryer/Plant.hpp"
#include "dryer/Texts.hpp"

namespace procsim::dryer
{

namespace
{

struct CalibrateArgs
{
    std::string plant;
    std::string out = ".";
    int maxIterations = 50; // Levenberg-Marquardt iterations per fit
    bool profile = true;    // when the plant file has one
};

std::optional<CalibrateArgs> parse(int argc, char** argv)
{
    CalibrateArgs a;
    std::optional<long> iterations;
    std::string profile = "on";
    CommandLine cl("dryer calibrate",
                   std::string(texts::help::calibrate) + "\n" + std::string(texts::help::plant));
    cl.input(a.plant, "plant file");
    cl.text("--out", a.out);
    cl.integer("--max-iterations", iterations, 1, 1000);
    cl.text("--profile", profile);
    if (!cl.parse(argc, argv)) return std::nullopt;
    if (profile != "on" && profile != "off") throw cl.refuse("--profile", "'on' or 'off'", profile);
    a.profile = profile == "on";
    if (iterations) a.maxIterations = static_cast<int>(*iterations);
    return a;
}

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
    auto q = [](const BatchSpec& b) { return b.measuredElectricity ? *b.measuredElectricity : std::nan(""); };
    auto fixed = [](int decimals) { return [decimals](double v) { return formatFixed(v, decimals); }; };
    return {
        {"time", "h:min", "h", [](const BatchResult& r) { return r.dryingTime / 3600; },
         [](const BatchSpec& b, double) { return b.measuredTime ? *b.measuredTime / 3600 : std::nan(""); },
         [](double h) { return std::isnan(h) ? std::string("-") : formatHoursMinutes(h * 3600); }},
        {"electricity", "kWh", "kWh", [](const BatchResult& r) { return r.electricityJ / 3.6e6; },
         [q](const BatchSpec& b, double) { return q(b) / 3.6e6; }, fixed(0)},
        {"E", "kJ/kg", "kJ_per_kg", [](const BatchResult& r) { return r.specificEnergy / 1e3; },
         [q, water](const BatchSpec& b, double) { return q(b) / water(b) / 1e3; }, fixed(0)},
        {"eta", "%", "percent", [](const BatchResult& r) { return r.eta * 100; },
         [q, water](const BatchSpec& b, double L) { return water(b) * L / q(b) * 100; }, fixed(1)},
    };
}

void printFit(const Plant& plant, const CalibrationResult& cr)
{
    fmt::print("calibration on batches");
    for (const auto& id : plant.calibrateOn) fmt::print(" {}", id);
    fmt::print(": {}\n", cr.report);
    for (std::size_t i = 0; i < plant.fit.size(); ++i)
        fmt::print("  {:<46} start {:>10.4f}  fitted {:>10.4f}\n", plant.fit[i].name, cr.start[i],
                   cr.fitted[i]);
}

std::vector<std::string> profileHeader(const Plant& plant, const std::vector<std::string>& refit)
{
    std::vector<std::string> head;
    for (const auto& a : plant.profile) head.push_back("held:" + a.name);
    for (const auto& n : refit) head.push_back("refitted:" + n);
    for (const auto& n :
         {"cost", "worst_time_error_percent", "worst_electricity_error_percent", "accepted", "failed"})
        head.push_back(n);
    for (const auto& id : plant.calibrateOn)
        for (const auto& n : {"time_error_percent_", "electricity_error_percent_"}) head.push_back(n + id);
    for (const auto& id : plant.predict)
        for (const auto& q : quantities()) head.push_back(q.name + "_" + q.csvUnit + "_" + id);
    return head;
}

// A failed point (a run did not integrate) has only its held values and cost.
std::vector<double> profileRow(const Plant& plant, const ProfilePoint& pt, std::size_t refitCount)
{
    const double nan = std::nan("");
    std::vector<double> row(pt.held);
    for (std::size_t i = 0; i < refitCount; ++i) row.push_back(pt.failed ? nan : pt.refitted[i]);
    row.insert(row.end(), {pt.cost, pt.worstTimeError * 100, pt.worstElectricityError * 100,
                           pt.accepted ? 1.0 : 0.0, pt.failed ? 1.0 : 0.0});
    for (std::size_t i = 0; i < plant.calibrateOn.size(); ++i)
    {
        row.push_back(pt.failed ? nan : pt.fitted[i].timeError * 100);
        row.push_back(pt.failed ? nan : pt.fitted[i].electricityError * 100);
    }
    for (std::size_t i = 0; i < plant.predict.size(); ++i)
        for (const auto& q : quantities()) row.push_back(pt.failed ? nan : q.model(pt.predicted[i].result));
    return row;
}

// profile.csv: one row per grid point, the held and refitted values, the
// errors on the calibration batches and the predictions.
void writeProfileCsv(const std::string& path, const Plant& plant, const std::vector<ProfilePoint>& points)
{
    std::vector<std::string> refit;
    for (const auto& pt : points)
        if (!pt.failed && refit.empty()) refit = pt.refitNames;
    CsvWriter csv(path, profileHeader(plant, refit));
    for (const auto& pt : points) csv.row(profileRow(plant, pt, refit.size()));
    csv.close();
}

void printProfilePoint(const Plant& plant, const ProfilePoint& pt)
{
    for (std::size_t a = 0; a < pt.held.size(); ++a)
        fmt::print("  {} = {:.4f}", plant.profile[a].name, pt.held[a]);
    if (pt.failed)
    {
        fmt::print("  -> a run did not integrate\n");
        return;
    }
    fmt::print("  -> worst error time {:.1f} %, electricity {:.1f} %{}", pt.worstTimeError * 100,
               pt.worstElectricityError * 100, pt.accepted ? "  fits" : "  rejected");
    for (const auto& c : pt.predicted)
        fmt::print("  | {}: {}{} h {:.0f} kWh", c.id, formatHoursMinutes(c.result.dryingTime),
                   c.result.reachedTarget ? "" : "+", c.result.electricityJ / 3.6e6);
    fmt::print("\n");
    std::fflush(stdout); // a profile takes minutes: show each point as it ends
}

// One batch of the calibrate-then-predict table: per quantity measured,
// central fit and the band over the profile fits; printed and returned as
// its calibration.csv row.
std::vector<std::string> calibrationRow(const Plant& plant, const std::vector<ProfilePoint>& points,
                                        const std::string& id, const std::string& role,
                                        const std::string& vent)
{
    const BatchSpec& b = plant.batch(id);
    const BatchResult r = simulate(plant.caseFor(b, vent));
    std::vector<std::string> row{id, role, vent};
    int members = 0;
    for (const auto& q : quantities())
    {
        const double m = q.measured(b, r.latentPerKg), c = q.model(r);
        const Band bd = band(points, id, q.model);
        members = bd.members;
        const std::string in = bd.members == 0 || std::isnan(m) ? "-" : bd.contains(m) ? "yes" : "no";
        row.insert(row.end(),
                   {formatFixed(m, 4), formatFixed(c, 4), bd.members ? formatFixed(bd.lo, 4) : "nan",
                    bd.members ? formatFixed(bd.hi, 4) : "nan",
                    in == "yes"  ? "1"
                    : in == "no" ? "0"
                                 : "nan"});
        const std::string central = q.show(c) + (r.reachedTarget || q.name != "time" ? "" : "+");
        const std::string range = bd.members ? q.show(bd.lo) + " .. " + q.show(bd.hi) : "-";
        fmt::print("{:<7}{:<11}{:<13}{:>10}{:>10}{:>22}  {}\n", id, role, q.name + " " + q.unit, q.show(m),
                   central, range, in);
    }
    row.push_back(std::to_string(members));
    return row;
}

// calibration.csv and its table: the calibration batches with their own
// venting, then the predicted ones with the predicted venting.
void reportCalibration(const std::string& path, const Plant& plant, const std::vector<ProfilePoint>& points)
{
    std::vector<std::string> head{"batch", "role", "venting"};
    for (const auto& q : quantities())
    {
        for (const std::string n : {"measured", "central", "band_min", "band_max"})
            head.push_back(q.name + "_" + n + "_" + q.csvUnit);
        head.push_back(q.name + "_measured_in_band");
    }
    head.push_back("band_members");
    CsvWriter csv(path, head);
    fmt::print("\n{:<7}{:<11}{:<13}{:>10}{:>10}{:>22}  measured in band\n", "batch", "role", "quantity",
               "measured", "central", "band (profile fits)");
    for (const auto& id : plant.calibrateOn)
        csv.row(calibrationRow(plant, points, id, "fitted", plant.batch(id).venting));
    for (const auto& id : plant.predict)
        csv.row(calibrationRow(plant, points, id, "predicted", plant.predictVenting));
    csv.close();
}

std::vector<ProfilePoint> runProfile(const Plant& plant, const CalibrateArgs& a)
{
    fmt::print(
        "\nprofile: hold, refit the rest on the calibration batches (fits: every time error within {:.1f} %, "
        "electricity within {:.1f} %)\n",
        plant.timeTolerance * 100, plant.electricityTolerance * 100);
    const auto points =
        profile(plant, a.maxIterations, [&](const ProfilePoint& pt) { printProfilePoint(plant, pt); });
    writeProfileCsv(a.out + "/profile.csv", plant, points);
    return points;
}

} // namespace

int calibrateCommand(int argc, char** argv)
{
    const auto args = parse(argc, argv);
    if (!args) return 0;
    Plant plant = readPlant(args->plant);
    if (plant.fit.empty())
        throw InputError(plant.file + ": key 'calibration' is missing (needed by calibrate)");
    const std::string& dir = args->out;
    createOutputDirectory(dir);
    printFit(plant, calibrate(plant, args->maxIterations));
    writePlant(plant, dir + "/calibrated.yaml",
               "plant file with parameters fitted by 'procsim dryer calibrate'");
    std::vector<ProfilePoint> points;
    if (args->profile && !plant.profile.empty()) points = runProfile(plant, *args);
    reportCalibration(dir + "/calibration.csv", plant, points);
    plotPng(dir + "/calibration.png", texts::plots::calibration,
            PlotVariables().set("csv", dir + "/calibration.csv"), 1200, 900);
    fmt::print("\nwrote {}/calibration.csv, calibration.png, calibrated.yaml{}\n", dir,
               points.empty() ? "" : ", profile.csv");
    return 0;
}

} // namespace procsim::dryer
