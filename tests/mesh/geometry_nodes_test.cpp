// Geometry nodes read from scenes (scene_standard_geometry.h): NURBS, fan,
// strip and quad sets, Geometry2D — each drawn from its fields, bad fields
// warned about and never fatal.
#include "mesh/scene_meshing.h"
#include "mesh_test_support.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace fl::mesh;

namespace {

SceneMeshes meshX3d(const std::string& body, std::unique_ptr<fl::scene::Scene>& keep) {
    auto r = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "nurbs.x3dv");
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << fl::scene::formatSceneDiagnostic(d);
    keep = std::move(r.scene);
    SceneMeshOptions o;
    return meshScene(*keep, o);
}

} // namespace

TEST(GeometryNodes, NurbsNodesAreDrawn) {
    std::unique_ptr<fl::scene::Scene> keep;
    const SceneMeshes s = meshX3d(R"(
        Shape { geometry NurbsPatchSurface {
            uDimension 3 vDimension 3 uOrder 3 vOrder 3 uTessellation 8 vTessellation 6
            controlPoint Coordinate { point [0 0 0, 1 0 0, 2 0 0, 0 1 1, 1 1 1, 2 1 1, 0 2 0, 1 2 0, 2 2 0] } } }
        Shape { geometry NurbsCurve { order 3 tessellation 20
            controlPoint CoordinateDouble { point [0 0 0, 1 1 0, 2 0 0] } } }
        Shape { geometry NurbsTrimmedSurface {
            uDimension 2 vDimension 2 uOrder 2 vOrder 2
            controlPoint Coordinate { point [0 0 0, 1 0 0, 0 1 0, 1 1 0] }
            trimmingContour Contour2D { children [
                ContourPolyline2D { controlPoint [0.2 0.2, 0.8 0.2, 0.8 0.8] }
                NurbsCurve2D { order 2 controlPoint [0.8 0.8, 0.2 0.8, 0.2 0.2] } ] } } }
        Shape { geometry NurbsPatchSurface { uDimension 3 vDimension 2
            controlPoint Coordinate { point [0 0 0, 1 0 0] } } })",
                                  keep);
    ASSERT_EQ(s.shapes.size(), 4u);
    EXPECT_EQ(s.shapes[0].mesh.triangleCount(), 8u * 6u * 2u);
    EXPECT_TRUE(s.shapes[1].mesh.isLines());
    EXPECT_EQ(s.shapes[1].mesh.segments.size(), 20u);
    EXPECT_NEAR(support::areaInXY(s.shapes[2].mesh), 0.36, 1e-6); // the 0.6 x 0.6 square kept
    EXPECT_TRUE(s.shapes[3].mesh.empty());
    ASSERT_FALSE(s.shapes[3].warnings.empty());
    EXPECT_NE(s.shapes[3].warnings[0].find("does not match the 2 control points"),
              std::string::npos);
    for (const std::string& note : s.notes)
        EXPECT_EQ(note.find("not drawn"), std::string::npos) << note;
}

TEST(GeometryNodes, FansStripsAndQuadsKeepTheirWinding) {
    std::unique_ptr<fl::scene::Scene> keep;
    // Each describes the same unit square facing +z, two triangles.
    const SceneMeshes s = meshX3d(R"(
        Shape { geometry TriangleFanSet { fanCount 4
            coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } } }
        Shape { geometry TriangleStripSet { stripCount 4
            coord Coordinate { point [0 0 0, 1 0 0, 0 1 0, 1 1 0] } } }
        Shape { geometry IndexedTriangleFanSet { index [0 1 2 3 -1]
            coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } } }
        Shape { geometry IndexedTriangleStripSet { index [0 1 3 2]
            coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } } }
        Shape { geometry QuadSet { coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } } }
        Shape { geometry IndexedQuadSet { index [0 1 2 3]
            coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } } }
        Shape { geometry TriangleFanSet { fanCount [3 3] colorPerVertex FALSE
            color Color { color [1 0 0, 1 0 0, 1 0 0, 0 0 1, 0 0 1, 0 0 1] }
            coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 0 0, 1 1 0, 0 1 0] } } })",
                                  keep);
    ASSERT_EQ(s.shapes.size(), 7u);
    for (std::size_t k = 0; k < s.shapes.size(); ++k) {
        EXPECT_EQ(s.shapes[k].mesh.triangleCount(), 2u) << "shape " << k;
        EXPECT_NEAR(support::areaInXY(s.shapes[k].mesh), 1.0, 1e-6) << "shape " << k;
        for (const Vec3f& n : s.shapes[k].mesh.normals)
            EXPECT_NEAR(n[2], 1.0, 1e-6) << "shape " << k;
    }
    // X3D: fan sets ignore colorPerVertex FALSE; the colours stay per vertex.
    const Mesh& coloured = s.shapes[6].mesh;
    ASSERT_EQ(coloured.colours.size(), coloured.vertexCount());
    EXPECT_EQ(coloured.colours[coloured.triangles[0][0]][0], 1.0f);
    EXPECT_EQ(coloured.colours[coloured.triangles[1][0]][2], 1.0f);
}

