#include "recent_files_menu.h"

#include "plain_text.h"

#include <QFileInfo>
#include <QSettings>

namespace fl::suite {
namespace {

constexpr int kMaxRecent = 8;
const char* const kKey = "file/recent";

} // namespace

RecentFilesMenu::RecentFilesMenu(const QString& title, std::function<void(const QString&)> open,
                                 QWidget* parent)
    : QMenu(title, parent), open_(std::move(open)) {
    fill();
}

void RecentFilesMenu::add(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QLatin1String(kKey)).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue(QLatin1String(kKey), recent);
    fill();
}

void RecentFilesMenu::fill() {
    clear();
    const QStringList recent = QSettings().value(QLatin1String(kKey)).toStringList();
    for (const QString& path : recent)
        // '&' in a file name is not a keyboard accelerator.
        addAction(QFileInfo(path).fileName().replace(QLatin1Char('&'), QStringLiteral("&&")), this,
                  [this, path] { open_(path); })
            ->setToolTip(plainToolTip(path));
    setEnabled(!recent.isEmpty());
}

} // namespace fl::suite
