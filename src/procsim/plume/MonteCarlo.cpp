#include "plume/MonteCarlo.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "common/YamlInput.hpp"
#include "plume/Texts.hpp"
#include "plume/GaussianCase.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

constexpr long maxYears = 100000;   // synthetic years: ~10 minutes per 1000 on one thread

namespace
{

const int kMonthDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};

double value(const MetHour& h, int v)
{
    switch (v)
    {
    case kDirection: return h.directionFrom;
    case kSpeed: return h.speed;
    case kTemperature: return h.temperatureC + 273.15;   // fitted in kelvin (always > 0)
    case kMixingHeight: return h.mixingHeight;
    default: return h.cloudOktas;
    }
}

// percentile p (0..100) of sorted values, linear between order statistics
double percentile(const std::vector<double>& sorted, double p)
{
    if (sorted.empty()) return 0;
    const double pos = p / 100 * (sorted.size() - 1);
    const std::size_t i = static_cast<std::size_t>(pos);
    if (i + 1 >= sorted.size()) return sorted.back();
    return sorted[i] + (pos - i) * (sorted[i + 1] - sorted[i]);
}

} // namespace

const char* metVariableName(int v)
{
    static const char* names[] = {"wind_direction_deg", "wind_speed_m_s", "temperature_K",
                                  "mixing_height_m", "cloud_cover_oktas"};
    return names[v];
}

int monthOfDay(int day)
{
    int d = (day - 1) % 365;
    for (int m = 0; m < 12; ++m)
    {
        if (d < kMonthDays[m]) return m;
        d -= kMonthDays[m];
    }
    return 11;
}

Climate fitClimate(const MetSeries& history, int startDay, double startHour)
{
    std::array<std::array<std::array<std::vector<double>, 4>, 12>, kMetVariables> samples;
    for (std::size_t t = 0; t < history.hours.size(); ++t)
    {
        const double hour = startHour + static_cast<double>(t);
        const int day = (startDay - 1 + static_cast<int>(hour / 24)) % 365 + 1;
        const int month = monthOfDay(day);
        const int block = static_cast<int>(std::fmod(hour, 24.0)) / 6;
        for (int v = 0; v < kMetVariables; ++v) samples[v][month][block].push_back(value(history.hours[t], v));
    }
    Climate c;
    for (int v = 0; v < kMetVariables; ++v)
        for (int m = 0; m < 12; ++m)
            for (int b = 0; b < 4; ++b)
            {
                const auto& s = samples[v][m][b];
                if (s.size() < 10)
                {
                    throw InputError("history: month " + std::to_string(m + 1) + ", hours "
                                     + std::to_string(6 * b) + "-" + std::to_string(6 * b + 6)
                                     + " has only " + std::to_string(s.size())
                                     + " values (give at least one full year of hourly meteorology)");
                }
                try
                {
                    c.fit[v][m][b] = fitGamma(s);
                }
                catch (const std::exception& e)
                {
                    throw InputError(std::string("history: ") + metVariableName(v) + ", month "
                                     + std::to_string(m + 1) + ": " + e.what());
                }
            }
    return c;
}

std::vector<MetHour> synthesiseYear(const Climate& c, double w, Stream& rng)
{
    std::vector<MetHour> out(8760);
    std::array<double, kMetVariables> z{};
    for (auto& v : z) v = rng.normal();   // stationary start
    const double s = std::sqrt(1 - w * w);
    for (int t = 0; t < 8760; ++t)
    {
        const int day = t / 24 + 1;
        const int month = monthOfDay(day);
        const int block = (t % 24) / 6;
        std::array<double, kMetVariables> x{};
        for (int v = 0; v < kMetVariables; ++v)
        {
            if (t > 0) z[v] = w * z[v] + s * rng.normal();
            x[v] = gammaQuantileZ(c.fit[v][month][block], z[v]);
        }
        MetHour& h = out[t];
        h.directionFrom = std::fmod(x[kDirection], 360.0);
        h.speed = x[kSpeed];
        h.temperatureC = x[kTemperature] - 273.15;
        h.mixingHeight = std::max(x[kMixingHeight], 50.0);
        h.cloudOktas = std::min(x[kCloud], 8.0);
    }
    return out;
}

