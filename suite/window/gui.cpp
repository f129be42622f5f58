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

std::optional<JoinRequest> parseJoinArguments(const std::vector<std::string>& args,
                                              std::string& error) {
    error.clear();
    if (args.empty() || args[0] != "--join") return std::nullopt;
    JoinRequest r;
    for (std::size_t i = 0; i < args.size(); i += 2) {
        if (i + 1 >= args.size()) {
            error = args[i] + " needs a value";
            return std::nullopt;
        }
        const std::string& v = args[i + 1];
        if (args[i] == "--join")
            r.url = v;
        else if (args[i] == "--class")
            r.classCode = v;
        else if (args[i] == "--name")
            r.name = v;
        else if (args[i] == "--role")
            r.role = v;
        else if (args[i] == "--key")
            r.key = v;
        else {
            error = "unknown option " + args[i] +
                    " (use --join URL --class CODE --name NAME "
                    "[--role student|instructor|observer] [--key KEY])";
            return std::nullopt;
        }
    }
    if (r.url.rfind("ws://", 0) != 0 && r.url.rfind("wss://", 0) != 0)
        error = "--join takes the server's address, ws://HOST:PORT";
    else if (r.classCode.empty() || r.name.empty())
        error = "--join needs --class CODE and --name NAME";
    else if (r.role != "student" && r.role != "instructor" && r.role != "observer")
        error = "--role is student, instructor or observer";
    if (!error.empty()) return std::nullopt;
    return r;
}

bool looksLikeSceneFile(const std::string& argument) {
    const QString a = QString::fromStdString(argument).toLower();
    for (const char* ext : {".x3d", ".x3dv", ".wrl", ".x3dz", ".x3dvz", ".gz"})
        if (a.endsWith(QLatin1String(ext))) return true;
    return QFileInfo::exists(QString::fromStdString(argument));
}

int runWindow(int argc, char** argv, const std::string& file,
              const std::optional<JoinRequest>& join) {
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
    if (join)
        window.joinClass(QString::fromStdString(join->url), QString::fromStdString(join->classCode),
                         QString::fromStdString(join->name), QString::fromStdString(join->role),
                         QString::fromStdString(join->key));
    return app.exec();
}

} // namespace fl::suite
