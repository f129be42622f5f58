// Meshing the paper's scenes: every kind of function geometry, placed by its
// transforms, coloured by its material at the moment asked for.
#include "mesh/mesh_export.h"
#include "mesh/mesh_topology.h"
#include "mesh/scene_meshing.h"
#include "scene/field_access.h"
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
    ASSERT_EQ(low.shapes.size(), 2u); // the floor (a standard Box), then the sphere
    EXPECT_FALSE(low.shapes[0].functionGeometry);
    EXPECT_EQ(low.shapes[0].mesh.triangleCount(), 12u);
    ASSERT_TRUE(low.shapes[1].functionGeometry);
    EXPECT_TRUE(analyseTopology(low.shapes[1].mesh).closed()); // seam and poles welded
    double lowest = 1e9, highest = -1e9;
    const auto zRange = [](const Mesh& m, double& lo, double& hi) {
        lo = 1e9, hi = -1e9;
        for (const auto& p : m.positions)
            lo = std::min(lo, double(p[1])), hi = std::max(hi, double(p[1]));
    };
    zRange(low.shapes[1].mesh, lowest, highest);
    // Half a bounce later it is higher up and redder.
    const SceneMeshes high = meshExample("bouncing_sphere.x3d", 0.5);
    double lowest2 = 0, highest2 = 0;
    zRange(high.shapes[1].mesh, lowest2, highest2);
    EXPECT_GT(lowest2, lowest + 0.1);
    EXPECT_GT(meanChannel(high.shapes[1].mesh, 0), meanChannel(low.shapes[1].mesh, 0) + 0.2);
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

namespace {

SceneMeshes meshText(const std::string& body, double seconds = 0) {
    auto r = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "ops.x3dv");
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << fl::scene::formatSceneDiagnostic(d);
    static std::vector<std::unique_ptr<fl::scene::Scene>> keep;
    keep.push_back(std::move(r.scene));
    SceneMeshOptions o;
    o.sceneSeconds = seconds;
    o.useFileResolution = false;
    o.mesh.resolution = 48;
    return meshScene(*keep.back(), o);
}

const std::string kBall =
    R"x(FShape { geometry FGeometry { definition "0.25 - x*x - y*y - z*z" } })x";
const std::string kCube =
    R"x(FShape { geometry FGeometry { definition "min(min(0.4 - abs(x), 0.4 - abs(y)), 0.4 - abs(z))" } })x";

double volumeOf(const SceneMeshes& s) {
    EXPECT_EQ(s.shapes.size(), 1u);
    if (s.shapes.empty()) return 0;
    EXPECT_TRUE(analyseTopology(s.shapes[0].mesh).closed());
    return analyseTopology(s.shapes[0].mesh).signedVolume;
}

} // namespace

TEST(FTransformOperations, SetOperationsCombineTheChildren) {
    const double ball = 4.0 / 3.0 * M_PI * 0.125, cube = 0.8 * 0.8 * 0.8;
    // The cube (half-size 0.4, corners at 0.69) pokes out of the ball (radius 0.5).
    const double uni =
        volumeOf(meshText("FTransform { operation \"union\" children [" + kBall + kCube + "] }"));
    const double inter = volumeOf(
        meshText("FTransform { operation \"intersection\" children [" + kBall + kCube + "] }"));
    const double diff = volumeOf(
        meshText("FTransform { operation \"difference\" children [" + kCube + kBall + "] }"));
    EXPECT_NEAR(uni + inter, ball + cube, 0.01); // inclusion-exclusion
    EXPECT_NEAR(diff, cube - inter, 0.01);
    EXPECT_GT(uni, std::max(ball, cube));
    EXPECT_LT(inter, std::min(ball, cube));
    // A user formula: max(f1, f2) is the union.
    const double formula = volumeOf(meshText(
        "FTransform { operation \"formula\" operationDefinition \"max(f1, f2)\" children [" +
        kBall + kCube + "] }"));
    EXPECT_NEAR(formula, uni, 1e-6);
}

