#include "plume/GaussianCase.hpp"

#include <cmath>

#include "common/Cli.hpp"

namespace procsim::plume
{

const std::vector<std::string>& gaussianSetupKeys()
{
    static const std::vector<std::string> keys = {
        "site",      "deposition", "dispersion", "area_subdivisions",
        "reduction", "sources",    "receptors",  "output"};
    return keys;
}

namespace
{

void readSite(const YamlInput& in, GaussianOptions& o)
{
    if (!in.has("site")) return;
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

// dispersion.model: one of the rural curves, or constant_k with its two diffusivities
void readDispersion(const YamlInput& in, GaussianOptions& o)
{
    if (!in.has("dispersion")) return;
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
        if (!o.constantK && d.has(k))
            throw d.error(k, "no diffusivity: it is read for model constant_k only");
}

void readEmissionSettings(const YamlInput& in, GaussianOptions& o)
{
    if (in.has("deposition"))
    {
        const YamlInput d = in.child("deposition");
        d.rejectUnknown({"velocity_m_s"});
        o.depositionVelocity = d.within("velocity_m_s", 0, 1, "m/s");
    }
    readDispersion(in, o);
    if (in.has("area_subdivisions"))
    {
        o.areaSubdivisions = static_cast<int>(in.integer("area_subdivisions"));
        if (o.areaSubdivisions < 1 || o.areaSubdivisions > 100) throw in.error("area_subdivisions", "1..100");
    }
    o.reduction = in.number("reduction", 0.0);
    if (o.reduction < 0 || o.reduction > 1) throw in.error("reduction", "a fraction 0..1");
}

} // namespace

GaussianSetup parseGaussianSetup(const YamlInput& in)
{
    GaussianSetup s;
    readSite(in, s.options);
    readEmissionSettings(in, s.options);
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

} // namespace procsim::plume
