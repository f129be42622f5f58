// `functionlab convert IN OUT`: between X3D XML, ClassicVRML and VRML97 (and
// their gzip forms), chosen by OUT's extension.
#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

#include "mesh/scene_preview.h"
#include "scene/gzip.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <fstream>
#include <iostream>

namespace fl::cli {
namespace {

const char* kConvertHelp =
    R"(usage: functionlab convert IN OUT [--no-preview | --preview-resolution N]

Reads the scene IN and writes it to OUT in the encoding OUT's extension names:
  .x3d   X3D XML          .x3dv  ClassicVRML       .wrl  VRML97
  add .gz (or use .x3dz, .x3dvz, .wrz) for gzip
Only fields written in IN are written (defaults stay implicit); PROTOs stay
PROTOs; unknown nodes and fields are kept. Diagnostics go to stderr as
FILE:LINE:COL: error|warning: message.

So that other X3D browsers, which know nothing of function nodes, show the
scene too, a coarse mesh of its function shapes at time 0 is added as one
plain Group, DEF FunctionLab_Preview, at the end of the scene. FunctionLab
drops it when it reads the file.

options:
  --no-preview              leave the preview out
  --preview-resolution N    cells along each domain box's longest side (default 32)

exit status: 0 written, 1 IN could not be read or OUT not written, 2 usage error
)";

} // namespace

int convertCommand(const Args& args) {
    std::vector<std::string> files;
    bool preview = true;
    mesh::PreviewOptions previewOptions;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            std::cout << kConvertHelp;
            return kExitOk;
        }
        if (a == "--no-preview") {
            preview = false;
            continue;
        }
        if (a == "--preview-resolution") {
            if (i + 1 >= args.size() || !parseNumber(args[i + 1], previewOptions.resolution) ||
                previewOptions.resolution < 2 || previewOptions.resolution > 1024) {
                std::cerr << "functionlab convert: --preview-resolution takes a number from 2 "
                             "to 1024\n\n"
                          << kConvertHelp;
                return kExitUsage;
            }
            ++i;
            continue;
        }
        if (a.starts_with("--")) {
            std::cerr << "functionlab convert: unknown option '" << a << "'\n\n" << kConvertHelp;
            return kExitUsage;
        }
        files.push_back(a);
    }
    if (files.size() != 2) {
        std::cerr << "functionlab convert: give IN and OUT\n\n" << kConvertHelp;
        return kExitUsage;
    }
    scene::Encoding encoding;
    bool gzipped = false;
    if (!scene::encodingForPath(files[1], encoding, gzipped)) {
        std::cerr << "functionlab convert: cannot tell the encoding from '" << files[1]
                  << "'; use .x3d, .x3dv or .wrl (optionally .gz)\n";
        return kExitUsage;
    }
    scene::ReadOptions options;
    options.compileFunctions = true;
    scene::ReadResult r = scene::readSceneFile(files[0], options);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return kExitDiagnostic;
    if (preview) {
        const mesh::PreviewResult p = mesh::addPreview(*r.scene, previewOptions);
        for (const std::string& w : p.warnings)
            std::cerr << "preview: warning: " << w << "\n";
    }
    std::string text = scene::writeScene(*r.scene, encoding);
    if (gzipped) text = scene::gzip(text);
    std::ofstream out(files[1], std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        std::cerr << files[1] << ": error: cannot write the file\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
