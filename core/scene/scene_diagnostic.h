#pragma once
// A message about a scene file, located by file:line:column.
#include "formula/diagnostic.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::scene {

using formula::Severity;

struct FilePos {
    int line = 0; // 0: the file as a whole
    int column = 0;
    bool operator==(const FilePos&) const = default; // (DiagnosticFix's == compares it)
};

// A change of the text that mends what a diagnostic says, for an editor to
// offer ("write &amp;"): `length` characters at `at` become `text`.
struct DiagnosticFix {
    FilePos at;
    int length = 0; // characters, not bytes
    std::string text;
    std::string label; // what the fix does, for a menu: "write &amp; for &"
    bool operator==(const DiagnosticFix&) const = default;
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
    std::optional<DiagnosticFix> fix = std::nullopt; // none when no one change mends it
};

// "FILE:LINE:COL: error: message (suggestion)"
std::string formatSceneDiagnostic(const SceneDiagnostic& d);

bool hasErrors(const std::vector<SceneDiagnostic>& diagnostics);

} // namespace fl::scene
