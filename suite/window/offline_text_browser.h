#pragma once
// A text browser for documents written by others (an assignment's
// instructions, grading evidence): it follows no link and loads no resource,
// so an image or link in the text cannot make the window read a file or the
// network (`![](/dev/zero)` in Markdown would). Markdown is read without HTML.
#include <QTextBrowser>

namespace fl::suite {

class OfflineTextBrowser : public QTextBrowser {
  public:
    explicit OfflineTextBrowser(QWidget* parent = nullptr);
    // Markdown without raw HTML; what is longer than `maxChars` is cut.
    void showMarkdown(const QString& markdown, qsizetype maxChars = 256 * 1024);
    QVariant loadResource(int type, const QUrl& name) override;
};

} // namespace fl::suite
