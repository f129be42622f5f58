#pragma once
// Setting a field of a node in the text the student wrote: the one edit that
// changes that field (its value replaced where it is written, or the field
// added at the start of the node), so a tool — the Accuracy panel writing a
// shape's resolution — changes the scene file without rewriting the rest of
// it: comments, layout and every other value stay as typed.
#include "scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::scene {

// Replace `length` bytes at `offset` of the scene file's text by `text`.
struct TextEdit {
    std::size_t offset = 0;
    std::size_t length = 0;
    std::string text;
};

// The edit that gives `node`'s numeric field `field` the value written as
// `value` (numbers separated by spaces, e.g. "48" or "8 48"), in files[0] of
// `scene` (the text it was read from). None, with `why`, when the node is not
// written in that text (built by code, in an Inline's file, inside a PROTO
// body or expansion) or the text does not hold the field where the reader
// said.
std::optional<TextEdit> setNumbersFieldEdit(const Scene& scene, const Node& node,
                                            std::string_view field, std::string_view value,
                                            std::string* why = nullptr);

// The same for a string field (SFString or MFString, e.g. a definition):
// the value written as X3D quoted strings, the rest of the text untouched.
std::optional<TextEdit> setStringsFieldEdit(const Scene& scene, const Node& node,
                                            std::string_view field,
                                            const std::vector<std::string>& strings,
                                            std::string* why = nullptr);

// The text with the edit applied.
std::string applied(std::string_view text, const TextEdit& edit);

} // namespace fl::scene
