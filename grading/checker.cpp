#include "checker.h"

#include "checks.h"
#include "submission_view.h"

#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <chrono>
#include <filesystem>

namespace fl::grading {
namespace {

RequirementResult checkOne(const SubmissionView& view, const Requirement& r, Budget& budget,
                           const CompareOptions& compare) {
    switch (r.kind) {
    case RequirementKind::ImplicitSurface:
    case RequirementKind::ExplicitSolid:
    case RequirementKind::Parametric:
        return checkShapeKind(view, r, budget);
    case RequirementKind::SetOperations:
        return checkSetOperations(view, r, budget, compare);
    case RequirementKind::Morphing:
        return checkMorphing(view, r, budget);
    case RequirementKind::Animation:
        return checkAnimation(view, r);
    case RequirementKind::LevelOfDetail:
        return checkLevelOfDetail(view, r);
    case RequirementKind::FunctionColour:
        return checkFunctionColour(view, r, budget);
    case RequirementKind::Tangible:
        return checkTangible(view, r, budget);
    case RequirementKind::PdeSurface:
        return checkPdeSurface(view, r);
    }
    return {r.id, r.kind, false, 0, r.points, "unknown requirement", {}};
}

} // namespace

CheckReport checkScene(const scene::Scene& scene, const std::vector<Requirement>& requirements,
                       const CheckOptions& options) {
    CheckReport report;
    report.gradable = true;
    Budget budget{options.budget};
    using Clock = std::chrono::steady_clock;
    auto started = Clock::now();
    const SubmissionView view(scene, options.moments);
    report.viewMilliseconds =
        std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    std::string cutShort; // requirements not met whose judging was cut short
    for (const Requirement& r : requirements) {
        started = Clock::now();
        const std::size_t cutBefore = budget.cutShort;
        report.requirements.push_back(checkOne(view, r, budget, options.compare));
        if (budget.cutShort > cutBefore && !report.requirements.back().met)
            cutShort += (cutShort.empty() ? "" : ", ") + r.id;
        report.requirementMilliseconds.push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - started).count());
        report.score += report.requirements.back().points;
        report.maxScore += r.points;
    }
    // Whenever a verdict was cut short, the JSON says so (docs/grading.md).
    report.budgetExceeded = budget.exceeded || !cutShort.empty();
    if (!cutShort.empty() && !budget.exceeded)
        report.diagnostics.push_back(
            {scene::Severity::Warning,
             scene.pathOf(0),
             {1, 1},
             "the checker could not finish judging " + cutShort +
                 " within its limits: what it could not judge is not counted",
             "ask your instructor to look at it (the limits are in docs/grading.md)"});
    if (budget.exceeded)
        report.diagnostics.push_back(
            {scene::Severity::Warning,
             scene.pathOf(0),
             {1, 1},
             "the checker's budget of " + std::to_string(options.budget / 1'000'000) +
                 " million instruction evaluations ran out: what it could not judge is not "
                 "counted",
             "simplify the definitions, or ask your instructor"});
    return report;
}

std::string sceneFileOf(const std::filesystem::path& submission, std::string* problem) {
    std::error_code ec;
    if (!std::filesystem::is_directory(submission, ec)) return submission.string();
    const std::filesystem::path& folder = submission;
    std::vector<std::filesystem::path> scenes;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = e.path().filename().string();
        if (scene::isSceneFileName(name) && e.is_regular_file(ec)) scenes.push_back(e.path());
    }
    std::sort(scenes.begin(), scenes.end());
    scenes.erase(std::unique(scenes.begin(), scenes.end()), scenes.end());
    if (scenes.size() == 1) return scenes.front().string();
    if (!problem) return {};
    *problem = scenes.empty() ? "the folder holds no scene file (.x3d, .x3dv, .wrl or their gzip "
                                "forms)"
                              : "the folder holds " + std::to_string(scenes.size()) +
                                    " scene files; a submission has one at its top";
    return {};
}

CheckReport checkSubmission(const std::string& path, const std::vector<Requirement>& requirements,
                            const CheckOptions& options) {
    std::string problem;
    const std::string file = sceneFileOf(path, &problem);
    CheckReport report;
    if (file.empty()) {
        report.diagnostics.push_back({scene::Severity::Error, path, {1, 1}, problem, {}});
        return report;
    }
    scene::ReadResult read = scene::readSceneFile(file);
    if (!read.ok()) {
        report.diagnostics = read.diagnostics;
        for (const Requirement& r : requirements)
            report.maxScore += r.points;
        return report;
    }
    report = checkScene(*read.scene, requirements, options);
    // The reader's warnings go with the verdict: they are what a student fixes next.
    report.diagnostics.insert(report.diagnostics.begin(), read.diagnostics.begin(),
                              read.diagnostics.end());
    return report;
}

} // namespace fl::grading
