// Coarse graining (coupling/Particle.hpp): a parcel of cg = 2 in a cell
// stands for the 8 original particles that would fill the same cell, so the
// same bed described both ways must give the parcel 8 times the force, heat
// and water of each original, at the same voidage, slip and temperatures,
// for every registered model of every family (the loops over the
// registries take in a model added later). The reference is the bed of 8
// originals (cg = 1), which is the coupling as it was before coarse
// graining: nothing here is computed by the code under test on the parcel's
// side only. A family that evaluated a law at the parcel's diameter cg d
// (the mistake found in other codes' Gunn and Ranz-Marshall heat models)
// gives another Re and fails; EveryLawDependsOnTheDiameter makes sure each
// law would show it.

#include "CartesianMesh.hpp"
#include "CoarseGraining.hpp"
#include "HeatExchange.hpp"
#include "InputError.hpp"
#include "ModelFamilies.hpp"
#include "MoistureExchange.hpp"
#include "MomentumExchange.hpp"
#include "VoidFractionModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

using namespace spoutlab;

namespace
{

const double side = 0.04;      // the cell, a 40 mm cube
const double radius = 4e-3;    // the original particles' radius
const Vec3 v{0.05, 0.0, -0.2}; // every particle's velocity
const GasProperties air{1.0324, 2.029e-5};
const GasThermalProperties hotAir{1.0324, 2.029e-5, 1008.6, 0.02917};
const double diffusivity = 3.2e-5;
const double pressure = 101325.0;

// Every setting any registered model asks for (a model reads its own).
Parameters settings(const std::string& name)
{
    Parameters p(name + "Props");
    p.set("a", "1").set("b", "5").set("c", "1");          // reactionEngineering
    p.set("D0", "5e-6").set("activationEnergy", "30000"); // kernelDiffusion
    p.set("nShells", "15");
    p.set("region", "voidage").set("spoutVoidage", "0.8"); // spoutDowncomer
    return p;
}

CartesianMesh cell()
{
    return CartesianMesh({0.0, side}, {0.0, side}, {0.0, side});
}

// The same solid two ways: one parcel of cg = 2 at the cell's centre, or its
// 8 originals, one in each octant; every particle wholly inside the cell.
std::vector<Particle> parcel()
{
    Particle p;
    p.id = 1;
    p.x = Vec3{0.5 * side, 0.5 * side, 0.5 * side};
    p.v = v;
    p.radius = 2.0 * radius;
    p.coarseGraining = 2.0;
    p.temperature = 310.0;
    return {p};
}

std::vector<Particle> originals()
{
    std::vector<Particle> out;
    for (int k = 0; k < 8; ++k)
    {
        Particle p;
        p.id = k + 1;
        p.x = Vec3{(k & 1 ? 0.75 : 0.25) * side, (k & 2 ? 0.75 : 0.25) * side, (k & 4 ? 0.75 : 0.25) * side};
        p.v = v;
        p.radius = radius;
        p.temperature = 310.0;
        out.push_back(p);
    }
    return out;
}

// The clipped voidage the laws see, from the packed bed to the dilute spout
// (the exchange takes it as a field, so it is the same for both beds).
const std::vector<double> voidages{0.42, 0.7, 0.85, 0.97};

struct Bed
{
    std::vector<Particle> particles;
    VoidFractionResult vf;
    ExchangeResult momentum;
};

Bed exchanged(const std::vector<Particle>& particles, const std::string& dragName, double eps)
{
    const CartesianMesh mesh = cell();
    const std::vector<Vec3> U{{0.3, 0.1, 2.5}}, gradP{{0.0, 0.0, -1000.0}};
    const std::vector<double> epsField{eps};
    Bed bed{particles, VoidFractionModel::New("divided", settings("divided"))->compute(mesh, particles), {}};
    const MomentumExchange exchange(DragModel::New(dragName, settings(dragName)));
    bed.momentum = exchange.compute(mesh, particles, bed.vf, GasCellFields{U, gradP, epsField}, air, Vec3{});
    return bed;
}

void expectTimes(double parcelValue, double originalValue, double times, const std::string& what)
{
    EXPECT_NEAR(parcelValue, times * originalValue, 1e-13 * std::fabs(times * originalValue)) << what;
}

void expectTimes(const Vec3& parcelValue, const Vec3& originalValue, double times, const std::string& what)
{
    EXPECT_LT(mag(parcelValue - originalValue * times), 1e-13 * mag(originalValue * times)) << what;
}

} // namespace

