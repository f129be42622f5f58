#include "plain_text.h"

#include <QLabel>
#include <QMessageBox>
#include <QTextDocument>

namespace fl::suite {

namespace {

// Characters that steer the drawing of what follows them instead of being
// drawn: the bidirectional controls (an override reverses the rest of a
// line: "evil\u202Etxt.exe"), and the line and paragraph separators.
bool steersDrawing(char32_t c) {
    return (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) || c == 0x200E ||
           c == 0x200F || c == 0x061C || c == 0x2028 || c == 0x2029;
}

bool isControl(char32_t c) {
    return c < 0x20 || (c >= 0x7F && c <= 0x9F);
}

} // namespace

QLabel* plainLabel(const QString& text, QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setTextFormat(Qt::PlainText);
    label->setText(text);
    return label;
}

QString visibleText(const QString& text, bool keepLineBreaks) {
    QString out;
    out.reserve(text.size());
    for (const char32_t c : text.toUcs4()) {
        const bool lineBreak = c == '\n' || c == '\t';
        if ((isControl(c) && !(keepLineBreaks && lineBreak)) || steersDrawing(c))
            out += QStringLiteral("\u27E8U+%1\u27E9")
                       .arg(static_cast<uint>(c), 4, 16, QLatin1Char('0'))
                       .toUpper();
        else
            out += QString::fromUcs4(&c, 1);
    }
    return out;
}

QString plainToolTip(const QString& text) {
    if (text.isEmpty()) return {};
    return Qt::convertFromPlainText(visibleText(text, true), Qt::WhiteSpaceNormal);
}

namespace {

int showPlainly(QWidget* parent, QMessageBox::Icon icon, const QString& title, const QString& text,
                QMessageBox::StandardButtons buttons) {
    QMessageBox box(icon, title, visibleText(text, true), buttons, parent);
    box.setTextFormat(Qt::PlainText);
    return box.exec();
}

} // namespace

void warnPlainly(QWidget* parent, const QString& title, const QString& text) {
    showPlainly(parent, QMessageBox::Warning, title, text, QMessageBox::Ok);
}

bool askPlainly(QWidget* parent, const QString& title, const QString& text) {
    return showPlainly(parent, QMessageBox::Question, title, text,
                       QMessageBox::Yes | QMessageBox::No) == QMessageBox::Yes;
}

void informPlainly(QWidget* parent, const QString& title, const QString& text) {
    showPlainly(parent, QMessageBox::Information, title, text, QMessageBox::Ok);
}

} // namespace fl::suite
