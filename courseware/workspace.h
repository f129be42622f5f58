#pragma once
// A student's own folder for their work (issue 29 §2): an example or an
// assignment's starter is opened as a copy in ~/FunctionLab/FOLDER/, made on
// first use, so the course's files are never written over and what the file
// dialogs show is the student's, not the course's (nor its solutions).
#include <filesystem>
#include <string>

namespace fl::courseware {

// $FUNCTIONLAB_WORKSPACE, else ~/FunctionLab.
std::filesystem::path workspaceFolder();

struct WorkingCopy {
    std::filesystem::path path; // the copy (empty on failure)
    bool existed = false;       // the student's copy from before, opened as it is
    std::string error;          // why there is no copy
};

// The student's copy of `source` in workspaceFolder()/`folder` (an assignment
// id, or "examples"): made when there is none, else the one there (never
// overwritten: it holds their work).
WorkingCopy workingCopyOf(const std::filesystem::path& source, const std::string& folder);

} // namespace fl::courseware
