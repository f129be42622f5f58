// The standard X3D geometry as meshes: the right size and volume, closed once
// the vertices that sharp edges duplicate are welded, facing outward, and
// face sets that honour ccw, colours per vertex or per face, normals and
// crease angles — with a warning, not a crash, for bad indices.
#include "mesh/mesh_topology.h"
#include "mesh/standard_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace fl::mesh;

namespace {

void expectClosedOutwardSolid(const Mesh& m, double volume, double tolerance) {
    const Topology t = analyseTopology(weldedByPosition(m));
    EXPECT_TRUE(t.closed()) << t.boundaryEdges << " boundary edges";
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.consistentlyOriented());
    EXPECT_NEAR(t.signedVolume, volume, tolerance * volume);
    // Every normal is unit and points away from the centre (these solids are convex).
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        const Vec3f& n = m.normals[i];
        const Vec3f& p = m.positions[i];
        EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-5);
        EXPECT_GE(n[0] * p[0] + n[1] * p[1] + n[2] * p[2], 0);
    }
}

Mesh cubeFaceSet(bool ccw, FaceSetResult* result = nullptr) {
    FaceSet f;
    for (int i = 0; i < 8; ++i)
        f.points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    // Counter-clockwise from outside: -z, +z, -y, +y, -x, +x.
    f.coordIndex = {0, 2, 3, 1, -1, 4, 5, 7, 6, -1, 0, 1, 5, 4, -1,
                    2, 6, 7, 3, -1, 0, 4, 6, 2, -1, 1, 3, 7, 5};
    if (!ccw) std::reverse(f.coordIndex.begin(), f.coordIndex.end());
    f.ccw = ccw;
    FaceSetResult r = faceSetMesh(f);
    if (result) *result = r;
    return r.mesh;
}

} // namespace

TEST(StandardGeometry, PrimitivesHaveTheirX3dSizesAndVolumes) {
    expectClosedOutwardSolid(boxMesh({2, 3, 4}), 24, 1e-9);
    EXPECT_EQ(boxMesh({2, 3, 4}).triangleCount(), 12u);
    const double pi = std::numbers::pi;
    expectClosedOutwardSolid(sphereMesh(1.5, 96), 4.0 / 3 * pi * 1.5 * 1.5 * 1.5, 0.01);
    expectClosedOutwardSolid(cylinderMesh(0.5, 2, true, true, true, 96), pi * 0.25 * 2, 0.01);
    expectClosedOutwardSolid(coneMesh(1, 2, true, true, 96), pi * 2 / 3, 0.01);
    // Extents: centred on the origin, axis along y.
    for (const Mesh& m : {cylinderMesh(0.5, 2, true, true, true), coneMesh(1, 2, true, true)}) {
        float lo = 1e9f, hi = -1e9f;
        for (const Vec3f& p : m.positions) {
            lo = std::min(lo, p[1]);
            hi = std::max(hi, p[1]);
        }
        EXPECT_FLOAT_EQ(lo, -1);
        EXPECT_FLOAT_EQ(hi, 1);
    }
}

TEST(StandardGeometry, PartsLeftOutLeaveAnOpenSurface) {
    const Topology t = analyseTopology(weldedByPosition(cylinderMesh(1, 1, true, false, true)));
    EXPECT_FALSE(t.closed()); // no top
    EXPECT_TRUE(coneMesh(1, 1, false, false).empty());
}

TEST(StandardGeometry, FaceSetsFanPolygonsAndHonourCcw) {
    expectClosedOutwardSolid(cubeFaceSet(true), 1, 1e-9);
    // The same cube written clockwise with ccw FALSE is the same solid.
    const Mesh cw = cubeFaceSet(false);
    EXPECT_NEAR(analyseTopology(weldedByPosition(cw)).signedVolume, 1, 1e-9);
    EXPECT_EQ(cw.triangleCount(), 12u);
}

TEST(StandardGeometry, ColoursPerVertexOrPerFaceAndCreaseAngles) {
    FaceSet f;
    f.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    f.coordIndex = {0, 1, 4, -1, 1, 2, 4, -1, 2, 3, 4, -1, 3, 0, 4}; // a four-sided pyramid
    f.colours = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1}};
    f.colourPerVertex = false; // one colour per face
    const Mesh flat = faceSetMesh(f).mesh;
    ASSERT_EQ(flat.colours.size(), flat.vertexCount());
    EXPECT_EQ(flat.colours[0], (std::array<float, 4>{1, 0, 0, 1}));
    EXPECT_EQ(flat.colours[3], (std::array<float, 4>{0, 1, 0, 1}));
    // creaseAngle 0: each face flat, its three corners share its normal.
    EXPECT_EQ(flat.normals[0], flat.normals[1]);
    // A crease angle wider than the faces' angle: the apex normal is their mean, straight up.
    f.creaseAngle = std::numbers::pi;
    const Mesh smooth = faceSetMesh(f).mesh;
    EXPECT_NEAR(smooth.normals[2][2], 1, 1e-6); // corner 2 of face 0 is the apex
    EXPECT_NE(smooth.normals[0], flat.normals[0]);
}

