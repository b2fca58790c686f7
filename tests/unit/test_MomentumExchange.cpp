// Momentum exchange: beta from the drag law worked out by hand, what the
// particles gain the gas loses (both sides from the hand values), particles
// at rest feel V beta/(1-eps) u, and Us is the volume-weighted particle
// velocity.

#include "CartesianMesh.hpp"
#include "MomentumExchange.hpp"
#include "VoidFractionModel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace spoutlab;

namespace
{

const double pi = std::acos(-1.0);
const GasProperties air{1.2, 1.8e-5};
const Vec3 noGravity{0.0, 0.0, 0.0};

MomentumExchange gidaspowExchange()
{
    return MomentumExchange(DragModel::New("Gidaspow", Parameters("GidaspowProps")));
}

double sphereVolume(double r)
{
    return 4.0 / 3.0 * pi * r * r * r;
}

// Gidaspow's beta written out from docs/DESIGN.md §3.3 (Ergun below eps = 0.8,
// Wen-Yu with the Schiller-Naumann C_d and eps^-2.65 above), independently
// of coupling/Gidaspow.cpp, so the exchange is checked against the law and
// not against whatever beta it happens to carry.
double gidaspowByHand(double eps, double d, double slip)
{
    const double rho = air.rho, mu = air.mu;
    if (eps < 0.8)
    {
        return 150.0 * (1 - eps) * (1 - eps) * mu / (eps * d * d) + 1.75 * (1 - eps) * rho * slip / d;
    }
    const double re = eps * rho * slip * d / mu;
    const double cd = re < 1000.0 ? 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687)) : 0.44;
    return 0.75 * cd * rho * eps * (1 - eps) * slip / d * std::pow(eps, -2.65);
}

// What a cell holds, summed by hand from the particle-cell weights: solid
// volume S, momentum sum w V v, surface sum w A.
struct CellSums
{
    double solid = 0.0, area = 0.0;
    Vec3 momentum;
};

std::vector<CellSums> sumsByHand(std::size_t nCells, const std::vector<Particle>& particles,
                                 const VoidFractionResult& vf)
{
    std::vector<CellSums> sums(nCells);
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        const Particle& p = particles[n];
        for (const CellWeight& cw : vf.map.cells(n))
        {
            CellSums& c = sums[static_cast<std::size_t>(cw.cell)];
            c.solid += cw.weight * sphereVolume(p.radius);
            c.momentum += p.v * (cw.weight * sphereVolume(p.radius));
            c.area += cw.weight * 4.0 * pi * p.radius * p.radius;
        }
    }
    return sums;
}

} // namespace

