#include "function_kinds.h"

#include "text/kind_names.h"

namespace fl::scene {
namespace {

using text::kindNamed;
using text::KindNames;
using text::nameOfKind;

constexpr KindNames<GeometryType, 3> kGeometryTypes{{
    {"implicit", GeometryType::Implicit},
    {"explicit", GeometryType::Explicit},
    {"parametric", GeometryType::Parametric},
}};

constexpr KindNames<SetOperation, 6> kSetOperations{{
    {"group", SetOperation::Group},
    {"union", SetOperation::Union},
    {"intersection", SetOperation::Intersection},
    {"difference", SetOperation::Difference},
    {"morph", SetOperation::Morph},
    {"formula", SetOperation::Formula},
}};

} // namespace

std::optional<GeometryType> geometryTypeNamed(std::string_view word) {
    return kindNamed(kGeometryTypes, word);
}

std::string_view geometryTypeName(GeometryType type) {
    return nameOfKind(kGeometryTypes, type);
}

std::optional<SetOperation> setOperationNamed(std::string_view word) {
    return kindNamed(kSetOperations, word);
}

std::string_view setOperationName(SetOperation operation) {
    return nameOfKind(kSetOperations, operation);
}

} // namespace fl::scene
