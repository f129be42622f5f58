#pragma once
// A lab assignment: a folder courseware/assignments/ID/ whose manifest.json
// (schema "functionlab-assignment/1", docs/assignments.md) names the title,
// the instructions (Markdown), starter scenes, the automatic requirements the
// checker judges, manual rubric items, a due date with a late policy, and the
// reference solutions the tests grade. Checked on load: every problem is
// reported as manifest.json:LINE:COL with what to write instead.
#include "grading/gradebook.h"
#include "grading/requirement.h"

#include "scene/scene_diagnostic.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fl::courseware {

inline constexpr const char* kAssignmentSchema = "functionlab-assignment/1";

struct RubricItem {
    std::string id;
    std::string description;
    double points = 0;
};

// Late work loses `deductionPercent` of its score for every started
// `everyHours` past the due time, never more than down to `floorPercent`.
struct LatePolicy {
    double deductionPercent = 0;
    double everyHours = 24;
    double floorPercent = 0;
    // The factor a score is multiplied by, `hoursLate` after the due time.
    double factor(double hoursLate) const;
};

struct Assignment {
    std::filesystem::path folder;
    std::string id;
    std::string title;
    std::filesystem::path instructions; // Markdown
    std::vector<std::filesystem::path> starters;
    // The reference solutions that are here: only in an instructor's folder
    // (instructorFolderFor), never in what a student installs.
    std::vector<std::filesystem::path> solutions;
    std::optional<std::string> due; // ISO 8601 UTC, "2026-12-14T23:59:00Z"
    LatePolicy late;
    std::vector<grading::Requirement> requirements;
    std::vector<RubricItem> rubric;

    double automaticPoints() const;
    double manualPoints() const;
    // SHA-256 of what grades are made against (requirements with their
    // kinds, points and parameters; rubric items): a grade made against an
    // older rubric is graded again.
    std::string rubricHash() const;
    // What the gradebook keeps of it.
    grading::AssignmentRecord record() const;
};

struct AssignmentLoad {
    std::optional<Assignment> assignment; // present exactly when there are no errors
    std::vector<scene::SceneDiagnostic> diagnostics;
};

// Where the reference solutions of the assignment in `folder` (id `id`) are:
// $FUNCTIONLAB_INSTRUCTOR_DIR/ID, else the installed instructor part
// (share/functionlab/instructor/ID, the CMake component "instructor"), else
// `folder` itself when it is not the installed student courseware (the
// source tree, an instructor's own assignment). Empty when there is none.
std::filesystem::path instructorFolderFor(const std::filesystem::path& folder,
                                          const std::string& id);

// `folder` holds manifest.json.
AssignmentLoad loadAssignment(const std::filesystem::path& folder);
// The manifest's text (tests and fuzzing); paths resolve against `folder`.
AssignmentLoad parseAssignment(const std::string& manifestText, const std::filesystem::path& folder,
                               const std::string& manifestName = "manifest.json");

} // namespace fl::courseware
