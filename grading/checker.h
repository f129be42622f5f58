#pragma once
// The checker: one submission against an assignment's automatic
// requirements. Deterministic — the same scene and checker version give the
// same verdict, bit for bit — and bounded: one budget of work for the
// whole submission, reported when it runs out, never a hang.
#include "requirement.h"
#include "solid_difference.h"

#include "scene/scene.h"
#include "scene/scene_diagnostic.h"

#include <filesystem>
#include <string>
#include <vector>

namespace fl::grading {

// Bumped whenever a verdict may change: the gradebook records it.
inline constexpr const char* kCheckerVersion = "1";

struct CheckOptions {
    // Instructions evaluated for the whole submission (about 1-2 s of work):
    // a point costs its tape's length, an interval four times that.
    std::size_t budget = 400'000'000;
    int moments = 9; // of the scene's time judged
    // How finely solids are compared (`bench grading` varies it).
    CompareOptions compare;
};

struct CheckReport {
    bool gradable = false;
    std::vector<RequirementResult> requirements; // in the assignment's order
    double score = 0, maxScore = 0;
    bool budgetExceeded = false;
    std::vector<scene::SceneDiagnostic> diagnostics; // why not gradable; checker notes
    // Wall time of each requirement's check and of showing the scene, in ms:
    // measurements for `bench grading`, never part of a verdict or its JSON.
    std::vector<double> requirementMilliseconds;
    double viewMilliseconds = 0;
};

CheckReport checkScene(const scene::Scene& scene, const std::vector<Requirement>& requirements,
                       const CheckOptions& options = {});

// The scene file of a submission: the file itself, or the one scene at the
// top of a submission folder (none, with `problem`, when there is none or
// more than one).
std::string sceneFileOf(const std::filesystem::path& submission, std::string* problem = nullptr);

// A scene file (gzip forms too) or a folder holding one: read, then checked.
CheckReport checkSubmission(const std::string& path, const std::vector<Requirement>& requirements,
                            const CheckOptions& options = {});

} // namespace fl::grading
