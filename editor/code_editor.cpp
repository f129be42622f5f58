#include "code_editor.h"

#include "formula/builtins.h"
#include "scene/node_catalogue.h"

#include <QAbstractItemView>
#include <QAction>
#include <QCompleter>
#include <QContextMenuEvent>
#include <QFontDatabase>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QPainter>
#include <QScrollBar>
#include <QStringListModel>
#include <QTextBlock>
#include <QTextDocument>
#include <QToolTip>

#include <algorithm>

namespace fl::editor {
namespace {

class LineNumberArea : public QWidget {
  public:
    explicit LineNumberArea(CodeEditor* editor) : QWidget(editor), editor_(editor) {}
    QSize sizeHint() const override { return {editor_->lineNumberAreaWidth(), 0}; }

  protected:
    void paintEvent(QPaintEvent* event) override { editor_->paintLineNumbers(event); }

  private:
    CodeEditor* editor_;
};

// "name — signature: summary" entries for completion and tooltips.
struct Word {
    QString text, detail;
};

const std::vector<Word>& vocabulary() {
    static const std::vector<Word> words = [] {
        std::vector<Word> w;
        QSet<QString> fields;
        for (const auto& spec : scene::nodeCatalogue()) {
            w.push_back({QString::fromLatin1(spec.name.data(), qsizetype(spec.name.size())),
                         QStringLiteral("node")});
            for (const auto& f : spec.fields)
                fields.insert(QString::fromLatin1(f.name.data(), qsizetype(f.name.size())));
        }
        for (const QString& f : fields)
            w.push_back({f, QStringLiteral("field")});
        for (const auto& b : formula::builtinTable())
            w.push_back({QString::fromLatin1(b.name.data(), qsizetype(b.name.size())),
                         QString::fromLatin1(b.signature.data(), qsizetype(b.signature.size())) +
                             QStringLiteral(" — ") +
                             QString::fromLatin1(b.summary.data(), qsizetype(b.summary.size()))});
        std::sort(w.begin(), w.end(), [](const Word& a, const Word& b) { return a.text < b.text; });
        return w;
    }();
    return words;
}

bool isBracket(QChar c) {
    return QStringLiteral("()[]{}<>").contains(c);
}

} // namespace

CodeEditor::CodeEditor(QWidget* parent)
    : QPlainTextEdit(parent), highlighter_(new SceneHighlighter(document(), SceneSyntax::Xml)),
      lineNumbers_(new LineNumberArea(this)), completer_(new QCompleter(this)),
      completionModel_(new QStringListModel(this)) {
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setTabStopDistance(fontMetrics().horizontalAdvance(' ') * 2);
    connect(this, &QPlainTextEdit::blockCountChanged, this,
            [this] { setViewportMargins(lineNumberAreaWidth(), 0, 0, 0); });
    connect(this, &QPlainTextEdit::updateRequest, this, [this](const QRect& rect, int dy) {
        if (dy)
            lineNumbers_->scroll(0, dy);
        else
            lineNumbers_->update(0, rect.y(), lineNumbers_->width(), rect.height());
    });
    connect(this, &QPlainTextEdit::cursorPositionChanged, this, &CodeEditor::updateExtraSelections);
    setViewportMargins(lineNumberAreaWidth(), 0, 0, 0);

    completer_->setModel(completionModel_);
    completer_->setWidget(this);
    completer_->setCompletionMode(QCompleter::PopupCompletion);
    completer_->setCaseSensitivity(Qt::CaseSensitive);
    connect(completer_, qOverload<const QString&>(&QCompleter::activated), this,
            &CodeEditor::insertCompletion);
    updateExtraSelections();
}

void CodeEditor::setSyntax(SceneSyntax syntax) {
    highlighter_->setSyntax(syntax);
}

int CodeEditor::lineNumberAreaWidth() const {
    int digits = 1;
    for (int n = std::max(1, blockCount()); n >= 10; n /= 10)
        ++digits;
    return 8 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(digits, 3);
}

void CodeEditor::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    const QRect r = contentsRect();
    lineNumbers_->setGeometry(QRect(r.left(), r.top(), lineNumberAreaWidth(), r.height()));
}

void CodeEditor::paintLineNumbers(QPaintEvent* event) {
    QPainter painter(lineNumbers_);
    painter.fillRect(event->rect(), palette().window());
    QSet<int> errorLines;
    for (const auto& d : diagnostics_)
        if (d.error) errorLines.insert(d.line);
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    while (block.isValid() && top <= event->rect().bottom()) {
        const int bottom = top + qRound(blockBoundingRect(block).height());
        if (block.isVisible() && bottom >= event->rect().top()) {
            const int line = block.blockNumber() + 1;
            painter.setPen(errorLines.contains(line) ? QColor(Qt::red)
                                                     : palette().color(QPalette::PlaceholderText));
            painter.drawText(0, top, lineNumbers_->width() - 4, fontMetrics().height(),
                             Qt::AlignRight, QString::number(line));
        }
        block = block.next();
        top = bottom;
    }
}

