// Mesh exports: each format's layout checked byte for byte where it is
// binary, parsed back where a reader exists (X3D through our own scene reader,
// glTF's JSON through Qt), and a failed write never leaves a broken file.
#include "mesh/mesh_export.h"
#include "mesh_test_support.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fl::mesh;

namespace {

Mesh ball(bool colours = false) {
    MeshOptions o;
    o.resolution = 8;
    Mesh m = meshImplicit(fl::mesh::support::field("0.6 - x*x - y*y - z*z"), o).mesh;
    if (colours)
        for (const Vec3f& p : m.positions)
            m.colours.push_back({p[0] * 0.5f + 0.5f, 0.2f, 0.9f, 1.0f});
    return m;
}

} // namespace

TEST(Export, FormatFromTheExtension) {
    EXPECT_EQ(meshFormatForPath("a/b.STL"), MeshFormat::Stl);
    EXPECT_EQ(meshFormatForPath("b.obj"), MeshFormat::Obj);
    EXPECT_EQ(meshFormatForPath("b.ply"), MeshFormat::Ply);
    EXPECT_EQ(meshFormatForPath("b.glb"), MeshFormat::Glb);
    EXPECT_EQ(meshFormatForPath("b.x3d"), MeshFormat::X3d);
    EXPECT_FALSE(meshFormatForPath("b.gltf").has_value());
    std::string error;
    EXPECT_FALSE(writeMesh(ball(), "out.dae", error));
    EXPECT_NE(error.find(".stl, .obj"), std::string::npos);
}

TEST(Export, BinaryStlLayout) {
    const Mesh m = ball();
    const std::string s = encodeMesh(m, MeshFormat::Stl);
    ASSERT_EQ(s.size(), 84 + 50 * m.triangleCount());
    EXPECT_EQ(support::bytesAt<std::uint32_t>(s, 80), m.triangleCount());
    // The first facet's normal agrees with its winding and points outward.
    const float nx = support::bytesAt<float>(s, 84), ny = support::bytesAt<float>(s, 88),
                nz = support::bytesAt<float>(s, 92);
    const float px = support::bytesAt<float>(s, 96), py = support::bytesAt<float>(s, 100),
                pz = support::bytesAt<float>(s, 104);
    EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1, 1e-5);
    EXPECT_GT(nx * px + ny * py + nz * pz, 0);
}

TEST(Export, ObjAndPly) {
    const Mesh m = ball(true);
    const std::string obj = encodeMesh(m, MeshFormat::Obj);
    std::size_t v = 0, vn = 0, f = 0;
    std::istringstream lines(obj);
    for (std::string line; std::getline(lines, line);) {
        v += line.starts_with("v ");
        vn += line.starts_with("vn ");
        f += line.starts_with("f ");
    }
    EXPECT_EQ(v, m.vertexCount());
    EXPECT_EQ(vn, m.vertexCount());
    EXPECT_EQ(f, m.triangleCount());

    const std::string ply = encodeMesh(m, MeshFormat::Ply);
    const std::size_t body = ply.find("end_header\n") + 11;
    ASSERT_NE(body, std::string::npos + 11);
    EXPECT_NE(ply.find("element vertex " + std::to_string(m.vertexCount())), std::string::npos);
    EXPECT_NE(ply.find("property uchar red"), std::string::npos);
    EXPECT_EQ(ply.size() - body, m.vertexCount() * (24 + 4) + m.triangleCount() * 13);
}

TEST(Export, GlbIsAValidGltfContainer) {
    for (bool colours : {false, true}) {
        const Mesh m = ball(colours);
        const std::string g = encodeMesh(m, MeshFormat::Glb);
        ASSERT_EQ(support::bytesAt<std::uint32_t>(g, 0), 0x46546C67u);
        EXPECT_EQ(support::bytesAt<std::uint32_t>(g, 4), 2u);
        EXPECT_EQ(support::bytesAt<std::uint32_t>(g, 8), g.size());
        const std::uint32_t jsonLength = support::bytesAt<std::uint32_t>(g, 12);
        EXPECT_EQ(jsonLength % 4, 0u);
        const QJsonDocument doc = QJsonDocument::fromJson(QByteArray(g.data() + 20, jsonLength));
        ASSERT_TRUE(doc.isObject());
        const QJsonObject root = doc.object();
        EXPECT_EQ(root["asset"].toObject()["version"].toString(), "2.0");
        const QJsonArray accessors = root["accessors"].toArray();
        ASSERT_EQ(accessors.size(), colours ? 4 : 3);
        EXPECT_EQ(accessors[0].toObject()["count"].toInt(), int(m.vertexCount()));
        EXPECT_TRUE(accessors[0].toObject().contains("min"));
        EXPECT_EQ(accessors.last().toObject()["count"].toInt(), int(3 * m.triangleCount()));
        const std::size_t binAt = 20 + jsonLength;
        const std::uint32_t binLength = support::bytesAt<std::uint32_t>(g, binAt);
        EXPECT_EQ(support::bytesAt<std::uint32_t>(g, binAt + 4), 0x004E4942u);
        EXPECT_EQ(binLength,
                  std::uint32_t(root["buffers"].toArray()[0].toObject()["byteLength"].toInt() + 3) /
                      4 * 4);
        const auto primitive =
            root["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject();
        EXPECT_EQ(primitive["attributes"].toObject().contains("COLOR_0"), colours);
    }
    // An empty mesh is still a valid file: a scene with nothing in it.
    const std::string empty = encodeMesh(Mesh{}, MeshFormat::Glb);
    EXPECT_EQ(support::bytesAt<std::uint32_t>(empty, 8), empty.size());
}

TEST(Export, X3dReadsBackThroughOurOwnReader) {
    const Mesh m = ball(true);
    auto r = fl::scene::readSceneBytes(encodeMesh(m, MeshFormat::X3d), "mesh.x3d");
    ASSERT_TRUE(r.ok());
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << fl::scene::formatSceneDiagnostic(d);
    const fl::scene::Node* shape = r.scene->roots.at(0);
    const fl::scene::Node* faces = fl::scene::nodeField(*shape, "geometry");
    ASSERT_NE(faces, nullptr);
    EXPECT_EQ(fl::scene::numbersField(*faces, "coordIndex").size(), 4 * m.triangleCount());
    const fl::scene::Node* coords = fl::scene::nodeField(*faces, "coord");
    ASSERT_NE(coords, nullptr);
    EXPECT_EQ(fl::scene::numbersField(*coords, "point").size(), 3 * m.vertexCount());
    ASSERT_NE(fl::scene::nodeField(*faces, "color"), nullptr);
}

TEST(Export, AFailedWriteLeavesNoFile) {
    std::string error;
    EXPECT_FALSE(writeMesh(ball(), "/nonexistent-folder/x.stl", error));
    EXPECT_NE(error.find("cannot write"), std::string::npos);
    const auto path = std::filesystem::temp_directory_path() / "functionlab-export-test.obj";
    ASSERT_TRUE(writeMesh(ball(), path, error)) << error;
    EXPECT_GT(std::filesystem::file_size(path), 100u);
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
    std::filesystem::remove(path);
}
