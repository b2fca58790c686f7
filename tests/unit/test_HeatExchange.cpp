// Heat exchange: the heat the particles receive is the heat the gas equation
// gives, K is h times the particles' own surface per volume (the paper's
// 6 (1 - eps)/d), and a particle in a uniform gas gets h A (T_g - T_p).
// The correlations themselves are tested in test_HeatTransfer.cpp; here a
// coefficient that depends on the cell state in a known way stands in.

#include "CartesianMesh.hpp"
#include "HeatExchange.hpp"
#include "VoidFractionModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace spoutlab;

namespace
{

const double pi = std::acos(-1.0);
const GasThermalProperties air{1.0324, 2.029e-5, 1008.6, 0.02917};
const GasProperties airFlow{1.0324, 2.029e-5};

// h = 10 + 20 |slip| + 5 eps (as Nu = h d/k_c of the test's air), and the
// spout is x < 0.03: simple enough to evaluate by hand, and it depends on every
// input the real models use.
class LinearH : public HeatTransferModel
{
public:
    double nusselt(const HeatTransferCell& c, double, double) const override
    {
        return (10.0 + 20.0 * c.slip + 5.0 * c.voidFraction) * c.diameter / air.kappa;
    }
    int region(const HeatTransferCell& c) const override { return c.centre.x < 0.03 ? 1 : 0; }
    std::string name() const override { return "LinearH"; }
};

HeatExchange linearExchange()
{
    return HeatExchange(std::unique_ptr<HeatTransferModel>(new LinearH));
}

MomentumExchange gidaspow()
{
    return MomentumExchange(DragModel::New("Gidaspow", Parameters("GidaspowProps")));
}

std::vector<Vec3> centres(const CartesianMesh& mesh)
{
    std::vector<Vec3> c;
    for (label i = 0; i < mesh.nCells(); ++i) c.push_back(mesh.cellCentre(i));
    return c;
}

} // namespace

TEST(HeatExchange, ParticlesReceiveWhatTheGasGives)
{
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.066, 0.04, 0.114}, 6, 4, 6);
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Particle> particles;
    for (long id = 0; id < 300; ++id)
    {
        Particle p{id,
                   {0.066 * unit(gen), 0.04 * unit(gen), 0.114 * unit(gen)},
                   {unit(gen) - 0.5, unit(gen) - 0.5, unit(gen) - 0.5},
                   3e-3 + 1e-3 * unit(gen)};
        p.temperature = 300.0 + 50.0 * unit(gen);
        particles.push_back(p);
    }
    std::vector<Vec3> U(nCells), gradP(nCells);
    std::vector<double> Tgas(nCells);
    for (std::size_t c = 0; c < nCells; ++c)
    {
        U[c] = Vec3{unit(gen) - 0.5, unit(gen) - 0.5, 2.0 + unit(gen)};
        Tgas[c] = 320.0 + 100.0 * unit(gen);
    }
    const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(mesh, particles);
    const std::vector<double> eps = vfModel->voidFraction(mesh, vf.solidVolume);
    const ExchangeResult momentum =
        gidaspow().compute(mesh, particles, vf, GasCellFields{U, gradP, eps}, airFlow, Vec3{});
    const std::vector<Vec3> centre = centres(mesh);
    const HeatExchange heat = linearExchange();
    const HeatCellCoefficients cells =
        heat.cellCoefficients(mesh, particles, vf.map, momentum, GasHeatCellFields{centre, U, eps}, air);
    const std::vector<double> q = heat.particleHeatFlux(particles, vf.map, cells, Tgas);

    double toParticles = 0.0, fromGas = 0.0, scale = 0.0;
    for (double qi : q) toParticles += qi;
    for (std::size_t c = 0; c < nCells; ++c)
    {
        const double term = mesh.cellVolume(static_cast<label>(c)) * (cells.K[c] * Tgas[c] - cells.S[c]);
        fromGas += term;
        scale += std::fabs(term);
    }
    EXPECT_GT(scale, 1.0); // watts: the test exchanges real heat
    EXPECT_LT(std::fabs(toParticles - fromGas), 1e-12 * scale);
}

