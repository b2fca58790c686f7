#include "common/Cli.hpp"

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
    std::cerr << "procsim: " << oneLine(message) << '\n';
    return 1;
}

} // namespace procsim
