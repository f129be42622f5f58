#pragma once
// Text from others — names and chat from the class, node names and formula
// text from scene files, diagnostics that quote them, manifests, gradebook
// rows, device names — is shown as the characters it holds, never as markup:
// a label or tool tip that guesses "rich text" renders `<img src=/dev/zero>`
// and reads the file (issue 26 §2). Every widget of the window that shows
// such text takes it through these.
#include <QString>

class QLabel;
class QWidget;

namespace fl::suite {

// A label that draws its text as plain text, whatever it looks like.
QLabel* plainLabel(const QString& text = {}, QWidget* parent = nullptr);

// The text with every character that would change how the text around it is
// drawn — C0 and C1 controls, bidirectional overrides, embeddings, isolates
// and marks, line and paragraph separators — written as a visible ⟨U+202E⟩.
// Line breaks are kept when `keepLineBreaks`.
QString visibleText(const QString& text, bool keepLineBreaks = false);

// A tool tip that shows `text` literally (tool tips guess rich text too).
QString plainToolTip(const QString& text);

// A warning whose text is plain (QMessageBox::warning guesses rich text).
void warnPlainly(QWidget* parent, const QString& title, const QString& text);
// A yes/no question whose text is plain; true for yes.
bool askPlainly(QWidget* parent, const QString& title, const QString& text);
// Information whose text is plain.
void informPlainly(QWidget* parent, const QString& title, const QString& text);

} // namespace fl::suite
