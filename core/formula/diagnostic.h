#pragma once
// A message about formula text, located by line:column range, written for a
// student, with a suggestion where one exists.
#include "source_range.h"

#include <string>
#include <string_view>
#include <vector>

namespace fl::formula {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceRange range;
    std::string message;
    std::string suggestion; // empty when there is none
};

const char* severityName(Severity s);

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

// "LINE:COL: error: message (suggestion)" followed by the source line and a
// caret line underlining the range. `origin` prefixes the location when set.
std::string formatDiagnostic(const Diagnostic& d, std::string_view source,
                             std::string_view origin = {});

} // namespace fl::formula
