#pragma once
// Grading a class: every submission in a folder (a scene file or a folder
// per student) checked in its own isolated child process, several at once,
// each result written to the gradebook in its own transaction as soon as it
// is in — so a killed batch loses no finished result, and a batch run again
// skips what is unchanged (same content hash, checker version and rubric).
#include "gradebook.h"
#include "platform/isolated_run.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace fl::grading {

struct BatchSubmission {
    std::string student; // from the file or folder name (extensions dropped)
    std::filesystem::path path;
};

// The submissions of `folder`, by student id. Names that are not plain
// (hidden files, names with control characters) are left out and said so.
std::vector<BatchSubmission> findSubmissions(const std::filesystem::path& folder,
                                             std::vector<std::string>& skipped);

struct BatchOptions {
    int jobs = 2;
    platform::IsolationLimits limits;
    // The checker's command line for one submission (it prints `grade check
    // --json`'s object on stdout).
    std::function<std::vector<std::string>(const BatchSubmission&)> command;
    // Called after each submission (from the caller's thread of results).
    std::function<void(std::size_t done, std::size_t total, const BatchSubmission&,
                       const std::string& outcome)>
        progress;
    std::string checkerVersion;
    std::string dueUtc; // ISO 8601; empty: nothing is late
    std::function<double(double hoursLate)> lateFactor;
};

struct BatchSummary {
    std::size_t graded = 0, skipped = 0, notGradable = 0, failed = 0;
    std::vector<std::string> problems;        // "alice: the checker ran out of time (60 s)"
    std::vector<double> secondsPerSubmission; // wall time of each child, as it finished
};

BatchSummary gradeBatch(Gradebook& book, const AssignmentRecord& assignment,
                        const std::vector<BatchSubmission>& submissions,
                        const BatchOptions& options);

// The grade a `grade check --json` object describes (false when it is not one).
bool gradeFromCheckJson(const std::string& json, GradeRecord& g);

} // namespace fl::grading