// Two 20 mm cubes. The left one holds eight particles (radii 4 and 3.5 mm
// alternately, at +-5 mm from its centre, each wholly inside), eps = 0.776:
// Ergun. The right one holds two 3 mm particles, eps = 0.972: Wen-Yu. Every
// number the exchange should produce is worked out here from the particles.
TEST(MomentumExchange, BetaAndBothSidesOfTheExchangeByHand)
{
    const double a = 0.02;
    const CartesianMesh cells = CartesianMesh::uniform({0, 0, 0}, {2 * a, a, a}, 2, 1, 1);
    std::vector<Particle> particles;
    long id = 0;
    for (int i = 0; i < 2; ++i)
    {
        for (int j = 0; j < 2; ++j)
        {
            for (int k = 0; k < 2; ++k, ++id)
            {
                const Vec3 x{0.01 + (i ? 5e-3 : -5e-3), 0.01 + (j ? 5e-3 : -5e-3), 0.01 + (k ? 5e-3 : -5e-3)};
                const Vec3 v{0.1 * i - 0.05, 0.02 * j, 0.3 * k - 0.1 * i};
                particles.push_back(Particle{id, x, v, (i + j + k) % 2 ? 3.5e-3 : 4e-3});
            }
        }
    }
    particles.push_back(Particle{8, {0.03, 0.01, 0.006}, {0.0, 0.0, -0.2}, 3e-3});
    particles.push_back(Particle{9, {0.031, 0.011, 0.014}, {0.05, 0.0, 0.4}, 3e-3});
    const std::vector<Vec3> U{{0.1, 0.0, 1.2}, {-0.2, 0.1, 2.5}};
    const std::vector<Vec3> gradP{{0.0, 0.0, -3000.0}, {0.0, 0.0, -200.0}};

    // by hand: per cell S, phi, eps, Us, Sauter d, slip, beta
    const double cellVolume = a * a * a;
    const std::size_t inCell[2][2] = {{0, 8}, {8, 10}}; // particle index ranges
    double phi[2], eps[2], beta[2];
    Vec3 Us[2];
    for (int c = 0; c < 2; ++c)
    {
        double solid = 0.0, area = 0.0;
        Vec3 momentum;
        for (std::size_t n = inCell[c][0]; n < inCell[c][1]; ++n)
        {
            const double r = particles[n].radius;
            solid += sphereVolume(r);
            area += 4.0 * pi * r * r;
            momentum += particles[n].v * sphereVolume(r);
        }
        phi[c] = solid / cellVolume;
        eps[c] = 1.0 - phi[c];
        Us[c] = momentum / solid;
        beta[c] = gidaspowByHand(eps[c], 6.0 * solid / area, mag(U[c] - Us[c]));
    }
    ASSERT_LT(eps[0], 0.8); // the scene tests both branches
    ASSERT_GT(eps[1], 0.8);

    const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cells, particles);
    const std::vector<double> epsField{eps[0], eps[1]};
    const ExchangeResult r =
        gidaspowExchange().compute(cells, particles, vf, GasCellFields{U, gradP, epsField}, air, noGravity);

    Vec3 toParticles, fromGas;
    for (int c = 0; c < 2; ++c)
    {
        EXPECT_NEAR(r.beta[c], beta[c], 1e-12 * beta[c]) << "cell " << c;
        EXPECT_LT(mag(r.Us[c] - Us[c]), 1e-14) << "cell " << c;
        for (std::size_t n = inCell[c][0]; n < inCell[c][1]; ++n)
        {
            // F_i = V_i beta/(1 - eps) (u - v_i), the particle wholly in its cell
            const Vec3 drag =
                (U[c] - particles[n].v) * (sphereVolume(particles[n].radius) * beta[c] / phi[c]);
            EXPECT_LT(mag(r.dragForce[n] - drag), 1e-12 * mag(drag)) << "particle " << n;
            toParticles += r.dragForce[n];
        }
        fromGas += (U[c] - Us[c]) * (beta[c] * cellVolume);
    }
    // what the gas equation's beta (Us - u) takes from the gas, from the hand
    // beta and Us, is what the particles receive
    EXPECT_LT(mag(toParticles - fromGas), 1e-12 * mag(fromGas));
}