int monteCarloMain(int argc, char** argv)
{
    std::string casePath, outDir = "results";
    std::optional<long> yearsGiven, threadsGiven, seedGiven;
    CommandLine cl("plume montecarlo", std::string(texts::help::montecarlo));
    cl.input(casePath, "case file");
    cl.text("-o", outDir);
    cl.integer("--years", yearsGiven);
    cl.integer("--threads", threadsGiven);
    cl.integer("--seed", seedGiven);
    if (!cl.parse(argc, argv)) return 0;
    const long yearsOpt = yearsGiven.value_or(0), threadsOpt = threadsGiven.value_or(0);   // 0: the case's
    const bool haveSeed = seedGiven.has_value();
    const unsigned long long seedOpt = static_cast<unsigned long long>(seedGiven.value_or(0));
    const YamlInput in = YamlInput::load(casePath);
    std::vector<std::string> keys = gaussianSetupKeys();
    keys.insert(keys.end(), {"history", "history_start", "years", "weighting", "seed", "thresholds_ug_m3"});
    in.rejectUnknown(keys);
    GaussianSetup setup = parseGaussianSetup(in);
    setup.options.startDayOfYear = 1;   // synthetic years start on 1 January, 0 h
    setup.options.startHour = 0;
    int histDay = 1;
    double histHour = 0;
    if (in.has("history_start"))
    {
        const YamlInput hs = in.child("history_start");
        hs.rejectUnknown({"day_of_year", "hour"});
        if (hs.has("day_of_year"))
        {
            histDay = static_cast<int>(hs.integer("day_of_year"));
            if (histDay < 1 || histDay > 365) throw hs.error("day_of_year", "1..365");
        }
        histHour = hs.number("hour", 0.0, "h");
        if (histHour < 0 || histHour >= 24) throw hs.error("hour", "0..24 [h]");
    }
    long years = 50;
    if (in.has("years"))
    {
        years = in.integer("years", 1, maxYears);
    }
    if (yearsOpt > 0) years = yearsOpt;
    if (years > maxYears)
        throw InputError("plume montecarlo: " + std::to_string(years) + " synthetic years asked for (limit "
                         + std::to_string(maxYears) + ")");
    const double w = in.number("weighting", 0.5);
    if (!(w >= 0 && w < 1)) throw in.error("weighting", "a number in [0, 1)");
    unsigned long long seed = 2001;
    if (in.has("seed"))
    {
        const long s = in.integer("seed", 0, 2147483647L);
        seed = static_cast<unsigned long long>(s);
    }
    if (haveSeed) seed = seedOpt;
    std::vector<double> thresholds = {120, 150};
    if (in.has("thresholds_ug_m3"))
    {
        thresholds = in.numbers("thresholds_ug_m3", "ug/m3");
        if (thresholds.empty()) throw in.error("thresholds_ug_m3", "a list of concentrations [ug/m3]");
    }
    const std::string dir = fs::path(casePath).parent_path().string();
    const std::string histPath = relativeTo(dir, in.text("history"));
    const MetSeries history = readMet(histPath, true);
    if (history.hours.size() < 8760)
    {
        throw InputError(histPath + ": " + std::to_string(history.hours.size())
                         + " hours of history; expected at least one year (8760 hours)");
    }
    Climate climate;
    try
    {
        climate = fitClimate(history, histDay, histHour);
    }
    catch (const InputError& e)
    {
        throw InputError(histPath + ": " + std::string(e.what()).substr(9));
    }
    const GaussianModel model(setup.sources, setup.options);
    const std::size_t nr = setup.receptors.size();
    checkMemory(static_cast<double>(years) * 365 * static_cast<double>(nr), sizeof(double), casePath,
                std::to_string(years) + " synthetic years of daily values at " + std::to_string(nr) + " receptors");
    const unsigned threads = static_cast<unsigned>(
        threadsOpt > 0 ? threadsOpt : std::max(1u, std::thread::hardware_concurrency()));

    std::cout << "procsim plume montecarlo: " << casePath << "\n  history " << history.hours.size()
              << " h, " << years << " synthetic years, w = " << w << ", seed " << seed << ", "
              << threads << " threads, reduction " << setup.options.reduction * 100 << " %\n";
    fs::create_directories(outDir);

    // daily[realisation][receptor][day]
    std::vector<std::vector<std::vector<double>>> daily(
        years, std::vector<std::vector<double>>(nr, std::vector<double>(365, 0.0)));
    std::vector<std::array<long, 8>> sectors(years);   // synthetic wind-direction sectors
    std::vector<std::array<long, 4>> speeds(years);
    std::vector<MetHour> firstYear;
    std::atomic<long> next{0};
    std::mutex lock;
    const auto t0 = std::chrono::steady_clock::now();
    auto worker = [&]() {
        while (true)
        {
            const long r = next++;
            if (r >= years) return;
            Stream rng(seed, static_cast<std::uint64_t>(r));
            const auto met = synthesiseYear(climate, w, rng);
            auto& d = daily[r];
            for (int t = 0; t < 8760; ++t)
            {
                const PlumeHour ph = model.hourConditions(met[t], t);
                for (std::size_t k = 0; k < nr; ++k)
                    d[k][t / 24] += model.concentration(ph, setup.receptors[k]) * 1e9 / 24;
                sectors[r][static_cast<int>(met[t].directionFrom / 45.0) % 8]++;
                speeds[r][std::min(3, static_cast<int>(met[t].speed / 2.0))]++;
            }
            if (r == 0)
            {
                std::lock_guard<std::mutex> l(lock);
                firstYear = met;
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < std::min<unsigned>(threads, static_cast<unsigned>(years)); ++i)
        pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // --- outputs ---
    {
        CsvWriter f((fs::path(outDir) / "fits.csv").string(),
                    {"variable", "month", "hours", "shape", "scale", "mean", "n", "method"});
        for (int v = 0; v < kMetVariables; ++v)
            for (int m = 0; m < 12; ++m)
                for (int b = 0; b < 4; ++b)
                {
                    const GammaFit& g = climate.fit[v][m][b];
                    std::ostringstream sh, sc, mean;
                    sh << g.shape;
                    sc << g.scale;
                    mean << g.shape * g.scale;
                    f.row(std::vector<std::string>{metVariableName(v), std::to_string(m + 1),
                                                   std::to_string(6 * b) + "-" + std::to_string(6 * b + 6),
                                                   sh.str(), sc.str(), mean.str(), std::to_string(g.n),
                                                   g.moments ? "moments" : "max-likelihood"});
                }
        f.close();
    }
    writeMet((fs::path(outDir) / "synthetic_met_year1.csv").string(), firstYear, true);
    {
        std::array<long, 8> hist{};
        for (const auto& h : history.hours) hist[static_cast<int>(h.directionFrom / 45.0) % 8]++;
        std::array<long, 8> syn{};
        for (const auto& s : sectors)
            for (int k = 0; k < 8; ++k) syn[k] += s[k];
        CsvWriter f((fs::path(outDir) / "wind_sectors.csv").string(),
                    {"sector_from_deg", "to_deg", "history_fraction", "synthetic_fraction"});
        std::cout << "  wind from (deg)    history  synthetic\n";
        for (int k = 0; k < 8; ++k)
        {
            const double fh = static_cast<double>(hist[k]) / history.hours.size();
            const double fs_ = static_cast<double>(syn[k]) / (8760.0 * years);
            f.row(std::vector<double>{45.0 * k, 45.0 * (k + 1), fh, fs_});
            std::cout << "    " << std::setw(3) << 45 * k << "-" << std::left << std::setw(3) << 45 * (k + 1)
                      << std::right << std::fixed << std::setprecision(3) << std::setw(12) << fh
                      << std::setw(11) << fs_ << std::defaultfloat << std::setprecision(6) << '\n';
        }
        f.close();
        std::array<long, 4> sp{};
        for (const auto& s : speeds)
            for (int k = 0; k < 4; ++k) sp[k] += s[k];
        std::cout << "  synthetic wind speed: 0-2 m/s " << std::fixed << std::setprecision(3)
                  << sp[0] / (8760.0 * years) << ", 2-4 " << sp[1] / (8760.0 * years) << ", 4-6 "
                  << sp[2] / (8760.0 * years) << ", >6 " << sp[3] / (8760.0 * years) << std::defaultfloat
                  << std::setprecision(6) << '\n';
    }
    std::vector<std::string> sh = {"receptor", "mean [ug/m3]", "p5 24-h [ug/m3]", "p50 24-h [ug/m3]",
                                   "p95 24-h [ug/m3]", "max 24-h [ug/m3]"};
    for (double th : thresholds)
    {
        std::ostringstream a, b;
        a << "P(24-h > " << th << ")";
        b << "P(year with a 24-h > " << th << ")";
        sh.push_back(a.str());
        sh.push_back(b.str());
    }
    CsvWriter summary((fs::path(outDir) / "summary.csv").string(), sh);
    std::cout << "\n  receptor      mean     p5    p50    p95    max [ug/m3]";
    for (double th : thresholds) std::cout << "  P(24h>" << th << ")";
    std::cout << '\n';
    for (std::size_t k = 0; k < nr; ++k)
    {
        const std::string name = setup.receptors[k].name;
        std::vector<double> all;
        all.reserve(static_cast<std::size_t>(years) * 365);
        std::vector<long> yearsOver(thresholds.size(), 0);
        for (long r = 0; r < years; ++r)
        {
            std::vector<bool> over(thresholds.size(), false);
            for (double v : daily[r][k])
            {
                all.push_back(v);
                for (std::size_t q = 0; q < thresholds.size(); ++q)
                    if (v > thresholds[q]) over[q] = true;
            }
            for (std::size_t q = 0; q < thresholds.size(); ++q) yearsOver[q] += over[q];
        }
        double mean = 0;
        for (double v : all) mean += v;
        mean /= all.size();
        std::vector<double> sorted = all;
        std::sort(sorted.begin(), sorted.end());
        std::vector<std::string> row = {name};
        auto num = [](double v, int p = 3) {
            std::ostringstream os;
            os << std::fixed << std::setprecision(p) << v;
            return os.str();
        };
        row.insert(row.end(), {num(mean), num(percentile(sorted, 5)), num(percentile(sorted, 50)),
                               num(percentile(sorted, 95)), num(sorted.back())});
        std::cout << "  " << std::left << std::setw(9) << name << std::right << std::setw(9) << num(mean, 1)
                  << std::setw(7) << num(percentile(sorted, 5), 1) << std::setw(7) << num(percentile(sorted, 50), 1)
                  << std::setw(7) << num(percentile(sorted, 95), 1) << std::setw(7) << num(sorted.back(), 0) << "      ";
        for (std::size_t q = 0; q < thresholds.size(); ++q)
        {
            const double p = static_cast<double>(std::count_if(all.begin(), all.end(),
                                                               [&](double v) { return v > thresholds[q]; }))
                             / all.size();
            row.push_back(num(p, 5));
            row.push_back(num(static_cast<double>(yearsOver[q]) / years, 3));
            std::cout << std::setw(12) << num(p, 4);
        }
        std::cout << '\n';
        summary.row(row);

        // annual trend (Figs 2-3): statistics over realisations for each day
        std::vector<std::string> dh = {"day", "mean [ug/m3]", "p5 [ug/m3]", "p50 [ug/m3]", "p95 [ug/m3]"};
        for (double th : thresholds)
        {
            std::ostringstream a;
            a << "P(> " << th << ")";
            dh.push_back(a.str());
        }
        const std::string dfile = (fs::path(outDir) / ("daily_" + name + ".csv")).string();
        CsvWriter d(dfile, dh);
        for (int day = 0; day < 365; ++day)
        {
            std::vector<double> v(years);
            for (long r = 0; r < years; ++r) v[r] = daily[r][k][day];
            double m = 0;
            for (double x : v) m += x;
            m /= years;
            std::sort(v.begin(), v.end());
            std::vector<double> out = {static_cast<double>(day + 1), m, percentile(v, 5), percentile(v, 50),
                                       percentile(v, 95)};
            for (double th : thresholds)
                out.push_back(static_cast<double>(std::count_if(v.begin(), v.end(), [&](double x) { return x > th; }))
                              / years);
            d.row(out);
        }
        d.close();
        std::ostringstream gp;
        gp << "set termoption noenhanced\nset datafile separator ','\nset key top right\nset xlabel 'day of the year'\n"
              "set ylabel '24-h average PM10 [ug/m3]'\nset xrange [1:365]\nset grid\n"
              "set title 'Receptor " << name << ": " << years << " synthetic years (w = " << w << ")'\n"
              "plot '" << dfile << "' using 1:3:5 with filledcurves lc rgb '#cfe2ff' title '5th-95th percentile', "
              "'' using 1:3 with lines lc rgb '#6fa8dc' notitle, "
              "'' using 1:5 with lines lc rgb '#6fa8dc' notitle, "
              "'' using 1:2 with lines lw 2 lc rgb '#1c4587' title 'mean', "
              "'' using 1:4 with lines lw 1 dt 2 lc rgb 'black' title 'median'";
        for (std::size_t q = 0; q < thresholds.size(); ++q)
            gp << ", " << thresholds[q] << " with lines lw 2 lc rgb '" << (q ? "#cc0000" : "#e69138")
               << "' title '" << thresholds[q] << " ug/m3'";
        gp << '\n';
        plotPng((fs::path(outDir) / ("trend_" + name + ".png")).string(), gp.str(), 1000, 560);
    }
    summary.close();
    std::cout << "\n  P(24h>X): fraction of all simulated days; P(year ...) in summary.csv\n  wall time "
              << std::fixed << std::setprecision(1) << wall << " s for " << years << " years; outputs in "
              << outDir << "/\n" << std::defaultfloat;
    return 0;
}

} // namespace procsim::plume