TEST(FTransformOperations, ChildrenKeepTheirPlacesAndMorphFollowsTime) {
    // Two balls, one moved by a Transform: their union is two balls' worth.
    const double two =
        volumeOf(meshText("FTransform { operation \"union\" children [" + kBall +
                          " Transform { translation 2 0 0 children " + kBall + " } ] }"));
    EXPECT_NEAR(two, 2 * 4.0 / 3.0 * M_PI * 0.125, 0.01);
    // Morph from a small ball (t = 0) to the cube (t = 1, the end of a 2 s cycle).
    const std::string small =
        R"x(FShape { geometry FGeometry { definition "0.09 - x*x - y*y - z*z" } })x";
    const std::string morph =
        "FTransform { operation \"morph\" morphFactor \"t\" cycleInterval 2 children [" + small +
        kCube + "] }";
    const double ball = 4.0 / 3.0 * M_PI * 0.027;
    EXPECT_NEAR(volumeOf(meshText(morph, 0)), ball, 0.005);
    EXPECT_NEAR(volumeOf(meshText(morph, 2)), 0.512, 0.01);
    const double half = volumeOf(meshText(morph, 1));
    EXPECT_GT(half, ball + 0.05);
    EXPECT_LT(half, 0.512 - 0.05);
}

TEST(FTransformOperations, MetamorphosisExample) {
    const SceneMeshes at0 = meshExample("metamorphosis.x3d", 0),
                      at3 = meshExample("metamorphosis.x3d", 3);
    ASSERT_EQ(at0.shapes.size(), 2u);
    ASSERT_EQ(at3.shapes.size(), 2u);
    // The morph is a ball at t = 0 and the rounded cube half a cycle later.
    const double ball = analyseTopology(at0.shapes[0].mesh).signedVolume;
    const double cube = analyseTopology(at3.shapes[0].mesh).signedVolume;
    EXPECT_NEAR(ball, 4.0 / 3.0 * M_PI * 0.343, 0.02);
    EXPECT_GT(cube, ball + 0.3);
    // The ball bites the top off the cube on the right (centred at x = 1.2).
    double top = -1;
    for (const auto& p : at0.shapes[1].mesh.positions)
        if (std::abs(p[0] - 1.2) < 0.05 && std::abs(p[2]) < 0.05) top = std::max(top, double(p[1]));
    EXPECT_NEAR(top, 0.15, 0.03);
    EXPECT_TRUE(analyseTopology(at0.shapes[1].mesh).closed());
}

TEST(ScenePoints, AnExplicitSolidAsPointsShowsItsColouredInside) {
    // The watermelon drawn as points: they fill the solid, so the red flesh
    // shows inside the green rind.
    auto r = fl::scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/watermelon.x3d");
    ASSERT_TRUE(r.ok());
    SceneMeshOptions o;
    o.points = 20000;
    const SceneMeshes s = meshScene(*r.scene, o);
    ASSERT_EQ(s.shapes.size(), 1u);
    const Mesh& m = s.shapes[0].mesh;
    ASSERT_TRUE(m.isPointCloud());
    EXPECT_NEAR(double(m.vertexCount()), 20000, 2000);
    ASSERT_EQ(m.colours.size(), m.vertexCount());
    int red = 0, green = 0;
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        const auto& p = m.positions[i];
        const double radius = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const auto& c = m.colours[i];
        ASSERT_LT(radius, 1.0 + 1e-6); // inside the melon
        if (radius < 0.8 && c[0] > c[1] + 0.2) ++red;
        if (radius > 0.97 && c[1] > c[0]) ++green;
    }
    EXPECT_GT(red, 5000);
    EXPECT_GT(green, 100);
}

