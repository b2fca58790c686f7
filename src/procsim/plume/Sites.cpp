#include "plume/Sites.hpp"

#include "common/Checked.hpp"

namespace procsim::plume
{

namespace
{

// Bounds that keep a site physical (and its arithmetic finite).
constexpr double maxCoordinate = 1e7; // m: 10 000 km from the origin
constexpr double maxHeight = 1e4;     // m above the ground
constexpr double maxSize = 1e5;       // m: a 100 km source
constexpr double maxRate = 1e9;       // g/s

// size_m: [east-west, north-south] of an area or volume source
void readSize(const YamlInput& it, Source& s)
{
    const auto size = it.numbers("size_m", "m");
    if (size.size() != 2 || !(size[0] > 0 && size[0] <= maxSize) || !(size[1] > 0 && size[1] <= maxSize))
        throw it.error("size_m", "two positive numbers up to 1e5 [m] (east-west, north-south)");
    s.lx = size[0];
    s.ly = size[1];
}

} // namespace

std::vector<Source> parseSources(const YamlInput& list)
{
    std::vector<Source> out;
    for (const auto& it : list.items())
    {
        Source s;
        s.where = it.file() + ": " + it.path();
        s.name = it.text("name");
        const std::string type = it.text("type");
        s.x = it.within("x_m", -maxCoordinate, maxCoordinate, "m");
        s.y = it.within("y_m", -maxCoordinate, maxCoordinate, "m");
        s.rate = it.within("rate_g_s", 0, maxRate, "g/s") * 1e-3;
        if (it.has("controlled"))
        {
            try
            {
                s.controlled = it.node()["controlled"].as<bool>();
            }
            catch (const YAML::Exception&)
            {
                throw it.error("controlled", "true or false");
            }
        }
        if (type == "point")
        {
            it.rejectUnknown({"name", "type", "x_m", "y_m", "height_m", "rate_g_s", "controlled"});
            s.type = Source::Type::Point;
            s.height = it.within("height_m", 0, maxHeight, "m");
        }
        else if (type == "area")
        {
            it.rejectUnknown({"name", "type", "x_m", "y_m", "size_m", "height_m", "rate_g_s", "controlled"});
            s.type = Source::Type::Area;
            readSize(it, s);
            s.height = it.within("height_m", 0.0, 0, maxHeight, "m");
        }
        else if (type == "volume")
        {
            it.rejectUnknown(
                {"name", "type", "x_m", "y_m", "size_m", "bottom_m", "top_m", "rate_g_s", "controlled"});
            s.type = Source::Type::Volume;
            readSize(it, s);
            s.bottom = it.within("bottom_m", 0.0, 0, maxHeight, "m");
            s.top = it.within("top_m", 0, maxHeight, "m");
            if (!(s.bottom >= 0 && s.top > s.bottom)) throw it.error("top_m", "a height above bottom_m [m]");
            s.height = 0.5 * (s.bottom + s.top);
        }
        else
        {
            throw it.error("type", "one of point, area, volume");
        }
        out.push_back(s);
    }
    if (out.empty())
        throw InputError(list.file() + ": key '" + list.path() + "' expected at least one source");
    rejectDuplicates(out, &Source::name, list.file() + ": key '" + list.path() + "'", "source name");
    return out;
}

std::vector<Receptor> parseReceptors(const YamlInput& list)
{
    std::vector<Receptor> out;
    for (const auto& it : list.items())
    {
        it.rejectUnknown({"name", "x_m", "y_m", "height_m"});
        Receptor r;
        r.where = it.file() + ": " + it.path();
        r.name = it.text("name");
        checkFileNamePart(r.name, it.file() + ": key '" + it.path() + ".name'"); // names result files
        r.x = it.within("x_m", -maxCoordinate, maxCoordinate, "m");
        r.y = it.within("y_m", -maxCoordinate, maxCoordinate, "m");
        r.height = it.within("height_m", 0.0, 0, maxHeight, "m");
        out.push_back(r);
    }
    rejectDuplicates(out, &Receptor::name, list.file() + ": key '" + list.path() + "'", "receptor name");
    if (out.empty())
        throw InputError(list.file() + ": key '" + list.path() + "' expected at least one receptor");
    return out;
}

} // namespace procsim::plume
