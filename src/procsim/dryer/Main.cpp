// procsim dryer: batch hot-air tray dryer (the tray-dryer paper): energy
// metrics from batch records, psychrometrics, a physical batch simulation,
// calibration on measured batches and what-if sweeps.
#include "dryer/Main.hpp"

#include <vector>

#include "common/Subcommands.hpp"
#include "dryer/Commands.hpp"
#include "dryer/Texts.hpp"

namespace procsim::dryer
{

int main(int argc, char** argv)
{
    static const std::vector<Subcommand> commands = {
        {"metrics", metricsCommand},     {"psychro", psychroCommand}, {"simulate", simulateCommand},
        {"calibrate", calibrateCommand}, {"whatif", whatifCommand},   {"spouted", spoutedCommand},
    };
    return runSubcommand("dryer", texts::help::dryer, commands, argc, argv);
}

} // namespace procsim::dryer
