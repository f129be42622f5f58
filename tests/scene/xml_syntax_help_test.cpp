// What a student is told about an XML syntax error (scene/xml_syntax_help.h):
// a bare `&` or `<` in an attribute is found where it was written (not where
// the parser gave up), the message says what to write, and the fix, applied,
// makes the file read. Markup, comments and content are never mistaken for
// an attribute's formula.
#include "scene/scene_reader.h"
#include "scene/xml_syntax_help.h"

#include <gtest/gtest.h>

using namespace fl::scene;

namespace {

std::string scene(const std::string& definition) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<X3D profile='Immersive' version='3.3'><Scene>\n"
           "  <FShape><FGeometry definition='\"" +
           definition + "\"'/></FShape>\n</Scene></X3D>\n";
}

SceneDiagnostic firstError(const std::string& text) {
    const ReadResult r = readSceneBytes(text, "lab.x3d");
    EXPECT_FALSE(r.ok());
    for (const SceneDiagnostic& d : r.diagnostics)
        if (d.severity == Severity::Error) return d;
    return {};
}

// The text with the fix applied (columns are characters; this text is ASCII
// up to the fix).
std::string withFix(const std::string& text, const DiagnosticFix& fix) {
    std::size_t at = 0;
    for (int line = 1; line < fix.at.line; ++line)
        at = text.find('\n', at) + 1;
    at += std::size_t(fix.at.column - 1);
    return text.substr(0, at) + fix.text + text.substr(at + std::size_t(fix.length));
}

} // namespace

TEST(XmlSyntaxHelp, ABareAmpersandIsFoundWhereItWasWrittenAndFixed) {
    const std::string text = scene("sphere(1) & box(0.5, 0.5, 0.5)");
    const SceneDiagnostic d = firstError(text);
    EXPECT_EQ(d.pos.line, 3);
    const std::size_t lineStart = text.rfind('\n', text.find('&')) + 1;
    EXPECT_EQ(d.pos.column, int(text.find('&') - lineStart) + 1);        // the & itself
    EXPECT_EQ(d.message.rfind("write &amp; for &", 0), 0u) << d.message; // what to do, first
    EXPECT_NE(d.suggestion.find(".x3dv"), std::string::npos) << d.suggestion;
    ASSERT_TRUE(d.fix);
    EXPECT_EQ(d.fix->text, "&amp;");
    const ReadResult fixed = readSceneBytes(withFix(text, *d.fix), "lab.x3d");
    EXPECT_TRUE(fixed.ok()) << (fixed.diagnostics.empty() ? "" : fixed.diagnostics[0].message);
}

TEST(XmlSyntaxHelp, LogicalAndAndComparisonsAreFixedWhole) {
    const std::string andText = scene("x > 0 && y > 0 ? 1 : -1");
    const SceneDiagnostic a = firstError(andText);
    ASSERT_TRUE(a.fix);
    EXPECT_EQ(a.fix->length, 2);
    EXPECT_EQ(a.fix->text, "&amp;&amp;");
    EXPECT_TRUE(readSceneBytes(withFix(andText, *a.fix), "lab.x3d").ok());

    const std::string less = scene("x < 0 ? 1 : -1");
    const SceneDiagnostic l = firstError(less);
    ASSERT_TRUE(l.fix);
    EXPECT_NE(l.message.find("<"), std::string::npos);
    EXPECT_EQ(l.fix->text, "&lt;");
    EXPECT_TRUE(readSceneBytes(withFix(less, *l.fix), "lab.x3d").ok());

    // An entity started but not finished (`&amp b`): the & is still the place.
    const std::string unfinished = scene("sphere(1) &amp box(1, 1, 1)");
    const SceneDiagnostic u = firstError(unfinished);
    ASSERT_TRUE(u.fix) << u.message;
    const std::size_t at = unfinished.find("&amp");
    EXPECT_EQ(u.pos.column, int(at - unfinished.rfind('\n', at))); // the & itself
}

TEST(XmlSyntaxHelp, OnlyAttributeValuesAreTakenForFormulas) {
    // A stray & in element content, and a < in a comment before it: the
    // parser's own message stands (no fix), nothing is invented.
    const std::string content = "<?xml version=\"1.0\"?>\n<X3D profile='Immersive'>"
                                "<!-- a < b & c --><Scene> fish & chips </Scene></X3D>\n";
    const SceneDiagnostic d = firstError(content);
    EXPECT_FALSE(d.fix) << d.message;
    EXPECT_NE(d.message.find("malformed XML"), std::string::npos) << d.message;
    EXPECT_FALSE(explainXmlSyntaxError("", {1, 1}));
    EXPECT_FALSE(explainXmlSyntaxError("<a b='x & y'/>", {99, 1})); // past the end: bounded
}

TEST(XmlSyntaxHelp, ALongFileIsScannedWithBoundedMemory) {
    // 200 000 lines of markup before the mistake: found all the same.
    std::string text = "<?xml version=\"1.0\"?>\n<X3D profile='Immersive'><Scene>\n";
    for (int i = 0; i < 200000; ++i)
        text += "<!-- & < -->\n";
    text += "<FShape><FGeometry definition='\"a & b\"'/></FShape></Scene></X3D>\n";
    const SceneDiagnostic d = firstError(text);
    ASSERT_TRUE(d.fix) << d.message;
    EXPECT_EQ(d.pos.line, 200003);
}
