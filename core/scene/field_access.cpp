#include "field_access.h"

#include "xml_reader.h"

namespace fl::scene {

FieldValue typeDefault(FieldType type) {
    FieldValue v;
    v.type = type;
    if (isMultiple(type) || holdsNodes(type) || type == FieldType::Unknown) return v;
    if (type == FieldType::SFString) {
        v.strings.emplace_back();
        v.stringOrigins.push_back({});
        return v;
    }
    if (type == FieldType::SFImage) {
        v.numbers = {0, 0, 0};
        return v;
    }
    v.numbers.assign(static_cast<std::size_t>(componentsPerElement(type)), 0.0);
    if (type == FieldType::SFRotation) v.numbers[2] = 1.0;
    if (type == FieldType::SFMatrix3f || type == FieldType::SFMatrix3d)
        v.numbers = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (type == FieldType::SFMatrix4f || type == FieldType::SFMatrix4d)
        v.numbers = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    return v;
}

FieldValue defaultValue(const FieldSpec& spec) {
    FieldValue v;
    v.type = spec.type;
    if (holdsNodes(spec.type) || spec.defaultValue.empty()) return v;
    if (spec.type == FieldType::SFString) {
        std::string_view s = spec.defaultValue;
        if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
        v.strings.emplace_back(s);
        return v;
    }
    std::string problem;
    parseXmlAttributeValue(spec.defaultValue, spec.type, v, {}, {}, problem);
    return v;
}

FieldValue fieldValue(const Node& node, std::string_view name) {
    if (const Field* f = node.field(name)) return f->value;
    if (node.spec)
        if (const FieldSpec* spec = findFieldSpec(*node.spec, name)) return defaultValue(*spec);
    return {};
}

double numberField(const Node& node, std::string_view name, std::size_t index, double fallback) {
    const FieldValue v = fieldValue(node, name);
    return index < v.numbers.size() ? v.numbers[index] : fallback;
}

std::vector<double> numbersField(const Node& node, std::string_view name) {
    return fieldValue(node, name).numbers;
}

bool boolField(const Node& node, std::string_view name) {
    return numberField(node, name) != 0.0;
}

std::string stringField(const Node& node, std::string_view name) {
    const FieldValue v = fieldValue(node, name);
    return v.strings.empty() ? std::string() : v.strings.front();
}

std::vector<std::string> stringsField(const Node& node, std::string_view name) {
    return fieldValue(node, name).strings;
}

const Node* nodeField(const Node& node, std::string_view name) {
    const Field* f = node.field(name);
    return f && !f->value.nodes.empty() ? f->value.nodes.front() : nullptr;
}

std::vector<const Node*> nodesField(const Node& node, std::string_view name) {
    const Field* f = node.field(name);
    if (!f) return {};
    return {f->value.nodes.begin(), f->value.nodes.end()};
}

} // namespace fl::scene
