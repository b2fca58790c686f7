// Moisture exchange: a particle sees the gas of its cells weighted by its
// volume in each, dries by its model over the step, and the gas receives
// exactly the water the particles lose, with the vapour's enthalpy at the
// particle's temperature. Free-water kernels, whose rate is known by hand:
// m_dot = k_m pi d^2 (rho_v,sat(T_p) - rho_v,inf(T_g, W)).

#include "CartesianMesh.hpp"
#include "DividedVoidFraction.hpp"
#include "MoistureExchange.hpp"
#include "Psychrometrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace spoutlab;

namespace
{

const double pi = std::acos(-1.0);
const double rv = 287.042 / 0.621945; // R_v of the psychrometrics
const double p0 = 101325.0;

double saturated(double T)
{
    return psy::saturationPressure(T - 273.15) / (rv * T);
}
double vapour(double T, double W)
{
    return p0 * W / (0.621945 + W) / (rv * T);
}

MoistureExchange freeWater()
{
    return MoistureExchange(DryingModel::New("freeWater", Parameters("freeWaterProps")), p0);
}

Particle kernelAt(long id, const Vec3& x, double T)
{
    Particle p;
    p.id = id;
    p.x = x;
    p.radius = 4e-3;
    p.temperature = T;
    return p;
}

struct Gas
{
    std::vector<double> T, W, km;
    MoistureCellFields fields() const { return {T, W, km}; }
};

// n kernels at random places inside the 8 x 6 x 4 cm box of the tests'
// 4 x 3 x 2 mesh, at temperatures in [T0, T0 + spread)
std::vector<Particle> scatteredKernels(std::mt19937& rng, long n, double T0, double spread)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Particle> particles;
    for (long id = 1; id <= n; ++id)
    {
        particles.push_back(kernelAt(id,
                                     {0.004 + 0.072 * u(rng), 0.004 + 0.052 * u(rng), 0.004 + 0.032 * u(rng)},
                                     T0 + spread * u(rng)));
    }
    return particles;
}

// Each cell's gas at random: T in [T0, T0 + spread), W in [0.005, 0.005 +
// wSpread), k_m in [0.03, 0.07) m/s.
Gas randomGas(std::mt19937& rng, std::size_t nCells, double T0, double spread, double wSpread)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Gas gas;
    for (std::size_t c = 0; c < nCells; ++c)
    {
        gas.T.push_back(T0 + spread * u(rng));
        gas.W.push_back(0.005 + wSpread * u(rng));
        gas.km.push_back(0.03 + 0.04 * u(rng));
    }
    return gas;
}

} // namespace

// Two cells of 20 mm side; a particle on their common face has half its volume
// in each and sees the mean of their gas; one wholly in the second cell sees
// that cell's gas alone.
TEST(MoistureExchange, ParticleDriesInTheWeightedGasOfItsCells)
{
    const CartesianMesh mesh({0.0, 0.02, 0.04}, {0.0, 0.02}, {0.0, 0.02});
    const std::vector<Particle> particles{kernelAt(1, {0.02, 0.01, 0.01}, 320.0),
                                          kernelAt(2, {0.03, 0.01, 0.01}, 310.0)};
    DividedVoidFraction divided(Parameters("dividedProps"));
    const VoidFractionResult vf = divided.compute(mesh, particles);
    const Gas gas{{350.0, 330.0}, {0.01, 0.02}, {0.04, 0.06}};
    KernelMoisture kernels{{2.5e-4, 2.5e-4}, {0.3, 0.3}, {}, {}};
    const double dt = 0.01;
    const MoistureStep step = freeWater().advance(mesh, particles, vf.map, gas.fields(), kernels, dt);

    const double area = pi * 8e-3 * 8e-3;
    // particle 1: half in each cell (the face splits it into equal halves)
    const double m1 = 0.05 * area * (saturated(320.0) - vapour(340.0, 0.015));
    const double m2 = 0.06 * area * (saturated(310.0) - vapour(330.0, 0.02));
    EXPECT_NEAR(step.waterLost[0], m1 * dt, 1e-9 * m1 * dt);
    EXPECT_NEAR(step.waterLost[1], m2 * dt, 1e-9 * m2 * dt);
    EXPECT_NEAR(kernels.moisture[0], 0.3 - m1 * dt / 2.5e-4, 1e-12);
    // the latent heat of free water at the particle's temperature
    EXPECT_DOUBLE_EQ(step.latentHeat[0], psy::latentHeat(320.0 - 273.15));

    const double volume = 0.02 * 0.02 * 0.02;
    EXPECT_NEAR(step.vapourSource[0], 0.5 * m1 / volume, 1e-9 * m1 / volume);
    EXPECT_NEAR(step.vapourSource[1], (0.5 * m1 + m2) / volume, 1e-9 * m2 / volume);
    EXPECT_NEAR(step.vapourEnthalpy[1], 1860.0 * (0.5 * m1 * 320.0 + m2 * 310.0) / volume,
                1e-9 * 1860.0 * m2 * 310.0 / volume);
}

