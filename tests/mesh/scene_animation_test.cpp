// The one clock in meshing: what the scene's TimeSensors, interpolators and
// ROUTEs set at a moment is what gets meshed, and the same moment gives the
// same meshes bit for bit however it is reached.
#include "animation/animator.h"
#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>

using namespace fl;

namespace {

// A standard Box and a function-defined ball in one Transform that a
// PositionInterpolator carries from x = 0 to x = 4 over 4 seconds, and a
// second Box at x = 1 that an OrientationInterpolator turns about y.
const char* kMovingScene = R"(#X3D V3.3 utf8
PROFILE Immersive
COMPONENT FunctionLab:1
DEF MOVER Transform {
  children [
    DEF BOX Shape { geometry Box { size 0.2 0.2 0.2 } }
    DEF BALL FShape {
      geometry FGeometry {
        type "explicit"
        definition "0.1^2 - x*x - y*y - z*z"
        domainMin -0.2 -0.2 -0.2
        domainMax 0.2 0.2 0.2
        resolution 16
      }
    }
  ]
}
DEF TURNER Transform {
  children Transform { translation 1 0 0 children DEF TURNED Shape { geometry Box { size 0.2 0.2 0.2 } } }
}
DEF CLOCK TimeSensor { cycleInterval 4 loop TRUE }
DEF PATH PositionInterpolator { key [ 0 1 ] keyValue [ 0 0 0, 4 0 0 ] }
DEF SPIN OrientationInterpolator { key [ 0 1 ] keyValue [ 0 1 0 0, 0 1 0 3.14159265358979 ] }
ROUTE CLOCK.fraction_changed TO PATH.set_fraction
ROUTE PATH.value_changed TO MOVER.set_translation
ROUTE CLOCK.fraction_changed TO SPIN.set_fraction
ROUTE SPIN.value_changed TO TURNER.set_rotation
)";

std::unique_ptr<scene::Scene> read(const std::string& text) {
    auto r = scene::readSceneBytes(text, "moving.x3dv");
    EXPECT_TRUE(r.ok());
    return std::move(r.scene);
}

std::unique_ptr<scene::Scene> readExample(const std::string& name) {
    auto r = scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name);
    EXPECT_TRUE(r.ok()) << name;
    return std::move(r.scene);
}

std::array<double, 3> centroid(const mesh::Mesh& m) {
    std::array<double, 3> c{0, 0, 0};
    for (const auto& p : m.positions)
        for (int k = 0; k < 3; ++k)
            c[std::size_t(k)] += p[std::size_t(k)];
    for (double& v : c)
        v /= double(std::max<std::size_t>(1, m.positions.size()));
    return c;
}

const mesh::ShapeMesh& shapeNamed(const mesh::SceneMeshes& s, const std::string& def) {
    for (const auto& shape : s.shapes)
        if (shape.shape && shape.shape->defName == def) return shape;
    ADD_FAILURE() << "no shape " << def;
    return s.shapes.front();
}

mesh::SceneMeshes meshAt(const scene::Scene& s, double seconds,
                         const animation::Animator* animator = nullptr) {
    mesh::SceneMeshOptions o;
    o.sceneSeconds = seconds;
    o.animator = animator;
    return mesh::meshScene(s, o);
}

animation::Instant at(double seconds) {
    const std::int64_t ns = animation::secondsToNanoseconds(seconds);
    return {ns, ns, 0};
}

bool sameBits(const mesh::SceneMeshes& a, const mesh::SceneMeshes& b) {
    if (a.shapes.size() != b.shapes.size()) return false;
    for (std::size_t i = 0; i < a.shapes.size(); ++i) {
        const auto &p = a.shapes[i], &q = b.shapes[i];
        if (p.mesh.positions != q.mesh.positions || p.mesh.normals != q.mesh.normals ||
            p.mesh.colours != q.mesh.colours || p.mesh.triangles != q.mesh.triangles ||
            std::memcmp(&p.placement, &q.placement, sizeof p.placement) != 0 || p.t != q.t)
            return false;
    }
    return true;
}

} // namespace

TEST(SceneAnimation, PositionInterpolatorCarriesStandardAndFunctionShapes) {
    auto s = read(kMovingScene);
    // fraction = seconds / 4, translation x = 4 * fraction = seconds
    for (double seconds : {0.0, 1.0, 2.5, 3.0}) {
        const mesh::SceneMeshes m = meshAt(*s, seconds);
        for (const char* def : {"BOX", "BALL"}) {
            const auto c = centroid(shapeNamed(m, def).mesh);
            EXPECT_NEAR(c[0], seconds, 1e-3) << def << " at " << seconds << " s";
            EXPECT_NEAR(c[1], 0, 1e-3) << def;
            EXPECT_NEAR(c[2], 0, 1e-3) << def;
        }
    }
}

