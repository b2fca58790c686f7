// The shipped cases against the kinetics paper's statements (Figs 4-8, the
// Results text, Table S1 as summarised there) and its eqs 18-20.  Each test
// reads a statement at the precision the paper gives it; where the model does
// not meet a statement, the statement is asserted in test_PaperDepartures.cpp
// instead (ctest kinetics.departure.*, explained in the README), never here
// with a looser bound.
#include <gtest/gtest.h>

#include <cmath>

#include "PaperCases.hpp"

using namespace kt;

TEST(KineticsPaper, PhenolTowardZeroWithin3hForEveryFeedAndInitialPhenol)
{
    // Fig 5a: "rapidly decreased toward zero within around 3 h" for 0-200 ppm; Fig 6a: toward
    // zero for 15-50 mg/L.  Read as below a tenth of the initial phenol at 3 h.
    for (double ppm : {0.0, 30.0, 100.0, 200.0})
        EXPECT_LT(base({{"gas.inlet_ppm.AD", ppm}}).value("PH", 3 * hour), 0.1 * 30.0) << ppm << " ppm";
    for (double ph : {15.0, 50.0})
        EXPECT_LT(base({{"initial_mg_per_L.PH", ph}}).value("PH", 3 * hour), 0.1 * ph) << ph << " mg/L";
}

TEST(KineticsPaper, TocAbout4to5mgLAfter8hAt30mgLPhenol)
{
    // Fig 6: "After ca. 8 h, TOC reached a similar concentration of around 4-5 mg/L" (15, 30 and
    // 50 mg/L phenol, 30 ppm, 0.3 mA).  At 30 mg/L the model does; at 15 and 50 mg/L, and for the
    // plateau after 8 h, see the departures.
    const double toc = base().value("TOC", 8 * hour);
    EXPECT_GE(toc, 4.0);
    EXPECT_LE(toc, 5.0);
}

TEST(KineticsPaper, AceticAcidAt10hAbout1mgLAt05mA)
{
    // Fig 8, 30/30: "increasing corona current from 0.1 to 0.5 mA could obviously decrease acetic
    // acid from ca. 7 to 1 mg/L".  1 is read as 0.5-1.5 (half a unit of the quoted digit, the
    // same reading as for the 7, which the model misses: kinetics.departure.acetic_acid_0_1mA).
    const double aa = base({{"I", 0.5}}).value("AA", 10 * hour);
    EXPECT_NEAR(aa, 1.0, halfUnit);
    EXPECT_GT(base({{"I", 0.1}}).value("AA", 10 * hour), 5 * aa); // "obviously decrease"
}

TEST(KineticsPaper, MorePhenolLeavesMoreAceticAcid)
{
    // Fig 8: raising phenol/acetaldehyde from 15/30 to 50/30 leaves more acetic acid at 10 h
    double prev = 0;
    for (double ph : {15.0, 30.0, 50.0})
    {
        const double aa = base({{"initial_mg_per_L.PH", ph}}).value("AA", 10 * hour);
        EXPECT_GT(aa, prev);
        prev = aa;
    }
}

TEST(KineticsPaper, AcetaldehydeFeedDoesNotSlowPhenolButRaisesResidualAcetaldehyde)
{
    // Fig 5: phenol decay the same for 0-200 ppm; higher feed, higher residual aqueous AD
    const Results r0 = base({{"gas.inlet_ppm.AD", 0}});
    const Results r200 = base({{"gas.inlet_ppm.AD", 200}});
    EXPECT_NEAR(r0.value("PH", 3 * hour), r200.value("PH", 3 * hour), 1e-9);
    EXPECT_GT(r200.value("AD", 10 * hour), base().value("AD", 10 * hour));
    // "Influent concentrations of 100 ppm or higher obviously inhibited the TOC degradation"
    for (double ppm : {100.0, 200.0})
        EXPECT_GT(base({{"gas.inlet_ppm.AD", ppm}}).value("TOC", 8 * hour), base().value("TOC", 8 * hour))
            << ppm;
}

TEST(KineticsPaper, HigherCurrentFasterPhenolAndTocRemovalTocSlowerThanPhenol)
{
    // Fig 4 (15 ppm): increasing I increases phenol and TOC decomposition rates; "degradation rate
    // of TOC was relatively slow compared with that of phenol"
    double prevPh = 1e9, prevToc = 1e9;
    for (double i : {0.1, 0.3, 0.5})
    {
        const Results r = runShipped("fig4_current.yaml", {{"I", i}});
        EXPECT_LT(r.value("PH", 2 * hour), prevPh);
        EXPECT_LT(r.value("TOC", 6 * hour), prevToc);
        prevPh = r.value("PH", 2 * hour);
        prevToc = r.value("TOC", 6 * hour);
        const double phLeft = r.value("PH", 2 * hour) / r.value("PH", 0.0);
        const double tocLeft = r.value("TOC", 2 * hour) / r.value("TOC", 0.0);
        EXPECT_LT(phLeft, tocLeft) << i << " mA";
    }
}