std::pair<int, int> CodeEditor::rangeOf(const EditorDiagnostic& d) const {
    const QTextBlock block = document()->findBlockByNumber(std::max(d.line, 1) - 1);
    if (!block.isValid() || d.line <= 0) return {0, 0};
    const QString text = block.text();
    int start = std::clamp(d.column - 1, 0, int(text.size()));
    int end = start;
    while (end < text.size() &&
           (text[end].isLetterOrNumber() || text[end] == '_' || text[end] == '.'))
        ++end;
    if (end == start) end = std::min(start + 1, int(text.size())); // a symbol: itself
    if (end == start && start > 0) --start;                        // the end of the line
    return {block.position() + start, block.position() + end};
}

void CodeEditor::setDiagnostics(const QList<EditorDiagnostic>& diagnostics) {
    diagnostics_ = diagnostics;
    updateExtraSelections();
    lineNumbers_->update();
}

void CodeEditor::goTo(int line, int column) {
    const QTextBlock block = document()->findBlockByNumber(std::max(line, 1) - 1);
    if (!block.isValid()) return;
    QTextCursor c(document());
    c.setPosition(block.position() + std::clamp(column - 1, 0, int(block.text().size())));
    setTextCursor(c);
    centerCursor();
    setFocus();
}

void CodeEditor::updateExtraSelections() {
    QList<QTextEdit::ExtraSelection> selections;
    QTextEdit::ExtraSelection line;
    line.format.setBackground(palette().color(QPalette::AlternateBase));
    line.format.setProperty(QTextFormat::FullWidthSelection, true);
    line.cursor = textCursor();
    line.cursor.clearSelection();
    selections << line;
    for (const auto& d : diagnostics_) {
        const auto [start, end] = rangeOf(d);
        if (end <= start) continue;
        QTextEdit::ExtraSelection s;
        s.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        s.format.setUnderlineColor(d.error ? QColor(Qt::red) : QColor(0xe0, 0x90, 0x00));
        s.format.setToolTip(Qt::convertFromPlainText(d.message, Qt::WhiteSpaceNormal));
        s.cursor = QTextCursor(document());
        s.cursor.setPosition(start);
        s.cursor.setPosition(end, QTextCursor::KeepAnchor);
        selections << s;
    }
    // The bracket at (or just before) the cursor and its partner.
    const QString all = toPlainText();
    int at = textCursor().position();
    if (at < all.size() && isBracket(all[at])) {
    } else if (at > 0 && isBracket(all[at - 1])) {
        --at;
    } else {
        at = -1;
    }
    if (at >= 0) {
        static const QString open = QStringLiteral("([{<"), close = QStringLiteral(")]}>");
        const QChar c = all[at];
        const bool forward = open.contains(c);
        const QChar partner = forward ? close[open.indexOf(c)] : open[close.indexOf(c)];
        int depth = 0, match = -1;
        for (int i = at; i >= 0 && i < all.size(); i += forward ? 1 : -1) {
            if (all[i] == c) ++depth;
            if (all[i] == partner && --depth == 0) {
                match = i;
                break;
            }
        }
        for (int p : {at, match}) {
            if (p < 0) continue;
            QTextEdit::ExtraSelection s;
            s.format.setBackground(match >= 0 ? QColor(0xc8, 0xe6, 0xc9)
                                              : QColor(0xff, 0xcd, 0xd2));
            s.cursor = QTextCursor(document());
            s.cursor.setPosition(p);
            s.cursor.setPosition(p + 1, QTextCursor::KeepAnchor);
            selections << s;
        }
    }
    setExtraSelections(selections);
}

bool CodeEditor::isEditorKey(const QKeyEvent* key) {
    const bool control = (key->modifiers() & Qt::ControlModifier) &&
                         !(key->modifiers() & (Qt::AltModifier | Qt::MetaModifier));
    return control && (key->key() == Qt::Key_Space || key->key() == Qt::Key_Period);
}

