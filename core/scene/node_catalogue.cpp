#include "node_catalogue.h"

#include <algorithm>
#include <vector>

namespace fl::scene {

const FieldSpec kMetadataField = {"metadata", FieldType::SFNode, AccessType::InputOutput, "NULL"};

std::span<const NodeSpec> nodeCatalogue() {
    static const std::vector<NodeSpec> all = [] {
        std::vector<NodeSpec> v(standardNodes().begin(), standardNodes().end());
        v.insert(v.end(), functionNodes().begin(), functionNodes().end());
        std::sort(v.begin(), v.end(),
                  [](const NodeSpec& a, const NodeSpec& b) { return a.name < b.name; });
        return v;
    }();
    return all;
}

const NodeSpec* findNodeSpec(std::string_view typeName) {
    const auto all = nodeCatalogue();
    auto it =
        std::lower_bound(all.begin(), all.end(), typeName,
                         [](const NodeSpec& n, std::string_view name) { return n.name < name; });
    return it != all.end() && it->name == typeName ? &*it : nullptr;
}

std::string_view eventBaseName(std::string_view name) {
    if (name.starts_with("set_")) return name.substr(4);
    if (name.ends_with("_changed")) return name.substr(0, name.size() - 8);
    return {};
}

const FieldSpec* findFieldSpec(const NodeSpec& node, std::string_view fieldName,
                               bool* isEventName) {
    if (isEventName) *isEventName = false;
    for (const FieldSpec& f : node.fields)
        if (f.name == fieldName) return &f;
    if (fieldName == kMetadataField.name) return &kMetadataField;
    // set_name and name_changed address an inputOutput field's events.
    const std::string_view base = eventBaseName(fieldName);
    if (base.empty()) return nullptr;
    for (const FieldSpec& f : node.fields)
        if (f.name == base && f.access == AccessType::InputOutput) {
            if (isEventName) *isEventName = true;
            return &f;
        }
    return nullptr;
}

} // namespace fl::scene
