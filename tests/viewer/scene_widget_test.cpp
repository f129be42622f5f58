// The view follows the scene's own binding (issue 14): a set_bind event that
// binds another Viewpoint takes the camera there, an animated bound
// viewpoint carries it, a bound NavigationInfo changes how one moves — and
// a camera the user moved stays where it is while the scene's binding
// does not change.
#include "viewer/scene_widget.h"

#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"

#include "viewer/surface_format.h"
#include <QApplication>
#include <gtest/gtest.h>

using namespace fl;

namespace {

const char* kRide = R"(#X3D V3.3 utf8
PROFILE Immersive
DEF FRONT Viewpoint { position 0 0 10 description "front" }
DEF RIDE Viewpoint { position 0 0 5 description "ride" }
DEF WALKING NavigationInfo { type [ "WALK" "ANY" ] }
NavigationInfo { type [ "EXAMINE" "ANY" ] }
Shape { geometry Box {} }
DEF TIMER TimeSensor { cycleInterval 2 startTime 1 }
DEF PATH PositionInterpolator { key [ 0 1 ] keyValue [ 0 0 5, 4 0 5 ] }
ROUTE TIMER.isActive TO RIDE.set_bind
ROUTE TIMER.fraction_changed TO PATH.set_fraction
ROUTE PATH.value_changed TO RIDE.set_position
)";

struct Frames {
    std::shared_ptr<const scene::Scene> scene;
    std::shared_ptr<const mesh::SceneMeshes> at(double seconds) const {
        mesh::SceneMeshOptions o;
        o.sceneSeconds = seconds;
        o.placeInScene = false;
        auto m = std::make_shared<mesh::SceneMeshes>(mesh::meshScene(*scene, o));
        m->source = scene;
        return m;
    }
};

Frames load(const char* text) {
    auto r = scene::readSceneBytes(text, "ride.x3dv");
    EXPECT_TRUE(r.ok());
    return {std::shared_ptr<const scene::Scene>(std::move(r.scene))};
}

} // namespace

TEST(SceneWidget, FollowsTheScenesViewpointBinding) {
    const Frames frames = load(kRide);
    viewer::SceneWidget view;
    view.resize(320, 240);
    view.setMeshes(frames.at(0.5));
    EXPECT_EQ(view.pose().position, QVector3D(0, 0, 10)) << "the first viewpoint, bound at load";
    view.setMeshes(frames.at(2));
    EXPECT_EQ(view.pose().position, QVector3D(2, 0, 5)) << "set_bind took the camera to RIDE";
    view.setMeshes(frames.at(2.5));
    EXPECT_NEAR(view.pose().position.x(), 3, 1e-5)
        << "RIDE moves (fraction 0.75) and the camera with it";
    // The user looks elsewhere; a frame where nothing about RIDE changed
    // leaves the camera with the user.
    viewer::CameraPose mine = view.pose();
    mine.position = QVector3D(7, 7, 7);
    view.setPose(mine);
    view.setMeshes(frames.at(2.5));
    EXPECT_EQ(view.pose().position, QVector3D(7, 7, 7));
    view.setMeshes(frames.at(3.5));
    EXPECT_EQ(view.pose().position, QVector3D(0, 0, 10)) << "unbound at 3 s: FRONT again";
}

TEST(SceneWidget, FollowsTheScenesNavigationInfoBinding) {
    const Frames frames = load(R"(#X3D V3.3 utf8
PROFILE Immersive
NavigationInfo { type [ "EXAMINE" "ANY" ] }
DEF WALKING NavigationInfo { type [ "WALK" "ANY" ] }
Shape { geometry Box {} }
DEF TIMER TimeSensor { cycleInterval 2 startTime 1 }
ROUTE TIMER.isActive TO WALKING.set_bind
)");
    viewer::SceneWidget view;
    std::vector<viewer::SceneWidget::Navigation> told;
    QObject::connect(&view, &viewer::SceneWidget::navigationBound,
                     [&](viewer::SceneWidget::Navigation n) { told.push_back(n); });
    view.setMeshes(frames.at(0.5));
    EXPECT_EQ(view.navigation(), viewer::SceneWidget::Navigation::Examine);
    view.setMeshes(frames.at(2));
    EXPECT_EQ(view.navigation(), viewer::SceneWidget::Navigation::Walk);
    view.setMeshes(frames.at(3.5));
    EXPECT_EQ(view.navigation(), viewer::SceneWidget::Navigation::Examine);
    EXPECT_EQ(told, (std::vector{viewer::SceneWidget::Navigation::Walk,
                                 viewer::SceneWidget::Navigation::Examine}));
}

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    fl::viewer::useViewerSurfaceFormat();
    QApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
