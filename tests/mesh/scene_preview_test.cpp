// The preview `convert` adds for other X3D browsers: plain X3D geometry of
// every function shape, written in every encoding, and dropped again by our
// readers so that write-then-read stays the identity.
#include "mesh/scene_meshing.h"
#include "mesh/scene_preview.h"
#include "scene/field_access.h"
#include "scene/gzip.h"
#include "scene/preview_marker.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <string>

using namespace fl;

namespace {

std::unique_ptr<scene::Scene> readExample(const std::string& name) {
    auto r = scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name);
    EXPECT_TRUE(r.ok()) << name;
    return std::move(r.scene);
}

std::unique_ptr<scene::Scene> readText(const std::string& text) {
    auto r = scene::readSceneBytes(text, "written");
    EXPECT_TRUE(r.ok());
    return std::move(r.scene);
}

const scene::Node* previewOf(const scene::Scene& s) {
    for (const scene::Node* n : s.roots)
        if (n->defName == scene::kPreviewDefName) return n;
    return nullptr;
}

} // namespace

TEST(ScenePreview, DrawsEveryFunctionShapeAsPlainGeometry) {
    auto s = readExample("implicit_gallery.x3d");
    const std::size_t roots = s->roots.size();
    const mesh::PreviewResult p = mesh::addPreview(*s);
    EXPECT_EQ(p.shapes, 6u); // the gallery's six function shapes
    EXPECT_GT(p.triangles, 1000u);
    ASSERT_EQ(s->roots.size(), roots + 1);
    const scene::Node* group = previewOf(*s);
    ASSERT_NE(group, nullptr);
    EXPECT_EQ(group->type, "Group");
    const scene::Field* children = group->field("children");
    ASSERT_NE(children, nullptr);
    ASSERT_EQ(children->value.nodes.size(), 6u);
    std::size_t triangles = 0;
    for (const scene::Node* shape : children->value.nodes) {
        ASSERT_EQ(shape->type, "Shape");
        const scene::Node* faces = shape->field("geometry")->value.nodes.at(0);
        ASSERT_EQ(faces->type, "IndexedFaceSet");
        const auto& index = faces->field("coordIndex")->value.numbers;
        triangles += index.size() / 4;
        const auto& points =
            faces->field("coord")->value.nodes.at(0)->field("point")->value.numbers;
        for (double i : index)
            ASSERT_LT(i * 3, double(points.size()));
    }
    EXPECT_EQ(triangles, p.triangles);
}

TEST(ScenePreview, EveryReaderDropsItAgain) {
    for (const char* example : {"watermelon.x3d", "fan.x3d", "clock.x3d"}) {
        auto original = readExample(example);
        auto withPreview = readExample(example);
        ASSERT_GT(mesh::addPreview(*withPreview).shapes, 0u) << example;
        for (auto encoding :
             {scene::Encoding::Xml, scene::Encoding::ClassicVrml, scene::Encoding::Vrml97}) {
            // Against the scene written without a preview in the same
            // encoding: VRML97 has no COMPONENT statements to keep, say.
            auto plain = readText(scene::writeScene(*original, encoding));
            std::string text = scene::writeScene(*withPreview, encoding);
            ASSERT_NE(text.find(std::string(scene::kPreviewDefName)), std::string::npos);
            ASSERT_NE(text.find("IndexedFaceSet"), std::string::npos);
            for (bool gzipped : {false, true}) {
                auto back = readText(gzipped ? scene::gzip(text) : text);
                ASSERT_TRUE(back);
                EXPECT_EQ(previewOf(*back), nullptr) << example;
                std::string difference;
                EXPECT_TRUE(scene::sameModel(*plain, *back, &difference))
                    << example << " (encoding " << int(encoding) << "): " << difference;
            }
        }
    }
}

TEST(ScenePreview, AScenePreviewedTwiceHoldsOnePreview) {
    auto s = readExample("watermelon.x3d");
    mesh::addPreview(*s);
    auto back = readText(scene::writeScene(*s, scene::Encoding::ClassicVrml));
    mesh::addPreview(*back);
    std::size_t previews = 0;
    for (const scene::Node* n : back->roots)
        previews += n->defName == scene::kPreviewDefName;
    EXPECT_EQ(previews, 1u);
}

TEST(ScenePreview, NothingToDrawAddsNothing) {
    auto s = readText("#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry Box {} }\n");
    const std::size_t roots = s->roots.size();
    const mesh::PreviewResult p = mesh::addPreview(*s);
    EXPECT_EQ(p.shapes, 0u);
    EXPECT_EQ(s->roots.size(), roots); // standard shapes other browsers draw themselves
}

TEST(ScenePreview, SeeThroughShapesStaySeeThrough) {
    // The fan's wind is drawn translucent; Color has no alpha, so the
    // preview's Material carries it.
    auto s = readExample("fan.x3d");
    mesh::addPreview(*s);
    const scene::Node* group = previewOf(*s);
    ASSERT_NE(group, nullptr);
    bool seeThrough = false;
    for (const scene::Node* shape : group->field("children")->value.nodes) {
        const scene::Node* material =
            shape->field("appearance")->value.nodes.at(0)->field("material")->value.nodes.at(0);
        if (const scene::Field* t = material->field("transparency"))
            seeThrough |= t->value.numbers.at(0) > 0.1;
    }
    EXPECT_TRUE(seeThrough);
}
