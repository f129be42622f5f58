#pragma once
// A message about a scene file, located by file:line:column.
#include "formula/diagnostic.h"

#include <string>
#include <vector>

namespace fl::scene {

using formula::Severity;

struct FilePos {
    int line = 0; // 0: the file as a whole
    int column = 0;
};

struct SceneDiagnostic {
    Severity severity = Severity::Error;
    std::string file;
    FilePos pos;
    std::string message;
    std::string suggestion; // empty when there is none
    // A bound on size or work was passed (the scene costs too much), not a
    // mistake in its text: a class refuses it as too-costly.
    bool overBudget = false;
};

// "FILE:LINE:COL: error: message (suggestion)"
std::string formatSceneDiagnostic(const SceneDiagnostic& d);

bool hasErrors(const std::vector<SceneDiagnostic>& diagnostics);

} // namespace fl::scene
