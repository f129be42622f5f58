// The scene editor: what gets which colour (including formulas inside
// strings), where a diagnostic is underlined, what completion offers, find
// and replace, and the live parse (a text with errors keeps the last good
// scene; a late parse of older text is dropped).
#include "editor/code_editor.h"
#include "editor/find_bar.h"
#include "editor/live_parser.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QTextBlock>
#include <QTextLayout>
#include <gtest/gtest.h>

using namespace fl::editor;

namespace {

// The format the highlighter gave the character at `column` of `line` (0-based).
QTextCharFormat formatAt(CodeEditor& e, int line, int column) {
    const QTextBlock block = e.document()->findBlockByNumber(line);
    for (const QTextLayout::FormatRange& r : block.layout()->formats())
        if (column >= r.start && column < r.start + r.length) return r.format;
    return {};
}

bool sameColour(const QTextCharFormat& a, const QTextCharFormat& b) {
    return a.foreground().color() == b.foreground().color();
}

} // namespace

TEST(Highlighter, XmlNodesFieldsStringsAndTheFormulaInside) {
    CodeEditor e;
    e.setSyntax(SceneSyntax::Xml);
    e.setPlainText("<FGeometry definition='\"sin(x) + 2*t\"'/> <!-- note -->");
    auto* h = e.highlighter();
    EXPECT_TRUE(sameColour(formatAt(e, 0, 1), h->format(SceneHighlighter::Node)));   // FGeometry
    EXPECT_TRUE(sameColour(formatAt(e, 0, 11), h->format(SceneHighlighter::Field))); // definition
    EXPECT_TRUE(sameColour(formatAt(e, 0, 24), h->format(SceneHighlighter::Function))); // sin
    EXPECT_TRUE(sameColour(formatAt(e, 0, 28), h->format(SceneHighlighter::Variable))); // x
    EXPECT_TRUE(sameColour(formatAt(e, 0, 33), h->format(SceneHighlighter::Number)));   // 2
    EXPECT_TRUE(sameColour(formatAt(e, 0, 43), h->format(SceneHighlighter::Comment)));
}

TEST(Highlighter, ClassicKeywordsCommentsAndStringsAcrossLines) {
    CodeEditor e;
    e.setSyntax(SceneSyntax::Classic);
    // The string runs over the line break: its second line is still formula.
    e.setPlainText(
        "DEF BALL FShape { geometry FGeometry { definition [\"cos(u);\nz = v;\"] } } # c");
    auto* h = e.highlighter();
    EXPECT_TRUE(sameColour(formatAt(e, 0, 0), h->format(SceneHighlighter::Keyword)));   // DEF
    EXPECT_TRUE(sameColour(formatAt(e, 0, 9), h->format(SceneHighlighter::Node)));      // FShape
    EXPECT_TRUE(sameColour(formatAt(e, 0, 52), h->format(SceneHighlighter::Function))); // cos
    EXPECT_TRUE(sameColour(formatAt(e, 1, 0), h->format(SceneHighlighter::Variable)));  // z
    EXPECT_TRUE(sameColour(formatAt(e, 1, 14), h->format(SceneHighlighter::Comment)));
}

TEST(Highlighter, LettersOutsideAsciiNeverHangOrCrash) {
    CodeEditor e;
    e.setSyntax(SceneSyntax::Classic);
    e.setPlainText(QString::fromUtf8("DEF Würfel Transform { } # π ∞ 😀\nDEF π Group {}"));
    EXPECT_EQ(e.document()->blockCount(), 2);
    e.setSyntax(SceneSyntax::Xml);
    e.setPlainText(QString::fromUtf8("<Transform DEF='Würfel' π='1'/>"));
    EXPECT_EQ(e.document()->blockCount(), 1);
}

TEST(CodeEditor, DiagnosticsUnderlineTheWordAtTheirColumn) {
    CodeEditor e;
    e.setPlainText("line one\n  x = sine(y);\n");
    e.setDiagnostics({EditorDiagnostic{2, 7, true, "unknown function 'sine'"}});
    const auto [start, end] = e.rangeOf(e.diagnostics()[0]);
    QTextCursor c(e.document());
    c.setPosition(start);
    c.setPosition(end, QTextCursor::KeepAnchor);
    EXPECT_EQ(c.selectedText(), "sine");
    // Out-of-range places are harmless.
    EXPECT_EQ(e.rangeOf({99, 3, true, "past the end"}), std::make_pair(0, 0));
    e.goTo(99, 99);
    e.goTo(2, 999);
    EXPECT_EQ(e.textCursor().blockNumber(), 1);
}

TEST(CodeEditor, CompletionOffersNodesFieldsAndFunctions) {
    CodeEditor e;
    const QStringList fshape = e.completionsFor("FSh");
    EXPECT_TRUE(fshape.contains("FShape"));
    EXPECT_TRUE(e.completionsFor("smooth").contains("smoothstep"));
    EXPECT_TRUE(e.completionsFor("cycleI").contains("cycleInterval"));
    EXPECT_TRUE(e.completionsFor("zzzz").isEmpty());
}

