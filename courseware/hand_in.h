#pragma once
// File → Hand in: a submission is one folder holding the scene file and the
// files it uses — Inline and EXTERNPROTO scenes, ImageTexture and
// MovieTexture images — at the same places relative to it, which is what
// `functionlab grade check` and `grade batch` read. Only files inside the
// scene's own folder tree are packed (the reader never follows others).
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace fl::courseware {

struct HandIn {
    bool ok = false;
    std::filesystem::path folder;              // the submission
    std::vector<std::filesystem::path> packed; // relative to it, the scene first
    std::vector<std::string> problems;         // what was not packed, and why
};

// `scene` as read from `sceneFile`; `text`: the text to hand in (the
// editor's, which may be newer than the file). Writes into `folder`
// (created; refused when it exists and is not empty).
HandIn packSubmission(const scene::Scene& scene, const std::filesystem::path& sceneFile,
                      const std::string& text, const std::filesystem::path& folder);

} // namespace fl::courseware
