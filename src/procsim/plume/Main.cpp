#include "plume/Main.hpp"

#include <iostream>
#include <string>

#include "common/Cli.hpp"
#include "plume/EulerianCase.hpp"
#include "plume/GaussianCase.hpp"
#include "plume/MonteCarlo.hpp"

namespace procsim::plume
{

namespace
{

const char* kHelp =
    "usage: procsim plume <model> CASE.yaml [options]   (procsim plume <model> --help)\n"
    "\n"
    "PM10 dispersion around stone-processing plants (the Saraburi studies).\n"
    "\n"
    "models:\n"
    "  eulerian     advection-diffusion over terrain in terrain-following coordinates\n"
    "               (QUICK + Adams-Bashforth, K_H/K_V, 1/4-power wind), scenarios such\n"
    "               as an 80 % emission cut; receptor 1-h/24-h/weekly averages, ParaView\n"
    "  gaussian     ISCST3-style Gaussian plume: Pasquill-Gifford classes, ISC3 rural\n"
    "               sigmas, ground and mixing-height reflection, deposition by depletion\n"
    "  montecarlo   gamma fits of historical meteorology, N synthetic years (weighting w),\n"
    "               the Gaussian model for each: percentiles and exceedance probabilities\n";

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || isHelp(argv[1]))
    {
        (argc < 2 ? std::cerr : std::cout) << kHelp;
        return argc < 2 ? 2 : 0;
    }
    const std::string model = argv[1];
    if (model == "eulerian") return eulerianMain(argc - 1, argv + 1);
    if (model == "gaussian") return gaussianMain(argc - 1, argv + 1);
    if (model == "montecarlo") return monteCarloMain(argc - 1, argv + 1);
    throw InputError("plume: unknown model '" + model + "' (expected eulerian, gaussian or montecarlo)");
}

} // namespace procsim::plume