// 300 random particles in 36 cells, many cut by faces, in dense cells
// (clipped at eps = 0.3) and dilute ones: beta of every cell from the law by
// hand (with the cell sums taken from the particle-cell weights), and the
// gas side sum_c beta V (u - Us) from those hand values against the sum of
// the particle drags.
TEST(MomentumExchange, ParticleDragBalancesGasMomentumLoss)
{
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.066, 0.04, 0.114}, 6, 4, 6);
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Particle> particles;
    for (long id = 0; id < 300; ++id)
    {
        // denser towards the bottom, so the cells span both branches of the law
        const double z = 0.114 * unit(gen) * unit(gen);
        const Vec3 x{0.066 * unit(gen), 0.04 * unit(gen), z};
        const Vec3 v{unit(gen) - 0.5, unit(gen) - 0.5, unit(gen) - 0.5};
        particles.push_back(Particle{id, x, v, 3e-3 + 1e-3 * unit(gen)});
    }
    std::vector<Vec3> U(nCells), gradP(nCells);
    for (std::size_t c = 0; c < nCells; ++c)
    {
        U[c] = Vec3{unit(gen) - 0.5, unit(gen) - 0.5, 2.0 + unit(gen)}; // net upflow
        gradP[c] = Vec3{0.0, 0.0, -1000.0 * unit(gen)};
    }
    for (const std::string vfName : {"divided", "centre"})
    {
        const auto vfModel = VoidFractionModel::New(vfName, Parameters("vf"));
        const VoidFractionResult vf = vfModel->compute(mesh, particles);
        const std::vector<CellSums> sums = sumsByHand(nCells, particles, vf);
        std::vector<double> eps(nCells);
        for (std::size_t c = 0; c < nCells; ++c)
        {
            eps[c] = std::max(1.0 - sums[c].solid / mesh.cellVolume(static_cast<label>(c)), 0.3);
        }
        const ExchangeResult r = gidaspowExchange().compute(mesh, particles, vf, GasCellFields{U, gradP, eps},
                                                            air, Vec3{0, 0, -9.81});
        Vec3 toParticles, fromGas;
        int dense = 0, dilute = 0;
        for (const Vec3& f : r.dragForce) toParticles += f;
        for (std::size_t c = 0; c < nCells; ++c)
        {
            if (sums[c].solid <= 0.0) continue;
            const Vec3 Us = sums[c].momentum / sums[c].solid;
            const double beta = gidaspowByHand(eps[c], 6.0 * sums[c].solid / sums[c].area, mag(U[c] - Us));
            EXPECT_NEAR(r.beta[c], beta, 1e-12 * beta) << vfName << " cell " << c;
            fromGas += (U[c] - Us) * (beta * mesh.cellVolume(static_cast<label>(c)));
            (eps[c] < 0.8 ? dense : dilute) += 1;
        }
        EXPECT_GT(dense, 0) << vfName;
        EXPECT_GT(dilute, 0) << vfName;
        EXPECT_LT(mag(toParticles - fromGas), 1e-12 * mag(fromGas)) << vfName;
    }
}

TEST(MomentumExchange, ParticlesAtRestInUniformGas)
{
    // One 10 cm cube, five 8 mm particles at rest, unclipped eps = 1 - S/V.
    const CartesianMesh cube({0.0, 0.1}, {0.0, 0.1}, {0.0, 0.1});
    const double r = 4e-3;
    std::vector<Particle> particles;
    for (long id = 0; id < 5; ++id)
        particles.push_back(Particle{id, {0.02 + 0.015 * static_cast<double>(id), 0.05, 0.05}, {}, r});
    const auto vfModel = VoidFractionModel::New("centre", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cube, particles);
    const double volume = sphereVolume(r);
    const double eps = 1.0 - 5.0 * volume / 1e-3;
    const std::vector<Vec3> U{{0.0, 0.0, 1.5}};
    const std::vector<Vec3> gradP{{0.0, 0.0, -2000.0}};
    const std::vector<double> epsField{eps};
    const Vec3 g{0.0, 0.0, -9.81};
    const ExchangeResult res =
        gidaspowExchange().compute(cube, particles, vf, GasCellFields{U, gradP, epsField}, air, g);

    const auto drag = DragModel::New("Gidaspow", Parameters("GidaspowProps"));
    const double beta = drag->beta(DragState{eps, 2 * r, 1.5}, air);
    EXPECT_NEAR(res.beta[0], beta, 1e-12 * beta);
    for (std::size_t n = 0; n < particles.size(); ++n)
    {
        const double expectedDrag = volume * beta / (1.0 - eps) * 1.5;
        EXPECT_NEAR(res.dragForce[n].z, expectedDrag, 1e-12 * expectedDrag);
        EXPECT_EQ(res.dragForce[n].x, 0.0);
        // -V grad(p) - rho_g g V = V (2000 + 1.2 * 9.81), upwards
        const double expectedPressure = volume * (2000.0 + 1.2 * 9.81);
        EXPECT_NEAR(res.pressureForce[n].z, expectedPressure, 1e-12 * expectedPressure);
        EXPECT_NEAR(res.totalForce[n].z, expectedDrag + expectedPressure, 1e-12 * expectedPressure);
    }
}

