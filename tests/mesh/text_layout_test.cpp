// Text layout (text_layout.h) by the X3D FontStyle rules. The font here is
// a block font of known metrics — each character a 0.5 x 0.7 box on the
// baseline, advance 0.6, ascent 0.8, descent 0.2 (times size) — so every
// place is computable; the real glyphs from Qt are tested in viewer_tests.
#include "mesh/scene_meshing.h"
#include "mesh/text_layout.h"
#include "mesh_test_support.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace fl::mesh;

namespace {

OutlinedLine blockFont(const std::string& text, const FontRequest& font) {
    OutlinedLine l;
    const double s = font.size;
    double x = 0;
    for (char c : text) {
        if (c != ' ') {
            l.glyphStarts.push_back(l.contours.size());
            l.contours.push_back({{x, 0}, {x + 0.5 * s, 0}, {x + 0.5 * s, 0.7 * s}, {x, 0.7 * s}});
        }
        x += 0.6 * s;
    }
    l.advance = x;
    l.ascent = 0.8 * s;
    l.descent = 0.2 * s;
    return l;
}

struct Box {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
};

Box boundsOf(const Mesh& m) {
    Box b;
    for (const Vec3f& p : m.positions) {
        b.x0 = std::min(b.x0, double(p[0]));
        b.x1 = std::max(b.x1, double(p[0]));
        b.y0 = std::min(b.y0, double(p[1]));
        b.y1 = std::max(b.y1, double(p[1]));
    }
    return b;
}

const auto area = support::areaInXY;

TextLayout twoLines() {
    TextLayout t;
    t.lines = {"ABCD", "AB"};
    t.font.size = 2;
    return t;
}

} // namespace

TEST(TextLayout, BeginFirstStartsAtTheOriginOnTheFirstBaseline) {
    const Mesh m = textMesh(twoLines(), blockFont);
    ASSERT_FALSE(m.empty());
    const Box b = boundsOf(m);
    EXPECT_NEAR(b.x0, 0, 1e-6);
    EXPECT_NEAR(b.x1, 3 * 1.2 + 1.0, 1e-6); // the fourth box of the longer line
    EXPECT_NEAR(b.y1, 1.4, 1e-6);           // the first line's boxes stand on y = 0
    EXPECT_NEAR(b.y0, -2.0, 1e-6);          // the second baseline one size * spacing down
    EXPECT_NEAR(area(m), 6 * 1.0 * 1.4, 1e-6);
    for (const Vec3f& n : m.normals)
        EXPECT_EQ(n, (Vec3f{0, 0, 1}));
}

TEST(TextLayout, MajorJustificationPlacesEachLine) {
    TextLayout t = twoLines();
    t.justifyMajor = "MIDDLE";
    Box b = boundsOf(textMesh(t, blockFont));
    EXPECT_NEAR(b.x0, -2.4, 1e-6); // "ABCD" advances 4.8, centred
    t.justifyMajor = "END";
    b = boundsOf(textMesh(t, blockFont));
    EXPECT_NEAR(b.x1, -0.2, 1e-6); // ends at 0 with the last box's 0.2 of spare advance
    t.justifyMajor = "FIRST";      // same as BEGIN
    EXPECT_NEAR(boundsOf(textMesh(t, blockFont)).x0, 0, 1e-6);
}

TEST(TextLayout, MinorJustificationAndSpacing) {
    TextLayout t = twoLines();
    t.spacing = 2;
    EXPECT_NEAR(boundsOf(textMesh(t, blockFont)).y0, -4.0, 1e-6);
    t.spacing = 1;
    t.justifyMinor = "BEGIN"; // the top (ascent 1.6) of the first line at 0
    EXPECT_NEAR(boundsOf(textMesh(t, blockFont)).y1, 1.4 - 1.6, 1e-6);
    t.justifyMinor = "END"; // the bottom (descent 0.4) of the last line at 0
    EXPECT_NEAR(boundsOf(textMesh(t, blockFont)).y0, 0.4, 1e-6);
    t.justifyMinor = "MIDDLE"; // block from +1.6 to -2.4 centred on 0
    const Box b = boundsOf(textMesh(t, blockFont));
    EXPECT_NEAR(b.y1, 1.4 + 0.4, 1e-6);
    t.justifyMinor = "FIRST";
    t.topToBottom = false; // the second line above the first
    EXPECT_NEAR(boundsOf(textMesh(t, blockFont)).y1, 2.0 + 1.4, 1e-6);
}

