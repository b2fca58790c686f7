#include "plume/GaussianCase.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "common/Cli.hpp"
#include "common/CommandLine.hpp"
#include "common/Csv.hpp"
#include "common/Plot.hpp"
#include "common/YamlInput.hpp"
#include "plume/Texts.hpp"

namespace fs = std::filesystem;

namespace procsim::plume
{

namespace
{

} // namespace

const std::vector<std::string>& gaussianSetupKeys()
{
    static const std::vector<std::string> keys = {"site", "deposition", "dispersion", "area_subdivisions",
                                                  "reduction", "sources", "receptors", "output"};
    return keys;
}

GaussianSetup parseGaussianSetup(const YamlInput& in)
{
    GaussianSetup s;
    GaussianOptions& o = s.options;
    if (in.has("site"))
    {
        const YamlInput site = in.child("site");
        site.rejectUnknown({"latitude_deg", "start_day_of_year", "start_hour"});
        o.latitudeDeg = site.number("latitude_deg", o.latitudeDeg, "deg");
        if (std::abs(o.latitudeDeg) > 90) throw site.error("latitude_deg", "-90..90 [deg]");
        if (site.has("start_day_of_year"))
        {
            o.startDayOfYear = static_cast<int>(site.integer("start_day_of_year"));
            if (o.startDayOfYear < 1 || o.startDayOfYear > 365) throw site.error("start_day_of_year", "1..365");
        }
        o.startHour = site.number("start_hour", 0.0, "h");
        if (o.startHour < 0 || o.startHour >= 24) throw site.error("start_hour", "0..24 [h]");
    }
    if (in.has("deposition"))
    {
        const YamlInput d = in.child("deposition");
        d.rejectUnknown({"velocity_m_s"});
        o.depositionVelocity = d.within("velocity_m_s", 0, 1, "m/s");
    }
    if (in.has("dispersion"))
    {
        const YamlInput d = in.child("dispersion");
        d.rejectUnknown({"model", "K_H_m2_s", "K_V_m2_s"});
        const std::string m = d.text("model", o.curves);
        if (m == "constant_k")
        {
            o.constantK = true;
            o.kH = d.within("K_H_m2_s", 1e-6, 1e6, "m2/s");
            o.kV = d.within("K_V_m2_s", 1e-6, 1e6, "m2/s");
        }
        else if (DispersionCurves::create(m))
        {
            o.curves = m;
        }
        else
        {
            std::string known;
            for (const auto& n : DispersionCurves::curveNames()) known += n + ", ";
            throw d.error("model", "one of " + known + "constant_k");
        }
        for (const char* k : {"K_H_m2_s", "K_V_m2_s"})
            if (!o.constantK && d.has(k)) throw d.error(k, "no diffusivity: it is read for model constant_k only");
    }
    if (in.has("area_subdivisions"))
    {
        o.areaSubdivisions = static_cast<int>(in.integer("area_subdivisions"));
        if (o.areaSubdivisions < 1 || o.areaSubdivisions > 100) throw in.error("area_subdivisions", "1..100");
    }
    o.reduction = in.number("reduction", 0.0);
    if (o.reduction < 0 || o.reduction > 1) throw in.error("reduction", "a fraction 0..1");
    if (in.has("output"))
    {
        const YamlInput out = in.child("output");
        out.rejectUnknown({"standard_24h_ug_m3"});
        if (out.has("standard_24h_ug_m3")) s.standardUgM3 = out.positive("standard_24h_ug_m3", "ug/m3");
    }
    s.sources = parseSources(in.child("sources"));
    s.receptors = parseReceptors(in.child("receptors"));
    for (const auto& src : s.sources)
        for (const auto& r : s.receptors)
            if (src.type != Source::Type::Area && r.x == src.x && r.y == src.y)
                throw InputError(r.where + ": receptor '" + r.name + "' sits on source '" + src.name
                                 + "' (the Gaussian plume is singular there)");
    return s;
}

int gaussianMain(int argc, char** argv)
{
    std::string casePath, outDir = "results";
    CommandLine cl("plume gaussian", std::string(texts::help::gaussian));
    cl.input(casePath, "case file");
    cl.text("-o", outDir);
    if (!cl.parse(argc, argv)) return 0;
    const YamlInput in = YamlInput::load(casePath);
    std::vector<std::string> keys = gaussianSetupKeys();
    keys.push_back("meteorology");
    in.rejectUnknown(keys);
    const GaussianSetup setup = parseGaussianSetup(in);
    const std::string dir = fs::path(casePath).parent_path().string();
    const MetSeries met = readMet(relativeTo(dir, in.text("meteorology")), true);
    const GaussianModel model(setup.sources, setup.options);

    fs::create_directories(outDir);
    const std::size_t nr = setup.receptors.size();
    const int hours = static_cast<int>(met.hours.size());
    std::vector<std::vector<double>> c(nr, std::vector<double>(hours));
    std::vector<std::string> header = {"hour", "class", "wind_speed_m_s", "wind_direction_deg", "mixing_height_m"};
    for (const auto& r : setup.receptors) header.push_back(r.name + " [ug/m3]");
    CsvWriter hourly((fs::path(outDir) / "hourly.csv").string(), header);
    std::array<int, 7> classCount{};
    for (int h = 0; h < hours; ++h)
    {
        const PlumeHour ph = model.hourConditions(met.hours[h], h);
        ++classCount[ph.cls];
        std::vector<std::string> row = {std::to_string(met.firstHour + h), std::string(1, className(ph.cls))};
        std::ostringstream a, b, m;
        a << ph.u10;
        b << ph.directionFrom;
        m << ph.mixingHeight;
        row.insert(row.end(), {a.str(), b.str(), m.str()});
        for (std::size_t r = 0; r < nr; ++r)
        {
            c[r][h] = model.concentration(ph, setup.receptors[r]) * 1e9;
            std::ostringstream v;
            v << std::setprecision(6) << c[r][h];
            row.push_back(v.str());
        }
        hourly.row(row);
    }
    hourly.close();
    std::vector<std::string> dh = {"day"};
    for (const auto& r : setup.receptors) dh.push_back(r.name + " [ug/m3]");
    CsvWriter daily((fs::path(outDir) / "daily.csv").string(), dh);
    const int days = hours / 24;
    std::vector<double> max24(nr, 0.0), max1(nr, 0.0), mean(nr, 0.0);
    for (int d = 0; d < days; ++d)
    {
        std::vector<double> row = {static_cast<double>(d + 1)};
        for (std::size_t r = 0; r < nr; ++r)
        {
            double s = 0;
            for (int h = d * 24; h < (d + 1) * 24; ++h) s += c[r][h];
            row.push_back(s / 24);
            max24[r] = std::max(max24[r], s / 24);
        }
        daily.row(row);
    }
    daily.close();
    std::cout << "procsim plume gaussian: " << casePath << "\n  " << hours << " h, " << setup.sources.size()
              << " sources, " << nr << " receptors, reduction " << setup.options.reduction * 100
              << " %, deposition velocity " << setup.options.depositionVelocity << " m/s, dispersion "
              << model.dispersionTitle() << "\n  hours per class:";
    for (int k = 1; k <= 6; ++k) std::cout << ' ' << className(k) << ' ' << classCount[k];
    std::cout << "\n\n  " << std::left << std::setw(12) << "receptor" << std::right << std::setw(12) << "mean"
              << std::setw(12) << "max 1-h" << std::setw(12) << "max 24-h" << "   [ug/m3]\n";
    for (std::size_t r = 0; r < nr; ++r)
    {
        for (int h = 0; h < hours; ++h)
        {
            mean[r] += c[r][h] / hours;
            max1[r] = std::max(max1[r], c[r][h]);
        }
        std::cout << "  " << std::left << std::setw(12) << setup.receptors[r].name << std::right << std::fixed
                  << std::setprecision(2) << std::setw(12) << mean[r] << std::setw(12) << max1[r] << std::setw(12)
                  << (days > 0 ? max24[r] : 0.0) << (max24[r] > setup.standardUgM3 ? " *" : "") << '\n'
                  << std::defaultfloat << std::setprecision(6);
    }
    if (days > 0)
    {
        std::ostringstream gp;
        gp << "set termoption noenhanced\nset datafile separator ','\nset key outside right\nset xlabel 'day'\nset ylabel '24-h average PM10 [ug/m3]'\n"
              "set title 'Gaussian plume: 24-h averages at the receptors'\nset grid\nplot for [c=2:"
           << nr + 1 << "] '" << (fs::path(outDir) / "daily.csv").string()
           << "' using 1:c with linespoints title columnheader(c), " << setup.standardUgM3
           << " with lines lw 2 lc rgb 'red' title 'standard'\n";
        plotPng((fs::path(outDir) / "daily.png").string(), gp.str());
    }
    std::cout << "\n  (* = a 24-h average above " << setup.standardUgM3 << " ug/m3); outputs in " << outDir
              << "/ (hourly.csv, daily.csv, daily.png)\n";
    return 0;
}

} // namespace procsim::plume
