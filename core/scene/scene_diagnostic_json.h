#pragma once
// A scene diagnostic in JSON, the one form every writer uses (`check`,
// `grade check`, the grader's report): {"file", "line", "column",
// "severity", "message", "suggestion"}.
#include "scene/scene_diagnostic.h"
#include "text/json_text.h"

#include <string>

namespace fl::scene {

inline std::string sceneDiagnosticJson(const SceneDiagnostic& d) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about
    // literal + std::string chains.
    std::string out = "{\"file\":";
    out += text::jsonString(d.file);
    out += ",\"line\":" + std::to_string(d.pos.line);
    out += ",\"column\":" + std::to_string(d.pos.column);
    out += ",\"severity\":";
    out += text::jsonString(formula::severityName(d.severity));
    out += ",\"message\":";
    out += text::jsonString(d.message);
    out += ",\"suggestion\":";
    out += text::jsonString(d.suggestion);
    return out + "}";
}

} // namespace fl::scene