TEST(TextLayout, LengthAndMaxExtentSqueeze) {
    TextLayout t = twoLines();
    t.length = {2.4}; // "ABCD" from 4.8 to 2.4: half as wide
    Box b = boundsOf(textMesh(t, blockFont));
    EXPECT_NEAR(b.x1, 2.4 - 0.1, 1e-6);
    t.length.clear();
    t.maxExtent = 1.2; // the longest line (4.8) squeezed to 1.2, the other in proportion
    const Mesh m = textMesh(t, blockFont);
    b = boundsOf(m);
    EXPECT_NEAR(b.x1, 1.2 - 0.05, 1e-6);
    EXPECT_NEAR(area(m), 6 * 1.0 * 1.4 / 4, 1e-6);
    t.maxExtent = 100; // wider than needed: untouched
    EXPECT_NEAR(boundsOf(textMesh(t, blockFont)).x1, 4.6, 1e-6);
}

TEST(TextLayout, RightToLeftAndVerticalText) {
    TextLayout t = twoLines();
    t.leftToRight = false; // BEGIN: the text runs leftwards from 0
    Box b = boundsOf(textMesh(t, blockFont));
    EXPECT_NEAR(b.x0, -4.8, 1e-6);
    EXPECT_LE(b.x1, 0.0);
    t = twoLines();
    t.horizontal = false; // columns of characters downwards, the columns rightwards
    const Mesh m = textMesh(t, blockFont);
    b = boundsOf(m);
    EXPECT_NEAR(area(m), 6 * 1.0 * 1.4, 1e-6);
    EXPECT_LT(b.y1, 0.1);
    EXPECT_GT(b.y0, -8.1); // "ABCD": four characters of size 2 below y = 0
    EXPECT_GT(b.x1, 1.5);  // the second column one size * spacing to the right
    t.topToBottom = false; // upwards: BEGIN starts the column at y = 0
    b = boundsOf(textMesh(t, blockFont));
    EXPECT_GT(b.y0, -0.1);
    EXPECT_LT(b.y1, 8.1);
}

TEST(TextLayout, VeryLongTextIsCutWithAWarning) {
    TextLayout t;
    t.lines = {std::string(kMaxTextCharacters + 5, 'A')};
    std::vector<std::string> warnings;
    const Mesh m = textMesh(t, blockFont, &warnings);
    EXPECT_EQ(m.triangleCount(), 2 * kMaxTextCharacters);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("only the first"), std::string::npos);
}

TEST(TextLayout, AFontSourceWithoutFontsIsReported) {
    std::vector<std::string> warnings;
    const Mesh m = textMesh(
        twoLines(),
        [](const std::string&, const FontRequest&) {
            OutlinedLine none;
            none.problem = "no fonts";
            return none;
        },
        &warnings);
    EXPECT_TRUE(m.empty());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "Text: no fonts");
}

TEST(TextLayout, NoFontSourceOrBadSizeDrawsNothing) {
    EXPECT_TRUE(textMesh(twoLines(), {}).empty());
    TextLayout t = twoLines();
    t.font.size = -1;
    EXPECT_TRUE(textMesh(t, blockFont).empty());
    t.font.size = std::nan("");
    EXPECT_TRUE(textMesh(t, blockFont).empty());
}

TEST(TextLayout, SceneTextUsesTheGivenFontSourceOrSaysWhyNot) {
    auto r = fl::scene::readSceneBytes(R"(#X3D V3.3 utf8
PROFILE Full
Shape { geometry Text { string ["AB"] fontStyle FontStyle { size 2 justify ["END" "BEGIN"] } } })",
                                       "text.x3dv");
    ASSERT_TRUE(r.ok());
    SceneMeshOptions o;
    SceneMeshes without = meshScene(*r.scene, o);
    ASSERT_FALSE(without.notes.empty());
    EXPECT_NE(without.notes[0].find("Text is not drawn without a font source"), std::string::npos);
    o.text = blockFont;
    const SceneMeshes with = meshScene(*r.scene, o);
    ASSERT_EQ(with.shapes.size(), 1u);
    const Box b = boundsOf(with.shapes[0].mesh);
    EXPECT_NEAR(b.x1, -0.2, 1e-6);
    EXPECT_NEAR(b.y1, 1.4 - 1.6, 1e-6);
}
