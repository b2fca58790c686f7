// The shared input rules every procsim command relies on: the one number
// reader, step counts, names that become file names, and outputs that are put
// in place only when the command succeeds.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "TestUtil.hpp"
#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "common/YamlInput.hpp"

using namespace procsim;

namespace
{

std::string contents(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

TEST(InputChecks, NumbersAreFiniteAndFillTheWholeText)
{
    EXPECT_EQ(parseFinite("12.5"), 12.5);
    EXPECT_EQ(parseFinite(" -3e2 "), -300.0);
    EXPECT_EQ(parseFinite("1e-400"), 0.0); // underflow is a number
    for (const char* bad :
         {"12.5abc", "", " ", "inf", "-inf", ".inf", "nan", ".nan", "NaN", "1e400", "abc", "1,5"})
        EXPECT_FALSE(parseFinite(bad)) << bad;
    EXPECT_EQ(parseInteger("42", 1, 100), 42L);
    for (const char* bad : {"0", "101", "4.0", "4x", "99999999999999999999999", ""})
        EXPECT_FALSE(parseInteger(bad, 1, 100)) << bad;
}

TEST(InputChecks, YamlNumbersGoThroughTheCheckedReader)
{
    const std::string f =
        kt::writeFile("checks.yaml", "a: .inf\nb: 1e308\nc: 3abc\nd: 5\nlist: [1, .nan]\nn: 2147483648\n");
    const YamlInput in = YamlInput::load(f);
    EXPECT_THROW(in.number("a"), InputError);
    EXPECT_EQ(in.number("b"), 1e308);
    EXPECT_THROW(in.within("b", 0, 1e9), InputError);
    EXPECT_THROW(in.number("c"), InputError);
    EXPECT_EQ(in.within("d", 0, 10), 5.0);
    EXPECT_THROW(in.numbers("list"), InputError);
    EXPECT_THROW(in.integer("n"), InputError); // beyond int
    try
    {
        in.number("a", "h");
        FAIL();
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(std::string(e.what()), f + ": key 'a' expected a finite number [h], got '.inf'");
    }
}

TEST(InputChecks, DuplicateYamlKeysAreRefusedAtAnyDepth)
{
    EXPECT_THROW(YamlInput::load(kt::writeFile("dup1.yaml", "a: 1\na: 2\n")), InputError);
    EXPECT_THROW(YamlInput::load(kt::writeFile("dup2.yaml", "s:\n  - {x: 1, x: 2}\n")), InputError);
    EXPECT_NO_THROW(YamlInput::load(kt::writeFile("dup3.yaml", "s:\n  - {x: 1}\n  - {x: 2}\n")));
}

TEST(InputChecks, CsvCellsAreCheckedAndMissingOnlyWhereAllowed)
{
    const std::string f = kt::writeFile("cells.csv", "t,v\n1,2\n2,nan\n");
    EXPECT_THROW(readCsv(f), InputError);
    EXPECT_TRUE(std::isnan(readCsv(f, true).rows[1][1]));
    EXPECT_THROW(readCsv(kt::writeFile("trail.csv", "t,v\n1,12.5abc\n"), true), InputError);
    EXPECT_THROW(readCsv(kt::writeFile("dupcol.csv", "t,t\n1,2\n")), InputError);
}

TEST(InputChecks, StepCountsAreCountedInDoubleAndCapped)
{
    EXPECT_EQ(stepCount(3600, 10, 1000, "w", "an hour", "hint"), 360L);
    EXPECT_EQ(stepCount(3600, 7200, 1000, "w", "an hour", "hint"), 1L);
    try
    {
        stepCount(3600, 1e-7, 10000000, "case.yaml: key 'time.dt_s'", "an hour", "use a larger dt_s");
        FAIL();
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(
            std::string(e.what()),
            "case.yaml: key 'time.dt_s': an hour needs about 3.6e+10 steps (limit 10000000); use a larger dt_s");
    }
}

TEST(InputChecks, NamesThatBecomeFileNames)
{
    EXPECT_NO_THROW(checkFileNamePart("R1_north-2", "w"));
    for (const char* bad : {"", ".", "..", "a/b", "a\\b", "a\nb"})
        EXPECT_THROW(checkFileNamePart(bad, "w"), InputError) << bad;
    EXPECT_THROW(rejectDuplicates(std::vector<std::string>{"a", "b", "a"}, "w", "name"), InputError);
}

TEST(InputChecks, OutputsOfAFailedBatchLeaveTheEarlierFiles)
{
    const std::string path = kt::scratchDir() + "/staged.csv";
    writeTextFile(path, "earlier\n"); // no batch: in place at once
    EXPECT_EQ(contents(path), "earlier\n");
    {
        OutputBatch batch;
        CsvWriter w(path, {"x"});
        w.row(std::vector<double>{1});
        w.close();
        EXPECT_EQ(contents(path), "earlier\n"); // staged, not yet in place
    }                                           // no commit: the run failed
    EXPECT_EQ(contents(path), "earlier\n");
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    {
        OutputBatch batch;
        CsvWriter w(path, {"x"});
        w.row(std::vector<double>{2});
        w.close();
        batch.commit();
    }
    EXPECT_EQ(contents(path), "x\n2\n");
}

TEST(InputChecks, OneRunCannotWriteAFileTwiceOrAnInfinity)
{
    const std::string path = kt::scratchDir() + "/twice.csv";
    OutputBatch batch;
    writeTextFile(path, "a\n");
    EXPECT_THROW(writeTextFile(path, "b\n"), InputError);
    CsvWriter w(kt::scratchDir() + "/inf.csv", {"x"});
    EXPECT_THROW(w.row(std::vector<double>{INFINITY}), InputError);
}
