#pragma once
// A scene diagnostic as the commands print it in JSON (check, grade check):
// {"file", "line", "column", "severity", "message", "suggestion"}.
#include "cli/json.h"

#include "scene/scene_diagnostic.h"

#include <string>

namespace fl::cli {

inline std::string sceneDiagnosticJson(const scene::SceneDiagnostic& d) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about
    // literal + std::string chains.
    std::string out = "{\"file\":";
    out += jsonString(d.file);
    out += ",\"line\":" + std::to_string(d.pos.line);
    out += ",\"column\":" + std::to_string(d.pos.column);
    out += ",\"severity\":";
    out += jsonString(formula::severityName(d.severity));
    out += ",\"message\":";
    out += jsonString(d.message);
    out += ",\"suggestion\":";
    out += jsonString(d.suggestion);
    return out + "}";
}

} // namespace fl::cli
