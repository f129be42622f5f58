#include "recovery_file.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>

namespace fl::suite {
namespace {

QString recoveryPath() {
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(folder);
    return folder + QStringLiteral("/recovery.x3d");
}

} // namespace

void keepUnsavedText(const QString& text, const QString& of) {
    QSaveFile out(recoveryPath());
    if (out.open(QIODevice::WriteOnly)) {
        out.write(text.toUtf8());
        out.commit();
        QSettings().setValue(QStringLiteral("file/recoveryOf"), of);
    }
}

std::optional<KeptText> keptText() {
    QFile f(recoveryPath());
    if (!f.exists() || !f.open(QIODevice::ReadOnly)) return std::nullopt;
    return KeptText{QString::fromUtf8(f.readAll()),
                    QSettings().value(QStringLiteral("file/recoveryOf")).toString()};
}

void forgetKeptText() {
    QFile::remove(recoveryPath());
}

} // namespace fl::suite
