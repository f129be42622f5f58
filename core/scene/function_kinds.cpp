#include "function_kinds.h"

#include <array>
#include <utility>

namespace fl::scene {
namespace {

constexpr std::array<std::pair<std::string_view, GeometryType>, 3> kGeometryTypes{{
    {"implicit", GeometryType::Implicit},
    {"explicit", GeometryType::Explicit},
    {"parametric", GeometryType::Parametric},
}};

constexpr std::array<std::pair<std::string_view, SetOperation>, 6> kSetOperations{{
    {"group", SetOperation::Group},
    {"union", SetOperation::Union},
    {"intersection", SetOperation::Intersection},
    {"difference", SetOperation::Difference},
    {"morph", SetOperation::Morph},
    {"formula", SetOperation::Formula},
}};

template <class Kind, std::size_t N>
std::optional<Kind> named(const std::array<std::pair<std::string_view, Kind>, N>& table,
                          std::string_view word) {
    for (const auto& [name, kind] : table)
        if (name == word) return kind;
    return std::nullopt;
}

template <class Kind, std::size_t N>
std::string_view nameIn(const std::array<std::pair<std::string_view, Kind>, N>& table, Kind kind) {
    for (const auto& [name, k] : table)
        if (k == kind) return name;
    return {};
}

} // namespace

std::optional<GeometryType> geometryTypeNamed(std::string_view word) {
    return named(kGeometryTypes, word);
}

std::string_view geometryTypeName(GeometryType type) {
    return nameIn(kGeometryTypes, type);
}

std::optional<SetOperation> setOperationNamed(std::string_view word) {
    return named(kSetOperations, word);
}

std::string_view setOperationName(SetOperation operation) {
    return nameIn(kSetOperations, operation);
}

} // namespace fl::scene