bool CodeEditor::event(QEvent* event) {
    // The editor's own keys win over the window's shortcuts while it has
    // focus (View → Play/Pause also answers Ctrl+Space elsewhere).
    if (event->type() == QEvent::ShortcutOverride && isEditorKey(static_cast<QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const int position =
            cursorForPosition(help->pos() - QPoint(viewportMargins().left(), 0)).position();
        QStringList messages;
        for (const auto& d : diagnostics_) {
            const auto [start, end] = rangeOf(d);
            if (position >= start && position <= end)
                messages << (d.fix
                                 ? tr("%1\nCtrl+. or right-click: %2").arg(d.message, d.fix->label)
                                 : d.message);
        }
        if (messages.isEmpty()) {
            QTextCursor c = cursorForPosition(help->pos() - QPoint(viewportMargins().left(), 0));
            c.select(QTextCursor::WordUnderCursor);
            for (const Word& w : vocabulary())
                if (w.text == c.selectedText() && w.detail.contains('(')) messages << w.detail;
        }
        if (messages.isEmpty())
            QToolTip::hideText();
        else
            // Messages quote the scene's own text: never read as markup.
            QToolTip::showText(help->globalPos(),
                               Qt::convertFromPlainText(messages.join('\n'), Qt::WhiteSpaceNormal),
                               this);
        return true;
    }
    return QPlainTextEdit::event(event);
}

QString CodeEditor::wordBeforeCursor() const {
    const QTextCursor c = textCursor();
    const QString text = c.block().text().left(c.positionInBlock());
    int i = int(text.size());
    while (i > 0 && (text[i - 1].isLetterOrNumber() || text[i - 1] == '_'))
        --i;
    return text.mid(i);
}

QStringList CodeEditor::completionsFor(const QString& prefix) const {
    QStringList out;
    for (const Word& w : vocabulary())
        if (w.text.startsWith(prefix) && w.text != prefix && !out.contains(w.text)) out << w.text;
    return out;
}

void CodeEditor::showCompletions(bool forced) {
    const QString prefix = wordBeforeCursor();
    if (!forced && prefix.size() < 3) {
        completer_->popup()->hide();
        return;
    }
    const QStringList words = completionsFor(prefix);
    if (words.isEmpty()) {
        completer_->popup()->hide();
        return;
    }
    completionModel_->setStringList(words);
    completer_->setCompletionPrefix(prefix);
    QRect r = cursorRect();
    r.setWidth(completer_->popup()->sizeHintForColumn(0) +
               completer_->popup()->verticalScrollBar()->sizeHint().width());
    completer_->complete(r);
}

void CodeEditor::insertCompletion(const QString& completion) {
    QTextCursor c = textCursor();
    c.insertText(completion.mid(completer_->completionPrefix().size()));
    setTextCursor(c);
}

void CodeEditor::keyPressEvent(QKeyEvent* event) {
    if (completer_->popup()->isVisible()) {
        switch (event->key()) {
        case Qt::Key_Enter:
        case Qt::Key_Return:
        case Qt::Key_Escape:
        case Qt::Key_Tab:
        case Qt::Key_Backtab:
            event->ignore(); // the completer takes these
            return;
        default:
            break;
        }
    }
    if (isEditorKey(event) && event->key() == Qt::Key_Period) {
        applyFixAtCursor();
        return;
    }
    const bool forced = isEditorKey(event) && event->key() == Qt::Key_Space;
    if (!forced) QPlainTextEdit::keyPressEvent(event);
    const QString typed = event->text();
    if (forced || (!typed.isEmpty() && (typed[0].isLetterOrNumber() || typed[0] == '_')))
        showCompletions(forced);
    else if (!typed.isEmpty())
        completer_->popup()->hide();
}

std::optional<EditorFix> CodeEditor::fixAt(int position) const {
    const QTextBlock block = document()->findBlock(position);
    const int line = block.blockNumber() + 1;
    std::optional<EditorFix> best;
    int bestDistance = 0;
    for (const auto& d : diagnostics_) {
        if (!d.fix || d.line != line) continue;
        const auto [start, end] = rangeOf(d);
        const int distance = position < start ? start - position : std::max(0, position - end);
        if (!best || distance < bestDistance) {
            best = d.fix;
            bestDistance = distance;
        }
    }
    return best;
}

std::optional<EditorFix> CodeEditor::fixAtCursor() const {
    return fixAt(textCursor().position());
}

bool CodeEditor::applyFixAtCursor() {
    const auto fix = fixAtCursor();
    if (!fix) return false;
    applyFix(*fix);
    return true;
}

void CodeEditor::applyFix(const EditorFix& fix) {
    const QTextBlock block = document()->findBlockByNumber(fix.line - 1);
    if (!block.isValid()) return;
    const int start = block.position() + std::clamp(fix.column - 1, 0, int(block.text().size()));
    QTextCursor c(document());
    c.setPosition(start);
    c.setPosition(std::min(start + fix.length, document()->characterCount() - 1),
                  QTextCursor::KeepAnchor);
    c.insertText(fix.text); // one undoable step
    setTextCursor(c);
}

void CodeEditor::contextMenuEvent(QContextMenuEvent* event) {
    QMenu* menu = createStandardContextMenu(event->pos());
    const int position =
        cursorForPosition(event->pos() - QPoint(viewportMargins().left(), 0)).position();
    if (const auto fix = fixAt(position)) {
        auto* apply = new QAction(tr("Fix: %1").arg(fix->label), menu);
        connect(apply, &QAction::triggered, this, [this, f = *fix] { applyFix(f); });
        QAction* first = menu->actions().isEmpty() ? nullptr : menu->actions().first();
        menu->insertAction(first, apply);
        menu->insertSeparator(first);
    }
    menu->exec(event->globalPos());
    delete menu;
}

} // namespace fl::editor
