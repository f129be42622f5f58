// `functionlab serve [SCENE] --port P --class CODE [--data DIR]
// [--instructor-key KEY] [--bind ADDR]`: the server of one class
// (docs/classroom.md). Prints `listening on ws://ADDR:P` once it accepts
// connections; stops cleanly on SIGINT and SIGTERM (every applied version is
// already in DIR's log, so a restart with the same DIR goes on from there).
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "classroom/class_session.h"
#include "classroom/edit_log.h"
#include "classroom/scene_policy.h"
#include "classroom/server.h"
#include "classroom/starter_scene.h"

#include "scene/read_limits.h"
#include "web/web_page.h"

#include <QCoreApplication>
#include <QHostAddress>
#include <QSocketNotifier>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

namespace fl::cli {

namespace {

int signalPipe[2] = {-1, -1};

void onStopSignal(int) {
    const char byte = 1;
    // write() is async-signal-safe; the event loop reads the byte and quits.
    [[maybe_unused]] const auto n = ::write(signalPipe[1], &byte, 1);
}

// The starting scene: no larger than a class scene may be (compressed or not).
bool readText(const std::string& path, std::size_t maxBytes, std::string& text, std::string& why) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxBytes) {
        why = path + " has " + std::to_string(size) + " bytes; a class scene may have at most " +
              scene::byteSizeText(maxBytes);
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        why = "cannot read " + path;
        return false;
    }
    text.assign(maxBytes + 1, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    if (text.size() > maxBytes) {
        why =
            path + " is larger than " + scene::byteSizeText(maxBytes) + ", as a class scene may be";
        return false;
    }
    return true;
}

// Caps the server's address space (RLIMIT_AS): a check that would need more
// fails with bad_alloc, which the worker turns into a refusal of that one
// edit, instead of the machine swapping or the kernel killing the class.
bool capMemory(long mebibytes, std::string& why) {
    if (mebibytes <= 0) return true;
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) != 0) {
        why = "cannot read the memory limit";
        return false;
    }
    const rlim_t wanted = rlim_t(mebibytes) << 20;
    if (limit.rlim_max != RLIM_INFINITY && wanted > limit.rlim_max) return true; // already lower
    limit.rlim_cur = wanted;
    if (::setrlimit(RLIMIT_AS, &limit) != 0) {
        why = "cannot set the memory limit";
        return false;
    }
    return true;
}

} // namespace

const CommandSpec& serveSpec() {
    static const CommandSpec spec{
        .name = "serve",
        .summary = "run a class's shared scene server (WebSocket)",
        .synopsis = {"serve [SCENE] --port P --class CODE [--data DIR] [--instructor-key KEY] "
                     "[--bind ADDR] [--memory-limit MIB] [--new] [--no-web | "
                     "--web-needs-class-code]"},
        .description =
            "Starts the server of one class: members join over WebSocket with the class code\n"
            "(docs/classroom-protocol.md), edit one shared scene under an automatic lock, and\n"
            "chat. Prints `listening on ws://ADDR:P` once it accepts connections and runs until\n"
            "SIGINT or SIGTERM. With --data, every applied version is written to DIR before\n"
            "anyone is told of it; a restart with the same DIR goes on from the newest version\n"
            "(SCENE is then ignored). Without SCENE the class starts from one sphere.\n"
            "A damaged log, a log missing from a folder that held a class, or a folder another\n"
            "server holds is refused with what to do.\n"
            "\n"
            "The same port answers browsers: http://ADDR:P/ is a read-only page of the class's\n"
            "scene (drawn by X_ITE, as export-web draws it) and chat, which follows every\n"
            "accepted edit within about a second. It follows the class as an observer over the\n"
            "protocol and adds no way to change anything. --no-web turns it off;\n"
            "--web-needs-class-code makes its address need ?class=CODE.\n",
        .positionals = {{"SCENE", "the scene the class starts from (X3D or ClassicVRML text)",
                         false}},
        .options = {{.name = "port",
                     .kind = OptionKind::Integer,
                     .valueName = "P",
                     .help = "the TCP port (0: any free port, printed)",
                     .min = 0,
                     .max = 65535},
                    {.name = "class",
                     .kind = OptionKind::Text,
                     .valueName = "CODE",
                     .help = "the class code members join with"},
                    {.name = "data",
                     .kind = OptionKind::Path,
                     .valueName = "DIR",
                     .help = "where the class's log and snapshots live (classroom.sqlite); "
                             "without it the class is kept in memory only"},
                    {.name = "instructor-key",
                     .kind = OptionKind::Text,
                     .valueName = "KEY",
                     .help = "the key an instructor joins with; without it nobody can"},
                    {.name = "bind",
                     .kind = OptionKind::Text,
                     .valueName = "ADDR",
                     .help = "the address to listen on",
                     .defaultValue = "127.0.0.1"},
                    {.name = "new",
                     .help = "with --data: start a new class even if the folder held one whose "
                             "log is missing or empty (its old versions are gone)"},
                    {.name = "no-web", .help = "do not answer browsers (no live web page)"},
                    {.name = "web-needs-class-code",
                     .help = "the live web page needs ?class=CODE in its address"},
                    {.name = "memory-limit",
                     .kind = OptionKind::Integer,
                     .valueName = "MIB",
                     .help = "the most memory (address space) the server may use, in MiB; an "
                             "edit whose check would need more is refused (0: no limit)",
                     .defaultValue = "4096",
                     .min = 0,
                     .max = 1 << 20}},
        .exitStatus = "0 stopped by a signal, 1 the scene, the data folder or the address could "
                      "not be used, 2 usage error",
    };
    return spec;
}

int serveCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(serveSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("port") || !a->given("class"))
        return usageError(serveSpec(), "--port and --class are required", std::cerr);
    const std::string code = a->text("class");
    if (code.empty() || code.size() > classroom::ClassroomLimits{}.maxClassCodeChars)
        return usageError(serveSpec(), "--class needs a code of 1 to 64 characters", std::cerr);
    QHostAddress address;
    if (!address.setAddress(QString::fromStdString(a->text("bind", "127.0.0.1"))))
        return usageError(serveSpec(), "--bind needs an IP address, not '" + a->text("bind") + "'",
                          std::cerr);

    classroom::ClassConfig config;
    config.classCode = code;
    config.instructorKey = a->text("instructor-key");
    config.initialScene = classroom::starterScene();
    if (const std::string path = a->positional("SCENE"); !path.empty()) {
        std::string why;
        if (!readText(path, config.limits.maxSceneBytes, config.initialScene, why)) {
            std::cerr << "functionlab serve: " << why << "\n";
            return kExitDiagnostic;
        }
    }
    if (std::string why; !capMemory(a->integer("memory-limit", 4096), why)) {
        std::cerr << "functionlab serve: " << why << "\n";
        return kExitDiagnostic;
    }
    int argc = 1;
    char name[] = "functionlab";
    char* argv[] = {name, nullptr};
    QCoreApplication app(argc, argv);
    try {
        std::unique_ptr<classroom::EditLog> log;
        if (a->given("data"))
            log = std::make_unique<classroom::EditLog>(a->text("data"), a->flag("new"));
        if (!log || !log->latest()) {
            const auto check = classroom::checkClassroomScene(config.initialScene);
            if (!check.ok) {
                const std::string shown = a->positional("SCENE").empty()
                                              ? std::string("the starter scene")
                                              : a->positional("SCENE");
                for (auto d : check.diagnostics) {
                    d.file = shown; // the user's file name, not the protocol's "scene"
                    std::cerr << scene::formatSceneDiagnostic(d) << "\n";
                }
                std::cerr << "functionlab serve: " << shown
                          << " cannot be a class scene (see above); fix it, or start without "
                             "SCENE from one sphere\n";
                return kExitDiagnostic;
            }
        }
        classroom::SteadyClock clock;
        classroom::ClassSession session(config, clock, log.get());
        if (!session.startNote().empty())
            std::cerr << "functionlab serve: " << session.startNote() << "\n";
        classroom::ServerOptions serverOptions;
        serverOptions.web = !a->flag("no-web");
        serverOptions.livePage.classCode = code;
        serverOptions.livePage.needsClassCode = a->flag("web-needs-class-code");
        if (serverOptions.web) {
            std::string why;
            if (const auto xIte = web::findXite(why))
                serverOptions.livePage.xIteDir = *xIte;
            else
                std::cerr << "functionlab serve: warning: the web page cannot draw: " << why
                          << "\n";
        }
        classroom::ClassroomServer server(session, serverOptions);
        QString why;
        if (!server.listen(address, static_cast<quint16>(a->integer("port", 0)), &why)) {
            std::cerr << "functionlab serve: cannot listen on " << a->text("bind", "127.0.0.1")
                      << ":" << a->integer("port", 0) << ": " << why.toStdString() << "\n";
            return kExitDiagnostic;
        }
        if (::socketpair(AF_UNIX, SOCK_STREAM, 0, signalPipe) != 0) {
            std::cerr << "functionlab serve: cannot watch for signals\n";
            return kExitDiagnostic;
        }
        QSocketNotifier notifier(signalPipe[0], QSocketNotifier::Read);
        QObject::connect(&notifier, &QSocketNotifier::activated, &app, [&] {
            char byte = 0;
            [[maybe_unused]] const auto n = ::read(signalPipe[0], &byte, 1);
            app.quit();
        });
        struct sigaction action {};
        action.sa_handler = onStopSignal;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESTART;
        sigaction(SIGINT, &action, nullptr);
        sigaction(SIGTERM, &action, nullptr);

        std::cout << "listening on ws://" << server.address().toString().toStdString() << ":"
                  << server.port() << std::endl;
        if (serverOptions.web)
            std::cout << "web page on http://" << server.address().toString().toStdString() << ":"
                      << server.port() << "/"
                      << (serverOptions.livePage.needsClassCode ? "?class=CODE" : "") << std::endl;
        app.exec();
        server.close();
        std::cerr << "functionlab serve: stopped at version " << session.version() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "functionlab serve: " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
