// The `functionlab` executable: with no arguments it will open the suite
// window (once the GUI exists); with a subcommand it serves scripts, CI and
// instructors.
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "window/gui.h"

#include <iostream>
#include <string>
#include <vector>

#ifndef FUNCTIONLAB_VERSION
#define FUNCTIONLAB_VERSION "0.0.0"
#endif

namespace {

const char* kHelp = R"(FunctionLab — function-defined 3D objects for teaching

usage: functionlab [--help] [--version] <command> [<args>]

commands:
  formula check "SRC"       check a formula or script; diagnostics with carets
  formula eval "SRC" --at X,Y,Z [--t T] [--param N=V ...] [--json]
                            evaluate a formula: value and gradient
  check FILE [--plan] [--json]
                            load a scene (.x3d .x3dv .wrl, gzip too); diagnostics as
                            FILE:LINE:COL; --plan: what varies with time, what is tangible
  convert IN OUT            convert a scene between X3D XML, ClassicVRML and VRML97
  mesh FILE -o OUT [--time T] [--error E | --resolution N]
  mesh --formula "SRC" --box X0,Y0,Z0,X1,Y1,Z1 -o OUT
                            polygonize function shapes; .stl .obj .ply .glb .x3d
  render FILE -o OUT.png [--time T] [--size WxH] [--viewpoint NAME]
                            draw one frame of a scene off screen
  bench eval [--json]       evaluator speed: FunctionLab vs hand-written C++ vs muParser
  bench accuracy FILE|--formula "SRC" --box ... [--json] [--plot OUT.svg]
                            what accuracy costs in time: adaptive mesher vs dense marching cubes

Run `functionlab <command> --help` for a command's options.

With no arguments functionlab opens its window on the watermelon example (or
on unsaved work from last time); `functionlab FILE` opens FILE in it.
)";

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) return fl::suite::runWindow(argc, argv, {});
    const std::string cmd = args[0];
    std::vector<std::string> rest(args.begin() + 1, args.end());
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        std::cout << kHelp;
        return fl::cli::kExitOk;
    }
    if (cmd == "--version") {
        std::cout << "functionlab " << FUNCTIONLAB_VERSION << "\n";
        return fl::cli::kExitOk;
    }
    try {
        if (cmd == "formula") return fl::cli::formulaCommand(rest);
        if (cmd == "bench") return fl::cli::benchCommand(rest);
        if (cmd == "check") return fl::cli::checkCommand(rest);
        if (cmd == "convert") return fl::cli::convertCommand(rest);
        if (cmd == "mesh") return fl::cli::meshCommand(rest);
        if (cmd == "render") return fl::cli::renderCommand(rest);
    } catch (const std::exception& e) {
        std::cerr << "functionlab: " << e.what() << "\n";
        return fl::cli::kExitDiagnostic;
    }
    if (args.size() == 1 && fl::suite::looksLikeSceneFile(cmd))
        return fl::suite::runWindow(argc, argv, cmd);
    std::cerr << "functionlab: unknown command '" << cmd << "'\n\n" << kHelp;
    return fl::cli::kExitUsage;
}
