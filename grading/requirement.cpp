#include "requirement.h"

#include "text/kind_names.h"

namespace fl::grading {
namespace {

constexpr text::KindNames<RequirementKind, 10> kKinds{{
    {"implicit-surface", RequirementKind::ImplicitSurface},
    {"explicit-solid", RequirementKind::ExplicitSolid},
    {"parametric", RequirementKind::Parametric},
    {"set-operations", RequirementKind::SetOperations},
    {"morphing", RequirementKind::Morphing},
    {"animation", RequirementKind::Animation},
    {"level-of-detail", RequirementKind::LevelOfDetail},
    {"function-colour", RequirementKind::FunctionColour},
    {"tangible", RequirementKind::Tangible},
    {"pde-surface", RequirementKind::PdeSurface},
}};

} // namespace

std::optional<RequirementKind> requirementKindNamed(std::string_view word) {
    return text::kindNamed(kKinds, word);
}

std::string_view requirementKindName(RequirementKind kind) {
    return text::nameOfKind(kKinds, kind);
}

} // namespace fl::grading
