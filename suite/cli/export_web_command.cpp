// `functionlab export-web SCENE -o DIR`: the scene as a static web page any
// browser opens, from a web server or the file system (web/web_page.h).
#include "cli/arguments.h"
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "scene/scene_reader.h"
#include "web/web_bake.h"
#include "web/web_page.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace fl::cli {

const CommandSpec& exportWebSpec() {
    static const CommandSpec spec{
        .name = "export-web",
        .summary = "write a scene as a web page any browser shows (X_ITE, no network)",
        .synopsis = {"export-web SCENE -o DIR [--resolutions N,N,...] [--frames N]"},
        .description =
            "Writes the folder DIR: index.html, which any current browser opens from a web\n"
            "server or straight from the file system with no network, the scene as standard\n"
            "X3D (scene.x3d, for any X3D browser), X_ITE (the X3D browser the page ships,\n"
            "pinned by web/package-lock.json), the files the scene names, and the scene's\n"
            "own source. Function shapes become meshes, each an X3D LOD of the resolutions\n"
            "given (finer as the reader comes closer); a shape that changes with time is\n"
            "meshed at N moments of its cycle, shown in turn by a TimeSensor through an\n"
            "IntegerSequencer and a Switch, so it plays at its own cycle (a wall clock shows\n"
            "the reader's time). Standard nodes, ROUTEs and viewpoints pass through; PROTOs\n"
            "are written expanded and Inlines as Groups. Script nodes and urls outside the\n"
            "scene's folder are left out, each with a warning on stderr. Files already in\n"
            "DIR are replaced, others left alone.\n",
        .positionals = {{.name = "SCENE", .help = "the scene to export"}},
        .options = {{.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "DIR",
                     .help = "the folder to write (made when missing; required)"},
                    {.name = "resolutions",
                     .kind = OptionKind::NumberList,
                     .valueName = "N,N,...",
                     .help = "the levels of detail: cells along each shape's longest side, "
                             "each 2 to 512",
                     .defaultValue = "16,32,64",
                     .min = 2,
                     .max = 512},
                    {.name = "frames",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "moments per cycle of a shape that changes with time",
                     .defaultValue = "24",
                     .min = 2,
                     .max = 360},
                    {.name = "threads",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "meshing threads (default: one per core)",
                     .min = 0,
                     .max = 256}},
        .exitStatus = "0 written, 1 the scene could not be read, X_ITE is missing or DIR not "
                      "written, 2 usage error",
    };
    return spec;
}

int exportWebCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(exportWebSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const std::string dir = a->text("output");
    if (dir.empty())
        return usageError(exportWebSpec(), "say where the page goes: -o DIR", std::cerr);
    std::string why;
    const auto xIte = web::findXite(why);
    if (!xIte) {
        std::cerr << "functionlab export-web: " << why << "\n";
        return kExitDiagnostic;
    }
    const std::string file = a->positional("SCENE");
    scene::ReadOptions options;
    options.compileFunctions = true;
    scene::ReadResult r = scene::readSceneFile(file, options);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return kExitDiagnostic;

    const auto started = std::chrono::steady_clock::now();
    web::BakeOptions bake;
    bake.resolutions = a->numbers("resolutions").value_or(std::vector<double>{16, 32, 64});
    bake.frames = int(a->number("frames", 24));
    bake.threads = int(a->number("threads", 0));
    const bool terminal = isatty(STDERR_FILENO);
    if (terminal)
        bake.progress = [](double done) {
            const int filled = int(std::lround(30 * done));
            std::fprintf(stderr, "\r[%-30s] meshing %3d%%",
                         std::string(std::size_t(std::clamp(filled, 0, 30)), '#').c_str(),
                         int(std::lround(100 * done)));
        };
    const web::BakeResult baked = web::bakeForWeb(*r.scene, bake);
    if (terminal) std::fprintf(stderr, "\n");
    for (const std::string& w : baked.warnings)
        std::cerr << "export-web: warning: " << w << "\n";
    if (!baked.error.empty()) {
        std::cerr << "functionlab export-web: " << file << ": " << baked.error << "\n";
        return kExitDiagnostic;
    }

    web::PageOptions page;
    page.xIteDir = *xIte;
    page.resolutions = bake.resolutions;
    page.frames = baked.animated > 0 ? bake.frames : 0;
    web::PageResult written;
    if (!web::writeWebFolder(baked, *r.scene, dir, page, written, why)) {
        std::cerr << "functionlab export-web: " << why << "\n";
        return kExitDiagnostic;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::fprintf(stderr,
                 "%s/index.html: %zu function shape(s) as meshes (%zu playing as frames), %zu "
                 "triangles, %zu files, %.1f MB, %.1f s\n",
                 dir.c_str(), baked.roots, baked.animated, baked.triangles, written.written.size(),
                 double(written.bytes) / 1e6, seconds);
    return kExitOk;
}

} // namespace fl::cli
