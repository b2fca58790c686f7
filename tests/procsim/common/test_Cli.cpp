// A message is one line whatever bytes of an input file it echoes: the
// readers that count lines most generously (Python's str.splitlines, which
// also breaks at VT, FF, FS, GS, RS, NEL and U+2028/2029) see one line, and
// a NUL cannot cut it short.
#include <gtest/gtest.h>

#include <string>

#include "common/Cli.hpp"

using procsim::InputError;
using procsim::messageLine;

namespace
{

// every byte printable ASCII: one line for any reader, no terminal control
bool printableAscii(const std::string& text)
{
    for (char ch : text)
        if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) > 0x7e) return false;
    return true;
}

} // namespace

TEST(MessageLine, PlainTextAndUtf8StayAsTheyAre)
{
    EXPECT_EQ(messageLine("case.yaml: key 'a.b' expected a number [m], got 'x'"),
              "case.yaml: key 'a.b' expected a number [m], got 'x'");
    EXPECT_EQ(messageLine("25 \xc2\xb0\x43, 3 \xc2\xb5g/m\xc2\xb3, \xe0\xb8\x81, \xf0\x9f\x98\x80"),
              "25 \xc2\xb0\x43, 3 \xc2\xb5g/m\xc2\xb3, \xe0\xb8\x81, \xf0\x9f\x98\x80");
}

TEST(MessageLine, LineBreaksOfALibraryTextBecomeSpaces)
{
    EXPECT_EQ(messageLine("first\nsecond\r\nthird"), "first second  third");
}

TEST(MessageLine, ControlCharactersAreEscaped)
{
    EXPECT_EQ(messageLine("a\tb\x0b\x0c\x1c\x1d\x1e\x1b[31m\x7f"),
              "a\\x09b\\x0b\\x0c\\x1c\\x1d\\x1e\\x1b[31m\\x7f");
    EXPECT_EQ(messageLine(std::string("a\0b", 3)), "a\\x00b");
}

TEST(MessageLine, LineBreakingCodePointsAreEscaped)
{
    // NEL (U+0085) and another C1 control, the line and paragraph separators
    EXPECT_EQ(messageLine("a\xc2\x85"
                          "b\xc2\x9f"
                          "c\xe2\x80\xa8"
                          "d\xe2\x80\xa9"
                          "e"),
              "a\\xc2\\x85b\\xc2\\x9fc\\xe2\\x80\\xa8d\\xe2\\x80\\xa9e");
    EXPECT_EQ(messageLine("\xc2\xa0\xe2\x80\xa7"), "\xc2\xa0\xe2\x80\xa7"); // their neighbours are text
}

TEST(MessageLine, BytesThatAreNotUtf8AreEscaped)
{
    EXPECT_EQ(messageLine("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(messageLine("\x80x"), "\\x80x");                          // a continuation byte alone
    EXPECT_EQ(messageLine("\xe2\x80"), "\\xe2\\x80");                   // cut short
    EXPECT_EQ(messageLine("\xc0\xaf"), "\\xc0\\xaf");                   // overlong '/'
    EXPECT_EQ(messageLine("\xed\xa0\x80"), "\\xed\\xa0\\x80");          // a surrogate
    EXPECT_EQ(messageLine("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80"); // above U+10FFFF
}

TEST(MessageLine, EveryByteGivesOneLine)
{
    std::string all;
    for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
    const std::string line = messageLine(all);
    for (std::size_t i = 0; i < line.size(); ++i)
    {
        const auto ch = static_cast<unsigned char>(line[i]);
        ASSERT_TRUE(ch >= 0x20 && ch != 0x7f) << "byte " << int(ch) << " at " << i;
    }
    // ASCII only: the bytes 0x80..0xff alone are never UTF-8
    EXPECT_TRUE(printableAscii(line));
}

TEST(MessageLine, InputErrorKeepsTheWholeEscapedMessage)
{
    using namespace std::string_literals;
    const InputError e("data.csv: line 4: got '1\0\x0b"
                       "2'"s);
    EXPECT_STREQ(e.what(), "data.csv: line 4: got '1\\x00\\x0b2'");
}
