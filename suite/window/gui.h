#pragma once
// Starting the window: `functionlab` with no arguments (the watermelon
// example, or unsaved work from last time) or with a scene file.
#include <string>

namespace fl::suite {

// Runs the window until it is closed; returns the exit code. `file` empty:
// the recovery file if there is one, else the watermelon example.
int runWindow(int argc, char** argv, const std::string& file);

// Whether an argument names a scene to open rather than a command.
bool looksLikeSceneFile(const std::string& argument);

} // namespace fl::suite
