#pragma once
// What a student should do about an XML syntax error. The XML parser says
// "Expected '#' or '[a-zA-Z]', but got ' '" where a student wrote the
// formula `a & b` inside a definition attribute; this finds the `&` (or the
// `<` of a comparison) that caused it and says, at its place, what to write
// instead — with the one change that mends it, for the editor to offer.
#include "scene_diagnostic.h"

#include <optional>
#include <string>
#include <string_view>

namespace fl::scene {

struct XmlSyntaxHelp {
    FilePos at; // the character to change
    std::string message;
    std::string suggestion;
    DiagnosticFix fix;
};

// `text`: the whole file; `reported`: where the parser stopped (1-based
// line and column, columns in characters). None when the error is not one
// of a bare `&` or `<` inside an attribute value.
std::optional<XmlSyntaxHelp> explainXmlSyntaxError(std::string_view text, FilePos reported);

} // namespace fl::scene