TEST(GeometryNodes, Geometry2DLiesInTheXYPlane) {
    std::unique_ptr<fl::scene::Scene> keep;
    const SceneMeshes s = meshX3d(R"(
        Shape { geometry Rectangle2D { size 2 3 } }
        Shape { geometry Disk2D { outerRadius 1 } }
        Shape { geometry Disk2D { innerRadius 0.5 outerRadius 1 } }
        Shape { geometry ArcClose2D { radius 1 startAngle 0 endAngle 1.5707963 } }
        Shape { geometry TriangleSet2D { vertices [0 0, 1 0, 0 1] } }
        Shape { geometry Circle2D { radius 2 } }
        Shape { geometry Arc2D { radius 1 startAngle 0 endAngle 3.14159265 } }
        Shape { geometry Polyline2D { lineSegments [0 0, 1 0, 1 1] } }
        Shape { geometry Polypoint2D { point [0 0, 1 1, 2 2] } })",
                                  keep);
    ASSERT_EQ(s.shapes.size(), 9u);
    EXPECT_NEAR(support::areaInXY(s.shapes[0].mesh), 6.0, 1e-6);
    EXPECT_NEAR(support::areaInXY(s.shapes[1].mesh), std::numbers::pi, 0.01);
    EXPECT_NEAR(support::areaInXY(s.shapes[2].mesh), 0.75 * std::numbers::pi, 0.01);
    EXPECT_NEAR(support::areaInXY(s.shapes[3].mesh), std::numbers::pi / 4, 0.01);
    EXPECT_NEAR(support::areaInXY(s.shapes[4].mesh), 0.5, 1e-6);
    for (std::size_t k : {5u, 6u, 7u})
        EXPECT_TRUE(s.shapes[k].mesh.isLines()) << "shape " << k;
    EXPECT_EQ(s.shapes[7].mesh.segments.size(), 2u);
    // A full circle ends where it starts; a half arc ends at (-1, 0).
    const Mesh& arc = s.shapes[6].mesh;
    EXPECT_NEAR(arc.positions.back()[0], -1.0, 1e-6);
    EXPECT_TRUE(s.shapes[8].mesh.isPointCloud());
    EXPECT_EQ(s.shapes[8].mesh.vertexCount(), 3u);
    for (const auto& shape : s.shapes)
        for (const Vec3f& p : shape.mesh.positions)
            EXPECT_EQ(p[2], 0.0f);
}

TEST(GeometryNodes, StripsWithoutNormalsAreSmoothWhereTrianglesMeet) {
    std::unique_ptr<fl::scene::Scene> keep;
    // A strip folded along x = 1: the shared vertices average both faces.
    const SceneMeshes s = meshX3d(R"(
        Shape { geometry TriangleStripSet { stripCount 4
            coord Coordinate { point [0 0 0, 0 1 0, 1 0 0, 1 1 0] } } }
        Shape { geometry TriangleStripSet { stripCount 6 normalPerVertex FALSE
            coord Coordinate { point [0 0 0, 0 1 0, 1 0 0, 1 1 0, 1 0 -1, 1 1 -1] } } }
        Shape { geometry TriangleStripSet { stripCount 6
            coord Coordinate { point [0 0 0, 0 1 0, 1 0 0, 1 1 0, 1 0 -1, 1 1 -1] } } })",
                                  keep);
    ASSERT_EQ(s.shapes.size(), 3u);
    auto normalAt = [](const Mesh& m, float x, float z) {
        for (std::size_t i = 0; i < m.positions.size(); ++i)
            if (m.positions[i][0] == x && m.positions[i][2] == z && m.positions[i][1] == 0)
                return m.normals[i];
        return Vec3f{0, 0, 0};
    };
    const Vec3f flat = normalAt(s.shapes[1].mesh, 1, 0);
    const Vec3f smooth = normalAt(s.shapes[2].mesh, 1, 0);
    EXPECT_NEAR(std::abs(flat[0]) + std::abs(flat[2]), 1.0, 1e-5); // one face's own
    // The mean of the three triangles there: two facing z, one facing x.
    EXPECT_NEAR(std::abs(smooth[0]), 1 / std::sqrt(5.0), 1e-5);
    EXPECT_NEAR(std::abs(smooth[2]), 2 / std::sqrt(5.0), 1e-5);
}

TEST(GeometryNodes, HostileSizesAreBoundedOrRefusedWithAWarning) {
    std::unique_ptr<fl::scene::Scene> keep;
    const SceneMeshes s = meshX3d(R"(
        Shape { geometry Arc2D { endAngle 1e8 } }
        Shape { geometry LineSet { vertexCount [2147483647] coord Coordinate { point [0 0 0, 1 1 1] } } }
        Shape { geometry Box { size 1e39 1 1 } }
        Shape { geometry NurbsPatchSurface { uDimension 2 vDimension 2 uOrder 2 vOrder 2
            uTessellation 4096 vTessellation 4096
            controlPoint Coordinate { point [0 0 0, 1 0 0, 0 1 0, 1 1 0] } } }
        Shape { geometry NurbsCurve { knot [-1e308 -1e308 -1e308 1e308 1e308 1e308]
            controlPoint Coordinate { point [0 0 0, 1 0 0, 2 0 0] } } })",
                                  keep);
    ASSERT_EQ(s.shapes.size(), 5u);
    EXPECT_LE(s.shapes[0].mesh.vertexCount(), 49u);
    EXPECT_EQ(s.shapes[1].mesh.segments.size(), 1u);
    EXPECT_TRUE(s.shapes[2].mesh.empty());
    ASSERT_FALSE(s.shapes[2].warnings.empty());
    EXPECT_NE(s.shapes[2].warnings[0].find("too large"), std::string::npos);
    EXPECT_LE(s.shapes[3].mesh.triangleCount(), 2u * 1048576u);
    ASSERT_FALSE(s.shapes[3].warnings.empty());
    EXPECT_NE(s.shapes[3].warnings[0].find("more than 1048576 cells"), std::string::npos);
    // An overflowing knot range falls back to uniform knots: a finite curve.
    ASSERT_FALSE(s.shapes[4].mesh.empty());
    for (const Vec3f& p : s.shapes[4].mesh.positions)
        EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
}
