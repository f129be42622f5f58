#include "requirement.h"

#include <array>
#include <utility>

namespace fl::grading {
namespace {

constexpr std::array<std::pair<std::string_view, RequirementKind>, 8> kKinds{{
    {"implicit-surface", RequirementKind::ImplicitSurface},
    {"explicit-solid", RequirementKind::ExplicitSolid},
    {"parametric", RequirementKind::Parametric},
    {"set-operations", RequirementKind::SetOperations},
    {"morphing", RequirementKind::Morphing},
    {"animation", RequirementKind::Animation},
    {"level-of-detail", RequirementKind::LevelOfDetail},
    {"function-colour", RequirementKind::FunctionColour},
}};

} // namespace

std::optional<RequirementKind> requirementKindNamed(std::string_view word) {
    for (const auto& [name, kind] : kKinds)
        if (name == word) return kind;
    return std::nullopt;
}

std::string_view requirementKindName(RequirementKind kind) {
    for (const auto& [name, k] : kKinds)
        if (k == kind) return name;
    return "?";
}

} // namespace fl::grading
