// Setting a field in the text the student wrote (scene/field_text_edit.h):
// the edit changes that field and nothing else, in both encodings, whether
// the field was written or left at its default; what cannot be edited in
// place says why.
#include "scene/field_access.h"
#include "scene/field_text_edit.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace fl::scene;

namespace {

const Node* findType(const std::vector<Node*>& nodes, std::string_view type);

const Node* findIn(const Node& n, std::string_view type) {
    if (n.type == type) return &n;
    for (const Field& f : n.fields)
        if (const Node* found = findType(f.value.nodes, type)) return found;
    return nullptr;
}

const Node* findType(const std::vector<Node*>& nodes, std::string_view type) {
    for (const Node* n : nodes)
        if (n)
            if (const Node* found = findIn(*n, type)) return found;
    return nullptr;
}

// Reads `text`, sets FGeometry's `field` to `value`, reads the result back.
std::vector<double> setAndReread(const std::string& text, const std::string& path,
                                 std::string_view field, std::string_view value,
                                 std::string* edited = nullptr) {
    const ReadResult r = readSceneBytes(text, path);
    EXPECT_TRUE(r.ok());
    if (!r.ok()) return {};
    const Node* g = findType(r.scene->roots, "FGeometry");
    EXPECT_NE(g, nullptr);
    if (!g) return {};
    std::string why;
    const auto edit = setNumbersFieldEdit(*r.scene, *g, field, value, &why);
    EXPECT_TRUE(edit) << why;
    if (!edit) return {};
    const std::string out = applied(text, *edit);
    if (edited) *edited = out;
    const ReadResult again = readSceneBytes(out, path);
    EXPECT_TRUE(again.ok()) << out;
    if (!again.ok()) return {};
    return numbersField(*findType(again.scene->roots, "FGeometry"), field);
}

const std::string kXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile="Immersive" version="3.3"><Scene>
  <!-- a comment that stays -->
  <FShape><FGeometry DEF="G" definition="1 - x*x - y*y - z*z" resolution="32"/></FShape>
</Scene></X3D>
)";

const std::string kClassic = R"(#X3D V3.3 utf8
PROFILE Immersive
# a comment that stays
FShape { geometry DEF G FGeometry {
  definition "1 - x*x - y*y - z*z"
  resolution 32
  lodRange 8 256
} }
)";

} // namespace

TEST(FieldTextEdit, ReplacesAWrittenXmlValueAndNothingElse) {
    std::string out;
    EXPECT_EQ(setAndReread(kXml, "a.x3d", "resolution", "48", &out), std::vector<double>{48});
    EXPECT_NE(out.find("resolution=\"48\""), std::string::npos) << out;
    EXPECT_NE(out.find("<!-- a comment that stays -->"), std::string::npos);
    EXPECT_EQ(out.size(), kXml.size()); // "32" -> "48"
}

TEST(FieldTextEdit, AddsAnXmlFieldLeftAtItsDefault) {
    std::string out;
    EXPECT_EQ(setAndReread(kXml, "a.x3d", "lodRange", "8 48", &out), (std::vector<double>{8, 48}));
    EXPECT_NE(out.find("<FGeometry lodRange='8 48' DEF=\"G\""), std::string::npos) << out;
}

TEST(FieldTextEdit, ReplacesWrittenClassicValuesOfEveryArity) {
    std::string out;
    EXPECT_EQ(setAndReread(kClassic, "a.x3dv", "resolution", "96.5", &out),
              std::vector<double>{96.5});
    EXPECT_NE(out.find("  resolution 96.5\n"), std::string::npos) << out;
    EXPECT_EQ(setAndReread(kClassic, "a.x3dv", "lodRange", "16 64", &out),
              (std::vector<double>{16, 64}));
    EXPECT_NE(out.find("  lodRange 16 64\n"), std::string::npos) << out;
    EXPECT_NE(out.find("# a comment that stays"), std::string::npos);
}

TEST(FieldTextEdit, AddsAClassicFieldInsideTheNodesBrace) {
    std::string text = kClassic;
    text.replace(text.find("  resolution 32\n"), 16, "");
    std::string out;
    EXPECT_EQ(setAndReread(text, "a.x3dv", "resolution", "20", &out), std::vector<double>{20});
    EXPECT_NE(out.find("FGeometry { resolution 20\n"), std::string::npos) << out;
}

TEST(FieldTextEdit, CountsColumnsInCharactersNotBytes) {
    // Multi-byte characters before the field on its line.
    std::string text = kXml;
    text.replace(text.find("<FShape>"), 8, "<FShape><!-- é∂ --> ");
    EXPECT_EQ(setAndReread(text, "a.x3d", "resolution", "40"), std::vector<double>{40});
    std::string classic = kClassic;
    classic.replace(classic.find("  resolution 32"), 15, "  # π\n  resolution 32");
    EXPECT_EQ(setAndReread(classic, "a.x3dv", "resolution", "40"), std::vector<double>{40});
}