TEST(HeatExchange, CellCoefficientsByHand)
{
    // Two cells 5 cm apart along x; the first holds particles of radius 3 and 4 mm
    // at 300 K and 340 K, the second nothing. Gas at rest, particles moving at
    // 1 m/s along x and 2 m/s along y: Us = (27/91, 128/91, 0), |slip| = |Us|.
    const CartesianMesh cells = CartesianMesh::uniform({0, 0, 0}, {0.1, 0.05, 0.05}, 2, 1, 1);
    std::vector<Particle> particles{Particle{1, {0.02, 0.025, 0.025}, {1.0, 0.0, 0.0}, 3e-3},
                                    Particle{2, {0.03, 0.025, 0.025}, {0.0, 2.0, 0.0}, 4e-3}};
    particles[0].temperature = 300.0;
    particles[1].temperature = 340.0;
    const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cells, particles);
    const std::vector<Vec3> U(2), gradP(2);
    const std::vector<double> eps = vfModel->voidFraction(cells, vf.solidVolume);
    const ExchangeResult momentum =
        gidaspow().compute(cells, particles, vf, GasCellFields{U, gradP, eps}, airFlow, Vec3{});
    const std::vector<Vec3> centre = centres(cells);
    const HeatCellCoefficients c = linearExchange().cellCoefficients(cells, particles, vf.map, momentum,
                                                                     GasHeatCellFields{centre, U, eps}, air);

    const double V = 0.05 * 0.05 * 0.05;
    const double solid = 4.0 / 3.0 * pi * (27e-9 + 64e-9);
    const double epsCell = 1.0 - solid / V;
    const double slip = std::sqrt(27.0 * 27.0 + 128.0 * 128.0) / 91.0;
    const double h = 10.0 + 20.0 * slip + 5.0 * epsCell;
    const double a1 = 4.0 * pi * 9e-6, a2 = 4.0 * pi * 16e-6;
    EXPECT_NEAR(c.h[0], h, 1e-12 * h);
    EXPECT_NEAR(c.K[0], h * (a1 + a2) / V, 1e-12 * c.K[0]);
    EXPECT_NEAR(c.S[0], h * (a1 * 300.0 + a2 * 340.0) / V, 1e-12 * c.S[0]);
    // the paper's 6 (1 - eps)/d_32 is the same surface per volume
    EXPECT_NEAR(c.K[0], h * 6.0 * (1.0 - epsCell) / momentum.sauterDiameter[0], 1e-12 * c.K[0]);
    // Re = eps rho |slip| d32 / mu
    const double d32 = 2.0 * 91.0 / 25.0 * 1e-3;
    EXPECT_NEAR(c.reynolds[0], epsCell * air.rho * slip * d32 / air.mu, 1e-10 * c.reynolds[0]);
    EXPECT_EQ(c.region[0], 1);
    // the empty cell exchanges nothing and belongs to no region
    EXPECT_EQ(c.h[1], 0.0);
    EXPECT_EQ(c.K[1], 0.0);
    EXPECT_EQ(c.S[1], 0.0);
    EXPECT_EQ(c.region[1], -1);
}

TEST(HeatExchange, ParticleInUniformGasGetsHATimesDifference)
{
    const CartesianMesh cube({0.0, 0.1}, {0.0, 0.1}, {0.0, 0.1});
    std::vector<Particle> particles{Particle{1, {0.05, 0.05, 0.05}, {}, 4e-3},
                                    Particle{2, {0.05, 0.05, 0.2}, {}, 4e-3}}; // lost: outside
    particles[0].temperature = 306.15;
    const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cube, particles);
    const std::vector<Vec3> U{{0.0, 0.0, 2.0}}, gradP(1);
    const std::vector<double> eps = vfModel->voidFraction(cube, vf.solidVolume);
    const ExchangeResult momentum =
        gidaspow().compute(cube, particles, vf, GasCellFields{U, gradP, eps}, airFlow, Vec3{});
    const std::vector<Vec3> centre{cube.cellCentre(0)};
    const HeatExchange heat = linearExchange();
    const HeatCellCoefficients cells =
        heat.cellCoefficients(cube, particles, vf.map, momentum, GasHeatCellFields{centre, U, eps}, air);
    const std::vector<double> q = heat.particleHeatFlux(particles, vf.map, cells, {423.15});
    const double h = 10.0 + 20.0 * 2.0 + 5.0 * eps[0];
    const double expected = h * 4.0 * pi * 16e-6 * (423.15 - 306.15);
    EXPECT_NEAR(q[0], expected, 1e-12 * expected);
    EXPECT_EQ(q[1], 0.0);
    EXPECT_NEAR(HeatExchange::particleH(vf.map, cells)[0], h, 1e-12 * h);
}
