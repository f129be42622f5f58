#pragma once
// Shared body of the scene fuzz targets: read, and when the scene loads, write
// it in X3D XML and ClassicVRML (and VRML97 when it was read as VRML97) and
// read that back. Any crash, hang, sanitizer report or unbounded allocation is
// a finding, and so is a written scene that does not read back as the same
// model (issue 20: converting between encodings loses nothing).
#include "scene/scene_builder.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <cstdio>
#include <cstdlib>
#include <string>

inline void fuzzSceneText(std::string text) {
    fl::scene::ReadOptions options;
    options.limits.maxNodes = 20000; // keep each run small; the limits themselves are tested
    options.limits.maxExpandedNodes = 20000;
    options.compileFunctions = false; // the formula target covers formulas
    fl::scene::ReadResult r = fl::scene::readSceneBytes(std::move(text), "fuzz", options);
    if (!r.ok()) return;
    for (auto e : {fl::scene::Encoding::Xml, fl::scene::Encoding::ClassicVrml,
                   fl::scene::Encoding::Vrml97}) {
        // VRML97 holds only VRML97 content: written from an X3D scene, its
        // reader may rightly refuse it.
        if (e == fl::scene::Encoding::Vrml97 && r.scene->encoding != e) continue;
        const std::string written = fl::scene::writeScene(*r.scene, e);
        fl::scene::ReadResult back = fl::scene::readSceneBytes(written, "written", options);
        std::string difference;
        if (!back.ok()) {
            difference = "does not read back:";
            for (const auto& d : back.diagnostics)
                if (d.severity == fl::scene::Severity::Error)
                    difference += " " + fl::scene::formatSceneDiagnostic(d);
        } else if (!fl::scene::sameModel(*r.scene, *back.scene, &difference) && difference.empty())
            difference = "a different model";
        if (!difference.empty()) {
            std::fprintf(stderr, "written as %s, the scene %s\n--- written ---\n%s\n",
                         std::string(fl::scene::encodingName(e)).c_str(), difference.c_str(),
                         written.substr(0, 4000).c_str());
            std::abort();
        }
    }
}
