#include "offline_text_browser.h"

namespace fl::suite {

OfflineTextBrowser::OfflineTextBrowser(QWidget* parent) : QTextBrowser(parent) {
    setOpenLinks(false);
    setOpenExternalLinks(false);
}

void OfflineTextBrowser::showMarkdown(const QString& markdown, qsizetype maxChars) {
    document()->setMarkdown(markdown.left(maxChars),
                            QTextDocument::MarkdownFeatures(QTextDocument::MarkdownDialectGitHub |
                                                            QTextDocument::MarkdownNoHTML));
}

QVariant OfflineTextBrowser::loadResource(int, const QUrl&) {
    return {}; // nothing is fetched: a missing image is drawn as a placeholder
}

} // namespace fl::suite
