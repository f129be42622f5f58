#pragma once
// The text editor for scenes: line numbers, the current line, matching
// brackets, diagnostics underlined where they point (hover for the message),
// completion of node names, field names and built-in functions (with their
// signatures), and undo/redo from QPlainTextEdit.
#include "scene_highlighter.h"

#include <QPlainTextEdit>

class QCompleter;
class QStringListModel;

namespace fl::editor {

struct EditorDiagnostic {
    int line = 0;   // 1-based; 0: the whole file (not underlined)
    int column = 0; // 1-based
    bool error = true;
    QString message;
};

class CodeEditor : public QPlainTextEdit {
    Q_OBJECT
  public:
    explicit CodeEditor(QWidget* parent = nullptr);

    void setSyntax(SceneSyntax syntax);
    SceneHighlighter* highlighter() const { return highlighter_; }

    // Underlines each at its place: from its column to the end of the word there.
    void setDiagnostics(const QList<EditorDiagnostic>& diagnostics);
    const QList<EditorDiagnostic>& diagnostics() const { return diagnostics_; }
    // The character range [start, end) a diagnostic underlines.
    std::pair<int, int> rangeOf(const EditorDiagnostic& d) const;
    void goTo(int line, int column);

    int lineNumberAreaWidth() const;
    void paintLineNumbers(QPaintEvent* event);
    // The words completion offers for a prefix (nodes, fields, functions).
    QStringList completionsFor(const QString& prefix) const;

  protected:
    void resizeEvent(QResizeEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool event(QEvent* event) override;

  private:
    void updateExtraSelections();
    void insertCompletion(const QString& completion);
    QString wordBeforeCursor() const;
    void showCompletions(bool forced);

    SceneHighlighter* highlighter_;
    QWidget* lineNumbers_;
    QList<EditorDiagnostic> diagnostics_;
    QCompleter* completer_;
    QStringListModel* completionModel_;
};

} // namespace fl::editor
