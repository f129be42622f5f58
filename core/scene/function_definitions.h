#pragma once
// Compiles every formula of every function node when a scene loads, and checks
// what the formula engine cannot see (a geometry type, key/keyValue pairs,
// domain boxes). Formula errors are reported at the scene file's line:column.
#include "read_limits.h"
#include "scene.h"

#include <vector>

namespace fl::scene {

// Fills scene.definitions; appends diagnostics. A text met again (the nodes
// of PROTO instances) is compiled once and its tape shared. The work is
// bounded by `limits` (maxCompileSteps, maxTapeInstructions): past either,
// one located error and nothing more is compiled.
void compileFunctionDefinitions(Scene& scene, std::vector<SceneDiagnostic>& diagnostics,
                                const ReadLimits& limits = {});

// Which definition fields a function node type has, and what kind of formula
// each holds (docs/nodes.md).
struct DefinitionField {
    std::string_view field;
    formula::DefinitionKind kind;
};
std::vector<DefinitionField> definitionFields(const Node& node);

} // namespace fl::scene
