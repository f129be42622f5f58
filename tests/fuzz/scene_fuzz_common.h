#pragma once
// Shared body of the scene fuzz targets: read, and when the scene loads, write
// it in every encoding and read that back. Any crash, hang, sanitizer report
// or unbounded allocation is a finding.
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <string>

inline void fuzzSceneText(std::string text) {
    fl::scene::ReadOptions options;
    options.limits.maxNodes = 20000; // keep each run small; the limits themselves are tested
    options.limits.maxExpandedNodes = 20000;
    fl::scene::ReadResult r = fl::scene::readSceneBytes(std::move(text), "fuzz", options);
    if (!r.ok()) return;
    for (auto e : {fl::scene::Encoding::Xml, fl::scene::Encoding::ClassicVrml,
                   fl::scene::Encoding::Vrml97}) {
        fl::scene::ReadResult back =
            fl::scene::readSceneBytes(fl::scene::writeScene(*r.scene, e), "written", options);
        (void)back;
    }
}
