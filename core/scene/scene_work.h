#pragma once
// What showing a scene will cost, before anyone meshes it (issue 26 §3): the
// instructions of its compiled formulas and, per function geometry, the cells
// a dense grid at the file's resolution has and the instructions evaluating
// its formula there takes. Adaptive meshing prunes most of them; this is the
// bound a class scene is held to before it reaches every window, and what
// `functionlab check --plan` prints.
#include "scene.h"

#include <cstddef>
#include <optional>

namespace fl::scene {

struct SceneWork {
    std::size_t tapeInstructions = 0; // every compiled definition, each PROTO instance counted
    double meshCells = 0;             // resolution^3 (u x v for parametric surfaces) per geometry
    double meshEvaluations = 0;       // cells x the instructions of the geometry's formula
    // Where the costliest geometry is written: the node, or the PROTO
    // instance (outermost) that made it; and that geometry's share.
    const Node* costliest = nullptr;
    double costliestEvaluations = 0;
};

// Needs the scene's compiled definitions (the scene as read with
// compileFunctions). Shapes in Inlines count too.
SceneWork estimateSceneWork(const Scene& scene);

// A bound on what showing a scene may cost (a class scene's); 0: no bound.
struct WorkBudget {
    double maxMeshCells = 0;
    double maxMeshEvaluations = 0;
};

// An error (SceneDiagnostic::overBudget) at the costliest shape when the
// scene's meshing work passes the budget; nothing when it does not.
std::optional<SceneDiagnostic> checkWorkBudget(const Scene& scene, const WorkBudget& budget);

} // namespace fl::scene
