// dryingStepBench: what one coupling step of drying costs per particle in the
// physics core, without OpenFOAM or LIGGGHTS: the latent heat and the advance
// of every drying model (DryingModel::advanceWithLatentHeat, as
// MoistureExchange calls it) for N kernels in the spouted bed's conditions,
// best of R repeats.
//
//   cmake --build build --target dryingStepBench
//   build/bin/dryingStepBench [--particles N] [--steps S] [--repeat R]
//
// Kernels of 7.5-8.5 mm at 300-400 K in gas at 330-420 K with a humidity
// ratio of 0.007-0.017 and k_m of 0.02-0.1 m/s (fixed pseudo-random draws),
// 3e-4 s steps, the case's kernel-diffusion parameters (spoutDraftPlates'
// spoutedBedDict), resolved and with kernelSteps 10. Prints microseconds
// per particle-step and the water and heat the steps took (the same from run
// to run: a check that the work was done).

#include "DryingModel.hpp"
#include "Parameters.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace spoutlab;

namespace
{

struct Bed
{
    std::vector<double> temperature, diameter, km, gasTemperature, humidity;
};

Bed bed(int n)
{
    Bed b;
    unsigned seed = 12345;
    auto draw = [&seed] {
        seed = seed * 1103515245u + 12345u;
        return (seed >> 8) / double(1u << 24);
    };
    for (int i = 0; i < n; ++i)
    {
        b.temperature.push_back(300.0 + 100.0 * draw());
        b.diameter.push_back(7.5e-3 + 1e-3 * draw());
        b.km.push_back(0.02 + 0.08 * draw());
        b.gasTemperature.push_back(330.0 + 90.0 * draw());
        b.humidity.push_back(0.007 + 0.01 * draw());
    }
    return b;
}

Parameters props(const std::string& model, const std::string& kernelSteps)
{
    Parameters p("constant/couplingProperties/" + model + "Props");
    if (model == "kernelDiffusion")
    {
        p.set("D0", "1.4904e-4").set("activationEnergy", "41762").set("nShells", "15");
        p.set("kernelSteps", kernelSteps);
    }
    if (model == "reactionEngineering") p.set("a", "1").set("b", "5").set("c", "1");
    return p;
}

// microseconds per particle-step of one run; water and heat summed
double run(const DryingModel& model, const Bed& b, int steps, double& water, double& heat)
{
    const int n = static_cast<int>(b.temperature.size()), width = model.stateSize();
    std::vector<double> moisture(n, 0.3333), state(static_cast<std::size_t>(std::max(1, width * n)));
    for (int i = 0; i < n; ++i)
    {
        if (width) model.initialise(moisture[i], &state[static_cast<std::size_t>(width) * i]);
    }
    water = heat = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k)
    {
        for (int i = 0; i < n; ++i)
        {
            const double d = b.diameter[i];
            const Kernel kernel{d, 2.48e-4 * d * d * d / 512e-9, b.temperature[i] + 1e-3 * (k % 7)};
            double* s = width ? &state[static_cast<std::size_t>(width) * i] : nullptr;
            double latent = 0.0;
            const double lost = model.advanceWithLatentHeat(
                kernel, moisture[i], s, MoistAir{b.gasTemperature[i], b.humidity[i], 101325.0}, b.km[i], 3e-4,
                latent);
            water += lost;
            heat += lost * latent;
        }
    }
    const std::chrono::duration<double, std::micro> took = std::chrono::steady_clock::now() - start;
    return took.count() / (static_cast<double>(n) * steps);
}

} // namespace

int main(int argc, char** argv)
{
    int n = 3000, steps = 300, repeat = 3;
    for (int a = 1; a + 1 < argc; a += 2)
    {
        const int value = std::atoi(argv[a + 1]);
        if (!std::strcmp(argv[a], "--particles"))
            n = value;
        else if (!std::strcmp(argv[a], "--steps"))
            steps = value;
        else if (!std::strcmp(argv[a], "--repeat"))
            repeat = value;
        else
        {
            std::fprintf(stderr, "dryingStepBench: unknown option %s (--particles, --steps, --repeat)\n",
                         argv[a]);
            return 1;
        }
    }
    if (n < 1 || steps < 1 || repeat < 1)
    {
        std::fprintf(stderr, "dryingStepBench: expected --particles, --steps and --repeat of at least 1\n");
        return 1;
    }
    const Bed b = bed(n);
    std::printf("dryingStepBench: %d kernels x %d steps of 3e-4 s, best of %d\n", n, steps, repeat);
    std::printf("%-20s %14s %16s %16s\n", "model", "us / particle", "water [kg]", "heat [J]");
    for (const std::string row :
         {"freeWater", "reactionEngineering", "kernelDiffusion", "kernelDiffusion 10"})
    {
        // "kernelDiffusion 10": kernelSteps 10, as the spouted bed runs it
        const std::string name = row.substr(0, row.find(' '));
        const std::string kernelSteps = row == name ? "1" : row.substr(row.find(' ') + 1);
        const auto model = DryingModel::New(name, props(name, kernelSteps));
        double best = 1e300, water = 0.0, heat = 0.0;
        for (int r = 0; r < repeat; ++r) best = std::min(best, run(*model, b, steps, water, heat));
        std::printf("%-20s %14.4f %16.9e %16.9e\n", row.c_str(), best, water, heat);
    }
    return 0;
}
