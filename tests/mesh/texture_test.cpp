// Image textures on standard geometry: X3D's default texture coordinates
// (Box faces upright, Sphere and Cylinder wrapped from the back, face sets by
// their bounding box), given coordinates and indices, TextureTransform,
// PixelTexture pixels and ImageTexture urls resolved next to the scene.
#include "mesh/scene_meshing.h"
#include "mesh/standard_geometry.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace fl::mesh;

namespace {

// The texture coordinate of the vertex at p with normal n (first match).
std::array<float, 2> stAt(const Mesh& m, Vec3f p, Vec3f n) {
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        bool same = true;
        for (std::size_t k = 0; k < 3; ++k)
            same = same && std::abs(m.positions[i][k] - p[k]) < 1e-5f &&
                   std::abs(m.normals[i][k] - n[k]) < 1e-3f;
        if (same) return m.texCoords.at(i);
    }
    ADD_FAILURE() << "no vertex there";
    return {-1, -1};
}

SceneMeshes meshX3d(const std::string& body, std::unique_ptr<fl::scene::Scene>& keep,
                    const std::string& path = "texture.x3dv") {
    auto r = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, path);
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << fl::scene::formatSceneDiagnostic(d);
    keep = std::move(r.scene);
    SceneMeshOptions o;
    o.placeInScene = false;
    return meshScene(*keep, o);
}

} // namespace

TEST(TextureCoordinates, BoxFacesShowTheImageUpright) {
    const Mesh m = boxMesh({2, 2, 2});
    ASSERT_EQ(m.texCoords.size(), m.positions.size());
    // Front (+z): lower left (0, 0), upper right (1, 1).
    EXPECT_EQ(stAt(m, {-1, -1, 1}, {0, 0, 1}), (std::array<float, 2>{0, 0}));
    EXPECT_EQ(stAt(m, {1, 1, 1}, {0, 0, 1}), (std::array<float, 2>{1, 1}));
    // Back (-z) seen from behind: +x is on the left.
    EXPECT_EQ(stAt(m, {1, -1, -1}, {0, 0, -1}), (std::array<float, 2>{0, 0}));
    // Right (+x): -z is on the right.
    EXPECT_EQ(stAt(m, {1, -1, 1}, {1, 0, 0}), (std::array<float, 2>{0, 0}));
    // Top (+y) seen from above with -z up: the back edge is t = 1.
    EXPECT_EQ(stAt(m, {-1, 1, -1}, {0, 1, 0}), (std::array<float, 2>{0, 1}));
    // Bottom (-y) seen from below with +z up.
    EXPECT_EQ(stAt(m, {-1, -1, 1}, {0, -1, 0}), (std::array<float, 2>{0, 1}));
}

TEST(TextureCoordinates, SphereAndCylinderWrapFromTheBack) {
    const Mesh s = sphereMesh(1, 16);
    ASSERT_EQ(s.texCoords.size(), s.positions.size());
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        const auto& p = s.positions[i];
        const auto& st = s.texCoords[i];
        EXPECT_NEAR(st[1], std::acos(std::clamp(-p[1], -1.0f, 1.0f)) / M_PI, 1e-5); // t up
        if (std::abs(p[1]) > 0.999f) continue;                                      // poles
        // s = 0 (and 1) at -z, 0.25 at -x, 0.5 at +z, 0.75 at +x.
        const double a = std::atan2(-p[0], -p[2]) / (2 * M_PI);                 // -0.5 .. 0.5
        const double d = std::abs(st[0] - a) - std::floor(std::abs(st[0] - a)); // modulo 1
        EXPECT_LT(std::min(d, 1 - d), 1e-5) << p[0] << " " << p[2];
    }
    const Mesh c = cylinderMesh(1, 2, true, true, true, 16);
    EXPECT_EQ(stAt(c, {0, -1, 1}, {0, 0, 1}), (std::array<float, 2>{0.5f, 0}));
    EXPECT_EQ(stAt(c, {0, 1, -1}, {0, 1, 0}), (std::array<float, 2>{0.5f, 1})); // top cap, back
}