TEST(StandardGeometry, BadIndicesWarnAndNeverCrash) {
    FaceSet f;
    f.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    f.coordIndex = {0, 1, 2, -1, 0, 1, 7, -1, 0, 1, -1};
    f.colours = {{1, 0, 0, 1}};
    f.colourIndex = {0, 0, 5};
    const FaceSetResult r = faceSetMesh(f);
    EXPECT_EQ(r.mesh.triangleCount(), 1u);
    EXPECT_EQ(r.warnings.size(), 2u); // a bad index, a two-vertex polygon
    EXPECT_EQ(r.mesh.colours[2], (std::array<float, 4>{0.8f, 0.8f, 0.8f, 1})); // grey, not garbage
    EXPECT_TRUE(faceSetMesh({}).mesh.empty());
}

TEST(StandardGeometry, PointSetsArePoints) {
    const Mesh m = pointSetMesh({{0, 0, 0}, {1, 2, 3}}, {{1, 0, 0, 1}, {0, 1, 0, 1}});
    EXPECT_TRUE(m.isPointCloud());
    EXPECT_EQ(m.vertexCount(), 2u);
    EXPECT_EQ(m.colours.size(), 2u);
    EXPECT_TRUE(pointSetMesh({{0, 0, 0}}, {}).colours.empty());
}

TEST(StandardGeometry, ElevationGridsFaceUpWithTheirHeights) {
    ElevationGrid g;
    g.xDimension = 3;
    g.zDimension = 2;
    g.xSpacing = 0.5;
    g.zSpacing = 2;
    g.height = {0, 1, 0, 0, 1, 0};
    const FaceSetResult r = elevationGridMesh(g);
    EXPECT_EQ(r.mesh.triangleCount(), 4u); // two quads
    for (const Vec3f& n : r.mesh.normals)
        EXPECT_GT(n[1], 0.4f); // up (slopes of 2: 1/sqrt 5)
    float top = 0;
    for (const Vec3f& p : r.mesh.positions)
        top = std::max(top, p[1]);
    EXPECT_FLOAT_EQ(top, 1);
    g.height.resize(2); // too few heights: a warning, zeros, no crash
    EXPECT_FALSE(elevationGridMesh(g).warnings.empty());
    g.xDimension = 1;
    EXPECT_TRUE(elevationGridMesh(g).mesh.empty());
}

TEST(StandardGeometry, ExtrusionsSweepTheirCrossSectionAndFaceOutward) {
    // The default: a unit square swept from y = 0 to 1, capped: a 2 x 1 x 2 box.
    const FaceSetResult box = extrusionMesh(Extrusion{});
    expectClosedOutwardSolid(box.mesh, 4, 1e-6);
    // A circle swept along a bent spine, scaled down: closed, outward, right volume order.
    Extrusion tube;
    tube.crossSection.clear();
    for (int i = 0; i <= 32; ++i)
        tube.crossSection.push_back({0.2 * std::cos(2 * std::numbers::pi * i / 32),
                                     -0.2 * std::sin(2 * std::numbers::pi * i / 32)});
    tube.crossSection.back() = tube.crossSection.front(); // closed: the same point, exactly
    tube.spine = {{0, 0, 0}, {0, 1, 0}, {1, 2, 0}, {2, 2, 0}};
    const FaceSetResult bent = extrusionMesh(tube);
    const Topology t = analyseTopology(weldedByPosition(bent.mesh));
    EXPECT_TRUE(t.closed());
    EXPECT_GT(t.signedVolume, 0);
    // Open at both ends: the sides still face away from the spine.
    tube.beginCap = tube.endCap = false;
    const FaceSetResult open = extrusionMesh(tube);
    const auto& n = open.mesh.normals[0];
    const auto& p = open.mesh.positions[0];
    EXPECT_GT(n[0] * p[0] + n[2] * p[2], 0);
}

TEST(StandardGeometry, LineSetsAreSegmentsOfTheirPolylines) {
    FaceSet f;
    f.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    f.coordIndex = {0, 1, 2, -1, 2, 3, 9, 0}; // a bad index breaks the second polyline
    f.colours = {{1, 0, 0, 1}, {0, 0, 1, 1}};
    f.colourPerVertex = false; // one colour per polyline
    const FaceSetResult r = lineSetMesh(f);
    EXPECT_TRUE(r.mesh.isLines());
    EXPECT_EQ(r.mesh.segments.size(), 3u); // 0-1, 1-2, then 2-3 (3-9 and 9-0 are lost)
    EXPECT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.mesh.colours.front(), (std::array<float, 4>{1, 0, 0, 1}));
    EXPECT_EQ(r.mesh.colours.back(), (std::array<float, 4>{0, 0, 1, 1}));
    for (const Vec3f& n : r.mesh.normals)
        EXPECT_EQ(n, (Vec3f{0, 0, 0})); // unlit
}
