// Meshing the paper's scenes: every kind of function geometry, placed by its
// transforms, coloured by its material at the moment asked for.
#include "mesh/mesh_topology.h"
#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fl::mesh;

namespace {

SceneMeshes meshExample(const std::string& name, double seconds = 0) {
    auto r = fl::scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name);
    EXPECT_TRUE(r.ok());
    static std::vector<std::unique_ptr<fl::scene::Scene>> keep; // meshes point at their nodes
    keep.push_back(std::move(r.scene));
    SceneMeshOptions o;
    o.sceneSeconds = seconds;
    return meshScene(*keep.back(), o);
}

double meanChannel(const Mesh& m, int channel) {
    double sum = 0;
    for (const auto& c : m.colours)
        sum += c[std::size_t(channel)];
    return m.colours.empty() ? 0 : sum / double(m.colours.size());
}

} // namespace

TEST(SceneMeshing, WatermelonIsGreenOutsideAndRedInside) {
    const SceneMeshes s = meshExample("watermelon.x3d");
    ASSERT_EQ(s.shapes.size(), 1u);
    const Mesh& m = s.shapes[0].mesh;
    ASSERT_TRUE(s.shapes[0].error.empty()) << s.shapes[0].error;
    EXPECT_TRUE(analyseTopology(m).closed());
    ASSERT_EQ(m.colours.size(), m.vertexCount());
    // Vertices on the rind (distance ~1 from the centre) are green; on the cut
    // faces, well inside, they are red.
    int green = 0, red = 0;
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        const auto& p = m.positions[i];
        const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const auto& c = m.colours[i];
        if (r > 0.99 && c[1] > c[0]) ++green;
        if (r < 0.5 && c[0] > c[1] + 0.2) ++red;
    }
    EXPECT_GT(green, 1000);
    EXPECT_GT(red, 50);
}

TEST(SceneMeshing, BouncingSphereChangesColourWithTime) {
    const SceneMeshes low = meshExample("bouncing_sphere.x3d", 0.0);
    ASSERT_EQ(low.shapes.size(), 1u);
    EXPECT_TRUE(analyseTopology(low.shapes[0].mesh).closed()); // seam and poles welded
    double lowest = 1e9, highest = -1e9;
    const auto zRange = [](const Mesh& m, double& lo, double& hi) {
        lo = 1e9, hi = -1e9;
        for (const auto& p : m.positions)
            lo = std::min(lo, double(p[1])), hi = std::max(hi, double(p[1]));
    };
    zRange(low.shapes[0].mesh, lowest, highest);
    // Half a bounce later it is higher up and redder.
    const SceneMeshes high = meshExample("bouncing_sphere.x3d", 0.5);
    double lowest2 = 0, highest2 = 0;
    zRange(high.shapes[0].mesh, lowest2, highest2);
    EXPECT_GT(lowest2, lowest + 0.1);
    EXPECT_GT(meanChannel(high.shapes[0].mesh, 0), meanChannel(low.shapes[0].mesh, 0) + 0.2);
}

TEST(SceneMeshing, ClockHandsTurnWithTime) {
    // The second hand points up at 0 s and to the right (clockwise) at 15 s.
    auto tip = [](const SceneMeshes& s, std::size_t shape) {
        std::array<double, 2> far{0, 0};
        double best = -1;
        for (const auto& p : s.shapes[shape].mesh.positions) {
            const double d = p[0] * p[0] + p[1] * p[1];
            if (d > best) best = d, far = {p[0], p[1]};
        }
        return far;
    };
    const SceneMeshes at0 = meshExample("clock.x3d", 0), at15 = meshExample("clock.x3d", 15);
    ASSERT_EQ(at0.shapes.size(), at15.shapes.size());
    // Find the second hand: the shape whose tip moved by a quarter turn.
    bool found = false;
    for (std::size_t i = 0; i < at0.shapes.size(); ++i) {
        const auto a = tip(at0, i), b = tip(at15, i);
        if (a[1] > 0.5 && std::abs(a[0]) < 0.1 && b[0] > 0.5 && std::abs(b[1]) < 0.1) found = true;
    }
    EXPECT_TRUE(found);
}
