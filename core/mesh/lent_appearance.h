#pragma once
// Standard shapes without an appearance of their own take the one an FShape
// without geometry beside them lends (docs/nodes.md, "Standard shapes with
// function properties"): its FMaterial's colour over the lender's box — its
// bboxCenter/bboxSize, else the bounds of every shape it lends to — in the
// lender's coordinates. Done after the walk: a lender may come after the
// shapes it lends to.
#include "scene_walk.h"

namespace fl::mesh {

void lendAppearances(const SceneWalkContext& context, SceneMeshes& out);

} // namespace fl::mesh
