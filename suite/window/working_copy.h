#pragma once
// The student's copies of the course's files (issue 29 §2): an example or a
// starter opens from ~/FunctionLab/FOLDER/ (courseware/workspace.h), and
// nothing is ever saved into the installed courseware.
#include <QString>

namespace fl::suite {

struct PanelContext;

// Opens the student's copy of `coursePath` (made on first use in the
// workspace's `folder`: an assignment id, or "examples"); says where it is.
bool openWorkingCopy(PanelContext& context, const QString& coursePath, const QString& folder);

// Where Save As starts for the file at `path`: its own place, unless that
// is the course's (or there is none): then the workspace.
QString saveAsStartFor(const QString& path);

// Whether Save must ask for a place: no file yet, or a file of the course's.
bool saveNeedsAPlace(const QString& path);

} // namespace fl::suite
