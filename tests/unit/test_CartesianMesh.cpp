#include "CartesianMesh.hpp"
#include "InputError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace spoutlab;

namespace
{

// Graded in x (widths 1, 2, 3), one cell in y, two in z.
CartesianMesh gradedMesh()
{
    return CartesianMesh({0.0, 1.0, 3.0, 6.0}, {0.0, 2.0}, {-1.0, 0.0, 1.0});
}

} // namespace

TEST(CartesianMesh, CountsNumberingAndVolumes)
{
    const CartesianMesh m = gradedMesh();
    EXPECT_EQ(m.nCells(), 6);
    EXPECT_EQ(m.cellIndex(1, 0, 1), 4); // i + nx (j + ny k) = 1 + 3 (0 + 1)
    EXPECT_DOUBLE_EQ(m.cellVolume(0), 1.0 * 2.0 * 1.0);
    EXPECT_DOUBLE_EQ(m.cellVolume(4), 2.0 * 2.0 * 1.0);
    EXPECT_DOUBLE_EQ(m.cellVolume(5), 3.0 * 2.0 * 1.0);
    double total = 0.0;
    for (label c = 0; c < m.nCells(); ++c) total += m.cellVolume(c);
    EXPECT_DOUBLE_EQ(total, 6.0 * 2.0 * 2.0);
}

TEST(CartesianMesh, PointsInside)
{
    const CartesianMesh m = gradedMesh();
    EXPECT_EQ(m.findCell({0.5, 1.0, -0.5}, -1), m.cellIndex(0, 0, 0));
    EXPECT_EQ(m.findCell({2.0, 1.0, 0.5}, -1), m.cellIndex(1, 0, 1));
    EXPECT_EQ(m.findCell({5.9, 0.1, 0.9}, 0), m.cellIndex(2, 0, 1));
}

TEST(CartesianMesh, InteriorFacesBelongToThePlusSide)
{
    const CartesianMesh m = gradedMesh();
    EXPECT_EQ(m.findCell({1.0, 1.0, -0.5}, -1), m.cellIndex(1, 0, 0));
    EXPECT_EQ(m.findCell({3.0, 1.0, -0.5}, -1), m.cellIndex(2, 0, 0));
    EXPECT_EQ(m.findCell({0.5, 1.0, 0.0}, -1), m.cellIndex(0, 0, 1));
    EXPECT_EQ(m.findCell({3.0, 1.0, 0.0}, -1), m.cellIndex(2, 0, 1)); // interior edge
    // Just below a face stays on the - side.
    EXPECT_EQ(m.findCell({std::nextafter(1.0, 0.0), 1.0, -0.5}, -1), m.cellIndex(0, 0, 0));
}

TEST(CartesianMesh, OuterBoundaryIsInside)
{
    const CartesianMesh m = gradedMesh();
    EXPECT_EQ(m.findCell({0.0, 1.0, -0.5}, -1), m.cellIndex(0, 0, 0));
    EXPECT_EQ(m.findCell({6.0, 1.0, -0.5}, -1), m.cellIndex(2, 0, 0));
    EXPECT_EQ(m.findCell({2.0, 2.0, -0.5}, -1), m.cellIndex(1, 0, 0));
    EXPECT_EQ(m.findCell({2.0, 0.0, 1.0}, -1), m.cellIndex(1, 0, 1));
    EXPECT_EQ(m.findCell({0.0, 0.0, -1.0}, -1), m.cellIndex(0, 0, 0)); // corners
    EXPECT_EQ(m.findCell({6.0, 2.0, 1.0}, -1), m.cellIndex(2, 0, 1));
}

TEST(CartesianMesh, SlightlyOutsideIsMinusOne)
{
    const CartesianMesh m = gradedMesh();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(m.findCell({-1e-12, 1.0, 0.5}, -1), -1);
    EXPECT_EQ(m.findCell({std::nextafter(6.0, 7.0), 1.0, 0.5}, -1), -1);
    EXPECT_EQ(m.findCell({2.0, 2.0 + 1e-12, 0.5}, -1), -1);
    EXPECT_EQ(m.findCell({2.0, 1.0, -1.0 - 1e-12}, -1), -1);
    EXPECT_EQ(m.findCell({2.0, 1.0, 1.0 + 1e-12}, 3), -1);
    EXPECT_EQ(m.findCell({nan, 1.0, 0.5}, -1), -1);
}