TEST(ScenePoints, TheFileAsksForPointsPerGeometryAndTheCheckerGuardsIt) {
    const SceneMeshes s = meshText(
        R"x(FShape { geometry FGeometry { definition "0.25 - x*x - y*y - z*z" points 3000 } }
            FShape { geometry FGeometry { type "parametric" points 400
                                          definition "x = u; y = v; z = 0.5;" } })x");
    ASSERT_EQ(s.shapes.size(), 2u);
    EXPECT_TRUE(s.shapes[0].mesh.isPointCloud());
    EXPECT_EQ(s.shapes[0].mesh.vertexCount(), 3000u); // on the implicit surface
    EXPECT_TRUE(s.shapes[1].mesh.isPointCloud());
    EXPECT_EQ(s.shapes[1].mesh.vertexCount(), 400u); // 20 x 20 over (u, v)
    // A whole scene of one kind merges; the other kind is left to its own file.
    EXPECT_EQ(mergeMeshes(s.shapes, Primitive::Points).vertexCount(), 3400u);
    EXPECT_TRUE(mergeMeshes(s.shapes).empty());

    auto bad = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\nFShape { geometry "
                                         "FGeometry { definition \"1\" points -5 } }",
                                         "bad.x3dv");
    bool explained = false;
    for (const auto& d : bad.diagnostics)
        explained = explained || (d.message.find("points gives the size") != std::string::npos &&
                                  d.pos.line == 3);
    EXPECT_TRUE(explained);
}

TEST(SceneStandardShapes, StandardGeometryIsMeshedColouredAndPlaced) {
    const SceneMeshes s = meshText(R"x(
        Transform { translation 2 0 0 children [
          Shape { appearance Appearance { material Material { diffuseColor 1 0 0
                                                               specularColor 0.5 0.5 0.5
                                                               shininess 0.8 transparency 0.25 } }
                  geometry Box { size 1 1 1 } } ] }
        Shape { geometry IndexedFaceSet { coordIndex [0 1 2 -1] solid FALSE
                  coord Coordinate { point [0 0 0, 1 0 0, 0 1 0] }
                  color Color { color [0 0 1, 0 1 0, 1 1 1] } } }
        Shape { geometry Text { string "no font given" } })x");
    ASSERT_EQ(s.shapes.size(), 2u);
    const ShapeMesh& box = s.shapes[0];
    EXPECT_FALSE(box.functionGeometry);
    ASSERT_EQ(box.mesh.colours.size(), box.mesh.vertexCount());
    EXPECT_EQ(box.mesh.colours[0], (std::array<float, 4>{1, 0, 0, 0.75f}));
    EXPECT_FLOAT_EQ(box.look.specular[0], 0.5f);
    EXPECT_FLOAT_EQ(box.look.shininess, 0.8f);
    EXPECT_TRUE(box.look.lit && box.look.solid);
    for (const Vec3f& p : box.mesh.positions)
        ASSERT_NEAR(p[0], 2, 0.5 + 1e-6); // moved by the Transform
    const ShapeMesh& triangle = s.shapes[1];
    EXPECT_FALSE(triangle.look.lit); // X3D: no Material, no lighting
    EXPECT_FALSE(triangle.look.solid);
    ASSERT_EQ(triangle.mesh.colours.size(), 3u);
    EXPECT_EQ(triangle.mesh.colours[0], (std::array<float, 4>{0, 0, 1, 1})); // Color, not Material
    ASSERT_EQ(s.notes.size(), 1u);
    EXPECT_NE(s.notes[0].find("Text is not drawn without a font source"), std::string::npos);
}

TEST(SceneStandardShapes, MeshesCanStayInTheirOwnCoordinatesWithTheirPlacement) {
    auto r = fl::scene::readSceneBytes(
        "#X3D V3.3 utf8\nPROFILE Full\nTransform { translation 1 2 3 scale 2 2 2 children "
        "Shape { geometry Box { size 1 1 1 } } }",
        "placed.x3dv");
    ASSERT_TRUE(r.ok());
    SceneMeshOptions o;
    o.placeInScene = false;
    const SceneMeshes local = meshScene(*r.scene, o);
    ASSERT_EQ(local.shapes.size(), 1u);
    const ShapeMesh& box = local.shapes[0];
    for (const Vec3f& p : box.mesh.positions)
        ASSERT_NEAR(std::abs(p[0]), 0.5, 1e-6); // unmoved
    const Matrix4 expected{2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1};
    for (std::size_t i = 0; i < 16; ++i)
        EXPECT_NEAR(box.placement[i], expected[i], 1e-12) << i;
}

