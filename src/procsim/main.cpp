// procsim: process models from the source papers, one subcommand each.
#include <iostream>
#include <string>
#include <vector>

#include "Texts.hpp"
#include "common/Cli.hpp"
#include "common/Subcommands.hpp"

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

struct Model
{
    const char* name;
    const char* summary; // one line of procsim --help
    int (*main)(int, char**);
};

// the models this build has (each directory of src/procsim is optional)
const Model models[] = {
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

} // namespace

int main(int argc, char** argv)
{
    std::string usage(procsim::texts::help::procsim);
    std::vector<procsim::Subcommand> table;
    for (const auto& m : models)
    {
        usage +=
            "  " + std::string(m.name) + std::string(12 - std::string(m.name).size(), ' ') + m.summary + '\n';
        // each model runs guarded: one line for bad input, outputs only on success
        table.push_back({m.name, [&m](int c, char** v) { return procsim::runGuarded(m.main, c, v); }});
    }
    try
    {
        return procsim::runSubcommand("", usage, table, argc, argv);
    }
    catch (const procsim::InputError& e)
    {
        std::cerr << "procsim: " << procsim::messageLine(e.what()) << '\n';
        return 2;
    }
}
