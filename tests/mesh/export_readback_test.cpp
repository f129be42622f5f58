// Every export parsed back and compared with the mesh it came from: the same
// positions (as floats), triangles (0-based here, whatever the format
// counts from), normals and colours, in the same axes. A 1-based OBJ written
// 0-based, swapped axes or a lost colour fails here. (Issue 18: counting
// lines or bytes would not see them.)
#include "mesh/mesh_export.h"
#include "mesh/scene_meshing.h"
#include "mesh_test_support.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

using namespace fl::mesh;

namespace {

// An off-centre, coloured, asymmetric mesh: a swap of axes or a shift of
// indices changes what it says.
Mesh sample() {
    MeshOptions o;
    o.resolution = 8;
    Mesh m =
        meshImplicit(fl::mesh::support::field("0.3 - (x-0.2)^2 - 2*(y+0.1)^2 - 3*z*z"), o).mesh;
    for (const Vec3f& p : m.positions)
        m.colours.push_back({0.5f + 0.5f * p[0], 0.5f + 0.4f * p[1], 0.75f, 1.0f}); // in [0, 1]
    return m;
}

Vec3f unit(const Vec3f& n) {
    const float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return l > 0 ? Vec3f{n[0] / l, n[1] / l, n[2] / l} : n;
}

// What a reader got back, to compare with the mesh.
struct ReadBack {
    std::vector<Vec3f> positions, normals;
    std::vector<std::array<float, 3>> colours;
    std::vector<Triangle> triangles;
};

void expectSame(const Mesh& m, const ReadBack& r, float positionTolerance, float colourTolerance,
                const char* format) {
    ASSERT_EQ(r.positions.size(), m.positions.size()) << format;
    ASSERT_EQ(r.triangles.size(), m.triangles.size()) << format;
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(r.positions[i][k], m.positions[i][k], positionTolerance)
                << format << " vertex " << i << " axis " << k;
    EXPECT_EQ(r.triangles, m.triangles) << format;
    if (!r.normals.empty()) {
        ASSERT_EQ(r.normals.size(), m.positions.size()) << format;
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const Vec3f n = unit(m.normals[i]);
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(r.normals[i][k], n[k], 1e-4) << format << " normal " << i;
        }
    }
    if (colourTolerance >= 0) {
        ASSERT_EQ(r.colours.size(), m.positions.size()) << format;
        for (std::size_t i = 0; i < m.positions.size(); ++i)
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(r.colours[i][k], m.colours[i][k], colourTolerance)
                    << format << " colour " << i;
    }
}

} // namespace

TEST(ExportReadBack, Obj) {
    const Mesh m = sample();
    ReadBack r;
    std::istringstream in(encodeMesh(m, MeshFormat::Obj));
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "v") {
            Vec3f p;
            std::array<float, 3> c;
            words >> p[0] >> p[1] >> p[2] >> c[0] >> c[1] >> c[2];
            r.positions.push_back(p);
            r.colours.push_back(c);
        } else if (tag == "vn") {
            Vec3f n;
            words >> n[0] >> n[1] >> n[2];
            r.normals.push_back(n);
        } else if (tag == "f") {
            Triangle t;
            for (auto& i : t) {
                std::string ref; // "v//vn", counted from 1
                words >> ref;
                const auto slash = ref.find("//");
                ASSERT_NE(slash, std::string::npos) << line;
                ASSERT_EQ(ref.substr(0, slash), ref.substr(slash + 2)) << line;
                const long index = std::stol(ref.substr(0, slash));
                ASSERT_GE(index, 1) << "OBJ counts from 1: " << line;
                i = std::uint32_t(index - 1);
            }
            r.triangles.push_back(t);
        }
    }
    expectSame(m, r, 1e-6f, 1e-6f, "OBJ");
}

TEST(ExportReadBack, Ply) {
    const Mesh m = sample();
    const std::string s = encodeMesh(m, MeshFormat::Ply);
    std::size_t p = s.find("end_header\n");
    ASSERT_NE(p, std::string::npos);
    p += 11;
    ReadBack r;
    for (std::size_t i = 0; i < m.vertexCount(); ++i, p += 28) {
        r.positions.push_back({support::bytesAt<float>(s, p), support::bytesAt<float>(s, p + 4),
                               support::bytesAt<float>(s, p + 8)});
        r.normals.push_back({support::bytesAt<float>(s, p + 12), support::bytesAt<float>(s, p + 16),
                             support::bytesAt<float>(s, p + 20)});
        r.colours.push_back({support::bytesAt<std::uint8_t>(s, p + 24) / 255.0f,
                             support::bytesAt<std::uint8_t>(s, p + 25) / 255.0f,
                             support::bytesAt<std::uint8_t>(s, p + 26) / 255.0f});
        EXPECT_EQ(support::bytesAt<std::uint8_t>(s, p + 27), 255) << "alpha";
    }
    for (std::size_t i = 0; i < m.triangleCount(); ++i, p += 13) {
        ASSERT_EQ(support::bytesAt<std::uint8_t>(s, p), 3);
        r.triangles.push_back({support::bytesAt<std::uint32_t>(s, p + 1),
                               support::bytesAt<std::uint32_t>(s, p + 5),
                               support::bytesAt<std::uint32_t>(s, p + 9)});
    }
    EXPECT_EQ(p, s.size());
    expectSame(m, r, 0, 0.5f / 255 + 1e-6f, "PLY");
}

