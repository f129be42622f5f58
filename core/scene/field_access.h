#pragma once
// Reading a node's fields with the catalogue's defaults filled in, so callers
// never care whether a value was written in the file.
#include "scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace fl::scene {

// The value the file gave, else the node type's default, else an empty value.
FieldValue fieldValue(const Node& node, std::string_view name);
// The default of a field type itself (X3D 19775-1 table 5.1): zeros,
// "0 0 1 0" for rotations, one empty string for SFString, empty MF fields.
FieldValue typeDefault(FieldType type);
// A field spec's default, parsed from the catalogue text.
FieldValue defaultValue(const FieldSpec& spec);

double numberField(const Node& node, std::string_view name, std::size_t index = 0,
                   double fallback = 0.0);
std::vector<double> numbersField(const Node& node, std::string_view name);
bool boolField(const Node& node, std::string_view name);
std::string stringField(const Node& node, std::string_view name);
std::vector<std::string> stringsField(const Node& node, std::string_view name);
const Node* nodeField(const Node& node, std::string_view name);
std::vector<const Node*> nodesField(const Node& node, std::string_view name);

} // namespace fl::scene
