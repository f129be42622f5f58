#pragma once
// What a classroom scene may be: read and checked by the same scene reader and
// formula checker as a file (every definition compiled), read from memory so
// no Inline or EXTERNPROTO url is ever followed, and refused outright when it
// names a url at all (Inline, EXTERNPROTO, Script, textures, sounds) — a
// class shares small function models, never references to elsewhere — or
// exceeds the class's size, node or formula limits.
#include "classroom_limits.h"

#include "scene/scene_diagnostic.h"

#include <string>
#include <vector>

namespace fl::classroom {

struct SceneCheck {
    std::vector<scene::SceneDiagnostic> diagnostics; // errors and warnings, located
    std::size_t nodes = 0;
    bool ok = false;
};

// The name scene diagnostics carry as their file: "scene:LINE:COL: ...".
inline constexpr const char* kSceneFileName = "scene";

SceneCheck checkClassroomScene(const std::string& text, const ClassroomLimits& limits = {});

} // namespace fl::classroom