TEST(ExportReadBack, Glb) {
    const Mesh m = sample();
    const std::string g = encodeMesh(m, MeshFormat::Glb);
    const std::uint32_t jsonLength = support::bytesAt<std::uint32_t>(g, 12);
    const QJsonObject root =
        QJsonDocument::fromJson(QByteArray(g.data() + 20, jsonLength)).object();
    const std::size_t bin = 20 + jsonLength + 8;
    const QJsonArray accessors = root["accessors"].toArray(), views = root["bufferViews"].toArray();
    const QJsonObject primitive =
        root["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject();
    const QJsonObject attributes = primitive["attributes"].toObject();
    // Where accessor `a`'s element i, component k starts in the file.
    auto offsetOf = [&](int a, std::size_t i, int k, int components, int size) {
        const QJsonObject acc = accessors[a].toObject();
        const QJsonObject view = views[acc["bufferView"].toInt()].toObject();
        const std::size_t stride = view.contains("byteStride")
                                       ? std::size_t(view["byteStride"].toInt())
                                       : std::size_t(components * size);
        return bin + std::size_t(view["byteOffset"].toInt()) +
               std::size_t(acc["byteOffset"].toInt()) + i * stride + std::size_t(k * size);
    };
    ReadBack r;
    const int position = attributes["POSITION"].toInt(), normal = attributes["NORMAL"].toInt(),
              colour = attributes["COLOR_0"].toInt(), indices = primitive["indices"].toInt();
    ASSERT_EQ(accessors[colour].toObject()["componentType"].toInt(), 5126); // float
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        Vec3f p, n;
        std::array<float, 3> c;
        for (int k = 0; k < 3; ++k) {
            p[k] = support::bytesAt<float>(g, offsetOf(position, i, k, 3, 4));
            n[k] = support::bytesAt<float>(g, offsetOf(normal, i, k, 3, 4));
            c[k] = support::bytesAt<float>(g, offsetOf(colour, i, k, 4, 4));
        }
        r.positions.push_back(p);
        r.normals.push_back(n);
        r.colours.push_back(c);
    }
    ASSERT_EQ(accessors[indices].toObject()["componentType"].toInt(), 5125); // uint32
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        r.triangles.push_back(
            {support::bytesAt<std::uint32_t>(g, offsetOf(indices, 3 * t, 0, 1, 4)),
             support::bytesAt<std::uint32_t>(g, offsetOf(indices, 3 * t + 1, 0, 1, 4)),
             support::bytesAt<std::uint32_t>(g, offsetOf(indices, 3 * t + 2, 0, 1, 4))});
    expectSame(m, r, 0, 0, "glTF");
}

TEST(ExportReadBack, X3d) {
    const Mesh m = sample();
    auto scene = fl::scene::readSceneBytes(encodeMesh(m, MeshFormat::X3d), "mesh.x3d");
    ASSERT_TRUE(scene.ok());
    const fl::scene::Node* faces = fl::scene::nodeField(*scene.scene->roots.at(0), "geometry");
    ASSERT_NE(faces, nullptr);
    ReadBack r;
    const auto points = fl::scene::numbersField(*fl::scene::nodeField(*faces, "coord"), "point");
    const auto vectors = fl::scene::numbersField(*fl::scene::nodeField(*faces, "normal"), "vector");
    const fl::scene::Node* colourNode = fl::scene::nodeField(*faces, "color");
    ASSERT_NE(colourNode, nullptr);
    const auto colours = fl::scene::numbersField(*colourNode, "color");
    const std::size_t stride = colourNode->type == "ColorRGBA" ? 4 : 3;
    for (std::size_t i = 0; 3 * i + 2 < points.size(); ++i) {
        r.positions.push_back(
            {float(points[3 * i]), float(points[3 * i + 1]), float(points[3 * i + 2])});
        r.normals.push_back(
            {float(vectors[3 * i]), float(vectors[3 * i + 1]), float(vectors[3 * i + 2])});
        r.colours.push_back({float(colours[stride * i]), float(colours[stride * i + 1]),
                             float(colours[stride * i + 2])});
    }
    const auto index = fl::scene::numbersField(*faces, "coordIndex");
    for (std::size_t i = 0; i + 3 < index.size(); i += 4) {
        ASSERT_EQ(index[i + 3], -1);
        r.triangles.push_back(
            {std::uint32_t(index[i]), std::uint32_t(index[i + 1]), std::uint32_t(index[i + 2])});
    }
    expectSame(m, r, 1e-6f, 1e-6f, "X3D");
    EXPECT_TRUE(fl::scene::boolField(*faces, "solid")); // the ellipsoid is closed
    EXPECT_TRUE(fl::scene::boolField(*faces, "ccw"));
}
