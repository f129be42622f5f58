#pragma once
// An FTransform whose `operation` combines its children (union,
// intersection, difference, morph or a formula) becomes one function: each
// child's definition inlined into one tape in the FTransform's coordinates,
// every instruction keeping the text it came from (ShapeMesh::texts), so a
// combined shape is meshed, picked and graded like any other.
#include "scene_walk.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::mesh {

struct ComposedShape {
    // field.box is not valid when the children's boxes do not overlap.
    ImplicitField field;
    const scene::Node* appearance = nullptr; // of the first FShape in it
    double resolution = 0;                   // the finest of its children's
    // The first FGeometry in it drawn with lod TRUE.
    const scene::Node* levelOfDetail = nullptr;
    std::vector<DefinitionText> texts; // SourceRange::source numbers these
};

// None when no child can take part (said in `notes`, with any child left out).
std::optional<ComposedShape> composeFunctionTransform(const SceneWalkContext& context,
                                                      WalkGuard& guard, const scene::Node& ft,
                                                      std::vector<std::string>& notes);

} // namespace fl::mesh
