// Affine maps (field/affine.h): composition, inverse, the column-major matrix
// round trip, and boxes through a map.
#include "field/affine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fl::field;

TEST(Affine, InverseUndoesRandomMaps) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int k = 0; k < 100; ++k) {
        const Affine a =
            Affine::translate(u(rng), u(rng), u(rng)) *
            Affine::rotate(u(rng), u(rng), u(rng), u(rng)) *
            Affine::scale(0.1 + std::abs(u(rng)), -0.1 - std::abs(u(rng)), 1 + u(rng) * 0.4);
        const auto back = a.inverse();
        ASSERT_TRUE(back);
        const Vec3 p{u(rng), u(rng), u(rng)};
        const Vec3 q = back->point(a.point(p));
        for (std::size_t i = 0; i < 3; ++i)
            EXPECT_NEAR(q[i], p[i], 1e-9);
        EXPECT_NEAR(a.determinant() * back->determinant(), 1.0, 1e-9);
        const Affine again = Affine::fromMatrix(a.matrix());
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(again.t[i], a.t[i]);
            for (int j = 0; j < 3; ++j)
                EXPECT_EQ(again.m[i][j], a.m[i][j]);
        }
    }
}

TEST(Affine, SingularMapsHaveNoInverseAndBadRotationsAreIdentity) {
    EXPECT_FALSE(Affine::scale(1, 0, 1).inverse());
    EXPECT_FALSE(Affine::scale(NAN, 1, 1).inverse());
    const Affine r = Affine::rotate(0, 0, 0, 1);
    EXPECT_EQ(r.m[0][0], 1);
    EXPECT_EQ(Affine::rotate({1, 0, 0}).m[1][1], 1); // three numbers are not a rotation
    const Vec3 turned = Affine::rotate({0, 0, 1, M_PI / 2}).point({1, 0, 0});
    EXPECT_NEAR(turned[0], 0, 1e-15);
    EXPECT_NEAR(turned[1], 1, 1e-15);
}

TEST(Affine, BoxBoundsHoldEveryMappedPoint) {
    const Affine a = Affine::rotate({1, 1, 0, 0.7}) * Affine::scale(2, 1, 0.5);
    const Box3 box{{-1, -2, 0}, {1, 0, 3}};
    const Box3 out = boundsOf(box, a);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 1000; ++k) {
        const Vec3 p{box.lo[0] + 2 * u(rng), box.lo[1] + 2 * u(rng), 3 * u(rng)};
        const Vec3 q = a.point(p);
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_GE(q[i], out.lo[i] - 1e-12);
            EXPECT_LE(q[i], out.hi[i] + 1e-12);
        }
    }
}
