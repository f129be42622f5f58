// `functionlab convert IN OUT`: between X3D XML, ClassicVRML and VRML97 (and
// their gzip forms), chosen by OUT's extension.
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "mesh/scene_preview.h"
#include "scene/gzip.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <fstream>
#include <iostream>

namespace fl::cli {

const CommandSpec& convertSpec() {
    static const CommandSpec spec{
        .name = "convert",
        .summary = "convert a scene between X3D XML, ClassicVRML and VRML97",
        .synopsis = {"convert IN OUT [--no-preview | --preview-resolution N]"},
        .description =
            "Reads the scene IN and writes it to OUT in the encoding OUT's extension names:\n"
            "  .x3d   X3D XML          .x3dv  ClassicVRML       .wrl  VRML97\n"
            "  add .gz (or use .x3dz, .x3dvz, .wrz) for gzip\n"
            "Only fields written in IN are written (defaults stay implicit); PROTOs stay\n"
            "PROTOs; unknown nodes and fields are kept. Diagnostics go to stderr as\n"
            "FILE:LINE:COL: error|warning: message.\n"
            "\n"
            "So that other X3D browsers, which know nothing of function nodes, show the\n"
            "scene too, a coarse mesh of its function shapes at time 0 is added as one\n"
            "plain Group, DEF FunctionLab_Preview, at the end of the scene. FunctionLab\n"
            "drops it when it reads the file.\n",
        .positionals = {{.name = "IN", .help = "the scene to read"},
                        {.name = "OUT", .help = "the file to write"}},
        .options = {{.name = "no-preview", .help = "leave the preview out"},
                    {.name = "preview-resolution",
                     .kind = OptionKind::Number,
                     .valueName = "N",
                     .help = "cells along each domain box's longest side in the preview (a real "
                             "number)",
                     .defaultValue = "32",
                     .min = 2,
                     .max = 1024}},
        .exitStatus = "0 written, 1 IN could not be read or OUT not written, 2 usage error",
    };
    return spec;
}

int convertCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(convertSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const std::vector<std::string> files{a->positional("IN"), a->positional("OUT")};
    const bool preview = !a->flag("no-preview");
    mesh::PreviewOptions previewOptions;
    previewOptions.resolution = a->number("preview-resolution", 32);
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
