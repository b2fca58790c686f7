#include "Vec3.hpp"

#include <gtest/gtest.h>

using spoutlab::Vec3;

TEST(Vec3, ArithmeticIsComponentWise)
{
    const Vec3 a{1.0, 2.0, 3.0};
    const Vec3 b{-4.0, 0.5, 2.0};
    const Vec3 s = a + b;
    const Vec3 d = a - b;
    const Vec3 m = 2.0 * a;
    const Vec3 q = a / 4.0;
    EXPECT_DOUBLE_EQ(s.x, -3.0);
    EXPECT_DOUBLE_EQ(s.y, 2.5);
    EXPECT_DOUBLE_EQ(s.z, 5.0);
    EXPECT_DOUBLE_EQ(d.x, 5.0);
    EXPECT_DOUBLE_EQ(d.y, 1.5);
    EXPECT_DOUBLE_EQ(d.z, 1.0);
    EXPECT_DOUBLE_EQ(m.z, 6.0);
    EXPECT_DOUBLE_EQ((a * 2.0).y, 4.0);
    EXPECT_DOUBLE_EQ(q.x, 0.25);
    EXPECT_DOUBLE_EQ((-a).y, -2.0);
}

TEST(Vec3, DotMagAndCross)
{
    const Vec3 a{3.0, 4.0, 12.0};
    EXPECT_DOUBLE_EQ(dot(a, Vec3{1.0, 1.0, 1.0}), 19.0);
    EXPECT_DOUBLE_EQ(magSqr(a), 169.0);
    EXPECT_DOUBLE_EQ(mag(a), 13.0);
    const Vec3 z = cross(Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0});
    EXPECT_DOUBLE_EQ(z.x, 0.0);
    EXPECT_DOUBLE_EQ(z.y, 0.0);
    EXPECT_DOUBLE_EQ(z.z, 1.0);
}