TEST(KineticsPaper, Fig7CatecholMajorHydroquinoneGoneBy300MinAceticAcidTheMajorStableProduct)
{
    // Fig 7 (15 mg/L, 30 ppm, 0.3 mA): "catechol was a major species, whereas hydroquinone and
    // resorcinol were minor"; all three "completely mineralized after about 300 min" (hydroquinone
    // here; catechol and resorcinol are departures).
    const Results r = runShipped("fig7_intermediates.yaml");
    const double cc = peak(r, "CC");
    EXPECT_GT(cc, 2 * peak(r, "HQ"));
    EXPECT_GT(cc, 2 * peak(r, "RC"));
    EXPECT_LT(r.value("HQ", 300 * minute), goneFractionOfPeak * peak(r, "HQ"));
    // "acetic acid was considered as the major stable intermediate": the largest single share of
    // TOC at 7 h (the 75 % the text gives is a departure)
    const double t = 7 * hour;
    auto carbon = [&](const char* s, double mw, double nc) {
        return r.value(s, t) / mw * nc * carbonMolarMass;
    };
    const double aa = carbon("AA", 60.052, 2);
    for (const double other : {carbon("UP_C6", 108.096, 6), carbon("CC", 110.112, 6), carbon("PH", 94.113, 6),
                               carbon("AD", 44.053, 2), carbon("UP_C1", 46.025, 1)})
        EXPECT_GT(aa, other);
}

TEST(KineticsPaper, SensitivityTableS1)
{
    // Table S1 as summarised in the text (+-10 % on k1, k2, k3, k4, k8, k12): phenol deviates by
    // ca. +-6 % with k8; acetaldehyde by ca. +-5-6 % with k1 and +-4-4.5 % with k2; k3 has the
    // largest effect on acetic acid (its -13 % is a departure: kinetics.departure.sensitivity_aa_k3),
    // while k1, k2, k4, k8 and k12 "contributed to less than 2 %" (k12 does not here:
    // kinetics.departure.sensitivity_aa_k12).  The paper does not say at which time; evaluated
    // at the end of the 10 h runs, hence a point either side.
    const CaseSource src = CaseSource::load(casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    const auto rows =
        sensitivity(src, {}, {"k1", "k2", "k3", "k4", "k8", "k12"}, {"PH", "AD", "AA"}, 10 * hour, 0.1);
    auto dev = [&](const std::string& k, const std::string& out, double change) {
        for (const auto& r : rows)
            if (r.parameter == k && r.output == out && r.change == change) return r.deviation;
        ADD_FAILURE() << k << " " << out;
        return 0.0;
    };
    for (double c : {0.1, -0.1})
    {
        EXPECT_NEAR(std::fabs(dev("k8", "PH", c)), 0.06, 0.01);
        EXPECT_NEAR(std::fabs(dev("k1", "AD", c)), 0.055, 0.01);
        EXPECT_NEAR(std::fabs(dev("k2", "AD", c)), 0.0425, 0.01);
        EXPECT_LT(dev("k3", "AA", c) * c, 0.0); // faster acetic acid oxidation, less acetic acid
        for (const char* k : {"k1", "k2", "k4", "k8", "k12"})
            EXPECT_GT(std::fabs(dev("k3", "AA", c)), std::fabs(dev(k, "AA", c))) << k;
        for (const char* k : {"k1", "k2", "k4", "k8"}) EXPECT_LT(std::fabs(dev(k, "AA", c)), 0.02) << k;
        // phenol is untouched by the acetaldehyde branch and by its products' constants
        for (const char* k : {"k1", "k2", "k3", "k4", "k12"}) EXPECT_EQ(dev(k, "PH", c), 0.0) << k;
    }
}

TEST(KineticsPaper, EnergeticEfficienciesFollowEqs18to20)
{
    const Results r = base();
    const Efficiency e = efficiency(r);
    ASSERT_TRUE(e.halfReached);
    // definition of t_1/2: TOC with discharge = half of TOC without discharge
    const double t = e.tHalf;
    const double w = 1.0, cp = 30.0, cin = 30.0, i = 0.3, v = 10.0;     // L, mg/L, ppm, mA, kV
    const double qg = 101.3e3 * 100e-6 / 60.0 / (gasConstant * 298.15); // mol/s
    const double mc = carbonMolarMass, ma = 44.053, mp = 94.113;
    const double rcp = 6 * mc / mp, rca = 2 * mc / ma;
    const double tocNoDischarge = cp * rcp + qg * cin * 1e-6 * ma * rca * t * 1000.0 / w; // mg C/L
    EXPECT_NEAR(r.value("TOC", t), 0.5 * tocNoDischarge, 0.02);
    // eq 18 as printed, with I V in W (mA x kV)
    const double jToc = (w * (cp / 1000) * rcp + qg * cin * 1e-6 * ma * rca * t) / (2 * mc) / (i * v * t);
    const double jP = w * (cp / 1000) / (2 * mp) / (i * v * t); // eq 19
    const double jA = qg * cin * 1e-6 / (i * v);                // eq 20
    EXPECT_NEAR(e.jToc, jToc, 1e-9 * jToc);
    ASSERT_EQ(e.jLiquid.size(), 1u);
    EXPECT_NEAR(e.jLiquid[0].second, jP, 1e-9 * jP);
    ASSERT_EQ(e.jGas.size(), 1u);
    EXPECT_NEAR(e.jGas[0].second, jA, 1e-9 * jA);
}
