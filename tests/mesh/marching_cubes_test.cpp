// The dense marching-cubes baseline: its generated case table closes every
// surface, faces outward, and it evaluates every grid corner exactly once.
#include "mesh/marching_cubes.h"
#include "mesh/mesh_error.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace fl::mesh;

namespace {

// The triangle soup welded by position, so its topology can be checked.
Mesh welded(const Mesh& soup) {
    Mesh m;
    std::map<std::array<float, 3>, std::uint32_t> index;
    std::vector<std::uint32_t> remap;
    for (const Vec3f& p : soup.positions) {
        auto [it, added] = index.emplace(p, std::uint32_t(m.positions.size()));
        if (added) m.positions.push_back(p);
        remap.push_back(it->second);
    }
    for (const Triangle& t : soup.triangles) {
        const Triangle w{remap[t[0]], remap[t[1]], remap[t[2]]};
        if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) m.triangles.push_back(w);
    }
    return m;
}

} // namespace

TEST(MarchingCubes, SphereIsClosedOutwardAndEvaluatesEveryCorner) {
    const ImplicitField f = support::field("0.8^2 - x*x - y*y - z*z", 1.0, BoxBoundary::Open);
    const DenseResult r = marchingCubes(f, 32, 2);
    // Every corner once, and the plane between the two slabs once more.
    EXPECT_EQ(r.evaluations.points, std::size_t(33 * 33 * 33 + 33 * 33));
    const Topology t = analyseTopology(welded(r.mesh));
    EXPECT_TRUE(t.closed());
    EXPECT_TRUE(t.consistentlyOriented());
    const double exact = 4.0 / 3.0 * M_PI * 0.512;
    EXPECT_NEAR(t.signedVolume, exact, 0.02 * exact);
}

TEST(MarchingCubes, AmbiguousConfigurationsLeaveNoCracks) {
    // A gyroid and noise hit every kind of face the table has.
    for (const char* formula : {"sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)",
                                "0.3*noise(6*x, 6*y, 6*z) + 0.05"}) {
        const ImplicitField f = support::field(formula, 1.0, BoxBoundary::Open);
        const Mesh m = welded(marchingCubes(f, 24, 1).mesh);
        const Topology t = analyseTopology(m);
        // Open only where the surface leaves the box: every border edge lies on a box face.
        EXPECT_TRUE(t.consistentlyOriented()) << formula;
        // A handful of edges where noise crosses two parallel grid edges at
        // the same fraction are welded into four uses (baseline only; known).
        EXPECT_LT(t.nonManifoldEdges * 1000, t.edges) << formula;
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
        for (const Triangle& tri : m.triangles)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = tri[std::size_t(k)], b = tri[std::size_t((k + 1) % 3)];
                ++uses[{std::min(a, b), std::max(a, b)}];
            }
        auto onBox = [&](std::uint32_t i) {
            for (float c : m.positions[i])
                if (std::abs(std::abs(c) - 1.0f) < 1e-6f) return true;
            return false;
        };
        for (const auto& [edge, count] : uses)
            if (count == 1) {
                EXPECT_TRUE(onBox(edge.first) && onBox(edge.second)) << formula;
            }
    }
}

TEST(MarchingCubes, ErrorFallsWithResolution) {
    const ImplicitField f = support::field("0.8^2 - x*x - y*y - z*z", 1.0, BoxBoundary::Open);
    const double coarse = measureSurfaceError(f, marchingCubes(f, 16).mesh).max;
    const double fine = measureSurfaceError(f, marchingCubes(f, 32).mesh).max;
    EXPECT_LT(fine, coarse / 2.5); // about 4x per halving on a smooth surface
}
