// The mechanism file and the species balances built from it (the paper's
// Table 2, rebuilt from Table 1), the [OH] model and one-line input errors.
#include <gtest/gtest.h>

#include "TestUtil.hpp"
#include "kinetics/Case.hpp"
#include "kinetics/Model.hpp"

using namespace procsim;
using namespace procsim::kinetics;

namespace
{

Mechanism paper()
{
    return Mechanism::load(kt::casesDir() + "/phenol_acetaldehyde_mechanism.yaml");
}

std::string errorOf(const std::string& yaml)
{
    try
    {
        Mechanism::fromYaml(YamlInput(YAML::Load(yaml), "m.yaml", ""));
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

const char* okSpecies = "species:\n  - {name: A, molar_mass_g_per_mol: 10, carbon: 1}\n"
                        "  - {name: B, molar_mass_g_per_mol: 10, carbon: 1}\n";

} // namespace

TEST(KineticsMechanism, PaperMechanismHasTable1)
{
    const Mechanism m = paper();
    EXPECT_EQ(m.species.size(), 10u);
    ASSERT_EQ(m.reactions.size(), 12u);
    EXPECT_EQ(m.radical, "OH");
    // Table 1 values, eqs 6-17 -> k1..k12 (L/mol/s)
    const double k[] = {5e9, 4e9, 5e9, 8e9, 7e9, 6.5e9, 1e9, 1e9, 1.1e10, 1e11, 1e10, 1e10};
    for (int i = 0; i < 12; ++i)
    {
        EXPECT_EQ(m.reactions[static_cast<std::size_t>(i)].id, "k" + std::to_string(i + 1));
        EXPECT_DOUBLE_EQ(m.reactions[static_cast<std::size_t>(i)].k, k[i]);
        EXPECT_EQ(m.reactions[static_cast<std::size_t>(i)].order, 2);
    }
}

TEST(KineticsMechanism, BalancesMatchTable2)
{
    // Linear form dy/dt = A y + b of the 8 organic balances (+ CO2) at a fixed [OH]
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    const Case c = src.build();
    const Model model(c);
    ASSERT_TRUE(model.isLinear());
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    model.linearForm(a, b);
    const double oh = 8.77e-10 * 0.3 / 17.007 / 1000.0; // mol/L (paper Fig 3, mg/L -> mol/L)
    EXPECT_NEAR(c.radicalConcentration(), oh, 1e-12 * oh);
    auto s = [&](const std::string& n) {
        for (std::size_t i = 0; i < model.size(); ++i)
            if (c.mech.species[model.stateSpecies()[i]].name == n) return static_cast<Eigen::Index>(i);
        ADD_FAILURE() << n;
        return Eigen::Index(0);
    };
    const double k1 = 5e9, k2 = 4e9, k3 = 5e9, k4 = 8e9, k5 = 7e9, k6 = 6.5e9, k7 = 1e9, k8 = 1e9,
                 k9 = 1.1e10, k10 = 1e11, k11 = 1e10, k12 = 1e10;
    const double tol = 1e-12;
    auto near = [&](double x, double y) { EXPECT_NEAR(x, y, tol * std::max(1.0, std::fabs(y))); };
    // d[AD]/dt = q_g C_in / W - (k1 + k2)[AD][OH]
    const double qg = 101.3e3 * 100e-6 / 60.0 / (gasConstant * 298.15);
    near(b[s("AD")], qg * 30e-6 / 1.0);
    near(a(s("AD"), s("AD")), -(k1 + k2) * oh);
    // d[UP_C1]/dt = k2[AD][OH] - k4[UP_C1][OH]
    near(a(s("UP_C1"), s("AD")), k2 * oh);
    near(a(s("UP_C1"), s("UP_C1")), -k4 * oh);
    // d[AA]/dt = k1[AD][OH] + k12[UP_C6][OH] - k3[AA][OH]
    near(a(s("AA"), s("AD")), k1 * oh);
    near(a(s("AA"), s("UP_C6")), k12 * oh);
    near(a(s("AA"), s("AA")), -k3 * oh);
    // d[PH]/dt = -(k5 + k6 + k7 + k8)[PH][OH]
    near(a(s("PH"), s("PH")), -(k5 + k6 + k7 + k8) * oh);
    // d[CC]/dt = k5[PH][OH] - k9[CC][OH], and likewise HQ, RC
    near(a(s("CC"), s("PH")), k5 * oh);
    near(a(s("CC"), s("CC")), -k9 * oh);
    near(a(s("HQ"), s("PH")), k6 * oh);
    near(a(s("HQ"), s("HQ")), -k10 * oh);
    near(a(s("RC"), s("PH")), k7 * oh);
    near(a(s("RC"), s("RC")), -k11 * oh);
    // d[UP_C6]/dt = k8[PH][OH] + k9[CC][OH] + k10[HQ][OH] + k11[RC][OH] - k12[UP_C6][OH]
    near(a(s("UP_C6"), s("PH")), k8 * oh);
    near(a(s("UP_C6"), s("CC")), k9 * oh);
    near(a(s("UP_C6"), s("HQ")), k10 * oh);
    near(a(s("UP_C6"), s("RC")), k11 * oh);
    near(a(s("UP_C6"), s("UP_C6")), -k12 * oh);
    // no other couplings among the 8 organics
    int nonzero = 0;
    for (const char* r : {"AD", "UP_C1", "AA", "PH", "CC", "HQ", "RC", "UP_C6"})
        for (const char* col : {"AD", "UP_C1", "AA", "PH", "CC", "HQ", "RC", "UP_C6"})
            nonzero += a(s(r), s(col)) != 0.0;
    EXPECT_EQ(nonzero, 18); // 1+2+3+1+2+2+2+5 terms of Table 2
}

TEST(KineticsMechanism, ErrorsAreOneLineAndNameTheProblem)
{
    const std::string unknown = errorOf(
        std::string(okSpecies) + "reactions:\n  - {id: r, equation: \"A + X -> B\", k: 1, units: L/mol/s}\n");
    EXPECT_NE(unknown.find("unknown species 'X'"), std::string::npos) << unknown;
    const std::string negative = errorOf(
        std::string(okSpecies) + "reactions:\n  - {id: r, equation: \"A -> B\", k: -1, units: 1/s}\n");
    EXPECT_NE(negative.find("reactions[0].k"), std::string::npos) << negative;
    EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;
    const std::string units = errorOf(
        std::string(okSpecies) + "reactions:\n  - {id: r, equation: \"A -> B\", k: 1, units: L/mol/s}\n");
    EXPECT_NE(units.find("'1/s' for a reaction of order 1"), std::string::npos) << units;
    const std::string missing =
        errorOf(std::string(okSpecies) + "reactions:\n  - {id: r, equation: \"A -> B\", units: 1/s}\n");
    EXPECT_NE(missing.find("'reactions[0].k' is missing"), std::string::npos) << missing;
    const std::string carbon = errorOf(
        std::string(okSpecies) + "reactions:\n  - {id: r, equation: \"A -> 2 B\", k: 1, units: 1/s}\n");
    EXPECT_NE(carbon.find("does not conserve carbon"), std::string::npos) << carbon;
    for (const auto& e : {unknown, negative, units, missing, carbon})
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(KineticsCase, OverridesAndErrors)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    const Case c = src.build({{"I", 0.5}, {"k.k3", 6e9}, {"initial_mg_per_L.PH", 15}});
    EXPECT_DOUBLE_EQ(c.current, 0.5);
    EXPECT_DOUBLE_EQ(c.mech.reactions[2].k, 6e9);
    EXPECT_NEAR(c.initial[c.mech.index("PH", "")], 15e-3 / 94.113, 1e-15);
    EXPECT_THROW(src.build({{"k.k99", 1}}), InputError);
    EXPECT_THROW(src.build({{"nosuch.section", 1}}), InputError);
    EXPECT_THROW(src.build({{"reactor.liquid_volume_L", -1}}), InputError);
}
