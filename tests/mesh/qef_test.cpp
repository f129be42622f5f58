// The quadratic error function of dual contouring: solve() finds the point
// on every plane it can, and solveInBox() the best point within a box —
// solve()'s own when it lies there, else on the box's faces, still on every
// plane the box allows; solveOnPlanes() the best point on planes it is
// told (a closed box's faces).
#include "mesh/qef.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

TEST(Qef, AShallowCreaseOnAHeldFaceIsFoundThere) {
    // The face y = 1 (seen at three points) and a plane 20 degrees from it
    // through the line x = 0.3, y = 1 (seen at three points below the
    // face): a crease whose small eigenvalue (about 0.03 of the largest)
    // solve()'s cutoff of 0.1 drops, leaving the point between the planes.
    // Held on the face, the crease is the one strong direction left.
    const double a = 20 * M_PI / 180;
    const Point n{std::sin(a), std::cos(a), 0};
    Qef q;
    for (double z : {0.2, 0.5, 0.8})
        q.add({0.5, 1, z}, {0, 1, 0});
    for (double t : {0.1, 0.2, 0.3}) // on the plane, down its slope from the crease
        q.add({0.3 + t * n[1], 1 - t * n[0], 0.5 + t - 0.2}, n);
    const Point free = q.solveInBox({0, 0.5, 0}, {1, 1.5, 1}, 0.1);
    const auto offPlane = [&](const Point& p) {
        return std::abs(n[0] * (p[0] - 0.3) + n[1] * (p[1] - 1));
    };
    EXPECT_GT(offPlane(free), 1e-2); // the failure this guards against
    const Point held =
        q.solveOnPlanes({false, true, false}, {0, 1, 0}, {0, 0.5, 0}, {1, 1.5, 1}, 0.1);
    EXPECT_EQ(held[1], 1.0);
    EXPECT_NEAR(held[0], 0.3, 1e-12);
    EXPECT_LT(offPlane(held), 1e-12);
    EXPECT_GE(held[2], 0.0); // along the crease: the mass point's place, in the box
    EXPECT_LE(held[2], 1.0);
}

TEST(Qef, HeldOnTwoFacesOnlyTheirLineIsFree) {
    // The edge where the faces x = 1 and z = 0 meet, crossed by the plane
    // y = 0.4: the corner (1, 0.4, 0), whatever the cutoff.
    Qef q;
    q.add({1, 0.2, 0.3}, {1, 0, 0});
    q.add({0.6, 0.5, 0}, {0, 0, 1});
    q.add({0.9, 0.4, 0.1}, {0, 1, 0});
    const Point p = q.solveOnPlanes({true, false, true}, {1, 0, 0}, {0, 0, -1}, {2, 1, 1}, 0.1);
    EXPECT_EQ(p[0], 1.0);
    EXPECT_EQ(p[2], 0.0);
    EXPECT_NEAR(p[1], 0.4, 1e-12);
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

// A curved patch (a cell of a sphere at a low resolution): its normals
// disagree by a few degrees, too much for the mean normal to stand for them,
// but one eigenvalue of A^T A dominates and the truncation keeps only its
// direction. solve() takes it by power iteration from the mean normal; the
// answer is the eigen-decomposition's.
TEST(Qef, ACurvedPatchKeepsOnlyItsDominantDirectionAsTheEigenSolverDoes) {
    const double radius = 0.8;
    std::vector<Point> points, normals;
    for (int i = 0; i < 6; ++i) { // up to 4 degrees from the direction (1, 1, 1)
        const double a = 0.07 * std::cos(1.3 * i), b = 0.05 * std::sin(2.1 * i);
        Eigen::Vector3d n = Eigen::Vector3d(1, 1, 1).normalized() +
                            a * Eigen::Vector3d(1, -1, 0).normalized() +
                            b * Eigen::Vector3d(1, 1, -2).normalized();
        n.normalize();
        points.push_back({radius * n[0], radius * n[1], radius * n[2]});
        normals.push_back({n[0], n[1], n[2]});
    }
    Qef q;
    for (std::size_t i = 0; i < points.size(); ++i)
        q.add(points[i], normals[i]);

    // The reference, from the same sums by Eigen's iterative solver.
    const Eigen::Vector3d origin(points[0][0], points[0][1], points[0][2]);
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Vector3d atb = Eigen::Vector3d::Zero(), mass = Eigen::Vector3d::Zero(),
                    nsum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d n(normals[i][0], normals[i][1], normals[i][2]);
        const Eigen::Vector3d p =
            Eigen::Vector3d(points[i][0], points[i][1], points[i][2]) - origin;
        ata += n * n.transpose();
        atb += n * n.dot(p);
        mass += p;
        nsum += n;
    }
    mass /= double(points.size());
    const double cutoff = 0.1;
    ASSERT_LT(nsum.norm() / double(points.size()), 0.9995) << "the mean-normal case";
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(ata);
    const Eigen::Vector3d values = eig.eigenvalues();
    ASSERT_LT(values[0] + values[1], cutoff * values[2]) << "one direction dominates";
    const Eigen::Vector3d mean = nsum.normalized();
    const double r0 = mean.dot(ata * mean);
    ASSERT_LT(ata.trace() - r0, cutoff * r0) << "and the mean normal shows it (the fast path)";
    const Eigen::Vector3d rhs = atb - ata * mass;
    const Eigen::Vector3d v = eig.eigenvectors().col(2);
    const Eigen::Vector3d expected = origin + mass + v * (v.dot(rhs) / values[2]);

    const Point got = q.solve(cutoff);
    for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(got[std::size_t(a)], expected[a], 1e-14) << "axis " << a;
    // And it lies on the sphere to the order of the patch's curvature.
    const double r = std::sqrt(got[0] * got[0] + got[1] * got[1] + got[2] * got[2]);
    EXPECT_NEAR(r, radius, 1e-2);
}
