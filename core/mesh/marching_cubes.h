#pragma once
// Dense marching cubes: the baseline the adaptive mesher is measured against
// (`functionlab bench accuracy`). Every grid corner is evaluated, crossings
// are linearly interpolated, no interval pruning, no refinement — the classic
// algorithm (Lorensen & Cline 1987) with its case table generated from the
// cube's faces at start-up (ambiguous faces separate the inside corners, so
// neighbouring cells agree and the mesh has no cracks).
#include "field_names.h"
#include "mesh.h"

#include <array>
#include <cstdint>

namespace fl::mesh {

struct DenseResult {
    Mesh mesh; // positions and triangles; normals from the triangles
    EvaluationCounts evaluations;
    double milliseconds = 0;
};

// The pieces of surface in one cell, by the same rule as the case table: for
// a corner configuration (bit i set: corner i = x + 2y + 4z is inside), the
// piece each of the 12 edges is on (-1: no crossing; edges 0-3 run along x
// at (y, z) = (0,0) (1,0) (0,1) (1,1), 4-7 along y at (x, z), 8-11 along z
// at (x, y)). Dual contouring uses it to give each piece its own vertex.
struct EdgeGroups {
    std::array<std::int8_t, 12> group{};
    int count = 0;
};
const EdgeGroups& edgeGroups(int config);

// Cells along the box's longest side, as meshImplicit; `threads` 0: one per core.
// Slabs run in parallel; vertices on slab borders are not welded.
DenseResult marchingCubes(const ImplicitField& field, double resolution, int threads = 0);

} // namespace fl::mesh
