#include "scene_diagnostic.h"

namespace fl::scene {

std::string formatSceneDiagnostic(const SceneDiagnostic& d) {
    std::string out = d.file.empty() ? std::string("<scene>") : d.file;
    if (d.pos.line > 0)
        out += ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column);
    out += ": ";
    out += formula::severityName(d.severity);
    out += ": ";
    out += d.message;
    if (!d.suggestion.empty()) out += " (" + d.suggestion + ")";
    return out;
}

bool hasErrors(const std::vector<SceneDiagnostic>& diagnostics) {
    for (const auto& d : diagnostics)
        if (d.severity == Severity::Error) return true;
    return false;
}

} // namespace fl::scene