// Random kernels in a 4 x 3 x 2 mesh: the water the cells receive is the
// water the particles lose, and the enthalpy is c_pv T_p times each share.
TEST(MoistureExchange, GasReceivesTheWaterTheParticlesLose)
{
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.08, 0.06, 0.04}, 4, 3, 2);
    std::mt19937 rng(7);
    std::vector<Particle> particles = scatteredKernels(rng, 40, 300.0, 30.0);
    DividedVoidFraction divided(Parameters("dividedProps"));
    const VoidFractionResult vf = divided.compute(mesh, particles);
    const Gas gas = randomGas(rng, static_cast<std::size_t>(mesh.nCells()), 320.0, 20.0, 0.02);
    KernelMoisture kernels{std::vector<double>(40, 2.5e-4), std::vector<double>(40, 0.3), {}, {}};
    const double dt = 3e-4;
    const MoistureStep step = freeWater().advance(mesh, particles, vf.map, gas.fields(), kernels, dt);

    double lost = 0.0, lostEnthalpy = 0.0, received = 0.0, enthalpy = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        lost += step.waterLost[i];
        lostEnthalpy += 1860.0 * step.waterLost[i] * particles[i].temperature;
        EXPECT_NEAR(kernels.moisture[i], 0.3 - step.waterLost[i] / 2.5e-4, 1e-15);
    }
    for (label c = 0; c < mesh.nCells(); ++c)
    {
        received += step.vapourSource[c] * mesh.cellVolume(c) * dt;
        enthalpy += step.vapourEnthalpy[c] * mesh.cellVolume(c) * dt;
    }
    ASSERT_GT(lost, 0.0);
    EXPECT_NEAR(received, lost, 1e-13 * lost);
    EXPECT_NEAR(enthalpy, lostEnthalpy, 1e-13 * lostEnthalpy);
}

// A particle outside the mesh (an empty row) neither dries nor gives water.
TEST(MoistureExchange, LostParticleExchangesNothing)
{
    const CartesianMesh mesh({0.0, 0.02}, {0.0, 0.02}, {0.0, 0.02});
    const std::vector<Particle> particles{kernelAt(1, {0.5, 0.01, 0.01}, 320.0)};
    DividedVoidFraction divided(Parameters("dividedProps"));
    const VoidFractionResult vf = divided.compute(mesh, particles);
    const Gas gas{{350.0}, {0.01}, {0.05}};
    KernelMoisture kernels{{2.5e-4}, {0.3}, {}, {}};
    const MoistureStep step = freeWater().advance(mesh, particles, vf.map, gas.fields(), kernels, 0.01);
    EXPECT_EQ(step.waterLost[0], 0.0);
    EXPECT_EQ(kernels.moisture[0], 0.3);
    EXPECT_EQ(step.vapourSource[0], 0.0);
}

