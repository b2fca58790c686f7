#include "plume/Sites.hpp"

namespace procsim::plume
{

std::vector<Source> parseSources(const YamlInput& list)
{
    std::vector<Source> out;
    for (const auto& it : list.items())
    {
        Source s;
        s.where = it.file() + ": " + it.path();
        s.name = it.text("name");
        const std::string type = it.text("type");
        s.x = it.number("x_m", "m");
        s.y = it.number("y_m", "m");
        s.rate = it.nonNegative("rate_g_s", "g/s") * 1e-3;
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
            s.height = it.nonNegative("height_m", "m");
        }
        else if (type == "area")
        {
            it.rejectUnknown({"name", "type", "x_m", "y_m", "size_m", "height_m", "rate_g_s", "controlled"});
            s.type = Source::Type::Area;
            const auto size = it.numbers("size_m", "m");
            if (size.size() != 2 || !(size[0] > 0) || !(size[1] > 0))
                throw it.error("size_m", "two positive numbers [m] (east-west, north-south)");
            s.lx = size[0];
            s.ly = size[1];
            s.height = it.number("height_m", 0.0, "m");
            if (s.height < 0) throw it.error("height_m", "a number >= 0 [m]");
        }
        else if (type == "volume")
        {
            it.rejectUnknown({"name", "type", "x_m", "y_m", "size_m", "bottom_m", "top_m", "rate_g_s", "controlled"});
            s.type = Source::Type::Volume;
            const auto size = it.numbers("size_m", "m");
            if (size.size() != 2 || !(size[0] > 0) || !(size[1] > 0))
                throw it.error("size_m", "two positive numbers [m] (east-west, north-south)");
            s.lx = size[0];
            s.ly = size[1];
            s.bottom = it.number("bottom_m", 0.0, "m");
            s.top = it.positive("top_m", "m");
            if (!(s.bottom >= 0 && s.top > s.bottom))
                throw it.error("top_m", "a height above bottom_m [m]");
            s.height = 0.5 * (s.bottom + s.top);
        }
        else
        {
            throw it.error("type", "one of point, area, volume");
        }
        out.push_back(s);
    }
    if (out.empty()) throw InputError(list.file() + ": key '" + list.path() + "' expected at least one source");
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
        r.x = it.number("x_m", "m");
        r.y = it.number("y_m", "m");
        r.height = it.number("height_m", 0.0, "m");
        if (r.height < 0) throw it.error("height_m", "a number >= 0 [m]");
        out.push_back(r);
    }
    if (out.empty()) throw InputError(list.file() + ": key '" + list.path() + "' expected at least one receptor");
    return out;
}

} // namespace procsim::plume