TEST(SceneAnimation, OrientationInterpolatorTurnsATransform) {
    auto s = read(kMovingScene);
    // angle = pi * seconds / 4 about +y: (1, 0, 0) turns to (cos a, 0, -sin a)
    for (double seconds : {0.0, 1.0, 2.0, 3.0}) {
        const double a = 3.14159265358979 * seconds / 4;
        const auto c = centroid(shapeNamed(meshAt(*s, seconds), "TURNED").mesh);
        EXPECT_NEAR(c[0], std::cos(a), 1e-3) << seconds << " s";
        EXPECT_NEAR(c[2], -std::sin(a), 1e-3) << seconds << " s";
    }
}

TEST(SceneAnimation, TheSharksTailSwings) {
    // TimeSensor SWIM (5 s) -> OrientationInterpolator -> the tail's Transform.
    auto s = readExample("shark.x3d");
    std::vector<std::array<double, 3>> tails;
    for (double seconds : {0.0, 1.25, 3.75}) {
        tails.push_back(centroid(mesh::mergeMeshes(meshAt(*s, seconds).shapes)));
    }
    // The whole shark's centroid moves with its tail: left at one quarter of
    // the swing, right at three quarters.
    EXPECT_GT(std::abs(tails[1][2] - tails[0][2]), 1e-3);
    EXPECT_GT(std::abs(tails[2][2] - tails[0][2]), 1e-3);
    EXPECT_LT((tails[1][2] - tails[0][2]) * (tails[2][2] - tails[0][2]), 0);
}

TEST(SceneAnimation, OneMomentIsTheSameHoweverItIsReached) {
    auto s = read(kMovingScene);
    const mesh::SceneMeshes cold = meshAt(*s, 2.5);

    // Played forward frame by frame to the moment.
    animation::Animator played(*s);
    for (int frame = 0; frame <= 150; ++frame)
        played.tick(at(frame / 60.0));
    EXPECT_TRUE(sameBits(cold, meshAt(*s, 2.5, &played)));

    // Past it and back: reset, then the moment.
    played.tick(at(3.9));
    played.reset();
    played.tick(at(2.5));
    EXPECT_TRUE(sameBits(cold, meshAt(*s, 2.5, &played)));

    // And a different moment really is different.
    EXPECT_FALSE(sameBits(cold, meshAt(*s, 1.0)));
}

TEST(SceneAnimation, FunctionShapesTakeTheirTFromTheOneClock) {
    // The bouncing sphere: cycleInterval 2, t = fraction of the cycle.
    auto s = readExample("bouncing_sphere.x3d");
    animation::Animator clock(*s);
    clock.tick(at(0.5));
    const mesh::SceneMeshes m = meshAt(*s, 0.5, &clock);
    bool found = false;
    for (const auto& shape : m.shapes) {
        if (!shape.functionGeometry) continue;
        EXPECT_DOUBLE_EQ(shape.t, clock.time(*shape.geometry));
        EXPECT_NEAR(shape.t, 0.25, 1e-12);
        found = true;
    }
    EXPECT_TRUE(found);
}

TEST(SceneAnimation, ShapesKnowTheTouchSensorsAClickOnThemTriggers) {
    auto s = read(R"(#X3D V3.3 utf8
PROFILE Immersive
Group {
  children [
    DEF OUTER TouchSensor {}
    DEF NEAR Shape { geometry Box {} }
    Transform {
      children [
        DEF INNER TouchSensor {}
        DEF OFF TouchSensor { enabled FALSE }
        DEF DEEP Shape { geometry Sphere {} }
      ]
    }
    Transform { children DEF BELOW Shape { geometry Cone {} } }
  ]
}
DEF ALONE Shape { geometry Cylinder {} }
)");
    const mesh::SceneMeshes m = meshAt(*s, 0);
    auto sensorsOf = [&](const std::string& def) {
        std::vector<std::string> names;
        for (const scene::Node* n : shapeNamed(m, def).touchSensors)
            names.push_back(n->defName);
        return names;
    };
    EXPECT_EQ(sensorsOf("NEAR"), std::vector<std::string>{"OUTER"});
    EXPECT_EQ(sensorsOf("BELOW"), std::vector<std::string>{"OUTER"});
    // The lowest group's enabled sensors shadow those above (X3D §20.2.1).
    EXPECT_EQ(sensorsOf("DEEP"), std::vector<std::string>{"INNER"});
    EXPECT_TRUE(sensorsOf("ALONE").empty());

    // The fan: a click on its head reaches SWITCH, on its stand nothing.
    auto fan = readExample("fan.x3d");
    const mesh::SceneMeshes f = meshAt(*fan, 0);
    std::size_t sensed = 0, deaf = 0;
    for (const auto& shape : f.shapes) {
        if (shape.touchSensors.empty()) {
            ++deaf;
            continue;
        }
        ++sensed;
        ASSERT_EQ(shape.touchSensors.size(), 1u);
        EXPECT_EQ(shape.touchSensors[0]->defName, "SWITCH");
    }
    EXPECT_GT(sensed, 0u);
    EXPECT_GT(deaf, 0u);
}

