// Momentum exchange: what the particles gain the gas loses, particles at rest
// feel V beta/(1-eps) u, and Us is the volume-weighted particle velocity.

#include "CartesianMesh.hpp"
#include "MomentumExchange.hpp"
#include "VoidFractionModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace spoutlab;

namespace {

const double pi = std::acos(-1.0);
const GasProperties air{1.2, 1.8e-5};
const Vec3 noGravity{0.0, 0.0, 0.0};

MomentumExchange gidaspowExchange() {
  return MomentumExchange(DragModel::New("Gidaspow", Parameters("GidaspowProps")));
}

double sphereVolume(double r) { return 4.0 / 3.0 * pi * r * r * r; }

}  // namespace

TEST(MomentumExchange, ParticleDragBalancesGasMomentumLoss) {
  const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.066, 0.04, 0.114}, 6, 4, 6);
  const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Particle> particles;
  for (long id = 0; id < 300; ++id) {
    const Vec3 x{0.066 * unit(gen), 0.04 * unit(gen), 0.114 * unit(gen)};
    const Vec3 v{unit(gen) - 0.5, unit(gen) - 0.5, unit(gen) - 0.5};
    particles.push_back(Particle{id, x, v, 3e-3 + 1e-3 * unit(gen)});
  }
  std::vector<Vec3> U(nCells), gradP(nCells);
  for (std::size_t c = 0; c < nCells; ++c) {
    U[c] = Vec3{unit(gen) - 0.5, unit(gen) - 0.5, 2.0 + unit(gen)};  // net upflow
    gradP[c] = Vec3{0.0, 0.0, -1000.0 * unit(gen)};
  }
  for (const std::string vfName : {"divided", "centre"}) {
    const auto vfModel = VoidFractionModel::New(vfName, Parameters("vf"));
    const VoidFractionResult vf = vfModel->compute(mesh, particles);
    const std::vector<double> eps = vfModel->voidFraction(mesh, vf.solidVolume);
    const ExchangeResult r = gidaspowExchange().compute(mesh, particles, vf, GasCellFields{U, gradP, eps}, air,
                                                        Vec3{0, 0, -9.81});
    Vec3 toParticles, fromGas;
    double scale = 0.0;
    for (const Vec3& f : r.dragForce) toParticles += f;
    for (std::size_t c = 0; c < nCells; ++c) {
      const Vec3 term = (U[c] - r.Us[c]) * (r.beta[c] * mesh.cellVolume(static_cast<label>(c)));
      fromGas += term;
      scale += mag(term);
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(mag(toParticles - fromGas), 1e-12 * mag(fromGas)) << vfName;
  }
}

TEST(MomentumExchange, ParticlesAtRestInUniformGas) {
  // One 10 cm cube, five 8 mm particles at rest, unclipped eps = 1 - S/V.
  const CartesianMesh cube({0.0, 0.1}, {0.0, 0.1}, {0.0, 0.1});
  const double r = 4e-3;
  std::vector<Particle> particles;
  for (long id = 0; id < 5; ++id) particles.push_back(Particle{id, {0.02 + 0.015 * static_cast<double>(id), 0.05, 0.05}, {}, r});
  const auto vfModel = VoidFractionModel::New("centre", Parameters("vf"));
  const VoidFractionResult vf = vfModel->compute(cube, particles);
  const double volume = sphereVolume(r);
  const double eps = 1.0 - 5.0 * volume / 1e-3;
  const std::vector<Vec3> U{{0.0, 0.0, 1.5}};
  const std::vector<Vec3> gradP{{0.0, 0.0, -2000.0}};
  const std::vector<double> epsField{eps};
  const Vec3 g{0.0, 0.0, -9.81};
  const ExchangeResult res = gidaspowExchange().compute(cube, particles, vf, GasCellFields{U, gradP, epsField}, air, g);

  const auto drag = DragModel::New("Gidaspow", Parameters("GidaspowProps"));
  const double beta = drag->beta(DragState{eps, 2 * r, 1.5}, air);
  EXPECT_NEAR(res.beta[0], beta, 1e-12 * beta);
  for (std::size_t n = 0; n < particles.size(); ++n) {
    const double expectedDrag = volume * beta / (1.0 - eps) * 1.5;
    EXPECT_NEAR(res.dragForce[n].z, expectedDrag, 1e-12 * expectedDrag);
    EXPECT_EQ(res.dragForce[n].x, 0.0);
    // -V grad(p) - rho_g g V = V (2000 + 1.2 * 9.81), upwards
    const double expectedPressure = volume * (2000.0 + 1.2 * 9.81);
    EXPECT_NEAR(res.pressureForce[n].z, expectedPressure, 1e-12 * expectedPressure);
    EXPECT_NEAR(res.totalForce[n].z, expectedDrag + expectedPressure, 1e-12 * expectedPressure);
  }
}

TEST(MomentumExchange, UsIsVolumeWeightedAndDiameterIsSauter) {
  // Radii 3 mm and 4 mm (volumes in ratio 27:64) moving along x and y.
  const CartesianMesh cells = CartesianMesh::uniform({0, 0, 0}, {0.1, 0.05, 0.05}, 2, 1, 1);
  const std::vector<Particle> particles{Particle{1, {0.02, 0.025, 0.025}, {1.0, 0.0, 0.0}, 3e-3},
                                        Particle{2, {0.03, 0.025, 0.025}, {0.0, 2.0, 0.0}, 4e-3}};
  const auto vfModel = VoidFractionModel::New("divided", Parameters("vf"));
  const VoidFractionResult vf = vfModel->compute(cells, particles);
  const std::vector<Vec3> U(2), gradP(2);
  const std::vector<double> eps = vfModel->voidFraction(cells, vf.solidVolume);
  const ExchangeResult r = gidaspowExchange().compute(cells, particles, vf, GasCellFields{U, gradP, eps}, air, noGravity);
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

TEST(MomentumExchange, LostParticleGetsNoForce) {
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

TEST(MomentumExchange, MismatchedSizesAreRejected) {
  const CartesianMesh cube({0.0, 0.1}, {0.0, 0.1}, {0.0, 0.1});
  const std::vector<Particle> particles{Particle{1, {0.05, 0.05, 0.05}, {}, 4e-3}};
  const auto vfModel = VoidFractionModel::New("centre", Parameters("vf"));
  const VoidFractionResult vf = vfModel->compute(cube, particles);
  const std::vector<Vec3> U(2), gradP(1);
  const std::vector<double> eps{0.9};
  EXPECT_THROW(gidaspowExchange().compute(cube, particles, vf, GasCellFields{U, gradP, eps}, air, noGravity),
               std::invalid_argument);
}
