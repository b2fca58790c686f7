#include "kinetics/Mechanism.hpp"

#include <cmath>
#include <sstream>

#include "common/Checked.hpp"
#include "common/Csv.hpp"

namespace procsim::kinetics
{

namespace
{

// "2 CO2" -> {2, "CO2"}; "CO2" -> {1, "CO2"}
std::pair<double, std::string> parseTerm(const std::string& raw, const YamlInput& where)
{
    const std::string t = trimmed(raw);
    std::istringstream is(t);
    double coef = 1;
    std::string name;
    if (!t.empty() && (std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '.'))
    {
        is >> coef;
        if (!is || !(coef > 0)) throw where.error("equation", "terms like '2 CO2'");
    }
    is >> name;
    std::string rest;
    if (name.empty() || (is >> rest))
        throw where.error("equation", "terms like 'A', '2 CO2' separated by ' + '");
    return {coef, name};
}

std::vector<std::string> splitPlus(const std::string& side)
{
    std::vector<std::string> out;
    if (trimmed(side).empty()) return out;
    std::size_t start = 0;
    while (true)
    {
        const auto p = side.find(" + ", start);
        out.push_back(side.substr(start, p == std::string::npos ? std::string::npos : p - start));
        if (p == std::string::npos) break;
        start = p + 3;
    }
    return out;
}

} // namespace

std::string rateUnit(int order)
{
    switch (order)
    {
    case 0: return "mol/L/s";
    case 1: return "1/s";
    case 2: return "L/mol/s";
    case 3: return "L2/mol2/s";
    default: return "?";
    }
}

int orderOfRateUnit(const std::string& unitIn)
{
    std::string u;
    for (char c : unitIn)
        if (c != ' ') u += c;
    if (u == "mol/L/s") return 0;
    if (u == "1/s" || u == "s-1") return 1;
    if (u == "L/mol/s" || u == "Lmol-1s-1" || u == "M-1s-1") return 2;
    if (u == "L2/mol2/s" || u == "L2mol-2s-1" || u == "M-2s-1") return 3;
    return -1;
}

Mechanism Mechanism::load(const std::string& path)
{
    Mechanism m = fromYaml(YamlInput::load(path));
    m.file = path;
    return m;
}

Mechanism Mechanism::fromYaml(const YamlInput& root)
{
    Mechanism m;
    m.file = root.file();
    root.rejectUnknown({"name", "description", "radical", "species", "reactions", "check_carbon"});
    m.name = root.text("name", "mechanism");
    const bool checkCarbon = root.text("check_carbon", "true") == "true";

    const YamlInput sp = root.child("species");
    for (const auto& s : sp.items())
    {
        s.rejectUnknown({"name", "description", "molar_mass_g_per_mol", "carbon", "organic"});
        Species x;
        x.name = s.text("name");
        x.description = s.text("description", "");
        x.molarMass = s.positive("molar_mass_g_per_mol", "g/mol");
        x.carbon = s.nonNegative("carbon", "carbon atoms per molecule");
        const std::string org = s.text("organic", x.carbon > 0 ? "true" : "false");
        if (org != "true" && org != "false") throw s.error("organic", "true or false");
        x.organic = org == "true";
        if (m.hasSpecies(x.name)) throw s.error("name", "a species name not used before");
        m.species.push_back(x);
    }
    if (m.species.empty()) throw sp.error("species", "at least one species");

    if (root.has("radical"))
    {
        m.radical = root.text("radical");
        m.index(m.radical, root.file() + ": key 'radical'");
    }

    const YamlInput rx = root.child("reactions");
    for (const auto& r : rx.items())
    {
        r.rejectUnknown({"id", "equation", "k", "units", "source", "note"});
        Reaction x;
        x.id = r.text("id");
        if (m.reaction(x.id) != std::string::npos) throw r.error("id", "a reaction id not used before");
        x.equation = r.text("equation");
        const auto arrow = x.equation.find("->");
        if (arrow == std::string::npos) throw r.error("equation", "'A + B -> C' (with '->')");
        for (int side = 0; side < 2; ++side)
        {
            const std::string text = side == 0 ? x.equation.substr(0, arrow) : x.equation.substr(arrow + 2);
            for (const auto& term : splitPlus(" " + text + " "))
            {
                const auto [coef, name] = parseTerm(term, r);
                if (!m.hasSpecies(name))
                {
                    throw InputError(r.file() + ": key '" + r.path() + ".equation' names unknown species '"
                                     + name + "' (declare it under 'species')");
                }
                (side == 0 ? x.reactants : x.products).push_back({m.index(name, ""), coef});
            }
        }
        double order = 0;
        for (const auto& t : x.reactants) order += t.stoich;
        if (std::fabs(order - std::round(order)) > 1e-12 || order > 3)
        {
            throw r.error("equation", "a reaction of order 0 to 3 (integer coefficients on the left)");
        }
        x.order = static_cast<int>(std::round(order));
        x.k = r.number("k", rateUnit(x.order));
        if (!(x.k >= 0 && x.k <= maxRateConstant))
            throw r.error("k", "a rate constant >= 0 [" + rateUnit(x.order) + "] up to "
                                   + formatNumber(maxRateConstant));
        const std::string unit = r.text("units");
        if (orderOfRateUnit(unit) != x.order)
        {
            throw r.error("units",
                          "'" + rateUnit(x.order) + "' for a reaction of order " + std::to_string(x.order));
        }
        if (checkCarbon)
        {
            double cin = 0, cout = 0;
            for (const auto& t : x.reactants) cin += t.stoich * m.species[t.species].carbon;
            for (const auto& t : x.products) cout += t.stoich * m.species[t.species].carbon;
            if (std::fabs(cin - cout) > 1e-12 * std::max(1.0, cin))
            {
                std::ostringstream os;
                os << r.file() << ": key '" << r.path() << ".equation' does not conserve carbon (" << cin
                   << " C in, " << cout
                   << " C out); add the CO2 formed as a product, or set check_carbon: false";
                throw InputError(os.str());
            }
        }
        m.reactions.push_back(x);
    }
    return m;
}

bool Mechanism::hasSpecies(const std::string& n) const
{
    for (const auto& s : species)
        if (s.name == n) return true;
    return false;
}

std::size_t Mechanism::index(const std::string& n, const std::string& where) const
{
    for (std::size_t i = 0; i < species.size(); ++i)
        if (species[i].name == n) return i;
    std::string list;
    for (const auto& s : species) list += (list.empty() ? "" : ", ") + s.name;
    throw InputError(where + ": unknown species '" + n + "' (mechanism has: " + list + ")");
}

std::size_t Mechanism::reaction(const std::string& id) const
{
    for (std::size_t i = 0; i < reactions.size(); ++i)
        if (reactions[i].id == id) return i;
    return std::string::npos;
}

std::size_t Mechanism::radicalIndex() const
{
    return index(radical, file + ": key 'radical'");
}

} // namespace procsim::kinetics
