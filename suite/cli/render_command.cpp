// `functionlab render`: one frame of a scene, drawn off screen into a PNG.
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"
#include "viewer/offscreen_render.h"
#include "viewer/surface_format.h"
#include "viewer/text_outliner.h"

#include <QFileInfo>
#include <QGuiApplication>
#include <QImageWriter>
#include <QSaveFile>

#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace fl::cli {
namespace {

bool hasDisplay() {
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        if (const char* v = std::getenv(name); v && *v) return true;
    return false;
}

// Without a display, once: the same command under xvfb-run.
void runUnderXvfb(const Args& args) {
    if (std::getenv("FUNCTIONLAB_UNDER_XVFB")) return;
    ::setenv("FUNCTIONLAB_UNDER_XVFB", "1", 1);
    std::vector<std::string> all{"xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"};
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    all.push_back(n > 0 ? std::string(self, std::size_t(n)) : std::string("functionlab"));
    all.push_back("render");
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execvp("xvfb-run", argv.data()); // returns only when it could not start
}

} // namespace

const CommandSpec& renderSpec() {
    static const CommandSpec spec{
        .name = "render",
        .summary = "draw one frame of a scene off screen",
        .synopsis = {"render FILE -o OUT.png [--time T] [--size WxH] [--viewpoint NAME]\n"
                     "[--resolution N]"},
        .description =
            "Draws one frame of the scene FILE off screen and writes it as an image\n"
            "(.png, or .jpg/.bmp by the extension): function shapes meshed at the moment T,\n"
            "standard shapes, the scene's lights, Background and the bound Viewpoint.\n",
        .positionals = {{.name = "FILE", .help = "the scene"}},
        .options = {{.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "OUT",
                     .help = "the image to write (required)"},
                    {.name = "time",
                     .kind = OptionKind::Number,
                     .valueName = "T",
                     .help = "the moment, in scene seconds",
                     .defaultValue = "0"},
                    {.name = "size",
                     .kind = OptionKind::Size,
                     .valueName = "WxH",
                     .help = "the image size in pixels",
                     .defaultValue = "800x600",
                     .min = 1,
                     .max = 16384},
                    {.name = "viewpoint",
                     .kind = OptionKind::Text,
                     .valueName = "NAME",
                     .help = "a Viewpoint by description or DEF name (default: the first; a view "
                             "of the whole scene when there is none)"},
                    {.name = "resolution",
                     .kind = OptionKind::Number,
                     .valueName = "N",
                     .help = "mesh every function shape at N cells along its box (default: each "
                             "FGeometry's resolution)",
                     .min = 0}},
        .notes = "Drawing needs OpenGL 3.3 and so a display; without one, render runs itself\n"
                 "under xvfb-run when that is installed (Debian: xvfb), else says so.\n",
        .exitStatus = "0 written, 1 the scene could not be read or nothing drawn, 2 usage error",
    };
    return spec;
}

int renderCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(renderSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    auto usage = [](const std::string& problem) {
        return usageError(renderSpec(), problem, std::cerr);
    };
    const std::string file = a->positional("FILE"), output = a->text("output"),
                      viewpoint = a->text("viewpoint");
    const double time = a->number("time", 0), resolution = a->number("resolution", 0);
    const auto [width, height] = a->size("size").value_or(std::pair{800, 600});
    if (output.empty()) return usage("give the image to write with -o OUT.png");
    const QByteArray format =
        QFileInfo(QString::fromStdString(output)).suffix().toLower().toLatin1();
    if (!QImageWriter::supportedImageFormats().contains(format))
        return usage("cannot tell the image format from '" + output + "'; use .png");

    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return kExitDiagnostic;

    if (!hasDisplay()) runUnderXvfb(args);
    if (!hasDisplay()) {
        std::cerr << "functionlab render: drawing needs a display; install xvfb (apt-get install "
                     "xvfb) or run: xvfb-run -a functionlab render ...\n";
        return kExitDiagnostic;
    }
    viewer::useViewerSurfaceFormat();
    int argc = 1;
    char name[] = "functionlab";
    char* argv[] = {name, nullptr};
    QGuiApplication app(argc, argv);

    mesh::SceneMeshOptions so;
    so.sceneSeconds = time;
    so.placeInScene = false;
    so.text = viewer::qtTextOutliner();
    so.useFileResolution = resolution <= 0;
    if (resolution > 0) so.mesh.resolution = resolution;
    const mesh::SceneMeshes meshes = mesh::meshScene(*r.scene, so);
    std::size_t triangles = 0, points = 0;
    for (const auto& s : meshes.shapes) {
        for (const auto& w : s.warnings)
            std::cerr << "warning: " << s.name << ": " << w << "\n";
        if (!s.error.empty()) std::cerr << "error: " << s.name << ": " << s.error << "\n";
        (s.mesh.isPointCloud() ? points : triangles) +=
            s.mesh.isPointCloud() ? s.mesh.vertexCount() : s.mesh.triangleCount();
    }
    for (const auto& note : meshes.notes)
        std::cerr << "note: " << note << "\n";

    viewer::OffscreenRequest request;
    request.size = QSize(width, height);
    request.viewpoint = QString::fromStdString(viewpoint);
    QString error;
    const std::optional<QImage> image = viewer::renderOffscreen(meshes, request, error);
    if (!image) {
        std::cerr << "functionlab render: " << error.toStdString() << "\n";
        return kExitDiagnostic;
    }
    QSaveFile out(QString::fromStdString(output));
    if (!out.open(QIODevice::WriteOnly) || !image->save(&out, format.constData()) ||
        !out.commit()) {
        std::cerr << "functionlab render: cannot write " << output
                  << ": check the folder exists and is writable\n";
        return kExitDiagnostic;
    }
    std::cerr << "wrote " << output << " (" << width << "x" << height << ", "
              << meshes.shapes.size() << " shapes, " << triangles << " triangles";
    if (points) std::cerr << ", " << points << " points";
    std::cerr << ")\n";
    return kExitOk;
}

} // namespace fl::cli
