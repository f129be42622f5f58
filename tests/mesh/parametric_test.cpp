// Parametric geometry: surfaces with seams and poles welded shut, curves as
// closed tubes, solids as their boundary, normals defined everywhere.
#include "formula/compiler.h"
#include "mesh/mesh_topology.h"
#include "mesh/parametric.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fl::mesh;

namespace {

ParametricField field(const std::string& script, std::array<double, 2> u = {0, 1},
                      std::array<double, 2> v = {0, 1}, std::array<double, 2> w = {0, 1}) {
    return fl::mesh::support::parametricField(script, u, v, w);
}

void expectClosedAndUnitNormals(const Mesh& m) {
    const Topology t = analyseTopology(m);
    EXPECT_TRUE(t.closed()) << t.boundaryEdges << " boundary edges";
    EXPECT_TRUE(t.manifold()) << t.nonManifoldEdges;
    EXPECT_TRUE(t.consistentlyOriented()) << t.misorientedEdges;
    for (const Vec3f& n : m.normals) {
        ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]));
        EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-5);
    }
}

} // namespace

TEST(Parametric, SphereSeamAndPolesAreWelded) {
    const ParametricField f =
        field("x = sin(v)*cos(u); y = sin(v)*sin(u); z = cos(v);", {0, 2 * M_PI}, {0, M_PI});
    ParametricOptions o;
    o.resolution = 32;
    const MeshResult r = meshParametric(f, o);
    ASSERT_TRUE(r.ok()) << r.error;
    expectClosedAndUnitNormals(r.mesh);
    const Topology t = analyseTopology(r.mesh);
    EXPECT_EQ(t.eulerCharacteristic, 2);
    EXPECT_NEAR(std::abs(t.signedVolume), 4.0 / 3.0 * M_PI, 0.02 * 4.0 / 3.0 * M_PI);
    // At the poles the normal is the pole's direction, not zero.
    for (std::size_t i = 0; i < r.mesh.vertexCount(); ++i) {
        const Vec3f& p = r.mesh.positions[i];
        const Vec3f& n = r.mesh.normals[i];
        EXPECT_GT(std::abs(p[0] * n[0] + p[1] * n[1] + p[2] * n[2]), 0.95f);
    }
    EXPECT_EQ(r.mesh.parameters.size(), r.mesh.vertexCount());
}

TEST(Parametric, TorusIsClosedWithTwoSeams) {
    const ParametricField f =
        field("x = (1 + 0.3*cos(v))*cos(u); y = (1 + 0.3*cos(v))*sin(u); z = 0.3*sin(v);",
              {0, 2 * M_PI}, {0, 2 * M_PI});
    const MeshResult r = meshParametric(f);
    ASSERT_TRUE(r.ok());
    expectClosedAndUnitNormals(r.mesh);
    EXPECT_EQ(analyseTopology(r.mesh).eulerCharacteristic, 0);
}

TEST(Parametric, CurveBecomesAClosedTube) {
    ParametricField f = field("x = cos(u); y = sin(u); z = 0.1*u;", {0, 4 * M_PI});
    f.box = {{-1, -1, 0}, {1, 1, 1.3}};
    const MeshResult r = meshParametric(f);
    ASSERT_TRUE(r.ok());
    expectClosedAndUnitNormals(r.mesh);
    EXPECT_GT(analyseTopology(r.mesh).signedVolume, 0);
}

TEST(Parametric, SolidsAreTheirBoundary) {
    const MeshResult cube = meshParametric(field("x = u; y = v; z = w;"));
    ASSERT_TRUE(cube.ok());
    expectClosedAndUnitNormals(cube.mesh);
    EXPECT_NEAR(analyseTopology(cube.mesh).signedVolume, 1, 1e-6);
    // A mirrored parametrisation still faces outward.
    const MeshResult mirrored = meshParametric(field("x = -u; y = v; z = w;"));
    EXPECT_NEAR(analyseTopology(mirrored.mesh).signedVolume, 1, 1e-6);
    // A ball by radius: its u = 0 and u = 2 pi faces meet inside and vanish,
    // its w = 0 face collapses to the centre.
    ParametricOptions o;
    o.resolution = 24;
    const MeshResult ball =
        meshParametric(field("x = w*sin(v)*cos(u); y = w*sin(v)*sin(u); z = w*cos(v);",
                             {0, 2 * M_PI}, {0, M_PI}, {0, 1}),
                       o);
    ASSERT_TRUE(ball.ok());
    const Topology t = analyseTopology(ball.mesh);
    EXPECT_NEAR(t.signedVolume, 4.0 / 3.0 * M_PI, 0.03 * 4.0 / 3.0 * M_PI);
}

