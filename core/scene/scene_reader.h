#pragma once
// The front door for scene files: detects the encoding (X3D XML, ClassicVRML,
// VRML97, gzip forms), reads, checks, expands PROTOs, and compiles every
// function definition with its diagnostics placed at file:line:column.
#include "read_limits.h"
#include "scene.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fl::scene {

struct ReadOptions {
    ReadLimits limits;
    bool compileFunctions = true; // compile every FGeometry/FMaterial/... definition
    // Load Inline and EXTERNPROTO urls (files in the scene's folder tree only;
    // a scene read from bytes has no folder, so nothing is followed there).
    bool followReferences = true;
};

struct ReadResult {
    std::unique_ptr<Scene> scene; // null when the file could not be read
    std::vector<SceneDiagnostic> diagnostics;
    bool ok() const { return scene != nullptr; }
};

// `bytes` may be gzip-compressed; `path` names the file in diagnostics.
ReadResult readSceneBytes(std::string bytes, const std::string& path,
                          const ReadOptions& options = {});
ReadResult readSceneFile(const std::filesystem::path& path, const ReadOptions& options = {});

} // namespace fl::scene
