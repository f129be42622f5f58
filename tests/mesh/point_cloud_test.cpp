// Point clouds: on the true surface, evenly spread, through a solid's inside,
// over a parametric object's parameters; the same points for the same seed;
// and written to every format that holds points.
#include "mesh_test_support.h"

#include "formula/compiler.h"
#include "mesh/mesh_export.h"
#include "mesh/point_cloud.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstring>

using namespace fl::mesh;
using namespace fl::mesh::support;

namespace {

double radius(const Vec3f& p) {
    return std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]);
}

double fractionWhere(const Mesh& m, bool (*test)(const Vec3f&)) {
    std::size_t n = 0;
    for (const Vec3f& p : m.positions)
        n += test(p) ? 1 : 0;
    return double(n) / double(m.vertexCount());
}

ParametricField parametric(const std::string& script, std::array<double, 2> u,
                           std::array<double, 2> v, std::array<double, 2> w = {0, 1}) {
    return parametricField(script, u, v, w);
}

} // namespace

TEST(PointCloud, SurfacePointsLieOnTheTrueSurfaceEvenlyWithOutwardNormals) {
    PointCloudOptions o;
    o.count = 20000;
    const MeshResult r = pointsOnSurface(field("0.8^2 - x*x - y*y - z*z"), o);
    ASSERT_TRUE(r.ok()) << r.error;
    const Mesh& m = r.mesh;
    EXPECT_TRUE(m.isPointCloud());
    EXPECT_TRUE(m.triangles.empty());
    ASSERT_EQ(m.vertexCount(), o.count);
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        const Vec3f& p = m.positions[i];
        ASSERT_NEAR(radius(p), 0.8, 1e-6) << "not moved onto the surface";
        const Vec3f& n = m.normals[i];
        EXPECT_NEAR(n[0] * p[0] + n[1] * p[1] + n[2] * p[2], 0.8, 1e-5); // radial, outward
    }
    // Even by area: a hemisphere holds half, the cap x > 0.4 (height 0.4 of
    // the diameter 1.6) a quarter.
    EXPECT_NEAR(fractionWhere(m, [](const Vec3f& p) { return p[2] > 0; }), 0.5, 0.02);
    EXPECT_NEAR(fractionWhere(m, [](const Vec3f& p) { return p[0] > 0.4f; }), 0.25, 0.02);
}

TEST(PointCloud, TheSameSeedGivesTheSamePoints) {
    const ImplicitField f = field("0.5 - abs(x) - abs(y) - abs(z)");
    PointCloudOptions o;
    o.count = 2000;
    const Mesh a = pointsOnSurface(f, o).mesh, b = pointsOnSurface(f, o).mesh;
    ASSERT_EQ(a.positions, b.positions);
    o.seed = 2;
    EXPECT_NE(pointsOnSurface(f, o).mesh.positions, a.positions);
    const Mesh c = pointsInSolid(f, o).mesh, d = pointsInSolid(f, o).mesh;
    EXPECT_EQ(c.positions, d.positions);
}

TEST(PointCloud, SolidPointsFillTheInsideUniformly) {
    PointCloudOptions o;
    o.count = 30000;
    const MeshResult r = pointsInSolid(field("0.8^2 - x*x - y*y - z*z"), o);
    ASSERT_TRUE(r.ok()) << r.error;
    const Mesh& m = r.mesh;
    EXPECT_TRUE(m.isPointCloud());
    EXPECT_NEAR(double(m.vertexCount()), double(o.count), 0.1 * double(o.count));
    for (const Vec3f& p : m.positions)
        ASSERT_LT(radius(p), 0.8 + 1e-6);
    for (const Vec3f& n : m.normals)
        ASSERT_EQ(n, (Vec3f{0, 0, 0})); // inside a solid there is no surface to light
    // Uniform by volume: the inner ball of half the radius holds an eighth.
    EXPECT_NEAR(fractionWhere(m, [](const Vec3f& p) { return radius(p) < 0.4; }), 0.125, 0.01);
}