TEST(SceneView, LightsViewpointsBackgroundAndNavigationInSceneCoordinates) {
    const SceneMeshes s = meshText(R"x(
        Background { skyColor [0.1 0.2 0.3, 1 1 1] }
        Background { skyColor 1 0 0 }
        NavigationInfo { type ["WALK" "ANY"] headlight FALSE speed 2 }
        Transform { translation 0 0 5 rotation 0 1 0 1.5707963 children [
          Viewpoint { description "Side" position 0 0 10 }
          PointLight { location 1 0 0 color 1 0 0 intensity 0.5 }
          DirectionalLight { direction 0 0 -1 on FALSE } ] }
        DEF TOP Viewpoint { position 0 10 0 orientation 1 0 0 -1.5707963 })x");
    const SceneView& v = s.view;
    EXPECT_TRUE(v.hasBackground);
    EXPECT_EQ(v.background, (std::array<float, 3>{0.1f, 0.2f, 0.3f})); // the first, its zenith
    EXPECT_TRUE(v.hasNavigation);
    EXPECT_EQ(v.navigation.types.front(), "WALK");
    EXPECT_FALSE(v.navigation.headlight);
    ASSERT_EQ(v.viewpoints.size(), 2u);
    EXPECT_EQ(v.viewpoints[0].name, "Side");
    // Turned a quarter about y and moved 5 along z: (0, 0, 10) lands at (10, 0, 5), looking -x.
    EXPECT_NEAR(v.viewpoints[0].position[0], 10, 1e-6);
    EXPECT_NEAR(v.viewpoints[0].position[2], 5, 1e-6);
    EXPECT_NEAR(v.viewpoints[0].direction[0], -1, 1e-6);
    EXPECT_EQ(v.viewpoints[1].name, "TOP");
    EXPECT_NEAR(v.viewpoints[1].direction[1], -1, 1e-6); // looking down
    ASSERT_EQ(v.lights.size(), 1u);                      // the one switched off is not there
    EXPECT_EQ(v.lights[0].kind, ViewLight::Kind::Point);
    EXPECT_NEAR(v.lights[0].location[2], 5 - 1, 1e-6);
    EXPECT_FLOAT_EQ(v.lights[0].intensity, 0.5f);
}

TEST(SceneMeshCache, PlayingTheClockMeshesItOnceAndTheBouncingSphereEachMoment) {
    for (const char* file : {"clock.x3d", "bouncing_sphere.x3d"}) {
        auto r = fl::scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + file);
        ASSERT_TRUE(r.ok());
        MeshCache cache;
        SceneMeshOptions o;
        o.cache = &cache;
        o.sceneSeconds = 10;
        const SceneMeshes first = meshScene(*r.scene, o);
        const std::size_t made = cache.misses();
        EXPECT_GT(made, 0u);
        for (double s : {10.25, 10.5, 11.0}) {
            o.sceneSeconds = s;
            const SceneMeshes later = meshScene(*r.scene, o);
            ASSERT_EQ(later.shapes.size(), first.shapes.size());
        }
        if (std::string(file) == "clock.x3d") {
            EXPECT_EQ(cache.misses(), made)
                << "the clock's geometry never changes: only its hands turn";
        } else {
            EXPECT_EQ(cache.misses(), made + 3)
                << "the sphere's geometry reads t: one mesh per moment";
        }
    }
}

