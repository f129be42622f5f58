#pragma once
// Reads the X3D XML encoding (ISO/IEC 19776-1) into a Scene, with QtCore's
// QXmlStreamReader (no network: DTDs are never fetched).
#include "scene_builder.h"

#include <string_view>

namespace fl::scene {

void readXml(SceneBuilder& builder);

bool looksLikeXml(std::string_view text);

// Parses an attribute's text as a value of `type` (also used for
// <field value=...> and <fieldValue value=...>). On failure returns false
// with `problem` set. `origin` is where the attribute value starts in
// `fileText` (origin.file < 0: not from a file).
// The text of a value of an unknown field, as kept: without the separators
// (spaces, commas) around it, which carry nothing and no writer could keep.
std::string_view trimmedUnknownValue(std::string_view text);

bool parseXmlAttributeValue(std::string_view text, FieldType type, FieldValue& out,
                            const StringOrigin& origin, std::string_view fileText,
                            std::string& problem);

} // namespace fl::scene