// Effects plan: a ROUTE that only moves a Transform moves a matrix. Played
// through one cache, the Boxes and the ball are made once; later moments
// only place them elsewhere.
TEST(SceneAnimation, ATransformRouteMovesAMatrixAndMeshesNothing) {
    auto s = read(kMovingScene);
    mesh::MeshCache cache;
    mesh::SceneMeshOptions o;
    o.placeInScene = false;
    o.cache = &cache;
    o.sceneSeconds = 0;
    const mesh::SceneMeshes first = mesh::meshScene(*s, o);
    const std::size_t made = cache.misses();
    EXPECT_EQ(made, 3u) << "two Boxes (one node each) and the ball";
    for (double seconds : {0.5, 1.25, 3.0, 0.25}) {
        o.sceneSeconds = seconds;
        const mesh::SceneMeshes later = mesh::meshScene(*s, o);
        EXPECT_EQ(cache.misses(), made) << "re-meshed at " << seconds << " s";
        EXPECT_EQ(shapeNamed(later, "BOX").mesh.positions, shapeNamed(first, "BOX").mesh.positions);
        EXPECT_NE(std::memcmp(&shapeNamed(later, "BOX").placement,
                              &shapeNamed(first, "BOX").placement, sizeof(mesh::Matrix4)),
                  0)
            << "the matrix moves at " << seconds << " s";
    }
}

// Standard geometry reads its values through the one clock too: a
// CoordinateInterpolator moves an IndexedFaceSet's points (and such a
// geometry is tessellated again at each moment, never taken from the cache).
TEST(SceneAnimation, CoordinateInterpolatorMovesPointsOfStandardGeometry) {
    auto s = read(R"(#X3D V3.3 utf8
PROFILE Immersive
DEF FACE Shape { geometry IndexedFaceSet { coordIndex [ 0 1 2 -1 ]
  coord DEF POINTS Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } } }
DEF CLOCK TimeSensor { cycleInterval 2 loop TRUE }
DEF SHAPE CoordinateInterpolator { key [ 0 1 ]
  keyValue [ 0 0 0, 1 0 0, 0 1 0,   0 0 0, 2 0 0, 0 2 0 ] }
ROUTE CLOCK.fraction_changed TO SHAPE.set_fraction
ROUTE SHAPE.value_changed TO POINTS.set_point
)");
    mesh::MeshCache cache;
    mesh::SceneMeshOptions o;
    o.cache = &cache;
    for (double seconds : {0.0, 1.0, 0.5}) {
        o.sceneSeconds = seconds;
        const mesh::SceneMeshes m = mesh::meshScene(*s, o);
        double right = 0;
        for (const auto& p : shapeNamed(m, "FACE").mesh.positions)
            right = std::max(right, double(p[0]));
        EXPECT_NEAR(right, 1 + seconds / 2, 1e-6) << seconds << " s"; // fraction = seconds / 2
    }
}

// Bindable nodes follow their ROUTEs: while a TimeSensor is active it binds
// the second Viewpoint and a WALK NavigationInfo (isActive TO set_bind); when
// it stops they are unbound and the first ones are bound again. A bound
// viewpoint an interpolator moves is where the keys say.
TEST(SceneAnimation, ViewpointAndNavigationBindingFollowRoutes) {
    auto s = read(R"(#X3D V3.3 utf8
PROFILE Immersive
DEF FRONT Viewpoint { position 0 0 10 description "front" }
DEF RIDE Viewpoint { position 0 0 5 description "ride" }
DEF LOOK NavigationInfo { type [ "EXAMINE" "ANY" ] }
DEF WALKING NavigationInfo { type [ "WALK" "ANY" ] }
Shape { geometry Box {} }
DEF TIMER TimeSensor { cycleInterval 2 startTime 1 }
DEF PATH PositionInterpolator { key [ 0 1 ] keyValue [ 0 0 5, 4 0 5 ] }
ROUTE TIMER.isActive TO RIDE.set_bind
ROUTE TIMER.isActive TO WALKING.set_bind
ROUTE TIMER.fraction_changed TO PATH.set_fraction
ROUTE PATH.value_changed TO RIDE.set_position
)");
    auto bound = [&](double seconds) {
        const mesh::SceneMeshes m = meshAt(*s, seconds);
        EXPECT_EQ(m.view.viewpoints.size(), 2u);
        return m.view;
    };
    EXPECT_EQ(bound(0.5).boundViewpoint, 0) << "before the timer starts: the first";
    EXPECT_EQ(bound(0.5).navigation.types.front(), "EXAMINE");
    const mesh::SceneView riding = bound(2);
    EXPECT_EQ(riding.boundViewpoint, 1);
    EXPECT_EQ(riding.navigation.types.front(), "WALK");
    EXPECT_NEAR(riding.viewpoints[1].position[0], 2, 1e-9) << "half way along the path";
    EXPECT_EQ(bound(3.5).boundViewpoint, 0) << "the timer stopped at 3 s: unbound";
    EXPECT_EQ(bound(3.5).navigation.types.front(), "EXAMINE");
}
