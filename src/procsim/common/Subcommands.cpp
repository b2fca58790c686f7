#include "common/Subcommands.hpp"

#include <iostream>

#include "common/Cli.hpp"

namespace procsim
{

int runSubcommand(const std::string& command, std::string_view usage, const std::vector<Subcommand>& table,
                  int argc, char** argv, const std::string& noun)
{
    if (argc < 2 || isHelp(argv[1]))
    {
        std::cout << usage;
        return argc < 2 ? 2 : 0;
    }
    for (const auto& s : table)
    {
        if (s.name == argv[1]) return s.run(argc - 1, argv + 1);
    }
    const std::string path = command.empty() ? "procsim" : "procsim " + command;
    throw InputError((command.empty() ? "" : command + ": ") + "unknown " + noun + " '" + argv[1] + "' (see "
                     + path + " --help)");
}

} // namespace procsim
