// procsim: process models from the source papers, one subcommand each.
#include <cstring>
#include <iostream>
#include <string>

#include "common/Cli.hpp"

#ifdef PROCSIM_WITH_KINETICS
#include "kinetics/Main.hpp"
#endif
#ifdef PROCSIM_WITH_DRYER
#include "dryer/Main.hpp"
#endif
#ifdef PROCSIM_WITH_PLUME
#include "plume/Main.hpp"
#endif

namespace
{

struct Command
{
    const char* name;
    const char* summary;
    int (*run)(int, char**);
};

const Command commands[] = {
#ifdef PROCSIM_WITH_KINETICS
    {"kinetics", "wetted-wall corona reactor kinetics (phenol/acetaldehyde), fitting, corona formulas",
     procsim::kinetics::main},
#endif
#ifdef PROCSIM_WITH_DRYER
    {"dryer", "batch hot-air tray dryer: energy metrics, batch simulation, what-if studies",
     procsim::dryer::main},
#endif
#ifdef PROCSIM_WITH_PLUME
    {"plume", "PM10 dispersion: Eulerian over terrain, Gaussian plume, Monte Carlo meteorology",
     procsim::plume::main},
#endif
};

void usage(std::ostream& os)
{
    os << "usage: procsim <command> [options]   (procsim <command> --help)\n\n"
          "Process models of the SpoutLab source papers. Inputs are YAML,\n"
          "results CSV and PNG.\n\ncommands:\n";
    for (const auto& c : commands)
    {
        os << "  " << c.name << std::string(12 - std::strlen(c.name), ' ') << c.summary << '\n';
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || procsim::isHelp(argv[1]))
    {
        usage(std::cout);
        return argc < 2 ? 2 : 0;
    }
    for (const auto& c : commands)
    {
        if (argv[1] == std::string(c.name))
        {
            return procsim::runGuarded(c.run, argc - 1, argv + 1);
        }
    }
    std::cerr << "procsim: unknown command '" << argv[1] << "' (see procsim --help)\n";
    return 2;
}
