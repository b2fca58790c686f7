#include "plume/Met.hpp"

#include <cmath>
#include <iomanip>

#include "common/Cli.hpp"
#include "common/Csv.hpp"

namespace procsim::plume
{

namespace
{

bool hasColumn(const CsvTable& t, const std::string& name)
{
    for (const auto& h : t.header)
        if (h == name) return true;
    return false;
}

} // namespace

MetSeries readMet(const std::string& path, bool full)
{
    const CsvTable t = readCsv(path);
    // a misspelt optional column (stability) would be ignored
    t.rejectUnknownColumns({"hour", "wind_speed_m_s", "wind_direction_deg", "temperature_C",
                            "mixing_height_m", "cloud_cover_oktas", "stability"},
                           path);
    if (t.rows.empty()) throw InputError(path + ": no meteorology rows (expected one row per hour)");
    const std::size_t ch = t.column("hour", path);
    const std::size_t cs = t.column("wind_speed_m_s", path);
    const std::size_t cd = t.column("wind_direction_deg", path);
    std::size_t ct = 0, cm = 0, cc = 0, cst = 0;
    if (full)
    {
        ct = t.column("temperature_C", path);
        cm = t.column("mixing_height_m", path);
        cc = t.column("cloud_cover_oktas", path);
    }
    const bool haveStability = hasColumn(t, "stability");
    if (haveStability) cst = t.column("stability", path);

    MetSeries m;
    const double first = t.rows[0][ch];
    if (!(first >= 0 && first <= 1e8 && first == std::floor(first)))
        throw InputError(path + ": column 'hour' expected a whole hour from 0 to 1e8, got "
                         + formatNumber(first));
    m.firstHour = static_cast<int>(first);
    for (std::size_t r = 0; r < t.rows.size(); ++r)
    {
        const auto& row = t.rows[r];
        const double hour = row[ch];
        const long expected = m.firstHour + static_cast<long>(r);
        if (hour != std::floor(hour))
            throw InputError(path + ": hour '" + std::to_string(hour) + "' is not a whole number");
        if (static_cast<long>(hour) != expected)
        {
            throw InputError(path + ": meteorology hour " + std::to_string(expected)
                             + " is missing (found hour " + std::to_string(static_cast<long>(hour))
                             + "; one row per hour, consecutive)");
        }
        MetHour h;
        h.speed = row[cs];
        h.directionFrom = row[cd];
        const std::string at = path + ": hour " + std::to_string(expected) + ": ";
        if (!(h.speed >= 0 && h.speed <= 100)) throw InputError(at + "wind_speed_m_s expected 0..100");
        if (!(h.directionFrom >= 0 && h.directionFrom <= 360))
            throw InputError(at + "wind_direction_deg expected 0..360");
        if (full)
        {
            h.temperatureC = row[ct];
            h.mixingHeight = row[cm];
            h.cloudOktas = row[cc];
            if (!(h.temperatureC >= -90 && h.temperatureC <= 60))
                throw InputError(at + "temperature_C expected -90..60");
            if (!(h.mixingHeight > 0 && h.mixingHeight <= 10000))
                throw InputError(at + "mixing_height_m expected > 0 and up to 10000");
            if (!(h.cloudOktas >= 0 && h.cloudOktas <= 8))
                throw InputError(at + "cloud_cover_oktas expected 0..8");
        }
        if (haveStability)
        {
            const double s = row[cst];
            if (!(s >= 1 && s <= 6 && s == std::floor(s)))
                throw InputError(at + "stability expected a class 1..6 (A..F)");
            h.stability = static_cast<int>(s);
        }
        m.hours.push_back(h);
    }
    return m;
}

void writeMet(const std::string& path, const std::vector<MetHour>& hours, bool full)
{
    std::vector<std::string> header = {"hour", "wind_speed_m_s", "wind_direction_deg"};
    if (full)
    {
        header.insert(header.end(), {"temperature_C", "mixing_height_m", "cloud_cover_oktas"});
    }
    CsvWriter w(path, header);
    for (std::size_t i = 0; i < hours.size(); ++i)
    {
        const auto& h = hours[i];
        std::vector<double> row = {static_cast<double>(i), h.speed, h.directionFrom};
        if (full) row.insert(row.end(), {h.temperatureC, h.mixingHeight, h.cloudOktas});
        w.row(row);
    }
    w.close();
}

} // namespace procsim::plume
