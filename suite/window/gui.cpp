#include "gui.h"

#include "examples.h"
#include "main_window.h"

#include "surface_format.h"
#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdlib>
#include <iostream>

namespace fl::suite {

bool looksLikeSceneFile(const std::string& argument) {
    const QString a = QString::fromStdString(argument).toLower();
    for (const char* ext : {".x3d", ".x3dv", ".wrl", ".x3dz", ".x3dvz", ".gz"})
        if (a.endsWith(QLatin1String(ext))) return true;
    return QFileInfo::exists(QString::fromStdString(argument));
}

int runWindow(int argc, char** argv, const std::string& file) {
    const bool display =
        std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY") || std::getenv("QT_QPA_PLATFORM");
    if (!display) {
        std::cerr << "functionlab: the window needs a display. To draw a scene into a picture "
                     "without one, use: functionlab render FILE -o OUT.png\n";
        return 1;
    }
    viewer::useViewerSurfaceFormat(4);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("FunctionLab"));
    QApplication::setApplicationName(QStringLiteral("FunctionLab"));
#ifdef FUNCTIONLAB_VERSION
    QApplication::setApplicationVersion(QStringLiteral(FUNCTIONLAB_VERSION));
#endif
    MainWindow window;
    window.show();
    bool opened = false;
    if (!file.empty()) {
        QString error;
        opened = window.openFile(QString::fromStdString(file), &error);
        if (!opened) std::cerr << "functionlab: " << error.toStdString() << "\n";
    } else {
        opened = window.recoverUnsavedWork();
    }
    if (!opened) {
        const QString melon = QDir(examplesFolder()).filePath(QStringLiteral("watermelon.x3d"));
        if (!QFileInfo::exists(melon) || !window.openFile(melon)) window.newScene();
    }
    return app.exec();
}

} // namespace fl::suite