TEST(SceneMeshCache, CachedMeshesStillTurnWithTheirTransforms) {
    auto r = fl::scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/clock.x3d");
    ASSERT_TRUE(r.ok());
    MeshCache cache;
    SceneMeshOptions o;
    o.cache = &cache;
    o.sceneSeconds = 0;
    const SceneMeshes midnight = meshScene(*r.scene, o);
    o.sceneSeconds = 15; // the second hand has turned a quarter
    const SceneMeshes later = meshScene(*r.scene, o);
    bool moved = false;
    for (std::size_t i = 0; i < midnight.shapes.size(); ++i)
        moved = moved || midnight.shapes[i].mesh.positions != later.shapes[i].mesh.positions;
    EXPECT_TRUE(moved);
}

TEST(SceneMeshing, WallClockNodesReadTheInstantsWallTime) {
    // The clock's hands use timeBase "local": three hours into the day they
    // stand elsewhere than at scene time 0, whatever the scene time says.
    auto r = fl::scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/clock.x3d");
    ASSERT_TRUE(r.ok());
    SceneMeshOptions o;
    const SceneMeshes start = meshScene(*r.scene, o);
    o.instant = fl::animation::Instant{0, 3 * 3600 * 1'000'000'000LL, 0};
    const SceneMeshes threeOClock = meshScene(*r.scene, o);
    o.instant = fl::animation::Instant{0, 0, 3 * 3600}; // midnight UTC is 3 o'clock here
    const SceneMeshes offset = meshScene(*r.scene, o);
    ASSERT_EQ(start.shapes.size(), threeOClock.shapes.size());
    bool moved = false;
    for (std::size_t i = 0; i < start.shapes.size(); ++i) {
        moved = moved || start.shapes[i].mesh.positions != threeOClock.shapes[i].mesh.positions;
        EXPECT_EQ(threeOClock.shapes[i].mesh.positions, offset.shapes[i].mesh.positions);
    }
    EXPECT_TRUE(moved);
}

TEST(SceneParameters, NamedParametersAreListedAndTheirValuesReshapeTheMesh) {
    const std::string body = R"x(FShape { geometry FGeometry {
        definition "param R = 0.5 in [0.2, 0.9]; return R*R - x*x - y*y - z*z;" } })x";
    auto r = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "p.x3dv");
    ASSERT_TRUE(r.ok());
    const auto params = sceneParameters(*r.scene);
    ASSERT_EQ(params.size(), 1u);
    EXPECT_EQ(params[0].name, "R");
    EXPECT_TRUE(params[0].hasRange);
    EXPECT_DOUBLE_EQ(params[0].hi, 0.9);
    SceneMeshOptions o;
    const double small = analyseTopology(meshScene(*r.scene, o).shapes[0].mesh).signedVolume;
    o.parameters = {{"R", 0.8}, {"unrelated", 3}};
    const double large = analyseTopology(meshScene(*r.scene, o).shapes[0].mesh).signedVolume;
    EXPECT_NEAR(large / small, std::pow(0.8 / 0.5, 3), 0.05);
}

TEST(SceneMeshing, AnExponentialDefUseGraphIsCutShortWithANote) {
    // Each group holds the previous one twice: 2^18 shapes if walked blindly
    // (the reader refuses a scene that unfolds to more than 4 M nodes, see
    // tests/scene/node_loop_test.cpp; below that the mesher has a budget).
    std::string body = "DEF G0 Shape { geometry Box {} }\n";
    for (int i = 1; i <= 18; ++i)
        body += "DEF G" + std::to_string(i) + " Group { children [ USE G" + std::to_string(i - 1) +
                " USE G" + std::to_string(i - 1) + " ] }\n";
    auto r = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "dag.x3dv");
    ASSERT_TRUE(r.ok());
    SceneMeshOptions o;
    const SceneMeshes s = meshScene(*r.scene, o);
    bool noted = false;
    for (const auto& n : s.notes)
        noted = noted || n.find("reuses (USE) nodes so often") != std::string::npos;
    EXPECT_TRUE(noted);
    EXPECT_LT(s.shapes.size(), 250000u);
}

