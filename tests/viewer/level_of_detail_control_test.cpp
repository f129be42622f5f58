// The view's level of detail: approaching refines in a few steps, moving a
// little never re-meshes, lod FALSE keeps the file's resolution, and the
// resolution stays within lodRange.
#include "viewer/level_of_detail_control.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl;

namespace {

std::unique_ptr<scene::Scene> read(const std::string& body) {
    auto r = scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "lod.x3dv");
    EXPECT_TRUE(r.ok());
    return std::move(r.scene);
}

viewer::CameraPose at(float z) {
    viewer::CameraPose p;
    p.position = {0, 0, z};
    p.viewCenter = {0, 0, 0};
    return p;
}

} // namespace

TEST(LevelOfDetail, ApproachingRefinesInAFewStepsWithinLodRange) {
    auto scene = read(R"x(FShape { geometry FGeometry { definition "1 - x*x - y*y - z*z"
                                                        lodRange 8 200 } })x");
    mesh::SceneMeshOptions o;
    o.placeInScene = false;
    const mesh::SceneMeshes meshes = mesh::meshScene(*scene, o);
    viewer::LevelOfDetail lod;
    int changes = 0;
    double last = 0;
    for (float z = 60; z >= 2.5f; z *= 0.97f) { // ~100 small steps in
        if (lod.update(meshes, at(z), QSize(800, 600))) ++changes;
        ASSERT_EQ(lod.resolutions().size(), 1u);
        const double r = lod.resolutions().begin()->second;
        EXPECT_GE(r, last); // never coarser while approaching
        EXPECT_GE(r, 8);
        EXPECT_LE(r, 200);
        last = r;
    }
    EXPECT_GT(last, 100);
    EXPECT_LE(changes, 12) << "the band should keep re-meshing rare";
    // Shaking the camera by 1% changes nothing.
    EXPECT_FALSE(lod.update(meshes, at(2.52f), QSize(800, 600)));
    // Far away: the coarsest.
    lod.update(meshes, at(1e4f), QSize(800, 600));
    EXPECT_EQ(lod.resolutions().begin()->second, 8);
}

TEST(LevelOfDetail, LodFalseKeepsTheFilesResolution) {
    auto scene = read(R"x(FShape { geometry FGeometry { definition "1 - x*x - y*y - z*z"
                                                        lod FALSE resolution 20 } })x");
    mesh::SceneMeshOptions o;
    const mesh::SceneMeshes meshes = mesh::meshScene(*scene, o);
    viewer::LevelOfDetail lod;
    EXPECT_FALSE(lod.update(meshes, at(2), QSize(800, 600)));
    EXPECT_TRUE(lod.resolutions().empty());
    EXPECT_EQ(meshes.shapes[0].resolution, 20);
}

// A shape combined by an FTransform is drawn with its first lod child's
// range, its resolution keyed by the FTransform, and meshed at what is picked.
TEST(LevelOfDetail, ACombinedShapeVariesWithItsChildsRange) {
    auto scene = read(R"x(DEF U FTransform { operation "union" children [
  FShape { geometry FGeometry { definition "0.3 - x*x - y*y - z*z" lodRange 8 64 } }
  FShape { geometry FGeometry { definition "0.2 - (x-0.5)^2 - y*y - z*z" lod FALSE } } ] })x");
    mesh::SceneMeshOptions o;
    o.placeInScene = false;
    const mesh::SceneMeshes meshes = mesh::meshScene(*scene, o);
    ASSERT_EQ(meshes.shapes.size(), 1u);
    ASSERT_TRUE(meshes.shapes[0].levelOfDetail);
    EXPECT_EQ(meshes.shapes[0].geometry, nullptr);
    viewer::LevelOfDetail lod;
    lod.update(meshes, at(1e4f), QSize(800, 600));
    ASSERT_EQ(lod.resolutions().size(), 1u);
    const scene::Node* ft = meshes.shapes[0].shape;
    ASSERT_TRUE(lod.resolutions().count(ft));
    EXPECT_EQ(lod.resolutions().at(ft), 8) << "far away: the coarsest of the child's range";
    lod.update(meshes, at(1.5f), QSize(800, 600));
    EXPECT_GT(lod.resolutions().at(ft), 8);
    EXPECT_LE(lod.resolutions().at(ft), 64);
    o.resolutions = {lod.resolutions().begin(), lod.resolutions().end()};
    const mesh::SceneMeshes again = mesh::meshScene(*scene, o);
    EXPECT_EQ(again.shapes[0].resolution, lod.resolutions().at(ft));
}
