// Every scene of the public corpus that loads is meshed — standard geometry
// (Box … IndexedFaceSet, ElevationGrid, Extrusion) and function shapes —
// without a crash, with finite positions and unit or zero normals, and every
// index inside its mesh. Geometry not drawn yet is named in a note.
#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

using namespace fl::mesh;
namespace fs = std::filesystem;

TEST(CorpusMeshing, EveryLoadingSceneMeshesSoundly) {
    const fs::path root = FUNCTIONLAB_CORPUS_DIR;
    if (!fs::exists(root)) GTEST_SKIP() << "no corpus at " << root;
    std::size_t scenes = 0, shapes = 0, triangles = 0, notes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        auto r = fl::scene::readSceneFile(entry.path());
        if (!r.ok()) continue;
        ++scenes;
        SceneMeshOptions o;
        o.useFileResolution = false;
        o.mesh.resolution = 12; // the point is soundness, not detail
        o.mesh.threads = 1;
        const SceneMeshes m = meshScene(*r.scene, o);
        notes += m.notes.size();
        for (const ShapeMesh& s : m.shapes) {
            ++shapes;
            triangles += s.mesh.triangleCount();
            for (const Vec3f& p : s.mesh.positions)
                ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
                    << entry.path() << " " << s.name;
            for (const Vec3f& n : s.mesh.normals) {
                const double len =
                    std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
                ASSERT_TRUE(len == 0 || std::abs(len - 1) < 1e-3) << entry.path() << " " << s.name;
            }
            for (const Triangle& t : s.mesh.triangles)
                for (std::uint32_t i : t)
                    ASSERT_LT(i, s.mesh.vertexCount()) << entry.path() << " " << s.name;
        }
    }
    std::cout << scenes << " scenes: " << shapes << " shapes, " << triangles << " triangles, "
              << notes << " notes\n";
    EXPECT_GT(shapes, 100u);
}

// The one clock on the corpus: every scene that animates itself (TimeSensors,
// ROUTEs) is played for 10 s of scene time, 2 frames a second, each frame
// meshed with what the animation set — as the window's player does. None may
// hang (CTest's timeout), crash, or place a shape at a non-finite position.
TEST(CorpusMeshing, EveryAnimatedScenePlaysTenSeconds) {
    const fs::path root = FUNCTIONLAB_CORPUS_DIR;
    if (!fs::exists(root)) GTEST_SKIP() << "no corpus at " << root;
    std::size_t played = 0, frames = 0, moved = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        auto r = fl::scene::readSceneFile(entry.path());
        if (!r.ok()) continue;
        fl::animation::Animator clock(*r.scene);
        if (clock.timeSensorCount() == 0 && clock.routeCount() == 0) continue;
        ++played;
        MeshCache cache;
        SceneMeshOptions o;
        o.useFileResolution = false;
        o.mesh.resolution = 8; // the point is the clock, not detail
        o.mesh.threads = 1;
        o.placeInScene = false;
        o.cache = &cache;
        o.animator = &clock;
        const std::int64_t start = 1'795'000'000 * fl::animation::kNanosecondsPerSecond;
        std::vector<Matrix4> first;
        for (int frame = 0; frame <= 20; ++frame, ++frames) {
            const std::int64_t ns = std::int64_t(frame) * fl::animation::kNanosecondsPerSecond / 2;
            o.instant = fl::animation::Instant{ns, start + ns, 0};
            clock.tick(*o.instant);
            const SceneMeshes m = meshScene(*r.scene, o);
            std::vector<Matrix4> placements;
            for (const ShapeMesh& s : m.shapes) {
                for (double v : s.placement)
                    ASSERT_TRUE(std::isfinite(v)) << entry.path() << " " << s.name;
                placements.push_back(s.placement);
            }
            if (frame == 0)
                first = placements;
            else if (placements != first) {
                ++moved;
                first = placements;
            }
        }
    }
    std::cout << played << " animated scenes played for 10 s (" << frames << " frames, " << moved
              << " frames moved a shape)\n";
    EXPECT_GT(played, 10u);
    EXPECT_GT(moved, 10u);
}
