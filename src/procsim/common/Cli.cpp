#include "common/Cli.hpp"

#include <exception>
#include <iostream>
#include <utility>

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
    return argv_[++index_];
}

long ArgReader::positiveInteger()
{
    const std::string v = value();
    try
    {
        std::size_t pos = 0;
        const long n = std::stol(v, &pos);
        if (n > 0 && pos == v.size()) return n;
    }
    catch (const std::exception&)
    {
    }
    throw InputError(command_ + ": option " + arg_ + " expects a positive integer, got '" + v + "'");
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

int runGuarded(int (*run)(int, char**), int argc, char** argv)
{
    try
    {
        return run(argc, argv);
    }
    catch (const InputError& e)
    {
        std::cerr << "procsim: " << e.what() << '\n';
    }
    catch (const std::exception& e)
    {
        std::cerr << "procsim: " << argv[0] << ": " << e.what() << '\n';
    }
    return 1;
}

} // namespace procsim