TEST(TextureCoordinates, FaceSetsUseTheirOwnOrTheBoundingBox) {
    FaceSet f;
    f.points = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}};
    f.coordIndex = {0, 1, 2, 3};
    Mesh m = faceSetMesh(f).mesh;
    // Longest side (x, 4) along s; y along t at the same scale.
    EXPECT_EQ(stAt(m, {4, 2, 0}, {0, 0, 1}), (std::array<float, 2>{1, 0.5f}));
    f.texCoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
    f.texCoordIndex = {4, 1, 2, 3};
    m = faceSetMesh(f).mesh;
    EXPECT_EQ(stAt(m, {0, 0, 0}, {0, 0, 1}), (std::array<float, 2>{0.5f, 0.5f}));
    f.texCoordIndex = {9, 1, 2, 3};
    const FaceSetResult bad = faceSetMesh(f);
    ASSERT_FALSE(bad.warnings.empty());
    EXPECT_NE(bad.warnings[0].find("texCoord"), std::string::npos);
}

TEST(SceneTextures, PixelTexturesAndTransformsReachTheLook) {
    std::unique_ptr<fl::scene::Scene> keep;
    const SceneMeshes s = meshX3d(R"(
        Shape { appearance Appearance {
                  texture PixelTexture { image 2 1 3 0xFF0000 0x00FF00 repeatS FALSE }
                  textureTransform TextureTransform { translation 0.5 0 scale 2 1 } }
                geometry IndexedFaceSet { coordIndex [0 1 2 3]
                  coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } } }
        Shape { geometry Box {} })",
                                  keep);
    ASSERT_EQ(s.shapes.size(), 2u);
    const ShapeMesh& quad = s.shapes[0];
    ASSERT_TRUE(quad.look.texture);
    EXPECT_EQ(quad.look.texture->width, 2);
    EXPECT_EQ(quad.look.texture->components, 3);
    EXPECT_EQ(quad.look.texture->rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));
    EXPECT_FALSE(quad.look.texture->repeatS);
    EXPECT_TRUE(quad.look.texture->repeatT);
    // Translated by 0.5, then scaled by 2 along s: corner (0, 0) -> (1, 0).
    EXPECT_EQ(stAt(quad.mesh, {0, 0, 0}, {0, 0, 1}), (std::array<float, 2>{1, 0}));
    EXPECT_EQ(stAt(quad.mesh, {1, 1, 0}, {0, 0, 1}), (std::array<float, 2>{3, 1}));
    // Without a texture the coordinates are not kept.
    EXPECT_FALSE(s.shapes[1].look.texture);
    EXPECT_TRUE(s.shapes[1].mesh.texCoords.empty());
}

TEST(SceneTextures, ImageUrlsAreFoundNextToTheSceneOrExplained) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "functionlab_textures";
    std::filesystem::create_directories(dir / "images");
    std::ofstream(dir / "images" / "wood.png") << "not really a png"; // decoding is the viewer's
    std::unique_ptr<fl::scene::Scene> keep;
    const SceneMeshes s = meshX3d(R"(
        Shape { appearance Appearance { texture ImageTexture { url ["http://x/wood.png" "images/wood.png"] } }
                geometry Box {} }
        Shape { appearance Appearance { texture ImageTexture { url "missing.jpg" } }
                geometry Box {} })",
                                  keep, (dir / "scene.x3dv").string());
    ASSERT_EQ(s.shapes.size(), 2u);
    ASSERT_TRUE(s.shapes[0].look.texture);
    EXPECT_EQ(std::filesystem::path(s.shapes[0].look.texture->file),
              std::filesystem::absolute(dir / "images" / "wood.png").lexically_normal());
    EXPECT_FALSE(s.shapes[1].look.texture);
    ASSERT_EQ(s.shapes[1].warnings.size(), 1u);
    EXPECT_NE(s.shapes[1].warnings[0].find("no file 'missing.jpg'"), std::string::npos);
}