TEST(Parametric, BadInputIsExplained) {
    EXPECT_NE(meshParametric(field("x = u; y = v; z = 0;", {1, 0})).error.find("uRange"),
              std::string::npos);
    const MeshResult point = meshParametric(field("x = 1; y = 2; z = 3;"));
    EXPECT_TRUE(point.ok());
    EXPECT_TRUE(point.mesh.empty());
    ASSERT_EQ(point.warnings.size(), 1u);
    const MeshResult nan = meshParametric(field("x = sqrt(u - 0.5); y = v; z = 0;"));
    EXPECT_TRUE(nan.ok());
    EXPECT_FALSE(nan.mesh.empty());
    EXPECT_EQ(nan.warnings.size(), 1u);
}

// Adaptive sampling: parameter lines are halved only where the object bends.
TEST(ParametricAdaptive, AFlatPatchKeepsTheCoarseGrid) {
    ParametricOptions o;
    o.resolution = 32;
    const MeshResult flat = meshParametric(field("x = u; y = v; z = 0;"), o);
    ASSERT_TRUE(flat.ok()) << flat.error;
    EXPECT_EQ(flat.mesh.triangleCount(), 2u * 8 * 8); // a quarter of the resolution per side
    o.adaptive = false;
    EXPECT_EQ(meshParametric(field("x = u; y = v; z = 0;"), o).mesh.triangleCount(), 2u * 32 * 32);
}

TEST(ParametricAdaptive, ABumpIsRefinedWhereItIsAndTheChordsMeetTheTolerance) {
    const ParametricField f = field("x = u; y = v; z = 0.3*exp(-200*((u - 0.5)^2 + (v - 0.5)^2));");
    ParametricOptions o;
    o.resolution = 32;
    const MeshResult r = meshParametric(f, o);
    ASSERT_TRUE(r.ok()) << r.error;
    const double tolerance = 0.02 * 2.0 / 32; // the default: 2% of a cell of the [-1, 1] box
    EXPECT_GT(r.stats.chordError, 0);
    EXPECT_LE(r.stats.chordError, tolerance);
    // Vertices crowd round the bump: its quarter of the patch (|u - 0.5|,
    // |v - 0.5| < 0.25) holds far more than a quarter of them.
    std::size_t nearBump = 0;
    for (const auto& p : r.mesh.parameters)
        if (std::abs(p[0] - 0.5f) < 0.25f && std::abs(p[1] - 0.5f) < 0.25f) ++nearBump;
    EXPECT_GT(double(nearBump), 0.5 * double(r.mesh.vertexCount()));
    // And the whole costs less than a uniform grid as fine as its finest span.
    o.adaptive = false;
    o.resolution = 128;
    EXPECT_LT(r.mesh.triangleCount(), meshParametric(f, o).mesh.triangleCount() / 2);
}

TEST(ParametricAdaptive, AnSCurveWhoseMidpointIsOnItsChordIsStillRefined) {
    // Over [0, 0.5] the curve's middle is on the chord; its quarters are not.
    ParametricOptions o;
    o.resolution = 4; // two segments to start from
    o.tubeRadius = 0.01;
    const MeshResult r = meshParametric(field("x = u; y = 0.3*sin(4*pi*u); z = 0;"), o);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_GT(r.stats.chordError, 0);
    EXPECT_GT(r.mesh.vertexCount(), (2u + 1) * 8 + 2); // more rings than the two segments give
}

TEST(ParametricAdaptive, ASmallerToleranceGivesMoreDetailWithinIt) {
    const ParametricField f =
        field("x = (1 + 0.3*cos(v))*cos(u); y = (1 + 0.3*cos(v))*sin(u); z = 0.3*sin(v);",
              {0, 2 * M_PI}, {0, 2 * M_PI});
    ParametricOptions coarse, fine;
    coarse.tolerance = 1e-2;
    fine.tolerance = 1e-4;
    fine.resolution = coarse.resolution = 64;
    const MeshResult a = meshParametric(f, coarse), b = meshParametric(f, fine);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_LE(a.stats.chordError, 1e-2);
    EXPECT_LE(b.stats.chordError, 1e-4);
    EXPECT_GT(b.mesh.triangleCount(), 4 * a.mesh.triangleCount());
    expectClosedAndUnitNormals(b.mesh); // the seams still meet vertex to vertex
}
