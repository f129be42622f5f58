#include "working_copy.h"

#include "panel_context.h"

#include "courseware/catalogue.h"
#include "courseware/workspace.h"

#include <QDir>
#include <QFileInfo>
#include <QStatusBar>

namespace fl::suite {

bool openWorkingCopy(PanelContext& context, const QString& coursePath, const QString& folder) {
    const courseware::WorkingCopy copy =
        courseware::workingCopyOf(coursePath.toStdString(), folder.toStdString());
    if (!copy.error.empty()) {
        context.problem(
            QObject::tr("Your copy of %1 cannot be made: %2")
                .arg(QFileInfo(coursePath).fileName(), QString::fromStdString(copy.error)));
        return false;
    }
    const QString path = QString::fromStdString(copy.path.string());
    if (!context.open(path)) return false;
    context.status->showMessage(
        copy.existed ? QObject::tr("Your copy from before: %1 (the course's own is unchanged)")
                           .arg(QDir::toNativeSeparators(path))
                     : QObject::tr("A copy of your own: %1").arg(QDir::toNativeSeparators(path)),
        10000);
    return true;
}

QString saveAsStartFor(const QString& path) {
    if (!saveNeedsAPlace(path)) return path;
    const QString workspace = QString::fromStdString(courseware::workspaceFolder().string());
    QDir().mkpath(workspace);
    return path.isEmpty() ? workspace : QDir(workspace).filePath(QFileInfo(path).fileName());
}

bool saveNeedsAPlace(const QString& path) {
    return path.isEmpty() || courseware::isInsideCourseware(path.toStdString());
}

} // namespace fl::suite
