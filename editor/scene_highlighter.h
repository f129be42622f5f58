#pragma once
// Colours for scene text: X3D XML (tags, attributes, comments) or ClassicVRML
// and VRML97 (node names, field names, keywords, comments), and inside the
// strings of function definitions the formula language (built-in functions,
// coordinates, operators, numbers, comments).
#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace fl::editor {

enum class SceneSyntax { Xml, Classic };

// The syntax a file name implies (.x3d: XML; .x3dv, .wrl: Classic), or a guess from the text.
SceneSyntax syntaxFor(const QString& fileName, const QString& text);

class SceneHighlighter : public QSyntaxHighlighter {
  public:
    SceneHighlighter(QTextDocument* document, SceneSyntax syntax);
    void setSyntax(SceneSyntax syntax);
    SceneSyntax syntax() const { return syntax_; }

    // The formats, exposed so tests can tell what a character was given.
    enum Kind { Node, Field, Keyword, String, Number, Comment, Function, Variable, Operator, Tag };
    QTextCharFormat format(Kind kind) const;

  protected:
    void highlightBlock(const QString& text) override;

  private:
    void highlightFormula(const QString& text, int from, int to);
    void highlightXml(const QString& text);
    void highlightClassic(const QString& text);

    SceneSyntax syntax_;
    QTextCharFormat formats_[10];
};

} // namespace fl::editor
