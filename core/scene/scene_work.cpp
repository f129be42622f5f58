#include "scene_work.h"

#include "field_access.h"
#include "function_kinds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fl::scene {

namespace {

// The cells a dense grid of the geometry has at its file resolution.
double cellsOf(const Node& geometry) {
    const double r = std::clamp(numberField(geometry, "resolution", 0, 32), 1.0, 1e6);
    if (geometryTypeNamed(stringField(geometry, "type")) != GeometryType::Parametric)
        return r * r * r;
    // A parametric surface is a u x v grid; a solid (w varying too) a volume.
    const std::vector<double> w = numbersField(geometry, "wRange");
    const bool solid = w.size() == 2 && w[1] > w[0];
    return solid ? r * r * r : r * r;
}

} // namespace

SceneWork estimateSceneWork(const Scene& scene) {
    SceneWork work;
    for (const Scene* shown : scenesShownBy(scene))
        for (const CompiledDefinition& d : shown->definitions) {
            const std::size_t size = d.tape ? d.tape->code.size() : 0;
            work.tapeInstructions += size;
            if (d.node->kind() != scene::NodeKind::FGeometry || d.field != "definition") continue;
            const double cells = cellsOf(*d.node);
            const double evaluations = cells * double(std::max<std::size_t>(size, 1));
            work.meshCells += cells;
            work.meshEvaluations += evaluations;
            if (evaluations > work.costliestEvaluations) {
                work.costliestEvaluations = evaluations;
                const Node* at = d.node;
                while (at->instance) // a body node copied for an instance: the instance
                    at = at->instance;
                work.costliest = at;
            }
        }
    return work;
}

std::optional<SceneDiagnostic> checkWorkBudget(const Scene& scene, const WorkBudget& budget) {
    const SceneWork work = estimateSceneWork(scene);
    const bool tooManyCells = budget.maxMeshCells > 0 && work.meshCells > budget.maxMeshCells;
    const bool tooMuchWork =
        budget.maxMeshEvaluations > 0 && work.meshEvaluations > budget.maxMeshEvaluations;
    if (!tooManyCells && !tooMuchWork) return std::nullopt;
    char figures[200];
    std::snprintf(figures, sizeof figures,
                  "%.3g cells and %.3g formula evaluations; at most %.3g and %.3g are allowed",
                  work.meshCells, work.meshEvaluations, budget.maxMeshCells,
                  budget.maxMeshEvaluations);
    const Node* at = work.costliest;
    return SceneDiagnostic{Severity::Error,
                           at ? scene.pathOf(at->file) : scene.pathOf(0),
                           at ? at->where : FilePos{},
                           std::string("meshing this scene at its resolutions would take ") +
                               figures + (at ? " (this shape costs the most)" : ""),
                           "lower the resolution of costly shapes, or use fewer or simpler "
                           "formulas",
                           true};
}

} // namespace fl::scene
