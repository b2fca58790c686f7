// What the files contain: unit conversions, TOC from carbon counts, the carbon
// columns, and the sweep table.
#include <gtest/gtest.h>

#include <cmath>

#include "TestUtil.hpp"
#include "common/Csv.hpp"
#include "kinetics/Run.hpp"
#include "kinetics/Study.hpp"

using namespace procsim;
using namespace procsim::kinetics;

TEST(KineticsOutputs, TimeseriesColumnsAreConsistent)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    const Results r = runCase(src.build());
    const std::string dir = kt::scratchDir() + "/outputs_run";
    writeRun(r, efficiency(r), dir, false);
    const CsvTable t = readCsv(dir + "/timeseries.csv");
    const std::string f = dir + "/timeseries.csv";
    ASSERT_EQ(t.rows.size(), 121u); // 10 h every 5 min, both ends
    const auto& sp = r.cas.mech.species;
    for (const auto& row : t.rows)
    {
        double tocFromColumns = 0, co2 = 0;
        for (const auto& s : sp)
        {
            const double mg = row[t.column(s.name + "_mg_per_L", f)];
            const double mol = row[t.column(s.name + "_mol_per_L", f)];
            EXPECT_NEAR(mg, mol * s.molarMass * 1000.0, 1e-8 * std::max(mg, 1e-12));
            if (s.organic)
                tocFromColumns += mol * s.carbon * 12.011 * 1000.0;
            else
                co2 += mol * s.carbon * 1.0; // 1 L
        }
        EXPECT_NEAR(row[t.column("TOC_mgC_per_L", f)], tocFromColumns, 1e-8 * tocFromColumns);
        EXPECT_NEAR(row[t.column("CO2_formed_mol", f)], co2, 1e-8 * std::max(co2, 1e-12));
        EXPECT_LT(row[t.column("carbon_balance_rel_error", f)], 1e-11); // round-off, see test_Solvers
    }
    // initial TOC: 30 mg/L phenol is 30 * 72.066 / 94.113 mg C/L
    EXPECT_NEAR(t.rows.front()[t.column("TOC_mgC_per_L", f)], 30.0 * 6 * 12.011 / 94.113, 1e-9);
}

TEST(KineticsOutputs, SweepTableHasOneRowPerCombination)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    const std::string dir = kt::scratchDir() + "/outputs_sweep";
    const auto runs =
        runSweep(src, {}, {{"initial_mg_per_L.PH", {15, 50}}, {"corona.current_mA", {0.1, 0.3, 0.5}}}, dir,
                 false, true, "");
    ASSERT_EQ(runs.size(), 6u);
    const CsvTable t = readCsv(dir + "/sweep_summary.csv", true); // nan: half time not reached
    ASSERT_EQ(t.rows.size(), 6u);
    EXPECT_EQ(t.header[0], "PH0_mg_per_L");
    EXPECT_EQ(t.header[1], "current_mA");
    EXPECT_DOUBLE_EQ(t.rows[4][0], 50);
    EXPECT_DOUBLE_EQ(t.rows[4][1], 0.3);
    // each run really used its values: initial TOC scales with phenol
    EXPECT_NEAR(runs[4].results.toc.front() / runs[1].results.toc.front(), 50.0 / 15.0, 1e-12);
    EXPECT_DOUBLE_EQ(runs[5].results.cas.current, 0.5);
}
