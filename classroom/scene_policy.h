#pragma once
// What a classroom scene may be: read and checked by the same scene reader and
// formula checker as a file (every definition compiled), read from memory so
// no Inline or EXTERNPROTO url is ever followed, and refused outright when it
// names a url at all (Inline, EXTERNPROTO, Script, textures, sounds) — a
// class shares small function models, never references to elsewhere — or
// exceeds the class's size, node or formula limits, or the work the class
// allows (formula instructions and compile steps, meshing cells and
// evaluations: scene/scene_work.h).
#include "classroom_limits.h"

#include "scene/scene_diagnostic.h"
#include "scene/scene_reader.h"
#include "scene/scene_work.h"

#include <string>
#include <vector>

namespace fl::classroom {

struct SceneCheck {
    std::vector<scene::SceneDiagnostic> diagnostics; // errors and warnings, located
    std::size_t nodes = 0;
    bool ok = false;
    // Refused for the work it would cost (a too-costly refusal), not for a
    // mistake in it; the first error says where.
    bool tooCostly = false;
    // Refused for its size (text, nodes, a formula's length): a too-large refusal.
    bool tooLarge = false;
};

// The name scene diagnostics carry as their file: "scene:LINE:COL: ...".
inline constexpr const char* kSceneFileName = "scene";

SceneCheck checkClassroomScene(const std::string& text, const ClassroomLimits& limits = {});

// How a class scene is read, and the work it may cost: what the server checks
// with, and what a window that shows the class's scene reads it with.
scene::ReadOptions readOptionsFor(const ClassroomLimits& limits);
scene::WorkBudget workBudgetFor(const ClassroomLimits& limits);

} // namespace fl::classroom
