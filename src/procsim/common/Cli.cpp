#include "common/Cli.hpp"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

#include "common/Csv.hpp"

namespace procsim
{

bool isHelp(const std::string& arg)
{
    return arg == "-h" || arg == "--help" || arg == "help";
}

namespace
{

std::string escaped(unsigned char byte)
{
    const char* hex = "0123456789abcdef";
    return {'\\', 'x', hex[byte >> 4], hex[byte & 15]};
}

// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF), or 0.
std::size_t utf8Length(const std::string& text, std::size_t i)
{
    const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = at(i);
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xbf; // the range of the second byte
    if (lead >= 0xc2 && lead <= 0xdf)
        n = 2;
    else if (lead >= 0xe0 && lead <= 0xef)
    {
        n = 3;
        if (lead == 0xe0) lo = 0xa0;
        if (lead == 0xed) hi = 0x9f;
    }
    else if (lead >= 0xf0 && lead <= 0xf4)
    {
        n = 4;
        if (lead == 0xf0) lo = 0x90;
        if (lead == 0xf4) hi = 0x8f;
    }
    if (n == 0 || i + n > text.size() || at(i + 1) < lo || at(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
    return n;
}

// U+0080..U+009F (C1 controls, NEL among them), U+2028 and U+2029 break
// lines for some readers (Python's splitlines, a few terminals).
bool breaksLine(const std::string& sequence)
{
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(sequence[k]); };
    if (sequence.size() == 2) return b(0) == 0xc2 && b(1) <= 0x9f;
    return sequence.size() == 3 && b(0) == 0xe2 && b(1) == 0x80 && (b(2) == 0xa8 || b(2) == 0xa9);
}

} // namespace

std::string messageLine(const std::string& text)
{
    std::string line;
    std::size_t i = 0;
    while (i < text.size())
    {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x80)
        {
            if (byte == '\n' || byte == '\r')
                line += ' ';
            else if (byte < 0x20 || byte == 0x7f)
                line += escaped(byte);
            else
                line += text[i];
            ++i;
            continue;
        }
        const std::size_t n = utf8Length(text, i);
        const bool keep = n > 0 && !breaksLine(text.substr(i, n));
        for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k)
            line += keep ? text.substr(i + k, 1) : escaped(static_cast<unsigned char>(text[i + k]));
        i += std::max<std::size_t>(n, 1);
    }
    return line;
}

int runGuarded(int (*run)(int, char**), int argc, char** argv)
{
    const std::string command = argv[0];
    std::string message;
    try
    {
        OutputBatch outputs;
        const int status = run(argc, argv);
        if (status == 0) outputs.commit();
        return status;
    }
    catch (const InputError& e)
    {
        message = e.what();
    }
    catch (const std::bad_alloc&)
    {
        message = command
                  + ": out of memory: the run is too large for this machine (reduce its size or"
                    " duration); no output was written";
    }
    catch (const std::filesystem::filesystem_error& e)
    {
        const std::string p = e.path1().string();
        message = command + ": cannot "
                  + (p.empty() ? "use the output directory" : "create or use '" + p + "'") + ": "
                  + e.code().message();
    }
    catch (const std::exception& e)
    {
        message = command + ": failed: " + e.what();
    }
    std::cerr << "procsim: " << messageLine(message) << '\n';
    return 1;
}

} // namespace procsim