// The families this file covers are all the solver selects: a new family in
// ModelFamilies.cpp must get its coarse-graining test here.
TEST(CoarseGraining, EveryFamilyIsCovered)
{
    std::set<std::string> keys;
    for (const ModelFamily& f : modelFamilies()) keys.insert(f.key);
    EXPECT_EQ(keys,
              (std::set<std::string>{"dragModel", "voidFractionModel", "heatTransferModel", "dryingModel"}));
}

TEST(CoarseGraining, ParcelIsItsOriginalsDiameterSurfaceAndVolume)
{
    const Particle p = parcel()[0], o = originals()[0];
    EXPECT_EQ(p.diameter(), o.diameter());
    EXPECT_EQ(p.multiplicity(), 8.0);
    EXPECT_EQ(p.volume(), 8.0 * o.volume());
    EXPECT_EQ(p.surface(), 8.0 * o.surface());
    EXPECT_EQ(o.diameter(), 2.0 * radius);
}

// Void fraction from the parcel's volume: the cell holds the same solid.
TEST(CoarseGraining, VoidFractionOfAParcelIsThatOfItsOriginals)
{
    const CartesianMesh mesh = cell();
    for (const std::string& name : VoidFractionModel::registry().names())
    {
        const auto model = VoidFractionModel::New(name, settings(name));
        const double byParcel = model->compute(mesh, parcel()).solidVolume[0];
        const double byOriginals = model->compute(mesh, originals()).solidVolume[0];
        EXPECT_NEAR(byParcel, byOriginals, 1e-14 * byOriginals) << name;
    }
}

TEST(CoarseGraining, ParcelFeelsCgCubedTimesTheDragOfAnOriginal)
{
    for (const std::string& name : DragModel::registry().names())
    {
        for (const double eps : voidages)
        {
            const Bed one = exchanged(parcel(), name, eps), eight = exchanged(originals(), name, eps);
            const std::string what = name + " at eps " + std::to_string(eps);
            // the law at the originals' diameter: the same beta, Us and d
            EXPECT_NEAR(one.momentum.sauterDiameter[0], 2.0 * radius, 1e-16) << what;
            expectTimes(one.momentum.beta[0], eight.momentum.beta[0], 1.0, what + ", beta");
            for (std::size_t k = 0; k < 8; ++k)
            {
                expectTimes(one.momentum.dragForce[0], eight.momentum.dragForce[k], 8.0, what + ", drag");
                expectTimes(one.momentum.totalForce[0], eight.momentum.totalForce[k], 8.0, what + ", total");
            }
        }
    }
}

TEST(CoarseGraining, ParcelReceivesCgCubedTimesTheHeatOfAnOriginal)
{
    const CartesianMesh mesh = cell();
    const std::vector<Vec3> centre{{0.5 * side, 0.5 * side, 0.5 * side}}, U{{0.3, 0.1, 2.5}};
    const std::vector<double> Tgas{400.0};
    for (const std::string& name : HeatTransferModel::registry().names())
    {
        const HeatExchange heat(HeatTransferModel::New(name, settings(name)));
        for (const double eps : voidages)
        {
            const std::vector<double> epsField{eps};
            const GasHeatCellFields fields{centre, U, epsField};
            const std::string what = name + " at eps " + std::to_string(eps);
            const Bed one = exchanged(parcel(), "Gidaspow", eps),
                      eight = exchanged(originals(), "Gidaspow", eps);
            const HeatCellCoefficients c1 = heat.cellCoefficients(mesh, one.particles, one.vf.map,
                                                                  one.momentum, fields, hotAir, diffusivity);
            const HeatCellCoefficients c8 = heat.cellCoefficients(
                mesh, eight.particles, eight.vf.map, eight.momentum, fields, hotAir, diffusivity);
            // Re, Nu and Sh at the originals' diameter: the same h and k_m
            expectTimes(c1.reynolds[0], c8.reynolds[0], 1.0, what + ", Re");
            expectTimes(c1.h[0], c8.h[0], 1.0, what + ", h");
            expectTimes(c1.km[0], c8.km[0], 1.0, what + ", k_m");
            expectTimes(c1.K[0], c8.K[0], 1.0, what + ", K");
            const std::vector<double> q1 = heat.particleHeatFlux(one.particles, one.vf.map, c1, Tgas);
            const std::vector<double> q8 = heat.particleHeatFlux(eight.particles, eight.vf.map, c8, Tgas);
            for (std::size_t k = 0; k < 8; ++k) expectTimes(q1[0], q8[k], 8.0, what + ", q");
        }
    }
}

