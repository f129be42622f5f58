#include "scene_highlighter.h"

#include "formula/builtins.h"
#include "scene/node_catalogue.h"
#include "scene/scene_writer.h"

#include <QRegularExpression>
#include <QSet>

namespace fl::editor {
namespace {

// Block states: inside an XML comment, or inside a string that runs on.
enum State { kNormal = 0, kInXmlComment = 1, kInString = 2 };

const QSet<QString>& nodeNames() {
    static const QSet<QString> names = [] {
        QSet<QString> s;
        for (const auto& spec : scene::nodeCatalogue())
            s.insert(QString::fromLatin1(spec.name.data(), qsizetype(spec.name.size())));
        return s;
    }();
    return names;
}

const QSet<QString>& functionNames() {
    static const QSet<QString> names = [] {
        QSet<QString> s;
        for (const auto& b : formula::builtinTable())
            s.insert(QString::fromLatin1(b.name.data(), qsizetype(b.name.size())));
        return s;
    }();
    return names;
}

const QSet<QString> kClassicKeywords{
    "DEF",     "USE",      "PROTO",     "EXTERNPROTO", "ROUTE",          "TO",
    "IS",      "TRUE",     "FALSE",     "NULL",        "PROFILE",        "COMPONENT",
    "META",    "IMPORT",   "EXPORT",    "AS",          "field",          "exposedField",
    "eventIn", "eventOut", "inputOnly", "outputOnly",  "initializeOnly", "inputOutput"};
const QSet<QString> kFormulaKeywords{"function", "return", "if", "else", "for", "pi", "e"};
const QSet<QString> kVariables{"x", "y", "z", "t", "u", "v", "w", "r", "g", "b", "fx", "fy", "fz"};

QTextCharFormat make(const QColor& colour, bool bold = false, bool italic = false) {
    QTextCharFormat f;
    f.setForeground(colour);
    if (bold) f.setFontWeight(QFont::Bold);
    f.setFontItalic(italic);
    return f;
}

} // namespace

SceneSyntax syntaxFor(const QString& fileName, const QString& text) {
    scene::Encoding encoding{};
    bool gzipped = false;
    if (scene::encodingForPath(fileName.toStdString(), encoding, gzipped))
        return encoding == scene::Encoding::Xml ? SceneSyntax::Xml : SceneSyntax::Classic;
    return text.trimmed().startsWith('<') ? SceneSyntax::Xml : SceneSyntax::Classic;
}

SceneHighlighter::SceneHighlighter(QTextDocument* document, SceneSyntax syntax)
    : QSyntaxHighlighter(document), syntax_(syntax) {
    formats_[Node] = make(QColor(0x1f, 0x4e, 0x9a), true);
    formats_[Field] = make(QColor(0x6a, 0x3d, 0x9a));
    formats_[Keyword] = make(QColor(0x9a, 0x1f, 0x3d), true);
    formats_[String] = make(QColor(0x2e, 0x7d, 0x32));
    formats_[Number] = make(QColor(0xb3, 0x5c, 0x00));
    formats_[Comment] = make(QColor(0x80, 0x80, 0x80), false, true);
    formats_[Function] = make(QColor(0x00, 0x6b, 0x8f), true);
    formats_[Variable] = make(QColor(0x8f, 0x00, 0x6b));
    formats_[Operator] = make(QColor(0x5d, 0x40, 0x37), true);
    formats_[Tag] = make(QColor(0x1f, 0x4e, 0x9a), true);
}

void SceneHighlighter::setSyntax(SceneSyntax syntax) {
    syntax_ = syntax;
    rehighlight();
}

QTextCharFormat SceneHighlighter::format(Kind kind) const {
    return formats_[kind];
}

void SceneHighlighter::highlightBlock(const QString& text) {
    setCurrentBlockState(kNormal);
    if (syntax_ == SceneSyntax::Xml)
        highlightXml(text);
    else
        highlightClassic(text);
}

// Inside a string: the formula language (a definition's text; other strings
// rarely hold words it knows).
void SceneHighlighter::highlightFormula(const QString& text, int from, int to) {
    static const QRegularExpression token(QStringLiteral(
        R"((//.*)|([A-Za-z_][A-Za-z0-9_]*)|(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+)|([-+*/^&|\\~<>=!?:]))"));
    auto it = token.globalMatch(text.mid(from, to - from));
    while (it.hasNext()) {
        const auto m = it.next();
        const int at = from + int(m.capturedStart());
        const int length = int(m.capturedLength());
        if (m.capturedLength(1)) {
            setFormat(at, length, formats_[Comment]);
        } else if (m.capturedLength(2)) {
            const QString word = m.captured(2);
            if (functionNames().contains(word))
                setFormat(at, length, formats_[Function]);
            else if (kFormulaKeywords.contains(word))
                setFormat(at, length, formats_[Keyword]);
            else if (kVariables.contains(word))
                setFormat(at, length, formats_[Variable]);
        } else if (m.capturedLength(3)) {
            setFormat(at, length, formats_[Number]);
        } else {
            setFormat(at, length, formats_[Operator]);
        }
    }
}

void SceneHighlighter::highlightXml(const QString& text) {
    int i = 0;
    const int n = int(text.size());
    if (previousBlockState() == kInXmlComment) {
        const int end = int(text.indexOf(QStringLiteral("-->")));
        if (end < 0) {
            setFormat(0, n, formats_[Comment]);
            setCurrentBlockState(kInXmlComment);
            return;
        }
        setFormat(0, end + 3, formats_[Comment]);
        i = end + 3;
    }
    // An attribute value that runs on from the line before (multi-line MFString).
    QChar openQuote;
    if (previousBlockState() >= kInString) {
        openQuote = QChar(char16_t(previousBlockState() - kInString));
        int end = int(text.indexOf(openQuote, i));
        const int stop = end < 0 ? n : end + 1;
        setFormat(i, stop - i, formats_[String]);
        highlightFormula(text, i, end < 0 ? n : end);
        if (end < 0) {
            setCurrentBlockState(previousBlockState());
            return;
        }
        i = stop;
    }
    static const QRegularExpression tag(QStringLiteral(R"(</?([A-Za-z_][\w.-]*))"));
    static const QRegularExpression attribute(QStringLiteral(R"(([A-Za-z_][\w.:-]*)\s*=\s*)"));
    while (i < n) {
        if (text.mid(i, 4) == QLatin1String("<!--")) {
            const int end = int(text.indexOf(QStringLiteral("-->"), i + 4));
            if (end < 0) {
                setFormat(i, n - i, formats_[Comment]);
                setCurrentBlockState(kInXmlComment);
                return;
            }
            setFormat(i, end + 3 - i, formats_[Comment]);
            i = end + 3;
            continue;
        }
        if (text[i] == '<') {
            const auto m = tag.match(text, i, QRegularExpression::NormalMatch,
                                     QRegularExpression::AnchorAtOffsetMatchOption);
            if (m.hasMatch()) {
                setFormat(int(m.capturedStart(1)), int(m.capturedLength(1)),
                          nodeNames().contains(m.captured(1)) ? formats_[Node] : formats_[Tag]);
                i = int(m.capturedEnd());
                continue;
            }
        }
        if (text[i] == '\'' || text[i] == '"') {
            const QChar quote = text[i];
            const int end = int(text.indexOf(quote, i + 1));
            const int stop = end < 0 ? n : end + 1;
            setFormat(i, stop - i, formats_[String]);
            highlightFormula(text, i + 1, end < 0 ? n : end);
            if (end < 0) {
                setCurrentBlockState(kInString + quote.unicode());
                return;
            }
            i = stop;
            continue;
        }
        const auto a = attribute.match(text, i, QRegularExpression::NormalMatch,
                                       QRegularExpression::AnchorAtOffsetMatchOption);
        if (a.hasMatch() && (i == 0 || !text[i - 1].isLetterOrNumber())) {
            setFormat(i, int(a.capturedLength(1)), formats_[Field]);
            i = int(a.capturedEnd());
            continue;
        }
        ++i;
    }
}

void SceneHighlighter::highlightClassic(const QString& text) {
    int i = 0;
    const int n = int(text.size());
    if (previousBlockState() == kInString) {
        int end = i;
        while (end < n && text[end] != '"')
            end += text[end] == '\\' ? 2 : 1;
        const int stop = std::min(end + 1, n);
        setFormat(0, stop, formats_[String]);
        highlightFormula(text, 0, std::min(end, n));
        if (end >= n) {
            setCurrentBlockState(kInString);
            return;
        }
        i = stop;
    }
    static const QRegularExpression word(QStringLiteral(R"([A-Za-z_][A-Za-z0-9_]*)"));
    static const QRegularExpression number(
        QStringLiteral(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?|0x[0-9A-Fa-f]+)"));
    while (i < n) {
        const QChar c = text[i];
        if (c == '#') {
            setFormat(i, n - i, formats_[Comment]);
            return;
        }
        if (c == '"') {
            int end = i + 1;
            while (end < n && text[end] != '"')
                end += text[end] == '\\' ? 2 : 1;
            const int stop = std::min(end + 1, n);
            setFormat(i, stop - i, formats_[String]);
            highlightFormula(text, i + 1, std::min(end, n));
            if (end >= n) {
                setCurrentBlockState(kInString);
                return;
            }
            i = stop;
            continue;
        }
        if (c.isLetter() || c == '_') {
            const auto m = word.match(text, i, QRegularExpression::NormalMatch,
                                      QRegularExpression::AnchorAtOffsetMatchOption);
            if (!m.hasMatch()) { // a letter outside A-Z (é, π): not a name we know
                ++i;
                continue;
            }
            const QString w = m.captured();
            if (kClassicKeywords.contains(w))
                setFormat(i, int(w.size()), formats_[Keyword]);
            else if (nodeNames().contains(w))
                setFormat(i, int(w.size()), formats_[Node]);
            else if (w[0].isLower())
                setFormat(i, int(w.size()), formats_[Field]);
            i += int(w.size());
            continue;
        }
        if (c.isDigit() ||
            ((c == '-' || c == '+' || c == '.') && i + 1 < n && text[i + 1].isDigit())) {
            const auto m = number.match(text, i, QRegularExpression::NormalMatch,
                                        QRegularExpression::AnchorAtOffsetMatchOption);
            if (m.hasMatch()) {
                setFormat(i, int(m.capturedLength()), formats_[Number]);
                i = int(m.capturedEnd());
                continue;
            }
        }
        ++i;
    }
}

} // namespace fl::editor
