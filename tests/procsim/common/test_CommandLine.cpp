// The command-line layer every procsim subcommand shares: each mistake gets
// the one line the header promises, and good command lines read as meant.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "common/CommandLine.hpp"

using procsim::CommandLine;
using procsim::InputError;

namespace
{

// argv from words; argv[0] is the subcommand, as procsim passes it
struct Argv
{
    explicit Argv(std::vector<std::string> w) : words(std::move(w))
    {
        for (auto& s : words) ptrs.push_back(s.data());
    }
    int argc() { return static_cast<int>(ptrs.size()); }
    char** argv() { return ptrs.data(); }
    std::vector<std::string> words;
    std::vector<char*> ptrs;
};

// A command like `procsim dryer simulate PLANT [--batch ID] [--out DIR] ...`
struct Simulate
{
    std::string plant, out = ".";
    std::optional<std::string> batch;
    std::optional<double> t;
    std::optional<long> years;
    std::vector<std::string> sweeps;
    bool quiet = false;
    CommandLine cl{"dryer simulate", "usage: procsim dryer simulate PLANT.yaml\n"};

    Simulate()
    {
        cl.input(plant, "plant file");
        cl.text("-o,--out", out);
        cl.text("--batch", batch);
        cl.number("--t", t);
        cl.integer("--years", years, 1, 100000);
        cl.list("--sweep", sweeps);
        cl.flag("-q,--quiet", quiet);
    }
    bool parse(std::vector<std::string> words)
    {
        words.insert(words.begin(), "simulate");
        Argv a(words);
        return cl.parse(a.argc(), a.argv());
    }
};

std::string errorOf(std::vector<std::string> words)
{
    Simulate s;
    try
    {
        s.parse(std::move(words));
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "(no error)";
}

} // namespace

TEST(CommandLine, ReadsOptionsInputAndDefaults)
{
    Simulate s;
    ASSERT_TRUE(
        s.parse({"plant.yaml", "--batch", "3", "--t=-5.5", "--sweep", "I=1", "--sweep", "V=2", "-q"}));
    EXPECT_EQ(s.plant, "plant.yaml");
    EXPECT_EQ(s.out, "."); // not given: the default stays
    EXPECT_EQ(s.batch.value_or("none"), "3");
    EXPECT_EQ(s.t.value_or(0), -5.5);
    EXPECT_FALSE(s.years.has_value());
    EXPECT_EQ(s.sweeps, (std::vector<std::string>{"I=1", "V=2"}));
    EXPECT_TRUE(s.quiet);
}

TEST(CommandLine, NegativeNumberIsAValueNotAnOption)
{
    Simulate s;
    ASSERT_TRUE(s.parse({"plant.yaml", "--t", "-40"}));
    EXPECT_EQ(s.t.value_or(0), -40);
}

TEST(CommandLine, AnEmptyValueIsStillGiven)
{
    Simulate s;
    ASSERT_TRUE(s.parse({"plant.yaml", "--batch", ""}));
    EXPECT_EQ(s.batch.value_or("none"), "");
}

TEST(CommandLine, HelpAnywhereIsPrintedAndEndsTheCommand)
{
    Simulate s;
    testing::internal::CaptureStdout();
    EXPECT_FALSE(s.parse({"plant.yaml", "--bogus", "--help"}));
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "usage: procsim dryer simulate PLANT.yaml\n");
}

TEST(CommandLine, OptionGivenTwiceIsRefused)
{
    EXPECT_EQ(errorOf({"p.yaml", "--batch", "1", "--batch", "2"}),
              "dryer simulate: option --batch given twice");
    EXPECT_EQ(errorOf({"p.yaml", "-o", "a", "--out", "b"}), "dryer simulate: option --out given twice");
    EXPECT_EQ(errorOf({"p.yaml", "--out", "a", "-o", "b"}), "dryer simulate: option -o given twice");
    EXPECT_EQ(errorOf({"p.yaml", "-q", "--quiet"}), "dryer simulate: option --quiet given twice");
}

TEST(CommandLine, UnknownOptionIsNamedWithWhereToLook)
{
    EXPECT_EQ(errorOf({"p.yaml", "--bogus"}),
              "dryer simulate: unknown option '--bogus' (see procsim dryer simulate --help)");
    EXPECT_EQ(errorOf({"--bogus", "x", "p.yaml"}),
              "dryer simulate: unknown option '--bogus' (see procsim dryer simulate --help)");
}

TEST(CommandLine, InputFileMissingOrTwice)
{
    EXPECT_EQ(errorOf({"--batch", "1"}),
              "dryer simulate: expected one plant file (see procsim dryer simulate --help)");
    EXPECT_EQ(errorOf({"a.yaml", "b.yaml"}), "dryer simulate: more than one plant file given ('b.yaml')");
}

TEST(CommandLine, OptionWithoutValue)
{
    EXPECT_EQ(errorOf({"p.yaml", "--out"}), "dryer simulate: option --out expects a value");
}

TEST(CommandLine, NumbersFollowTheInputRules)
{
    for (const std::string bad : {"inf", "nan", "1e400", "12.5abc", "abc", ""})
        EXPECT_EQ(errorOf({"p.yaml", "--t", bad}),
                  "dryer simulate: option --t expected a finite number, got '" + bad + "'");
    EXPECT_EQ(errorOf({"p.yaml", "--years", "0"}),
              "dryer simulate: option --years expected an integer from 1 to 100000, got '0'");
    EXPECT_EQ(errorOf({"p.yaml", "--years", "2.5"}),
              "dryer simulate: option --years expected an integer from 1 to 100000, got '2.5'");
    EXPECT_EQ(errorOf({"p.yaml", "--years", "100001"}),
              "dryer simulate: option --years expected an integer from 1 to 100000, got '100001'");
}

TEST(CommandLine, RefuseNamesCommandOptionAndValue)
{
    Simulate s;
    EXPECT_STREQ(s.cl.refuse("--t", "a dry bulb from -100 to 200 degC", "250").what(),
                 "dryer simulate: option --t expected a dry bulb from -100 to 200 degC, got '250'");
}