// The kernel of a parcel dries as one of its originals, to the bit: the same
// diameter, dry mass m_d/8, temperature, gas and k_m.
TEST(CoarseGraining, ParcelLosesCgCubedTimesTheWaterOfAnOriginal)
{
    const CartesianMesh mesh = cell();
    const std::vector<double> T{350.0}, W{0.01}, km{0.05};
    const double dryMass = 2.0e-4, dt = 0.01;
    for (const std::string& name : DryingModel::registry().names())
    {
        const MoistureExchange exchange(DryingModel::New(name, settings(name)), pressure);
        const std::size_t width = static_cast<std::size_t>(exchange.model().stateSize());
        auto dried = [&](const std::vector<Particle>& particles, double mass, KernelMoisture& kernels) {
            const std::size_t n = particles.size();
            kernels = KernelMoisture{std::vector<double>(n, mass),
                                     std::vector<double>(n, 0.3),
                                     std::vector<double>(width * n, 0.0),
                                     {}};
            for (std::size_t i = 0; i < n; ++i) exchange.initialise(kernels, i);
            const VoidFractionResult vf =
                VoidFractionModel::New("divided", settings("divided"))->compute(mesh, particles);
            MoistureStep step;
            for (int s = 0; s < 5; ++s)
                step = exchange.advance(mesh, particles, vf.map, MoistureCellFields{T, W, km}, kernels, dt);
            return step;
        };
        KernelMoisture k1, k8;
        const MoistureStep one = dried(parcel(), 8.0 * dryMass, k1);
        const MoistureStep eight = dried(originals(), dryMass, k8);
        ASSERT_GT(eight.waterLost[0], 0.0) << name;
        for (std::size_t k = 0; k < 8; ++k)
        {
            EXPECT_EQ(one.waterLost[0], 8.0 * eight.waterLost[k]) << name;
            EXPECT_EQ(one.latentHeat[0], eight.latentHeat[k]) << name;
            EXPECT_EQ(k1.moisture[0], k8.moisture[k]) << name;
        }
        expectTimes(one.vapourSource[0], eight.vapourSource[0], 1.0, name + ", vapour source");
    }
}

// A law that did not depend on the diameter would let a family that ignores
// cg (evaluating at cg d, the parcel's) pass the tests above: every law must
// change between d and 2 d.
TEST(CoarseGraining, EveryLawDependsOnTheDiameter)
{
    const double d = 2.0 * radius;
    for (const std::string& name : DragModel::registry().names())
    {
        const auto law = DragModel::New(name, settings(name));
        for (const double eps : voidages)
        {
            EXPECT_NE(law->beta({eps, d, 2.0}, air), law->beta({eps, 2.0 * d, 2.0}, air))
                << name << " " << eps;
        }
    }
    for (const std::string& name : HeatTransferModel::registry().names())
    {
        const auto model = HeatTransferModel::New(name, settings(name));
        for (const double eps : voidages)
        {
            const HeatTransferCell at{{0, 0, 0}, eps, d, 2.0}, atParcel{{0, 0, 0}, eps, 2.0 * d, 2.0};
            EXPECT_NE(model->h(at, hotAir), model->h(atParcel, hotAir)) << name << " " << eps;
            EXPECT_NE(model->massTransferCoefficient(at, hotAir, diffusivity),
                      model->massTransferCoefficient(atParcel, hotAir, diffusivity))
                << name << " " << eps;
        }
    }
    for (const std::string& name : DryingModel::registry().names())
    {
        const auto model = DryingModel::New(name, settings(name));
        std::vector<double> state(static_cast<std::size_t>(model->stateSize()), 0.0);
        model->initialise(0.3, state.data());
        const MoistAir gas{350.0, 0.01, pressure};
        const double atD = model->rate({d, 2e-4, 310.0}, 0.3, state.data(), gas, 0.05);
        const double atParcel = model->rate({2.0 * d, 2e-4, 310.0}, 0.3, state.data(), gas, 0.05);
        EXPECT_NE(atD, atParcel) << name;
    }
}

