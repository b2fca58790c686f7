// procsim kinetics: the wetted-wall corona reactor's liquid-phase kinetics
// for any mass-action mechanism: runs and sweeps, sensitivity, fitting, and
// the corona papers' gas-side formulas.
#include "kinetics/Main.hpp"

#include <iostream>
#include <vector>

#include "common/Subcommands.hpp"
#include "kinetics/Commands.hpp"
#include "kinetics/Texts.hpp"

namespace procsim::kinetics
{

namespace
{

int formatCommand(int, char**)
{
    std::cout << texts::help::format;
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    static const std::vector<Subcommand> commands = {
        {"run", runCommand},       {"sensitivity", sensitivityCommand}, {"fit", fitCommand},
        {"corona", coronaCommand}, {"format", formatCommand},
    };
    return runSubcommand("kinetics", texts::help::kinetics, commands, argc, argv);
}

} // namespace procsim::kinetics