TEST(CartesianMesh, SphereInsideCell)
{
    const CartesianMesh m = gradedMesh();
    const label c = m.cellIndex(1, 0, 1); // [1,3] x [0,2] x [0,1]
    EXPECT_TRUE(m.sphereInsideCell(c, {2.0, 1.0, 0.5}, 0.4));
    EXPECT_TRUE(m.sphereInsideCell(c, {2.0, 1.0, 0.5}, 0.5));  // touching top and bottom
    EXPECT_FALSE(m.sphereInsideCell(c, {2.0, 1.0, 0.5}, 0.6)); // through z faces
    EXPECT_FALSE(m.sphereInsideCell(c, {1.1, 1.0, 0.5}, 0.2)); // through x = 1
}

TEST(CartesianMesh, UniformFactoryAndGeometry)
{
    const CartesianMesh m = CartesianMesh::uniform({0, 0, 0}, {0.099, 0.04, 0.19}, 9, 4, 10);
    EXPECT_EQ(m.nCells(), 360);
    EXPECT_NEAR(m.cellVolume(17), 0.011 * 0.01 * 0.019, 1e-18);
    const Vec3 centre = m.cellCentre(m.cellIndex(8, 3, 9));
    EXPECT_NEAR(centre.x, 0.0935, 1e-15);
    EXPECT_NEAR(centre.z, 0.1805, 1e-15);
    EXPECT_EQ(m.findCell({0.099, 0.04, 0.19}, -1), m.nCells() - 1);
}

TEST(CartesianMesh, RejectsUnsortedOrShortFaceLists)
{
    EXPECT_THROW(CartesianMesh({0.0, 1.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}), InputError);
    EXPECT_THROW(CartesianMesh({0.0, 2.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}), InputError);
    EXPECT_THROW(CartesianMesh({0.0}, {0.0, 1.0}, {0.0, 1.0}), InputError);
    EXPECT_THROW(CartesianMesh::uniform({0, 0, 0}, {1, 1, 1}, 0, 1, 1), InputError);
}

TEST(CartesianMesh, ClearanceIsTheDistanceToTheNearestFace)
{
    // 11 mm x 10 mm x 19 mm cells; (5, 13, 100) mm is 3 mm from its cell's
    // nearest face (y = 10 mm), 5 from x = 0 and from z = 95 mm
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.099, 0.04, 0.19}, 9, 4, 10);
    const Vec3 p{0.005, 0.013, 0.1};
    EXPECT_NEAR(mesh.clearance(p, mesh.findCell(p, -1)), 0.003, 1e-15);
    // on a face (to round-off): none; outside: the distance beyond the box along one axis
    EXPECT_LT(mesh.clearance({0.022, 0.013, 0.1}, mesh.findCell({0.022, 0.013, 0.1}, -1)), 1e-15);
    EXPECT_NEAR(mesh.clearance({0.05, 0.02, 0.2}, -1), 0.01, 1e-15);
}

TEST(CartesianMesh, APointMovedLessThanItsClearanceStaysInItsCell)
{
    const CartesianMesh mesh = CartesianMesh::uniform({0, 0, 0}, {0.099, 0.04, 0.19}, 9, 4, 10);
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-0.02, 1.02), d(-1.0, 1.0);
    int moved = 0;
    for (int n = 0; n < 2000; ++n)
    {
        const Vec3 p{0.099 * u(gen), 0.04 * u(gen), 0.19 * u(gen)};
        const label cell = mesh.findCell(p, -1);
        const double c = mesh.clearance(p, cell);
        for (int k = 0; k < 10 && c > 0; ++k, ++moved)
        {
            Vec3 dir{d(gen), d(gen), d(gen)};
            dir = dir / mag(dir);
            EXPECT_EQ(mesh.findCell(p + dir * (0.999 * c), cell), cell);
        }
    }
    EXPECT_GT(moved, 15000);
}
