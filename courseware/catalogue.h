#pragma once
// What comes with FunctionLab for a course: the example scenes (the gallery)
// and the assignments, found in one courseware folder — installed next to the
// executable (../share/functionlab/courseware) or the source tree's. Titles
// and descriptions are the scenes' own, read by the scene reader.
#include "assignment.h"

#include <filesystem>
#include <string>
#include <vector>

namespace fl::courseware {

// The courseware folder (holding examples/ and assignments/).
std::filesystem::path coursewareFolder();
// Whether `path` lies in it: the course's own files, never a student's
// working copy (the window saves those into the workspace instead).
bool isInsideCourseware(const std::filesystem::path& path);

struct ExampleScene {
    std::filesystem::path path;
    std::string title;       // WorldInfo title, else the head's title meta, else the file name
    std::string description; // the head's "description" meta; may be empty
};

// The .x3d scenes of `folder` (their .x3dv twins show the same), by file name.
std::vector<ExampleScene> listExamples(const std::filesystem::path& folder = coursewareFolder() /
                                                                             "examples");

// Every assignment folder under `folder`, loaded (with its problems), by id.
std::vector<AssignmentLoad>
listAssignments(const std::filesystem::path& folder = coursewareFolder() / "assignments");

// An assignment named by id (looked up in the courseware's assignments) or
// by its folder's path.
AssignmentLoad findAssignment(const std::string& idOrFolder);

} // namespace fl::courseware