// The state used in place where the caller keeps it (LIGGGHTS' per-atom
// rows, here rows of their own scattered in reverse order) steps exactly as
// the exchange's own contiguous copy: kernel diffusion, kernel stepped every
// step and once per 3 steps, 7 steps from a fresh start.
TEST(MoistureExchange, StateInPlaceIsTheStateCopied)
{
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.08, 0.06, 0.04}, 4, 3, 2);
    std::mt19937 rng(11);
    std::vector<Particle> particles = scatteredKernels(rng, 20, 320.0, 40.0);
    DividedVoidFraction divided(Parameters("dividedProps"));
    const VoidFractionResult vf = divided.compute(mesh, particles);
    const Gas gas = randomGas(rng, static_cast<std::size_t>(mesh.nCells()), 340.0, 60.0, 0.01);
    for (const char* kernelSteps : {"1", "3"})
    {
        Parameters props("kernelDiffusionProps");
        props.set("D0", "1.4904e-4").set("activationEnergy", "41762").set("kernelSteps", kernelSteps);
        const MoistureExchange exchange(DryingModel::New("kernelDiffusion", props), p0);
        const std::size_t n = particles.size(),
                          width = static_cast<std::size_t>(exchange.model().stateSize());
        KernelMoisture copied{
            std::vector<double>(n, 2.5e-4), std::vector<double>(n, 0.3), std::vector<double>(width * n), {}};
        KernelMoisture inPlace{copied.dryMass, copied.moisture, {}, {}};
        std::vector<std::vector<double>> rows(n, std::vector<double>(width));
        for (std::size_t i = 0; i < n; ++i) inPlace.stateRows.push_back(rows[n - 1 - i].data());
        for (std::size_t i = 0; i < n; ++i)
        {
            exchange.initialise(copied, i);
            exchange.initialise(inPlace, i);
        }
        for (int k = 0; k < 7; ++k)
        {
            const MoistureStep a = exchange.advance(mesh, particles, vf.map, gas.fields(), copied, 3e-4);
            const MoistureStep b = exchange.advance(mesh, particles, vf.map, gas.fields(), inPlace, 3e-4);
            EXPECT_EQ(a.waterLost, b.waterLost) << kernelSteps;
            EXPECT_EQ(a.latentHeat, b.latentHeat) << kernelSteps;
            EXPECT_EQ(a.vapourSource, b.vapourSource) << kernelSteps;
            EXPECT_EQ(copied.moisture, inPlace.moisture) << kernelSteps;
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            EXPECT_EQ(std::vector<double>(&copied.state[width * i], &copied.state[width * (i + 1)]),
                      rows[n - 1 - i]);
        }
        ASSERT_GT(copied.moisture[0], 0.0);
        EXPECT_LT(copied.moisture[0], 0.3);
    }
}