TEST(FieldTextEdit, EveryExampleFunctionGeometryTakesANewResolution) {
    for (const char* name : {"watermelon.x3d", "watermelon.x3dv", "shark.x3d", "fan.x3d",
                             "implicit_gallery.x3d", "metamorphosis.x3d"}) {
        std::ifstream in(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name, std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        SCOPED_TRACE(name);
        EXPECT_EQ(setAndReread(bytes.str(), name, "resolution", "50"), std::vector<double>{50});
    }
}

TEST(FieldTextEdit, NodesNotWrittenInTheTextSayWhy) {
    const ReadResult r = readSceneBytes(kXml, "a.x3d");
    ASSERT_TRUE(r.ok());
    Node built;
    built.type = "FGeometry";
    std::string why;
    EXPECT_FALSE(setNumbersFieldEdit(*r.scene, built, "resolution", "48", &why));
    EXPECT_NE(why.find("not read from a file"), std::string::npos) << why;
    const std::string proto = R"(#X3D V3.3 utf8
PROFILE Immersive
PROTO P [] { FShape { geometry FGeometry { definition "1-x*x-y*y-z*z" resolution 32 } } }
P {}
)";
    const ReadResult p = readSceneBytes(proto, "p.x3dv");
    ASSERT_TRUE(p.ok());
    const Node* expanded = findType(p.scene->roots.front()->expansion, "FGeometry");
    ASSERT_NE(expanded, nullptr);
    EXPECT_FALSE(setNumbersFieldEdit(*p.scene, *expanded, "resolution", "48", &why));
    EXPECT_NE(why.find("PROTO"), std::string::npos) << why;
}

namespace {

// Sets FGeometry's definition to `strings` and reads the result back.
std::vector<std::string> setStringsAndReread(const std::string& text, const std::string& path,
                                             const std::vector<std::string>& strings,
                                             std::string* edited = nullptr) {
    // The strings are not all formulas: read as text only.
    ReadOptions asText;
    asText.compileFunctions = false;
    const ReadResult r = readSceneBytes(text, path, asText);
    EXPECT_TRUE(r.ok());
    if (!r.ok()) return {};
    const Node* g = findType(r.scene->roots, "FGeometry");
    std::string why;
    const auto edit = setStringsFieldEdit(*r.scene, *g, "definition", strings, &why);
    EXPECT_TRUE(edit) << why;
    if (!edit) return {};
    const std::string out = applied(text, *edit);
    if (edited) *edited = out;
    const ReadResult again = readSceneBytes(out, path, asText);
    EXPECT_TRUE(again.ok()) << out;
    if (!again.ok()) return {};
    return findType(again.scene->roots, "FGeometry")->field("definition")->value.strings;
}

// Strings a script may hold: quotes, backslashes, markup, what ends a
// classic list or starts a comment, and a line break.
const std::vector<std::string> kHostile = {
    "r = 0.8; // \"quoted\" ]", "g = 1 \\ 2; # not a comment",
    "b = x < 1 && y > 0 ? 1 : 0; <b>'&amp;'</b>", "line\nbreak"};

} // namespace

TEST(FieldTextEdit, StringsAreReplacedInPlaceInXml) {
    std::string out;
    EXPECT_EQ(setStringsAndReread(kXml, "a.x3d", kHostile, &out), kHostile);
    EXPECT_NE(out.find("<!-- a comment that stays -->"), std::string::npos) << out;
    EXPECT_NE(out.find("resolution=\"32\""), std::string::npos) << out;
    // Single-quoted attributes keep double quotes as they are.
    const std::string single =
        R"(<X3D profile='Immersive' version='3.3'><Scene><FShape><FGeometry definition='"1 - x*x"'/></FShape></Scene></X3D>)";
    EXPECT_EQ(setStringsAndReread(single, "a.x3d", {"2 - y", "z"}, &out),
              (std::vector<std::string>{"2 - y", "z"}));
    EXPECT_NE(out.find(R"(definition='"2 - y" "z"')"), std::string::npos) << out;
}

TEST(FieldTextEdit, StringsAreReplacedInPlaceInClassicEvenInLists) {
    std::string out;
    EXPECT_EQ(setStringsAndReread(kClassic, "a.x3dv", kHostile, &out), kHostile);
    EXPECT_NE(out.find("# a comment that stays"), std::string::npos) << out;
    EXPECT_NE(out.find("lodRange 8 256"), std::string::npos) << out;
    // A list with comments and ] inside strings, replaced whole.
    const std::string list = "#X3D V3.3 utf8\nPROFILE Immersive\nFShape { geometry FGeometry {\n"
                             "  definition [ \"a ] # b\" # a comment ]\n \"c\\\"d\" ]\n"
                             "  resolution 16 } }\n";
    EXPECT_EQ(setStringsAndReread(list, "a.x3dv", {"x"}, &out), (std::vector<std::string>{"x"}));
    EXPECT_NE(out.find("resolution 16"), std::string::npos) << out;
}

TEST(FieldTextEdit, AStringFieldLeftOutIsAdded) {
    const std::string xml = "<X3D profile='Immersive' version='3.3'><Scene><FShape><FGeometry "
                            "resolution='8'/></FShape></Scene></X3D>";
    EXPECT_EQ(setStringsAndReread(xml, "a.x3d", {"1 - x*x"}),
              (std::vector<std::string>{"1 - x*x"}));
    const std::string classic =
        "#X3D V3.3 utf8\nPROFILE Immersive\nFShape { geometry FGeometry { resolution 8 } }\n";
    EXPECT_EQ(setStringsAndReread(classic, "a.x3dv", {"1 - x*x", "y"}),
              (std::vector<std::string>{"1 - x*x", "y"}));
}
