// The kinetics paper's statements that the model, with Table 1's constants
// and the pseudo-steady [OH] of Fig 3, does not meet: documented departures
// (README, "Departures from the paper's statements").  Each test asserts the
// paper's reading, at the same precision as the statements the model meets
// (test_PaperTargets.cpp), and fails today.  The failure message starts with
// "DEPARTURE <name>:" and gives the paper's and the model's value; ctest's
// kinetics.departure.<name> passes only on that message, so the departure is
// reported on every run, a crash or a missing case cannot pass for it, and a
// model that comes to meet the statement fails the ctest until the statement
// moves to test_PaperTargets.cpp and the README is updated.  The model's
// value must also stay the one the README documents (to 1 %, its figures
// have three digits): a change prints "DRIFT <name>:", which fails the ctest
// too, so a departure cannot grow unnoticed.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <iomanip>
#include <sstream>
#include <string>

#include "PaperCases.hpp"

using namespace kt;

namespace
{

// documented: the model's value in the README's table of departures
void expectPaper(const char* name, const char* statement, double model, double lo, double hi,
                 const char* unit, double documented)
{
    std::ostringstream m;
    m << std::setprecision(3) << "DEPARTURE " << name << ": " << statement << ": paper " << lo << " to " << hi
      << unit << ", model " << model << unit;
    EXPECT_TRUE(model >= lo && model <= hi) << m.str();
    std::ostringstream d;
    d << std::setprecision(3) << "DRIFT " << name << ": the model gives " << model << unit
      << ", the README documents " << documented << unit;
    EXPECT_NEAR(model, documented, 0.01 * std::fabs(documented)) << d.str();
}

double sensitivityAt10h(const char* k, const char* output, double change)
{
    const CaseSource src = CaseSource::load(casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    for (const auto& r : sensitivity(src, {}, {k}, {output}, 10 * hour, 0.1))
        if (r.change == change) return r.deviation;
    ADD_FAILURE() << k << " " << output;
    return 0.0;
}

} // namespace

// Fig 7: "completely mineralized after about 300 min".  Catechol is formed while phenol lasts
// (1/((k5 + k6 + k7 + k8) [OH]) = 70 min) and decays with 1/(k9 [OH]) = 98 min.
TEST(KineticsDeparture, CatecholGoneBy300Min)
{
    const Results r = runShipped("fig7_intermediates.yaml");
    expectPaper("catechol_300min", "catechol at 300 min, fraction of its peak (Fig 7)",
                r.value("CC", 300 * minute) / peak(r, "CC"), 0.0, goneFractionOfPeak, "", 0.266);
}

// Fig 7, as above; resorcinol decays with 1/(k11 [OH]) = 108 min.
TEST(KineticsDeparture, ResorcinolGoneBy300Min)
{
    const Results r = runShipped("fig7_intermediates.yaml");
    expectPaper("resorcinol_300min", "resorcinol at 300 min, fraction of its peak (Fig 7)",
                r.value("RC", 300 * minute) / peak(r, "RC"), 0.0, goneFractionOfPeak, "", 0.303);
}

// Fig 7 text: "After ca. 7 h of treatment, acetic acid occupied approximately 75 % of the TOC"
// (read as 70-80 %).
TEST(KineticsDeparture, AceticAcidShareOfTocAt7h)
{
    expectPaper("acetic_share", "acetic acid share of TOC at 7 h (Fig 7)",
                aceticShareOfToc(runShipped("fig7_intermediates.yaml"), 7 * hour), 0.70, 0.80, "", 0.475);
}

// Fig 6: TOC at 8 h "around 4-5 mg/L" for every initial phenol from 15 to 50 mg/L.
TEST(KineticsDeparture, TocAt8hFor15mgLPhenol)
{
    expectPaper("toc_8h_15mgL", "TOC at 8 h, 15 mg/L phenol (Fig 6)",
                base({{"initial_mg_per_L.PH", 15}}).value("TOC", 8 * hour), 4.0, 5.0, " mg C/L", 2.67);
}

// As above; the paper notes that its own model underestimates the decomposition at 50 mg/L.
TEST(KineticsDeparture, TocAt8hFor50mgLPhenol)
{
    expectPaper("toc_8h_50mgL", "TOC at 8 h, 50 mg/L phenol (Fig 6)",
                base({{"initial_mg_per_L.PH", 50}}).value("TOC", 8 * hour), 4.0, 5.0, " mg C/L", 7.28);
}

// Fig 6: after 8 h TOC "remained essentially constant" at 4-5 mg/L: read as still 4-5 at 10 h.
TEST(KineticsDeparture, TocPlateauAfter8h)
{
    expectPaper("toc_plateau", "TOC at 10 h, 30 mg/L phenol (Fig 6)", base().value("TOC", 10 * hour), 4.0,
                5.0, " mg C/L", 2.95);
}

// Fig 5b: aqueous acetaldehyde "initially increased in the early stage for all runs.
// Subsequently, aqueous acetaldehyde gradually decreased": read as ending at least 5 % below its
// maximum, in every run with a feed.
TEST(KineticsDeparture, AqueousAcetaldehydeRisesThenFalls)
{
    double worst = 0;
    for (double ppm : {30.0, 100.0, 200.0})
    {
        const Results r = base({{"gas.inlet_ppm.AD", ppm}});
        worst = std::max(worst, r.value("AD", 10 * hour) / peak(r, "AD"));
    }
    expectPaper("acetaldehyde_falls",
                "aqueous acetaldehyde at 10 h, fraction of its maximum, 30-200 ppm (Fig 5b)", worst, 0.0,
                0.95, "", 1.0);
}

// Fig 8, 30/30: acetic acid at 10 h "ca. 7" mg/L at 0.1 mA (read as 6.5-7.5).
TEST(KineticsDeparture, AceticAcidAt10hAt01mA)
{
    expectPaper("acetic_acid_0_1mA", "acetic acid at 10 h, 0.1 mA, 30 mg/L / 30 ppm (Fig 8)",
                base({{"I", 0.1}}).value("AA", 10 * hour), 7.0 - halfUnit, 7.0 + halfUnit, " mg/L", 7.63);
}

// Table S1 as summarised: "k3 had the highest effect on the acetic acid at -13 % deviation"
// (for +10 %; a point either side, as for the statements the model meets).
TEST(KineticsDeparture, SensitivityOfAceticAcidToK3)
{
    expectPaper("sensitivity_aa_k3", "acetic acid deviation at 10 h for k3 +10 % (Table S1)",
                sensitivityAt10h("k3", "AA", 0.1), -0.14, -0.12, "", -0.115);
}

// Table S1: k1, k2, k4, k8 and k12 "contributed to less than 2 % in deviation" of acetic acid.
TEST(KineticsDeparture, SensitivityOfAceticAcidToK12)
{
    const double worst = std::max(std::fabs(sensitivityAt10h("k12", "AA", 0.1)),
                                  std::fabs(sensitivityAt10h("k12", "AA", -0.1)));
    expectPaper("sensitivity_aa_k12", "largest acetic acid deviation at 10 h for k12 +-10 % (Table S1)",
                worst, 0.0, 0.02, "", 0.0300);
}

// Table S1: "k4 was found to be sensitive to TOC at maximum at ca. -5 %".
TEST(KineticsDeparture, SensitivityOfTocToK4)
{
    expectPaper("sensitivity_toc_k4", "TOC deviation at 10 h for k4 +10 % (Table S1)",
                sensitivityAt10h("k4", "TOC", 0.1), -0.06, -0.04, "", -0.00232);
}