TEST(PointCloud, EmptyUndefinedAndOversizedRequestsAreExplained) {
    const MeshResult empty = pointsInSolid(field("-1 - x*x"));
    EXPECT_TRUE(empty.ok());
    EXPECT_TRUE(empty.mesh.empty());
    ASSERT_EQ(empty.warnings.size(), 1u);
    EXPECT_NE(empty.warnings[0].find("no point"), std::string::npos);

    const MeshResult half = pointsInSolid(field("sqrt(x) - 0.5 + 0*y"));
    ASSERT_TRUE(half.ok()) << half.error;
    EXPECT_FALSE(half.mesh.empty());
    ASSERT_EQ(half.warnings.size(), 1u);
    EXPECT_NE(half.warnings[0].find("NaN"), std::string::npos);

    PointCloudOptions tooMany;
    tooMany.count = 1'000'000'000;
    EXPECT_NE(pointsInSolid(field("1 - x*x"), tooMany).error.find("between 1 and"),
              std::string::npos);
    tooMany.count = 0;
    EXPECT_FALSE(pointsOnSurface(field("1 - x*x"), tooMany).ok());
}

TEST(PointCloud, ParametricPointsCoverTheParametersAndKeepThem) {
    PointCloudOptions o;
    o.count = 2500; // 50 x 50
    const MeshResult sphere = pointsOverParameters(
        parametric("x = sin(v)*cos(u); y = sin(v)*sin(u); z = cos(v);", {0, 2 * M_PI}, {0, M_PI}),
        o);
    ASSERT_TRUE(sphere.ok()) << sphere.error;
    const Mesh& m = sphere.mesh;
    EXPECT_EQ(m.vertexCount(), 2500u);
    EXPECT_EQ(m.parameters.size(), m.vertexCount());
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        EXPECT_NEAR(radius(m.positions[i]), 1, 1e-6);
        const Vec3f& n = m.normals[i];
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        // Unit where the surface is regular; zero at the poles, where it is not.
        EXPECT_TRUE(std::abs(len - 1) < 1e-5 || len == 0) << len;
    }
    EXPECT_FLOAT_EQ(m.parameters.back()[0], float(2 * M_PI));

    o.count = 8000; // 20^3 through a ball
    const MeshResult ball =
        pointsOverParameters(parametric("x = w*sin(v)*cos(u); y = w*sin(v)*sin(u); z = w*cos(v);",
                                        {0, 2 * M_PI}, {0, M_PI}, {0, 1}),
                             o);
    ASSERT_TRUE(ball.ok());
    EXPECT_EQ(ball.mesh.vertexCount(), 8000u);
    std::size_t inside = 0;
    for (const Vec3f& p : ball.mesh.positions)
        inside += radius(p) < 0.99 ? 1 : 0;
    EXPECT_GT(inside, 6000u); // through the volume, not only on the boundary
}

TEST(PointCloud, ExportsWritePointsWhereTheFormatHoldsThem) {
    PointCloudOptions o;
    o.count = 500;
    Mesh m = pointsOnSurface(field("0.8^2 - x*x - y*y - z*z"), o).mesh;
    m.colours.assign(m.vertexCount(), {1, 0, 0, 1});

    const std::string ply = encodeMesh(m, MeshFormat::Ply);
    EXPECT_NE(ply.find("element vertex 500\n"), std::string::npos);
    EXPECT_NE(ply.find("element face 0\n"), std::string::npos);

    const std::string glb = encodeMesh(m, MeshFormat::Glb);
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    const QJsonObject root =
        QJsonDocument::fromJson(QByteArray(glb.data() + 20, int(jsonLength))).object();
    const QJsonObject primitive =
        root["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject();
    EXPECT_EQ(primitive["mode"].toInt(), 0); // POINTS
    EXPECT_FALSE(primitive.contains("indices"));
    EXPECT_EQ(root["accessors"].toArray().size(), 3); // positions, normals, colours

    auto scene = fl::scene::readSceneBytes(encodeMesh(m, MeshFormat::X3d), "points.x3d");
    ASSERT_TRUE(scene.ok());
    for (const auto& d : scene.diagnostics)
        ADD_FAILURE() << fl::scene::formatSceneDiagnostic(d);
    const fl::scene::Node* set = fl::scene::nodeField(*scene.scene->roots.at(0), "geometry");
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(set->type, "PointSet");
    EXPECT_EQ(fl::scene::numbersField(*fl::scene::nodeField(*set, "coord"), "point").size(),
              3 * m.vertexCount());

    std::string error;
    EXPECT_FALSE(writeMesh(m, testing::TempDir() + "points.stl", error));
    EXPECT_NE(error.find("STL holds triangles only"), std::string::npos);
}
