#include "common/Cli.hpp"

#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <utility>

#include "common/Checked.hpp"
#include "common/Csv.hpp"

namespace procsim
{

bool isHelp(const std::string& arg)
{
    return arg == "-h" || arg == "--help" || arg == "help";
}

ArgReader::ArgReader(std::string command, int argc, char** argv)
    : command_(std::move(command)), argc_(argc), argv_(argv)
{
}

bool ArgReader::next()
{
    if (++index_ >= argc_) return false;
    arg_ = argv_[index_];
    return true;
}

std::string ArgReader::value()
{
    if (index_ + 1 >= argc_)
    {
        throw InputError(command_ + ": option " + arg_ + " expects a value");
    }
    if (!given_.insert(arg_).second)   // a second value would silently replace the first
    {
        throw InputError(command_ + ": option " + arg_ + " given twice");
    }
    return argv_[++index_];
}

long ArgReader::positiveInteger()
{
    const std::string v = value();
    if (const auto n = parseInteger(v, 1, 2147483647L)) return *n;
    throw InputError(command_ + ": option " + arg_ + " expects a positive integer, got '" + v + "'");
}

double ArgReader::finiteNumber()
{
    const std::string v = value();
    if (const auto x = parseFinite(v)) return *x;
    throw InputError(command_ + ": option " + arg_ + " expects a finite number, got '" + v + "'");
}

InputError ArgReader::unknown(const std::string& helpPath) const
{
    return InputError(command_ + ": unknown option '" + arg_ + "' (see procsim " + helpPath
                      + " --help)");
}

InputError ArgReader::extraPositional() const
{
    return InputError(command_ + ": more than one case file given ('" + arg_ + "')");
}

namespace
{

// One line: a message with line breaks (a library's text) is folded.
std::string oneLine(std::string text)
{
    for (char& ch : text)
    {
        if (ch == '\n' || ch == '\r') ch = ' ';
    }
    return text;
}

} // namespace

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
        message = command + ": out of memory: the run is too large for this machine (reduce its size or"
                            " duration); no output was written";
    }
    catch (const std::filesystem::filesystem_error& e)
    {
        const std::string p = e.path1().string();
        message = command + ": cannot " + (p.empty() ? "use the output directory" : "create or use '" + p + "'")
                  + ": " + e.code().message();
    }
    catch (const std::exception& e)
    {
        message = command + ": failed: " + e.what();
    }
    std::cerr << "procsim: " << oneLine(message) << '\n';
    return 1;
}

} // namespace procsim