TEST(MomentumExchange, UsIsVolumeWeightedAndDiameterIsSauter)
{
    // Radii 3 mm and 4 mm (volumes in ratio 27:64) moving along x and y.
    const CartesianMesh cells = CartesianMesh::uniform({0, 0, 0}, {0.1, 0.05, 0.05}, 2, 1, 1);
    const std::vector<Particle> particles{Particle{1, {0.02, 0.025, 0.025}, {1.0, 0.0, 0.0}, 3e-3},
                                          Particle{2, {0.03, 0.025, 0.025}, {0.0, 2.0, 0.0}, 4e-3}};
    const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cells, particles);
    const std::vector<Vec3> U(2), gradP(2);
    const std::vector<double> eps = vfModel->voidFraction(cells, vf.solidVolume);
    const ExchangeResult r =
        gidaspowExchange().compute(cells, particles, vf, GasCellFields{U, gradP, eps}, air, noGravity);
    EXPECT_NEAR(r.Us[0].x, 27.0 / 91.0, 1e-14);
    EXPECT_NEAR(r.Us[0].y, 2.0 * 64.0 / 91.0, 1e-14);
    // d32 = 6 sum V / sum pi d^2 = 2 sum r^3 / sum r^2 = 2 (27 + 64)/(9 + 16) mm
    EXPECT_NEAR(r.sauterDiameter[0], 2.0 * 91.0 / 25.0 * 1e-3, 1e-15);
    EXPECT_NEAR(r.solidFraction[0], (sphereVolume(3e-3) + sphereVolume(4e-3)) / (0.05 * 0.05 * 0.05), 1e-14);
    // The empty cell exchanges nothing.
    EXPECT_EQ(r.beta[1], 0.0);
    EXPECT_EQ(mag(r.Us[1]), 0.0);
    EXPECT_EQ(r.solidFraction[1], 0.0);
}

TEST(MomentumExchange, LostParticleGetsNoForce)
{
    const CartesianMesh cube({0.0, 0.1}, {0.0, 0.1}, {0.0, 0.1});
    const std::vector<Particle> particles{Particle{1, {0.05, 0.05, 0.05}, {}, 4e-3},
                                          Particle{2, {0.05, 0.05, 0.2}, {}, 4e-3}};
    const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cube, particles);
    const std::vector<Vec3> U{{0.0, 0.0, 1.0}}, gradP{{0.0, 0.0, -100.0}};
    const std::vector<double> eps = vfModel->voidFraction(cube, vf.solidVolume);
    const ExchangeResult r =
        gidaspowExchange().compute(cube, particles, vf, GasCellFields{U, gradP, eps}, air, Vec3{0, 0, -9.81});
    EXPECT_GT(r.totalForce[0].z, 0.0);
    EXPECT_EQ(mag(r.totalForce[1]), 0.0);
}

TEST(MomentumExchange, MismatchedSizesAreRejected)
{
    const CartesianMesh cube({0.0, 0.1}, {0.0, 0.1}, {0.0, 0.1});
    const std::vector<Particle> particles{Particle{1, {0.05, 0.05, 0.05}, {}, 4e-3}};
    const auto vfModel = VoidFractionModel::New("centre", Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(cube, particles);
    const std::vector<Vec3> U(2), gradP(1);
    const std::vector<double> eps{0.9};
    EXPECT_THROW(
        gidaspowExchange().compute(cube, particles, vf, GasCellFields{U, gradP, eps}, air, noGravity),
        std::invalid_argument);
}
