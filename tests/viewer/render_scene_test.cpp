// The entities behind the view: a new moment whose meshes did not change
// only moves matrices (the clock), a shape whose geometry changed is made
// again alone (the bouncing sphere, not its floor), and changing the drawing
// mode makes everything again. No drawing: no display needed.
#include "viewer/render_scene.h"

#include "mesh/mesh_cache.h"
#include "scene/scene_reader.h"

#include <Qt3DCore/QTransform>
#include <gtest/gtest.h>

using namespace fl;

namespace {

struct Player {
    std::unique_ptr<scene::Scene> scene;
    std::unique_ptr<mesh::MeshCache> cache = std::make_unique<mesh::MeshCache>();
    std::shared_ptr<const mesh::SceneMeshes> at(double seconds) {
        mesh::SceneMeshOptions o;
        o.sceneSeconds = seconds;
        o.placeInScene = false;
        o.cache = cache.get();
        return std::make_shared<const mesh::SceneMeshes>(mesh::meshScene(*scene, o));
    }
};

Player example(const char* file) {
    auto r = scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + file);
    EXPECT_TRUE(r.ok());
    Player p;
    p.scene = std::move(r.scene);
    return p;
}

} // namespace

TEST(RenderScene, TheClockTurnsByMatricesAlone) {
    Player clock = example("clock.x3d");
    Qt3DCore::QEntity root;
    viewer::RenderScene scene(&root);
    scene.setMeshes(clock.at(0));
    const std::size_t made = scene.entitiesMade();
    EXPECT_EQ(made, scene.shapeCount());
    std::vector<QMatrix4x4> before;
    for (auto* t : root.findChildren<Qt3DCore::QTransform*>())
        before.push_back(t->matrix());
    scene.setMeshes(clock.at(15)); // the second hand a quarter round
    EXPECT_EQ(scene.entitiesMade(), made);
    std::vector<QMatrix4x4> after;
    for (auto* t : root.findChildren<Qt3DCore::QTransform*>())
        after.push_back(t->matrix());
    EXPECT_NE(before, after);
}

TEST(RenderScene, OnlyTheShapeThatChangedIsMadeAgain) {
    Player bounce = example("bouncing_sphere.x3d");
    Qt3DCore::QEntity root;
    viewer::RenderScene scene(&root);
    scene.setMeshes(bounce.at(0));
    const std::size_t made = scene.entitiesMade();
    scene.setMeshes(bounce.at(0.25));
    EXPECT_EQ(scene.entitiesMade(), made + 1); // the sphere; the floor stays
    scene.setDrawAs(viewer::DrawAs::Edges);
    EXPECT_EQ(scene.entitiesMade(), made + 1 + scene.shapeCount());
}
