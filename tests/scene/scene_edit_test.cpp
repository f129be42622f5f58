// Several field changes made as one edit of the scene's text
// (scene/scene_edit.h): applied together they set every field, leave the
// comments and every other value as typed, and read back as the model they
// describe, whatever order they were asked in; the resolution edit the
// Accuracy panel writes moves a level of detail's finest end with it.
#include "scene/field_access.h"
#include "scene/scene_edit.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl::scene;

namespace {

const Node* firstOfKind(const Scene& s, NodeKind kind) {
    const Node* found = nullptr;
    s.forEachNode([&](const Node& n) {
        if (!found && n.kind() == kind) found = &n;
    });
    return found;
}

const char* kXml = R"X(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile='Immersive' version='3.3'><Scene>
  <!-- the student's note -->
  <FShape DEF='A'>
    <FGeometry definition='"sphere(1)"' lod='true' lodRange='4 40' domainMin='-2 -2 -2' domainMax='2 2 2'/>
    <FAppearance><FMaterial type='parametric' definition='"r = 1; g = 0; b = 0;"'/></FAppearance>
  </FShape>
</Scene></X3D>
)X";

const char* kClassic = "#X3D V3.3 utf8\nPROFILE Immersive\n# the student's note\n"
                       "DEF A FShape {\n  geometry FGeometry { definition \"sphere(1)\" }\n"
                       "  appearance FAppearance { material FMaterial { type \"parametric\"\n"
                       "    definition \"r = 1; g = 0; b = 0;\" } }\n}\n";

} // namespace

TEST(SceneEdit, SeveralFieldsInOneEditReadBackAsTheModelInBothEncodings) {
    for (const auto& [text, path] : {std::pair{kXml, "a.x3d"}, std::pair{kClassic, "a.x3dv"}}) {
        const ReadResult r = readSceneBytes(text, path);
        ASSERT_TRUE(r.ok()) << path;
        const Node* geometry = firstOfKind(*r.scene, NodeKind::FGeometry);
        const Node* material = firstOfKind(*r.scene, NodeKind::FMaterial);
        ASSERT_TRUE(geometry && material);
        // Asked for in text order and out of it: the edits sort themselves.
        SceneEdit edit(*r.scene);
        ASSERT_TRUE(edit.setStrings(*material, "definition", {"r = 0; g = 1; b = 0;"}));
        ASSERT_TRUE(edit.setStrings(*geometry, "definition", {"sphere(0.5) | box(0.2, 0.2, 0.2)"}));
        ASSERT_TRUE(edit.setNumbers(*geometry, "resolution", {48}));
        for (std::size_t i = 1; i < edit.edits().size(); ++i)
            EXPECT_GE(edit.edits()[i - 1].offset, edit.edits()[i].offset);
        const std::string after = edit.appliedTo(r.scene->files[0].text);
        EXPECT_NE(after.find("the student's note"), std::string::npos) << after;
        const ReadResult again = readSceneBytes(after, path);
        ASSERT_TRUE(again.ok()) << after;
        const Node* g = firstOfKind(*again.scene, NodeKind::FGeometry);
        const Node* m = firstOfKind(*again.scene, NodeKind::FMaterial);
        EXPECT_EQ(stringsField(*g, "definition"),
                  std::vector<std::string>{"sphere(0.5) | box(0.2, 0.2, 0.2)"});
        EXPECT_EQ(numberField(*g, "resolution"), 48);
        EXPECT_EQ(stringsField(*m, "definition"), std::vector<std::string>{"r = 0; g = 1; b = 0;"});
    }
}

TEST(SceneEdit, TheResolutionEditMakesTheChoiceTheCoarsestLevelOfDetail) {
    const ReadResult r = readSceneBytes(kXml, "a.x3d");
    ASSERT_TRUE(r.ok());
    const Node* geometry = firstOfKind(*r.scene, NodeKind::FGeometry);
    std::string why;
    const auto edit = resolutionEdit(*r.scene, *geometry, 24, &why);
    ASSERT_TRUE(edit) << why;
    EXPECT_EQ(edit->edits().size(), 2u);
    const ReadResult again = readSceneBytes(edit->appliedTo(r.scene->files[0].text), "a.x3d");
    ASSERT_TRUE(again.ok());
    const Node* g = firstOfKind(*again.scene, NodeKind::FGeometry);
    EXPECT_EQ(numberField(*g, "resolution"), 24);
    EXPECT_EQ(numbersField(*g, "lodRange"), (std::vector<double>{24, 40}));
    // Finer than the range's fine end: the range shrinks to one value.
    const auto fine = resolutionEdit(*r.scene, *geometry, 64, &why);
    ASSERT_TRUE(fine);
    const ReadResult f = readSceneBytes(fine->appliedTo(r.scene->files[0].text), "a.x3d");
    EXPECT_EQ(numbersField(*firstOfKind(*f.scene, NodeKind::FGeometry), "lodRange"),
              (std::vector<double>{64, 64}));
}

TEST(SceneEdit, ANodeNotWrittenInTheTextSaysWhyAndChangesNothing) {
    const ReadResult r = readSceneBytes(kClassic, "a.x3dv");
    ASSERT_TRUE(r.ok());
    Node built; // made by code: nowhere in the text
    built.type = "FGeometry";
    SceneEdit edit(*r.scene);
    std::string why;
    EXPECT_FALSE(edit.setNumbers(built, "resolution", {8}, &why));
    EXPECT_FALSE(why.empty());
    EXPECT_TRUE(edit.empty());
    EXPECT_EQ(edit.appliedTo(r.scene->files[0].text), r.scene->files[0].text);
}
