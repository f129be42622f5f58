#include "gui.h"

#include "classroom_panel.h"
#include "examples.h"
#include "main_window.h"

#include "platform/option_table.h"
#include "scene/scene_writer.h"
#include "viewer/surface_format.h"
#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdlib>
#include <iostream>

namespace fl::suite {

const cli::CommandSpec& joinSpec() {
    static const cli::CommandSpec spec{
        .name = "--join",
        .summary = "open the window and join a class",
        .synopsis = {"--join ws://HOST:PORT --class CODE --name NAME [--role ROLE] [--key KEY]"},
        .options = {{.name = "join",
                     .kind = cli::OptionKind::Text,
                     .valueName = "URL",
                     .help = "the class server's address, ws://HOST:PORT or wss://HOST:PORT"},
                    {.name = "class",
                     .kind = cli::OptionKind::Text,
                     .valueName = "CODE",
                     .help = "the class code the instructor gave"},
                    {.name = "name",
                     .kind = cli::OptionKind::Text,
                     .valueName = "NAME",
                     .help = "your name as the class sees it"},
                    {.name = "role",
                     .kind = cli::OptionKind::Choice,
                     .valueName = "ROLE",
                     .help = "who you are in the class",
                     .defaultValue = "student",
                     .choices = {"student", "instructor", "observer"}},
                    {.name = "key",
                     .kind = cli::OptionKind::Text,
                     .valueName = "KEY",
                     .help = "the instructor key (instructors only)"}},
    };
    return spec;
}

std::optional<JoinRequest> parseJoinArguments(const std::vector<std::string>& args,
                                              std::string& error) {
    error.clear();
    if (args.empty() || args[0] != "--join") return std::nullopt;
    const cli::ParseResult parsed = cli::parseArguments(joinSpec(), args);
    if (!parsed.ok()) {
        error = parsed.error.message;
        return std::nullopt;
    }
    const cli::ParsedArgs& a = *parsed.args;
    JoinRequest r;
    r.url = a.text("join");
    r.classCode = a.text("class");
    r.name = a.text("name");
    r.role = classroom::roleNamed(a.text("role")).value_or(classroom::Role::Student);
    r.key = a.text("key");
    if (r.url.rfind("ws://", 0) != 0 && r.url.rfind("wss://", 0) != 0)
        error = "--join takes the server's address, ws://HOST:PORT";
    else if (r.classCode.empty() || r.name.empty())
        error = "--join needs --class CODE and --name NAME";
    if (!error.empty()) return std::nullopt;
    return r;
}

bool looksLikeSceneFile(const std::string& argument) {
    if (scene::isSceneFileName(argument)) return true;
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
        window.classroomPanel()->join(
            QString::fromStdString(join->url), QString::fromStdString(join->classCode),
            QString::fromStdString(join->name), join->role, QString::fromStdString(join->key));
    return app.exec();
}

} // namespace fl::suite
