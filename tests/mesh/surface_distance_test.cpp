// Exact distances between meshes: the point-to-triangle distance against a
// brute-force minimum over a fine sampling of the triangle, the tree against
// every triangle, and the two-way figures on known shapes.
#include "mesh/standard_geometry.h"
#include "mesh/surface_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fl::mesh;

TEST(SurfaceDistance, PointToTriangleIsTheNearestPointOfTheTriangle) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> d(-1, 1);
    for (int trial = 0; trial < 200; ++trial) {
        const Point3 a{d(rng), d(rng), d(rng)}, b{d(rng), d(rng), d(rng)},
            c = trial % 10 == 0 ? a : Point3{d(rng), d(rng), d(rng)}; // some degenerate
        const Point3 p{2 * d(rng), 2 * d(rng), 2 * d(rng)};
        double best = 1e300;
        const int n = 200;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const double s = double(i) / n, t = double(j) / n;
                Point3 q;
                for (int k = 0; k < 3; ++k)
                    q[std::size_t(k)] = a[std::size_t(k)] +
                                        s * (b[std::size_t(k)] - a[std::size_t(k)]) +
                                        t * (c[std::size_t(k)] - a[std::size_t(k)]);
                best = std::min(best, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
            }
        const double exact = std::sqrt(squaredDistanceToTriangle(p, a, b, c));
        EXPECT_LE(exact, best + 1e-12);
        EXPECT_NEAR(exact, best, 0.02) << trial; // the sampling's own spacing
    }
}

TEST(SurfaceDistance, TheTreeFindsWhatEveryTriangleWouldAndTwoWaysAreMeasured) {
    const Mesh sphere = sphereMesh(1.0, 24);
    const TriangleTree tree(sphere);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> d(-2, 2);
    for (int trial = 0; trial < 100; ++trial) {
        const Point3 p{d(rng), d(rng), d(rng)};
        double brute = 1e300;
        for (const auto& t : sphere.triangles) {
            auto at = [&](std::uint32_t v) {
                return Point3{sphere.positions[v][0], sphere.positions[v][1],
                              sphere.positions[v][2]};
            };
            brute = std::min(brute, squaredDistanceToTriangle(p, at(t[0]), at(t[1]), at(t[2])));
        }
        EXPECT_DOUBLE_EQ(tree.squaredDistance(p), brute);
    }
    // A mesh against itself: zero. Against a copy moved by 0.1: 0.1 at most.
    EXPECT_LT(compareSurfaces(sphere, sphere, 2000).hausdorff, 1e-12);
    Mesh moved = sphere;
    for (auto& p : moved.positions)
        p[0] += 0.1f;
    const SurfaceDistance s = compareSurfaces(sphere, moved, 20000);
    EXPECT_GT(s.hausdorff, 0.09);
    EXPECT_LE(s.hausdorff, 0.1 + 1e-6);
    EXPECT_GT(s.rms, 0.01);
    EXPECT_LT(s.rms, 0.1);
}
