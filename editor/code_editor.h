#pragma once
// The text editor for scenes: line numbers, the current line, matching
// brackets, diagnostics underlined where they point (hover for the message),
// completion of node names, field names and built-in functions (with their
// signatures), fixes offered for diagnostics that have one (Ctrl+. or the
// context menu), and undo/redo from QPlainTextEdit.
#include "scene_highlighter.h"

#include <QPlainTextEdit>

#include <optional>

class QCompleter;
class QStringListModel;

namespace fl::editor {

// The change that mends a diagnostic (scene::DiagnosticFix, in characters).
struct EditorFix {
    int line = 0, column = 0; // 1-based
    int length = 0;           // characters replaced
    QString text;
    QString label; // "write &amp; for &"
};

struct EditorDiagnostic {
    int line = 0;   // 1-based; 0: the whole file (not underlined)
    int column = 0; // 1-based
    bool error = true;
    QString message;
    std::optional<EditorFix> fix = std::nullopt;
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

    // The fix of the diagnostic nearest the cursor on its line, if one has a
    // fix; applying it is one undoable step. False when there is none.
    std::optional<EditorFix> fixAtCursor() const;
    bool applyFixAtCursor();
    void applyFix(const EditorFix& fix);

  protected:
    void resizeEvent(QResizeEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool event(QEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

  private:
    void updateExtraSelections();
    void insertCompletion(const QString& completion);
    QString wordBeforeCursor() const;
    void showCompletions(bool forced);
    std::optional<EditorFix> fixAt(int position) const;
    // Ctrl+Space (completion) and Ctrl+. (the fix): the editor's while it has focus.
    static bool isEditorKey(const QKeyEvent* key);

    SceneHighlighter* highlighter_;
    QWidget* lineNumbers_;
    QList<EditorDiagnostic> diagnostics_;
    QCompleter* completer_;
    QStringListModel* completionModel_;
};

} // namespace fl::editor
