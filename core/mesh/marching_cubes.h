#pragma once
// Dense marching cubes: the baseline the adaptive mesher is measured against
// (`functionlab bench accuracy`). Every grid corner is evaluated, crossings
// are linearly interpolated, no interval pruning, no refinement — the classic
// algorithm (Lorensen & Cline 1987) with its case table generated from the
// cube's faces at start-up (ambiguous faces separate the inside corners, so
// neighbouring cells agree and the mesh has no cracks).
#include "implicit_field.h"
#include "mesh.h"

namespace fl::mesh {

struct DenseResult {
    Mesh mesh; // positions and triangles; normals from the triangles
    EvaluationCounts evaluations;
    double milliseconds = 0;
};

// Cells along the box's longest side, as meshImplicit; `threads` 0: one per core.
// Slabs run in parallel; vertices on slab borders are not welded.
DenseResult marchingCubes(const ImplicitField& field, double resolution, int threads = 0);

} // namespace fl::mesh