// Inside a kernelSteps block the model needs no gas (needsGas) and the
// exchange gathers none for those particles. Against the same model stepped
// by hand with each particle's weighted gas on every step, and the cell sums
// made by hand: the same water, latent heat, moisture, state, vapour source
// and enthalpy to the bit, with the gas and the particles' temperatures
// changing every step, over three blocks of 4 (the particles start their
// blocks on different steps), the state in rows of its own and copied.
TEST(MoistureExchange, SkippingTheGasInsideBlocksIsSteppingWithTheGas)
{
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.08, 0.06, 0.04}, 4, 3, 2);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Particle> particles = scatteredKernels(rng, 24, 320.0, 40.0);
    DividedVoidFraction divided(Parameters("dividedProps"));
    const VoidFractionResult vf = divided.compute(mesh, particles);
    Parameters props("kernelDiffusionProps");
    props.set("D0", "1.4904e-4").set("activationEnergy", "41762").set("kernelSteps", "4");
    const MoistureExchange exchange(DryingModel::New("kernelDiffusion", props), p0);
    const DryingModel& model = exchange.model();
    const std::size_t n = particles.size(), width = static_cast<std::size_t>(model.stateSize());
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    for (const bool inRows : {true, false})
    {
        KernelMoisture kernels{std::vector<double>(n, 2.5e-4), std::vector<double>(n, 0.3), {}, {}};
        std::vector<std::vector<double>> rows(n, std::vector<double>(width));
        if (inRows)
            for (std::size_t i = 0; i < n; ++i) kernels.stateRows.push_back(rows[n - 1 - i].data());
        else
            kernels.state.assign(width * n, 0.0);
        std::vector<double> moisture(kernels.moisture), state(width * n);
        for (std::size_t i = 0; i < n; ++i)
        {
            exchange.initialise(kernels, i);
            model.initialise(moisture[i], &state[width * i]);
        }
        const double dt = 3e-4;
        int skipped = 0;
        for (int k = 0; k < 13; ++k)
        {
            const Gas gas = randomGas(rng, nCells, 340.0, 60.0, 0.01);
            for (Particle& p : particles) p.temperature += 2.0 * (u(rng) - 0.5);
            // particles 0..2 join one step later each: blocks out of step
            const std::size_t active = std::min<std::size_t>(n, n - 3 + static_cast<std::size_t>(k));
            std::vector<Particle> now(particles.begin(), particles.begin() + active);
            ParticleCellMap map;
            for (std::size_t i = 0; i < active; ++i)
            {
                const ParticleCellMap::Row row = vf.map.cells(i);
                map.appendRow(std::vector<CellWeight>(row.begin(), row.end()));
            }
            KernelMoisture part{
                std::vector<double>(kernels.dryMass.begin(), kernels.dryMass.begin() + active),
                std::vector<double>(kernels.moisture.begin(), kernels.moisture.begin() + active),
                {},
                {}};
            if (inRows)
                part.stateRows.assign(kernels.stateRows.begin(), kernels.stateRows.begin() + active);
            else
                part.state.assign(kernels.state.begin(), kernels.state.begin() + width * active);
            for (std::size_t i = 0; i < active; ++i) skipped += !model.needsGas(part.stateOf(i, width));
            const MoistureStep step = exchange.advance(mesh, now, map, gas.fields(), part, dt);
            std::copy(part.moisture.begin(), part.moisture.end(), kernels.moisture.begin());
            if (!inRows) std::copy(part.state.begin(), part.state.end(), kernels.state.begin());
            // by hand: every particle in the gas of its cells
            std::vector<double> water(active), latent(active), sums(2 * nCells, 0.0);
            for (std::size_t i = 0; i < active; ++i)
            {
                double Tg = 0.0, W = 0.0, km = 0.0;
                for (const CellWeight& cw : map.cells(i))
                {
                    Tg += cw.weight * gas.T[cw.cell];
                    W += cw.weight * gas.W[cw.cell];
                    km += cw.weight * gas.km[cw.cell];
                }
                const Kernel kernel{2.0 * now[i].radius, kernels.dryMass[i], now[i].temperature};
                water[i] = model.advanceWithLatentHeat(kernel, moisture[i], &state[width * i],
                                                       MoistAir{Tg, W, p0}, km, dt, latent[i]);
                for (const CellWeight& cw : map.cells(i))
                {
                    sums[2 * cw.cell] += cw.weight * water[i];
                    sums[2 * cw.cell + 1] += cw.weight * water[i] * kernel.temperature;
                }
            }
            EXPECT_EQ(step.waterLost, water) << k;
            EXPECT_EQ(step.latentHeat, latent) << k;
            EXPECT_EQ(part.moisture, std::vector<double>(moisture.begin(), moisture.begin() + active)) << k;
            for (std::size_t c = 0; c < nCells; ++c)
            {
                const double perVolumeTime = 1.0 / (dt * mesh.cellVolume(static_cast<label>(c)));
                EXPECT_EQ(step.vapourSource[c], sums[2 * c] * perVolumeTime) << k << " " << c;
                EXPECT_EQ(step.vapourEnthalpy[c], psy::kCpVapour * sums[2 * c + 1] * perVolumeTime) << k;
            }
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            const double* row = inRows ? rows[n - 1 - i].data() : &kernels.state[width * i];
            EXPECT_EQ(std::vector<double>(row, row + width),
                      std::vector<double>(&state[width * i], &state[width * (i + 1)]));
        }
        EXPECT_GT(skipped, 200); // three of four particle-steps inside a block
        EXPECT_LT(kernels.moisture[5], 0.3);
    }
}