// --- the refusals: one line naming the file and the key ------------------------------

namespace
{

std::string refusal(void (*check)())
{
    try
    {
        check();
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CoarseGraining, FactorBelowOneOrNotFiniteIsRefused)
{
    const std::string file = "constant/couplingProperties";
    EXPECT_EQ(checkedCoarseGraining(1.0, "1", file), 1.0);
    EXPECT_EQ(checkedCoarseGraining(2.5, "2.5", file), 2.5);
    EXPECT_EQ(refusal([] { checkedCoarseGraining(0.5, "0.5", "constant/couplingProperties"); }),
              "constant/couplingProperties: key 'coarseGraining' expected a factor >= 1 (parcel diameter / "
              "original particle diameter), got '0.5'");
    for (const double bad : {0.0, -2.0, std::nan(""), HUGE_VAL})
    {
        EXPECT_THROW(checkedCoarseGraining(bad, "x", file), InputError) << bad;
    }
    EXPECT_NE(refusal([] {
                  checkedCoarseGraining(std::nan(""), "two", "constant/couplingProperties");
              }).find("got 'two'"),
              std::string::npos);
}

TEST(CoarseGraining, InputThatNeverScalesByCgIsRefusedUnlessCgIsOne)
{
    const std::string file = "constant/couplingProperties";
    EXPECT_NO_THROW(checkCoarseGrainedInput(1.0, false, file, "in.coupled"));
    EXPECT_NO_THROW(checkCoarseGrainedInput(2.0, true, file, "in.coupled"));
    EXPECT_EQ(
        refusal([] { checkCoarseGrainedInput(2.0, false, "constant/couplingProperties", "in.coupled"); }),
        "constant/couplingProperties: key 'coarseGraining' is not 1, but LIGGGHTS input 'in.coupled' never "
        "uses ${cg}: expected it to scale its particles by it (liggghts_inputs/README.md)");
    EXPECT_NO_THROW(checkNoOwnCg(false, file));
    EXPECT_EQ(refusal([] { checkNoOwnCg(true, "constant/couplingProperties"); }),
              "constant/couplingProperties: key 'liggghtsVariables/cg' expected nothing (spoutFoam passes "
              "LIGGGHTS cg from 'coarseGraining')");
}

// --- issue 27 item 2, the cheapest check: one parcel alone behaves as one particle -----

namespace
{

// One parcel of factor cg (radius cg r) alone at the centre of a 60 mm cell.
std::vector<Particle> aloneAt(double cg, double temperature)
{
    Particle p;
    p.id = 1;
    p.x = Vec3{0.03, 0.03, 0.03};
    p.v = v;
    p.radius = cg * radius;
    p.coarseGraining = cg;
    p.temperature = temperature;
    return {p};
}

CartesianMesh bigCell()
{
    return CartesianMesh({0.0, 0.06}, {0.0, 0.06}, {0.0, 0.06});
}

} // namespace

// Lumped heating in gas at 400 K: the parcel's temperature, stepped with the
// heat it receives over its own heat capacity (LIGGGHTS' m c_p, the parcel's
// mass), follows the single particle's at cg = 2 and 3, for every
// heat-transfer model.
TEST(CoarseGraining, AParcelHeatsAsOneParticle)
{
    const CartesianMesh mesh = bigCell();
    const std::vector<Vec3> centre{{0.03, 0.03, 0.03}}, U{{0.3, 0.1, 2.5}}, gradP{{0.0, 0.0, 0.0}};
    const std::vector<double> eps{0.9}, Tgas{400.0};
    const double density = 1231.0, cp = 2400.0, dt = 0.01;
    for (const std::string& name : HeatTransferModel::registry().names())
    {
        const HeatExchange heat(HeatTransferModel::New(name, settings(name)));
        const MomentumExchange momentum(DragModel::New("Gidaspow", settings("Gidaspow")));
        std::vector<double> history[3];
        for (int k = 0; k < 3; ++k)
        {
            std::vector<Particle> particles = aloneAt(k + 1.0, 306.0);
            const VoidFractionResult vf =
                VoidFractionModel::New("divided", settings("divided"))->compute(mesh, particles);
            for (int step = 0; step < 200; ++step)
            {
                const ExchangeResult ex =
                    momentum.compute(mesh, particles, vf, GasCellFields{U, gradP, eps}, air, Vec3{});
                const HeatCellCoefficients c = heat.cellCoefficients(
                    mesh, particles, vf.map, ex, GasHeatCellFields{centre, U, eps}, hotAir);
                const double q = heat.particleHeatFlux(particles, vf.map, c, Tgas)[0];
                particles[0].temperature += q * dt / (density * particles[0].volume() * cp);
                history[k].push_back(particles[0].temperature);
            }
        }
        ASSERT_GT(history[0].back(), 306.5) << name; // it heats
        for (int k = 1; k < 3; ++k)
        {
            for (std::size_t s = 0; s < history[0].size(); ++s)
            {
                EXPECT_NEAR(history[k][s], history[0][s], 1e-12 * history[0][s])
                    << name << ", cg " << k + 1 << ", step " << s;
            }
        }
    }
}

// Single-kernel drying at a fixed kernel temperature in air at 350 K: the
// moisture of a parcel at cg = 2 and 3 follows the particle's over 2 s, and
// the parcel gives cg^3 times its water, for every drying model.
TEST(CoarseGraining, AParcelDriesAsOneParticle)
{
    const CartesianMesh mesh = bigCell();
    const std::vector<double> T{350.0}, W{0.01}, km{0.05};
    const double dryMass = 2.0e-4, dt = 0.01;
    for (const std::string& name : DryingModel::registry().names())
    {
        const MoistureExchange exchange(DryingModel::New(name, settings(name)), pressure);
        const std::size_t width = static_cast<std::size_t>(exchange.model().stateSize());
        std::vector<double> moisture[3], water[3];
        for (int k = 0; k < 3; ++k)
        {
            const double cg = k + 1.0;
            const std::vector<Particle> particles = aloneAt(cg, 320.0);
            KernelMoisture kernels{{cg * cg * cg * dryMass}, {0.3}, std::vector<double>(width, 0.0), {}};
            exchange.initialise(kernels, 0);
            const VoidFractionResult vf =
                VoidFractionModel::New("divided", settings("divided"))->compute(mesh, particles);
            for (int step = 0; step < 200; ++step)
            {
                const MoistureStep s =
                    exchange.advance(mesh, particles, vf.map, MoistureCellFields{T, W, km}, kernels, dt);
                moisture[k].push_back(kernels.moisture[0]);
                water[k].push_back(s.waterLost[0] / (cg * cg * cg));
            }
        }
        ASSERT_LT(moisture[0].back(), 0.299) << name; // it dries
        for (int k = 1; k < 3; ++k)
        {
            for (std::size_t s = 0; s < moisture[0].size(); ++s)
            {
                EXPECT_NEAR(moisture[k][s], moisture[0][s], 1e-12 * moisture[0][s])
                    << name << ", cg " << k + 1 << ", step " << s;
                EXPECT_NEAR(water[k][s], water[0][s], 1e-11 * std::fabs(water[0][s]))
                    << name << ", cg " << k + 1 << ", step " << s;
            }
        }
    }
}
