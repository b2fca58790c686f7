#include "InputError.hpp"
#include "Parameters.hpp"

#include <gtest/gtest.h>

#include <string>

using spoutlab::InputError;
using spoutlab::Parameters;

namespace
{

// The message of the InputError thrown by f, or "" if none was thrown.
template <class F>
std::string inputErrorOf(F f)
{
    try
    {
        f();
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Parameters, ReadsScalarsWordsAndDefaults)
{
    Parameters p("couplingProperties/GidaspowProps");
    p.set("epsilonSwitch", "0.75").set("switch", "smooth").set("n", "4");
    EXPECT_TRUE(p.has("switch"));
    EXPECT_FALSE(p.has("other"));
    EXPECT_DOUBLE_EQ(p.getScalar("epsilonSwitch"), 0.75);
    EXPECT_DOUBLE_EQ(p.getScalar("absent", 2.5), 2.5);
    EXPECT_EQ(p.getWord("switch"), "smooth");
    EXPECT_EQ(p.getWord("absent", "sharp"), "sharp");
    EXPECT_EQ(p.getInteger("n"), 4);
    EXPECT_EQ(p.getInteger("absent", 7), 7);
    EXPECT_DOUBLE_EQ(Parameters().set("x", "1e-3").getScalar("x"), 1e-3);
}

TEST(Parameters, NonNumberGivesOneLineErrorNamingContextAndKey)
{
    Parameters p("couplingProperties/GidaspowProps");
    p.set("epsilonSwitch", "abc");
    const std::string msg = inputErrorOf([&] { p.getScalar("epsilonSwitch"); });
    EXPECT_EQ(msg, "couplingProperties/GidaspowProps: key 'epsilonSwitch' expected a number, got 'abc'");
    // A default does not hide a bad value that is present.
    EXPECT_FALSE(inputErrorOf([&] { p.getScalar("epsilonSwitch", 0.8); }).empty());
}

TEST(Parameters, MissingKeyGivesOneLineError)
{
    Parameters p("couplingProperties");
    const std::string msg = inputErrorOf([&] { p.getScalar("voidFractionMin"); });
    EXPECT_EQ(msg, "couplingProperties: key 'voidFractionMin' is missing (expected a number)");
    EXPECT_EQ(msg.find('\n'), std::string::npos);
    EXPECT_NE(inputErrorOf([&] { p.getWord("dragModel"); }).find("'dragModel' is missing"),
              std::string::npos);
}

TEST(Parameters, RejectsPartialNumbersNonFiniteAndNonIntegers)
{
    Parameters p("ctx");
    p.set("a", "1.5m").set("b", "").set("c", "inf").set("d", "nan").set("e", "2.5").set("w", "two words");
    for (const char* key : {"a", "b", "c", "d"})
    {
        EXPECT_NE(inputErrorOf([&] { p.getScalar(key); }).find(std::string("'") + key + "'"),
                  std::string::npos)
            << key;
    }
    EXPECT_NE(inputErrorOf([&] { p.getInteger("e"); }).find("expected an integer, got '2.5'"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([&] { p.getWord("w"); }).find("expected a word"), std::string::npos);
}

TEST(Parameters, InputErrorIsARuntimeError)
{
    EXPECT_THROW(Parameters("ctx").getScalar("x"), std::runtime_error);
}