TEST(SceneStandardShapes, LineSetsTakeTheEmissiveColourAndExportAsLines) {
    const SceneMeshes s = meshText(R"x(
        Shape { appearance Appearance { material Material { emissiveColor 0 1 0 } }
                geometry LineSet { vertexCount [3 2]
                                   coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 2 2 2, 3 3 3] } } })x");
    ASSERT_EQ(s.shapes.size(), 1u);
    const Mesh& m = s.shapes[0].mesh;
    ASSERT_TRUE(m.isLines());
    EXPECT_EQ(m.segments.size(), 3u);
    ASSERT_EQ(m.colours.size(), m.vertexCount());
    EXPECT_EQ(m.colours[0], (std::array<float, 4>{0, 1, 0, 1}));
    const Mesh merged = mergeMeshes(s.shapes, Primitive::Lines);
    EXPECT_NE(encodeMesh(merged, MeshFormat::Obj).find("\nl 1 2\n"), std::string::npos);
    EXPECT_NE(encodeMesh(merged, MeshFormat::Ply).find("element edge 3\n"), std::string::npos);
    EXPECT_NE(encodeMesh(merged, MeshFormat::Glb).find(R"("mode":1)"), std::string::npos);
    auto back = fl::scene::readSceneBytes(encodeMesh(merged, MeshFormat::X3d), "lines.x3d");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(fl::scene::nodeField(*back.scene->roots.at(0), "geometry")->type, "IndexedLineSet");
    std::string error;
    EXPECT_FALSE(writeMesh(merged, testing::TempDir() + "lines.stl", error));
}

// The paper's way of colouring a standard shape by a function: an FShape
// without geometry lends its appearance to the shapes grouped with it, mapped
// onto its bboxCenter/bboxSize box (else onto their bounds), in its own
// coordinates; a shape with an appearance of its own keeps it.
TEST(SceneMeshing, AnFShapeWithoutGeometryLendsItsColour) {
    auto r = fl::scene::readSceneBytes(R"x(#X3D V3.3 utf8
PROFILE Full
COMPONENT FunctionLab:1
Transform { translation 5 0 0 children [
  FShape { bboxCenter 0 0 0 bboxSize 2 2 2
    appearance FAppearance { material FMaterial { type "parametric"
      definition "r = u; g = 0; b = 1 - u;" } } }
  Transform { translation 0.5 0 0 children Shape { geometry Box { size 1 1 1 } } }
  Shape { appearance Appearance { material Material { diffuseColor 0 1 0 } }
          geometry Sphere { radius 0.2 } } ] })x",
                                       "lend.x3dv");
    ASSERT_TRUE(r.ok());
    for (bool placeInScene : {true, false}) {
        SceneMeshOptions o;
        o.placeInScene = placeInScene;
        const SceneMeshes meshes = meshScene(*r.scene, o);
        ASSERT_EQ(meshes.shapes.size(), 2u);
        const ShapeMesh& box = meshes.shapes[0];
        ASSERT_EQ(box.mesh.colours.size(), box.mesh.positions.size());
        ASSERT_TRUE(box.appearance) << "the lent appearance";
        // The box spans x = 0 .. 1 in the lender's box -1 .. 1: u from 0.5 to 1.
        float lo = 1, hi = 0;
        for (const auto& c : box.mesh.colours) {
            lo = std::min(lo, c[0]);
            hi = std::max(hi, c[0]);
            EXPECT_NEAR(c[0] + c[2], 1, 1e-5);
        }
        EXPECT_NEAR(lo, 0.5, 1e-4) << placeInScene;
        EXPECT_NEAR(hi, 1.0, 1e-4) << placeInScene;
        const ShapeMesh& ball = meshes.shapes[1];
        ASSERT_FALSE(ball.mesh.colours.empty());
        EXPECT_EQ(ball.mesh.colours[0][1], 1) << "its own Material stays";
    }
}
