#pragma once
// The kinds function nodes name by a word in the file — an FGeometry's
// `type`, an FTransform's `operation` — as types. The word is read once, at
// the edge; the mesher, the checker and the grader switch on the kind.
#include <cstdint>
#include <optional>
#include <string_view>

namespace fl::scene {

// FGeometry `type`: the surface f = 0, the FRep solid f >= 0, or x, y, z of
// parameters u, v, w.
enum class GeometryType : std::uint8_t { Implicit, Explicit, Parametric };
std::optional<GeometryType> geometryTypeNamed(std::string_view word);
std::string_view geometryTypeName(GeometryType type);

// FTransform `operation`: how the children are combined into one shape
// (`group`: they are not; each is drawn on its own).
enum class SetOperation : std::uint8_t { Group, Union, Intersection, Difference, Morph, Formula };
std::optional<SetOperation> setOperationNamed(std::string_view word);
std::string_view setOperationName(SetOperation operation);

} // namespace fl::scene
