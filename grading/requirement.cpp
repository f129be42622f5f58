#include "requirement.h"

#include "scene/kind_names.h"

namespace fl::grading {
namespace {

constexpr scene::KindNames<RequirementKind, 9> kKinds{{
    {"implicit-surface", RequirementKind::ImplicitSurface},
    {"explicit-solid", RequirementKind::ExplicitSolid},
    {"parametric", RequirementKind::Parametric},
    {"set-operations", RequirementKind::SetOperations},
    {"morphing", RequirementKind::Morphing},
    {"animation", RequirementKind::Animation},
    {"level-of-detail", RequirementKind::LevelOfDetail},
    {"function-colour", RequirementKind::FunctionColour},
    {"tangible", RequirementKind::Tangible},
}};

} // namespace

std::optional<RequirementKind> requirementKindNamed(std::string_view word) {
    return scene::kindNamed(kKinds, word);
}

std::string_view requirementKindName(RequirementKind kind) {
    return scene::nameOfKind(kKinds, kind);
}

} // namespace fl::grading