TEST(FindBar, ReplaceAllIsOneUndoStep) {
    CodeEditor e;
    e.setPlainText("x + x + X");
    FindBar bar(&e);
    bar.setPattern("x", "y");
    EXPECT_EQ(bar.replaceAll(), 3); // case-insensitive by default
    EXPECT_EQ(e.toPlainText(), "y + y + y");
    e.undo();
    EXPECT_EQ(e.toPlainText(), "x + x + X");
    bar.setPattern("nothing");
    EXPECT_FALSE(bar.findNext());
}

// Waits, letting Qt's events run, until the parser has nothing pending or
// `timeoutMs` passes; says which. (QTRY_VERIFY_WITH_TIMEOUT returns from a
// GoogleTest test without failing it, so a hung parser would pass.)
bool settles(const LiveParser& parser, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    while (parser.pending()) {
        if (clock.elapsed() > timeoutMs) return false;
        QTest::qWait(10);
    }
    return true;
}

TEST(LiveParser, ErrorsKeepTheLastGoodSceneAndOnlyTheNewestTextCounts) {
    LiveParser parser;
    parser.setDelay(10);
    QSignalSpy scenes(&parser, &LiveParser::sceneChanged);
    const QString good =
        "#X3D V3.3 utf8\nPROFILE Full\nFShape { geometry FGeometry { definition \"1 - x*x\" } }";
    parser.setText(good, "a.x3dv");
    ASSERT_TRUE(settles(parser, 10000)) << "the parser never finished";
    ASSERT_EQ(scenes.count(), 1);
    const auto first = parser.lastGoodScene();
    ASSERT_TRUE(first);

    QSignalSpy outcomes(&parser, &LiveParser::parsed);
    parser.setText(
        "#X3D V3.3 utf8\nPROFILE Full\nFShape { geometry FGeometry { definition \"sine(x)\" } }",
        "a.x3dv");
    ASSERT_TRUE(settles(parser, 10000)) << "the parser never finished";
    ASSERT_EQ(outcomes.count(), 1);
    const auto outcome = outcomes.takeFirst().at(0).value<ParseOutcome>();
    EXPECT_FALSE(outcome.scene);
    ASSERT_FALSE(outcome.inThisFile.isEmpty());
    EXPECT_EQ(outcome.inThisFile[0].line, 3);
    EXPECT_EQ(parser.lastGoodScene(), first); // kept

    // Many edits in a row: only the last is delivered.
    for (int i = 0; i < 20; ++i) {
        parser.setText(good + QString(" # %1").arg(i), "a.x3dv");
        parser.parseNow();
    }
    ASSERT_TRUE(settles(parser, 20000)) << "the parser never finished";
    EXPECT_EQ(outcomes.count(), 1);
}

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
    QApplication app(argc, argv);
    qRegisterMetaType<ParseOutcome>("fl::editor::ParseOutcome");
    return RUN_ALL_TESTS();
}

// Issue 29 §1: the `&` Lab 1 teaches, typed into an XML scene. The
// diagnostic says what to write at the `&` itself, and Ctrl+. (or the
// context menu) writes it: the text then reads.
TEST(DiagnosticFix, ABareAmpersandInAnXmlFormulaIsFixedWithCtrlPeriod) {
    CodeEditor e;
    e.setSyntax(SceneSyntax::Xml);
    const QString text = QStringLiteral(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<X3D profile='Immersive' version='3.3'><Scene>\n"
        "  <FShape><FGeometry definition='\"sphere(1) & box(0.5, 0.5, 0.5)\"'/></FShape>\n"
        "  <FShape><FGeometry definition='\"x > 0 && y < 1 ? 1 : -1\"'/></FShape>\n"
        "</Scene></X3D>\n");
    e.setPlainText(text);
    // Fixed one after the other, as a student would: & then && then <.
    for (int round = 0; round < 4; ++round) {
        const ParseOutcome outcome = parseSceneText(e.toPlainText(), "lab1.x3d");
        if (outcome.scene) break;
        ASSERT_EQ(outcome.inThisFile.size(), 1) << round;
        const EditorDiagnostic& d = outcome.inThisFile.front();
        ASSERT_TRUE(d.fix.has_value()) << d.message.toStdString();
        EXPECT_TRUE(d.message.contains("&amp;") || d.message.contains("&lt;"))
            << d.message.toStdString();
        e.setDiagnostics(outcome.inThisFile);
        e.goTo(d.line, 1); // the start of its line: the fix is still the nearest
        QTest::keyClick(&e, Qt::Key_Period, Qt::ControlModifier);
    }
    const QString fixed = e.toPlainText();
    EXPECT_TRUE(fixed.contains("sphere(1) &amp; box")) << fixed.toStdString();
    EXPECT_TRUE(fixed.contains("x > 0 &amp;&amp; y &lt; 1")) << fixed.toStdString();
    const ParseOutcome done = parseSceneText(fixed, "lab1.x3d");
    EXPECT_TRUE(done.scene) << (done.all.empty() ? "" : done.all.front().message);
    // One undo step per fix.
    e.undo();
    EXPECT_TRUE(e.toPlainText().contains("y < 1"));
}
