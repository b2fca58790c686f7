// procsim plume: PM10 dispersion around stone-processing plants (the
// Saraburi studies): Eulerian over terrain, Gaussian plume, Monte Carlo
// meteorology.
#include "plume/Main.hpp"

#include <vector>

#include "common/Subcommands.hpp"
#include "plume/Commands.hpp"
#include "plume/Texts.hpp"

namespace procsim::plume
{

int main(int argc, char** argv)
{
    static const std::vector<Subcommand> models = {
        {"eulerian", eulerianCommand}, {"gaussian", gaussianCommand}, {"montecarlo", monteCarloCommand}};
    return runSubcommand("plume", texts::help::plume, models, argc, argv, "model");
}

} // namespace procsim::plume
