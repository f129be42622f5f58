#include "examples.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QRegularExpression>

namespace fl::suite {

QString examplesFolder() {
    const QString installed =
        QCoreApplication::applicationDirPath() + QStringLiteral("/../share/functionlab/examples");
    if (QDir(installed).exists()) return QDir(installed).canonicalPath();
#ifdef FUNCTIONLAB_EXAMPLES_DIR
    return QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR);
#else
    return {};
#endif
}

QList<Example> listExamples(const QString& folder) {
    QList<Example> out;
    const QDir dir(folder);
    // XML files only: the .x3dv twins show the same scenes.
    for (const QString& name : dir.entryList({QStringLiteral("*.x3d")}, QDir::Files, QDir::Name)) {
        Example e;
        e.path = dir.filePath(name);
        e.title = name;
        QFile f(e.path);
        if (f.open(QIODevice::ReadOnly)) {
            const QString head = QString::fromUtf8(f.read(8192));
            static const QRegularExpression title(
                QStringLiteral(R"(<WorldInfo[^>]*title\s*=\s*['"]([^'"]*)['"])"));
            static const QRegularExpression description(QStringLiteral(
                R"(<meta\s+name\s*=\s*['"]description['"]\s+content\s*=\s*['"]([^'"]*)['"])"));
            if (auto m = title.match(head); m.hasMatch()) e.title = m.captured(1);
            if (auto m = description.match(head); m.hasMatch()) e.description = m.captured(1);
        }
        out << e;
    }
    return out;
}

} // namespace fl::suite
