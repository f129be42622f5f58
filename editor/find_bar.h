#pragma once
// Find and replace in the editor: next, previous, replace, replace all, with
// or without matching case.
#include <QWidget>

class QLineEdit;
class QCheckBox;
class QLabel;
class QMenu;
class QPlainTextEdit;

namespace fl::editor {

class FindBar : public QWidget {
    Q_OBJECT
  public:
    explicit FindBar(QPlainTextEdit* editor, QWidget* parent = nullptr);

    void open(bool withReplace);
    // Edit menu: undo, redo (the editor's), find, replace.
    void fillEditMenu(QMenu* menu);
    bool findNext(bool backwards = false);
    int replaceAll();
    void setPattern(const QString& find, const QString& replace = {});

  private:
    void replaceOne();
    QPlainTextEdit* editor_;
    QLineEdit *find_, *replace_;
    QCheckBox* matchCase_;
    QLabel* status_;
    QWidget* replaceRow_;
};

} // namespace fl::editor
