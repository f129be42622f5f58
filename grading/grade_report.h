#pragma once
// `functionlab grade report`: a folder of HTML — a page per student (each
// requirement met or not, with its evidence or reason and the places, and
// pictures of the submission: two moments when it moves) and the class
// summary (score distribution, pass rate per requirement, as inline SVG).
// Every text from a submission is escaped (scene::xmlEscape): a student's
// file cannot write into the page.
#include "gradebook.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fl::grading {

struct ReportOptions {
    // Renders a submission at `seconds` into `png` (320 x 240); false when it
    // could not (the page then says so). Null: no pictures.
    std::function<bool(const std::string& submission, double seconds,
                       const std::filesystem::path& png)>
        render;
    // The moments pictured for a submission (one when nothing moves).
    std::function<std::vector<double>(const std::string& submission)> moments;
    // The gradebook's log head the report was made from (and its signature):
    // `functionlab grade verify --head` checks the gradebook still has it.
    std::optional<SignedHead> signedHead;
};

struct ReportResult {
    std::vector<std::filesystem::path> pages; // index.html first
    std::size_t pictures = 0, picturesFailed = 0;
};

ReportResult writeReport(Gradebook& book, const AssignmentRecord& assignment,
                         const std::vector<std::string>& requirementIds,
                         const std::filesystem::path& folder, const ReportOptions& options);

} // namespace fl::grading
