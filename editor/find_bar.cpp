#include "find_bar.h"

#include <QAction>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextCursor>
#include <QTextDocument>
#include <QVBoxLayout>

namespace fl::editor {

FindBar::FindBar(QPlainTextEdit* editor, QWidget* parent)
    : QWidget(parent), editor_(editor), find_(new QLineEdit), replace_(new QLineEdit),
      matchCase_(new QCheckBox(tr("Match case"))), status_(new QLabel), replaceRow_(new QWidget) {
    replaceRow_->setObjectName(QStringLiteral("replaceRow"));
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(2, 2, 2, 2);
    auto* findRow = new QHBoxLayout;
    find_->setPlaceholderText(tr("Find"));
    auto* next = new QPushButton(tr("Next"));
    auto* previous = new QPushButton(tr("Previous"));
    auto* close = new QPushButton(tr("Close"));
    findRow->addWidget(find_);
    findRow->addWidget(next);
    findRow->addWidget(previous);
    findRow->addWidget(matchCase_);
    findRow->addWidget(status_);
    findRow->addWidget(close);
    column->addLayout(findRow);
    auto* replaceRow = new QHBoxLayout(replaceRow_);
    replaceRow->setContentsMargins(0, 0, 0, 0);
    replace_->setPlaceholderText(tr("Replace with"));
    auto* one = new QPushButton(tr("Replace"));
    auto* all = new QPushButton(tr("Replace all"));
    replaceRow->addWidget(replace_);
    replaceRow->addWidget(one);
    replaceRow->addWidget(all);
    column->addWidget(replaceRow_);
    connect(next, &QPushButton::clicked, this, [this] { findNext(false); });
    connect(previous, &QPushButton::clicked, this, [this] { findNext(true); });
    connect(find_, &QLineEdit::returnPressed, this, [this] { findNext(false); });
    connect(one, &QPushButton::clicked, this, &FindBar::replaceOne);
    connect(all, &QPushButton::clicked, this, [this] { replaceAll(); });
    connect(close, &QPushButton::clicked, this, [this] {
        hide();
        editor_->setFocus();
    });
    hide();
}

void FindBar::fillEditMenu(QMenu* edit) {
    edit->addAction(tr("&Undo"), QKeySequence::Undo, editor_, &QPlainTextEdit::undo);
    edit->addAction(tr("&Redo"), QKeySequence::Redo, editor_, &QPlainTextEdit::redo);
    edit->addSeparator();
    edit->addAction(tr("&Find…"), QKeySequence::Find, this, [this] { open(false); });
    QAction* replace = edit->addAction(tr("&Replace…"), this, [this] { open(true); });
    // Ctrl+H everywhere (the guide's key), beside the platform's own, if any
    // (a bare X server has none for Replace).
    QList<QKeySequence> keys{QKeySequence(Qt::CTRL | Qt::Key_H)};
    for (const QKeySequence& k : QKeySequence::keyBindings(QKeySequence::Replace))
        if (!keys.contains(k)) keys << k;
    replace->setShortcuts(keys);
}

void FindBar::open(bool withReplace) {
    replaceRow_->setVisible(withReplace);
    const QString selected = editor_->textCursor().selectedText();
    if (!selected.isEmpty() && !selected.contains(QChar::ParagraphSeparator))
        find_->setText(selected);
    show();
    find_->setFocus();
    find_->selectAll();
}

void FindBar::setPattern(const QString& find, const QString& replace) {
    find_->setText(find);
    replace_->setText(replace);
}

bool FindBar::findNext(bool backwards) {
    QTextDocument::FindFlags flags;
    if (backwards) flags |= QTextDocument::FindBackward;
    if (matchCase_->isChecked()) flags |= QTextDocument::FindCaseSensitively;
    bool found = editor_->find(find_->text(), flags);
    if (!found) { // wrap round
        QTextCursor c = editor_->textCursor();
        c.movePosition(backwards ? QTextCursor::End : QTextCursor::Start);
        editor_->setTextCursor(c);
        found = editor_->find(find_->text(), flags);
    }
    status_->setText(found ? QString() : tr("not found"));
    return found;
}

void FindBar::replaceOne() {
    QTextCursor c = editor_->textCursor();
    const Qt::CaseSensitivity cs =
        matchCase_->isChecked() ? Qt::CaseSensitive : Qt::CaseInsensitive;
    if (c.hasSelection() && c.selectedText().compare(find_->text(), cs) == 0)
        c.insertText(replace_->text());
    findNext(false);
}

int FindBar::replaceAll() {
    if (find_->text().isEmpty()) return 0;
    QTextDocument::FindFlags flags;
    if (matchCase_->isChecked()) flags |= QTextDocument::FindCaseSensitively;
    QTextCursor edit(editor_->document());
    edit.beginEditBlock(); // one undo step for all of them
    int n = 0;
    QTextCursor c = editor_->document()->find(find_->text(), 0, flags);
    while (!c.isNull()) {
        c.insertText(replace_->text());
        ++n;
        c = editor_->document()->find(find_->text(), c.position(), flags);
    }
    edit.endEditBlock();
    status_->setText(tr("%n replaced", nullptr, n));
    return n;
}

} // namespace fl::editor
