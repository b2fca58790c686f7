#include "common/Cli.hpp"

#include <exception>
#include <iostream>

namespace procsim
{

bool isHelp(const std::string& arg)
{
    return arg == "-h" || arg == "--help" || arg == "help";
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
