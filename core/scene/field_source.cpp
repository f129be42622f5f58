#include "field_source.h"

#include "field_access.h"

namespace fl::scene {

double FieldSource::number(const Node& n, std::string_view field, std::size_t index,
                           double fallback) const {
    const FieldValue v = value(n, field);
    return index < v.numbers.size() ? v.numbers[index] : fallback;
}

std::vector<double> FieldSource::numbers(const Node& n, std::string_view field) const {
    return value(n, field).numbers;
}

bool FieldSource::flag(const Node& n, std::string_view field) const {
    return number(n, field) != 0.0;
}

std::string FieldSource::string(const Node& n, std::string_view field) const {
    const FieldValue v = value(n, field);
    return v.strings.empty() ? std::string() : v.strings.front();
}

std::vector<std::string> FieldSource::strings(const Node& n, std::string_view field) const {
    return value(n, field).strings;
}

const Node* FieldSource::node(const Node& n, std::string_view field) const {
    const FieldValue v = value(n, field);
    return v.nodes.empty() ? nullptr : v.nodes.front();
}

std::vector<const Node*> FieldSource::nodes(const Node& n, std::string_view field) const {
    const FieldValue v = value(n, field);
    return {v.nodes.begin(), v.nodes.end()};
}

FieldValue FileFields::value(const Node& node, std::string_view field) const {
    return fieldValue(node, field);
}

} // namespace fl::scene
