// The quadratic error function of dual contouring: solve() finds the point
// on every plane it can, and solveInBox() the best point within a box —
// solve()'s own when it lies there, else on the box's faces, still on every
// plane the box allows.
#include "mesh/qef.h"

#include <gtest/gtest.h>

#include <cmath>

using fl::mesh::Qef;
using Point = std::array<double, 3>;

namespace {

Qef twoPlanes(double x0, double z0, int eachTimes = 2) {
    // The planes x = x0 and z = z0 (a crease along y), seen at a few points.
    Qef q;
    for (int i = 0; i < eachTimes; ++i) {
        q.add({x0, 0.1 * i, 0.2}, {1, 0, 0});
        q.add({0.3, 0.1 * i + 0.05, z0}, {0, 0, 1});
    }
    return q;
}

} // namespace

TEST(Qef, InsideTheBoxTheBoxChangesNothing) {
    const Qef q = twoPlanes(0.4, 0.6);
    const Point free = q.solve(0.1);
    const Point boxed = q.solveInBox({0, 0, 0}, {1, 1, 1}, 0.1);
    for (std::size_t a = 0; a < 3; ++a)
        EXPECT_EQ(free[a], boxed[a]);
    EXPECT_NEAR(free[0], 0.4, 1e-12);
    EXPECT_NEAR(free[2], 0.6, 1e-12);
}

TEST(Qef, ACreaseBesideTheBoxPutsThePointOnItsNearestFaceAndStillOnAPlane) {
    // The crease x = 1.2, z = 0.5 lies beside the unit box: the best point
    // within it keeps z = 0.5 (that plane crosses the box) and x on the face.
    const Qef q = twoPlanes(1.2, 0.5);
    const Point p = q.solveInBox({0, 0, 0}, {1, 1, 1}, 0.1);
    EXPECT_DOUBLE_EQ(p[0], 1.0);
    EXPECT_NEAR(p[2], 0.5, 1e-12);
    EXPECT_GE(p[1], 0.0);
    EXPECT_LE(p[1], 1.0);
}

TEST(Qef, AnObliqueCreaseIsFollowedAlongTheHeldFace) {
    // Two planes through C = (0.3, 0.5, 0), on the box's face z = 0, meeting
    // along a line that runs mostly along y (the watermelon's cut meeting its
    // rind); every point seen lies on that line below the face, so solve()
    // answers below it. With z held at 0, x and y must reach C: the reduced
    // system's small eigenvalue (0.04 of the largest) is needed, which
    // solve()'s cutoff of 0.1 would drop, leaving the point off both planes.
    const Point c{0.3, 0.5, 0};
    const double s = std::sqrt(0.5);
    const Point n1{s, 0, -s};
    const double l = std::hypot(0.675, 0.318, 0.666);
    const Point n2{-0.675 / l, -0.318 / l, -0.666 / l};
    const Point d{n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2],
                  n1[0] * n2[1] - n1[1] * n2[0]};
    const double down = d[2] < 0 ? 1 : -1; // along the line, towards z < 0
    auto on = [&](double t) {
        return Point{c[0] + down * t * d[0], c[1] + down * t * d[1], c[2] + down * t * d[2]};
    };
    Qef q;
    for (double t : {0.1, 0.15, 0.2})
        q.add(on(t), n1);
    q.add(on(0.1), n2);
    ASSERT_LT(q.solve(0.1)[2], 0); // the free answer is below the face
    const Point p = q.solveInBox({0, 0, 0}, {1, 1, 1}, 0.1);
    for (std::size_t a = 0; a < 3; ++a)
        EXPECT_NEAR(p[a], c[a], 1e-9) << a;
}

TEST(Qef, NothingAddedOrNotFiniteStaysInTheBox) {
    const Qef empty;
    const Point p = empty.solveInBox({0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(p, (Point{0, 0, 0}));
    Qef q;
    q.add({0.5, 0.5, 0.5}, {0, 0, 1});
    q.add({0.5, 0.5, 0.5}, {0, 0, 1}); // a plane twice: rank one, no wild point
    const Point r = q.solveInBox({0, 0, 0}, {1, 1, 1}, 0.1);
    for (double c : r)
        EXPECT_NEAR(c, 0.5, 1e-12);
}

TEST(Qef, PlanesFarBeyondTheBoxStillGiveAFinitePointInIt) {
    // Planes at +-1.5e308: their differences from the first overflow to
    // infinity; the point must still be a number in the box.
    Qef q;
    q.add({1.5e308, 0, 0}, {1, 0, 0});
    q.add({-1.5e308, 1.5e308, 0}, {0, 1, 0});
    q.add({-1.5e308, -1.5e308, 1.5e308}, {0.6, 0, 0.8});
    const Point p = q.solveInBox({-1, -1, -1}, {1, 1, 1}, 0.1);
    for (double c : p) {
        EXPECT_TRUE(std::isfinite(c));
        EXPECT_GE(c, -1.0);
        EXPECT_LE(c, 1.0);
    }
}
