#pragma once
// A reaction mechanism read from YAML: species (molar mass, carbon count) and
// mass-action reactions "A + B -> C + 2 D" with rate constants in stated units.
// Concentrations are mol/L throughout the kinetics model (the unit of the
// rate constants in the chemistry literature); time is in seconds.
#include <string>
#include <vector>

#include "common/YamlInput.hpp"

namespace procsim::kinetics
{

// Far above the diffusion limit (~1e10 L/mol/s): larger values are typing errors.
constexpr double maxRateConstant = 1e15;

struct Species
{
    std::string name;
    std::string description;
    double molarMass = 0; // g/mol
    double carbon = 0;    // carbon atoms per molecule
    bool organic = true;  // counted in TOC (false for CO2)
};

struct Term
{
    std::size_t species;
    double stoich;
};

struct Reaction
{
    std::string id;
    std::string equation;
    std::vector<Term> reactants;
    std::vector<Term> products;
    double k = 0;  // (L/mol)^(order-1) / s
    int order = 0; // sum of reactant stoichiometric coefficients
};

class Mechanism
{
public:
    static Mechanism load(const std::string& path);
    static Mechanism fromYaml(const YamlInput& root);

    std::string name;
    std::string file;
    std::vector<Species> species;
    std::vector<Reaction> reactions;
    std::string radical; // species whose concentration the [OH] model sets ("" = none)

    // index of a species; throws InputError naming `where` if unknown
    std::size_t index(const std::string& name, const std::string& where) const;
    bool hasSpecies(const std::string& name) const;
    std::size_t reaction(const std::string& id) const; // npos if unknown
    bool hasRadical() const { return !radical.empty(); }
    std::size_t radicalIndex() const;
};

// The unit string a rate constant of the given order must carry, e.g. "L/mol/s".
std::string rateUnit(int order);
// Parse a unit string; returns the reaction order it implies or -1.
int orderOfRateUnit(const std::string& unit);

} // namespace procsim::kinetics
