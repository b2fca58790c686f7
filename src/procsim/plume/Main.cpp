// procsim plume: PM10 dispersion around stone-processing plants (the
// Saraburi studies): Eulerian over terrain, Gaussian plume, Monte Carlo
// meteorology.
#include "plume/Main.hpp"

#include <vector>

#include "common/Subcommands.hpp"
#include "plume/EulerianCase.hpp"
#include "plume/GaussianCase.hpp"
#include "plume/MonteCarlo.hpp"
#include "plume/Texts.hpp"

namespace procsim::plume
{

int main(int argc, char** argv)
{
    static const std::vector<Subcommand> models = {
        {"eulerian", eulerianMain}, {"gaussian", gaussianMain}, {"montecarlo", monteCarloMain}};
    return runSubcommand("plume", texts::help::plume, models, argc, argv, "model");
}

} // namespace procsim::plume
